#include "example_dialog.h"

#include "model/examples.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace devsurf::app {

namespace {

QString description(const std::string& name) {
    // The model's descriptions are English; these are what the user reads.
    if (name == "sheet") {
        return ExampleDialog::tr("A flat rectangle of size × size strips.");
    }
    if (name == "annulus") {
        return ExampleDialog::tr("A flat annulus of size rings cut by radial rulings.");
    }
    if (name == "cylinder") {
        return ExampleDialog::tr("A closed cylinder of strips, size sectors around.");
    }
    if (name == "fig8") {
        return ExampleDialog::tr(
            "A flat square of size × size strips with curved creases, ready to fold: every "
            "interior crease carries the curved-fold condition and the bottom corners are "
            "pinned. Drag the middle vertices up (Drag tool, G).");
    }
    if (name == "fig6") {
        return ExampleDialog::tr(
            "Two strips joined by one curved crease with the curved-fold condition, the bottom "
            "corners pinned; size intervals per curve. Drag a top corner up to fold it.");
    }
    return ExampleDialog::tr("A strip, a pointed strip, a cone and a planar patch; size "
                             "intervals per curve.");
}

} // namespace

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
    m_description->setText(description(info.name));
}

QString ExampleDialog::exampleName() const {
    return m_examples->currentText();
}

int ExampleDialog::exampleSize() const {
    return m_size->value();
}

} // namespace devsurf::app
