#include "example_dialog.h"
#include "example_text.h"

#include "model/examples.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace devsurf::app {

ExampleDialog::ExampleDialog(QWidget* parent)
    : QDialog(parent), m_examples(new QComboBox(this)), m_size(new QSpinBox(this)),
      m_description(new QLabel(this)) {
    setWindowTitle(tr("New from Example"));
    for (const model::ExampleInfo& info : model::builtInExamples()) {
        m_examples->addItem(QString::fromStdString(info.name));
    }
    m_description->setWordWrap(true);
    auto* form = new QFormLayout;
    form->addRow(tr("&Example:"), m_examples);
    form->addRow(tr("&Size:"), m_size);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_description);
    layout->addWidget(buttons);
    connect(m_examples, &QComboBox::currentIndexChanged, this, &ExampleDialog::exampleChanged);
    m_examples->setCurrentIndex(1); // the annulus: the paper's showcase
    exampleChanged(m_examples->currentIndex());
}

void ExampleDialog::exampleChanged(int index) {
    const model::ExampleInfo& info = model::builtInExamples().at(static_cast<std::size_t>(index));
    m_size->setRange(info.minSize, info.maxSize);
    m_size->setValue(info.defaultSize);
    m_description->setText(exampleDescription(info.name));
}

QString ExampleDialog::exampleName() const {
    return m_examples->currentText();
}

int ExampleDialog::exampleSize() const {
    return m_size->value();
}

} // namespace devsurf::app
