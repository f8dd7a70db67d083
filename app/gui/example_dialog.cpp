#include "example_dialog.h"
#include "example_text.h"

#include "model/examples.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

namespace devsurf::app {

namespace {
const QString kHoldSheetKey = QStringLiteral("newFromExample/holdSheet");
} // namespace

ExampleDialog::ExampleDialog(QWidget* parent)
    : QDialog(parent), m_examples(new QComboBox(this)), m_size(new QSpinBox(this)),
      m_holdSheet(new QCheckBox(tr("&Hold the sheet it starts as"), this)),
      m_description(new QLabel(this)) {
    setWindowTitle(tr("New from Example"));
    for (const model::ExampleInfo& info : model::builtInExamples()) {
        m_examples->addItem(QString::fromStdString(info.name));
    }
    m_description->setWordWrap(true);
    // Wide enough for the longest description in a few lines; describe() fits the height.
    m_description->setMinimumWidth(60 * fontMetrics().averageCharWidth());
    auto* form = new QFormLayout;
    form->addRow(tr("&Example:"), m_examples);
    form->addRow(tr("&Size:"), m_size);
    m_holdSheet->setObjectName(QStringLiteral("exampleHoldSheet"));
    form->addRow(QString(), m_holdSheet);
    connect(m_holdSheet, &QCheckBox::toggled, this, [this](bool on) {
        if (m_holdSheet->isEnabled()) {
            QSettings().setValue(kHoldSheetKey, on);
        }
        describe();
    });
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
    const QSignalBlocker blocker(m_holdSheet);
    m_holdSheet->setEnabled(info.canHoldItsSheet);
    if (info.canHoldItsSheet) {
        m_holdSheet->setChecked(rememberedSheet() == model::ExampleSheet::Held);
        m_holdSheet->setToolTip(
            info.name == "cylinder"
                ? tr("Keep the development around the cylinder the design's unfolding rolls "
                     "onto, as Tools ▸ Hold the Sheet does: a drag that the sheet cannot follow "
                     "lags behind the mouse instead of stretching it.")
                : tr("Keep the development: the design stays foldable from the flat sheet it "
                     "starts as, and a drag that the sheet cannot follow lags behind the mouse "
                     "instead of stretching it. Of two pins at the ends of a straight line in "
                     "the sheet only the first stays pinned, since the sheet would keep that "
                     "line straight. Tools ▸ Hold the Sheet turns it off later."));
    } else if (info.holdsSheetAsBuilt) {
        m_holdSheet->setChecked(true);
        m_holdSheet->setToolTip(tr("This example comes holding its sheet."));
    } else {
        m_holdSheet->setChecked(false);
        m_holdSheet->setToolTip(
            tr("A torus unfolds into no one sheet: it keeps local conditions only."));
    }
    describe();
}

void ExampleDialog::describe() {
    const std::string name = exampleName().toStdString();
    const QString held = m_holdSheet->isEnabled() && m_holdSheet->isChecked()
                             ? heldExampleDescription(name)
                             : QString();
    m_description->setText(held.isEmpty() ? exampleDescription(name) : held);
    if (layout() != nullptr) {
        layout()->activate();
        resize(width(),
               heightForWidth(width()) > 0 ? heightForWidth(width()) : sizeHint().height());
    }
}

QString ExampleDialog::exampleName() const {
    return m_examples->currentText();
}

int ExampleDialog::exampleSize() const {
    return m_size->value();
}

model::ExampleSheet ExampleDialog::rememberedSheet() {
    return QSettings().value(kHoldSheetKey, true).toBool() ? model::ExampleSheet::Held
                                                           : model::ExampleSheet::AsBuilt;
}

model::ExampleSheet ExampleDialog::exampleSheet() const {
    return m_holdSheet->isChecked() ? model::ExampleSheet::Held : model::ExampleSheet::AsBuilt;
}

} // namespace devsurf::app
