#include "help_dialogs.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QFile>
#include <QHeaderView>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTableWidget>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace devsurf::app {

namespace {

// Menu text as the user reads it: without the mnemonic ampersand and the trailing ellipsis.
QString plainText(QString text) {
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    if (text.endsWith(QChar(0x2026))) {
        text.chop(1);
    }
    return text;
}

void collect(const QMenu* menu, const QString& path, QTableWidget* table) {
    for (QAction* action : menu->actions()) {
        if (action->menu() != nullptr) {
            collect(action->menu(), path + QStringLiteral(" ▸ ") + plainText(action->text()),
                    table);
            continue;
        }
        if (action->isSeparator() || action->shortcuts().isEmpty()) {
            continue;
        }
        QStringList keys;
        for (const QKeySequence& key : action->shortcuts()) {
            keys << key.toString(QKeySequence::NativeText);
        }
        const int row = table->rowCount();
        table->insertRow(row);
        table->setItem(row, 0, new QTableWidgetItem(keys.join(QStringLiteral(", "))));
        table->setItem(
            row, 1, new QTableWidgetItem(path + QStringLiteral(" ▸ ") + plainText(action->text())));
    }
}

} // namespace

ManualWindow::ManualWindow(QWidget* parent) : QDialog(parent), m_browser(new QTextBrowser(this)) {
    setObjectName(QStringLiteral("manualWindow"));
    setWindowTitle(tr("DevSurf User Manual"));
    setAttribute(Qt::WA_DeleteOnClose);
    m_browser->setObjectName(QStringLiteral("manualBrowser"));
    m_browser->setOpenExternalLinks(true);
    m_browser->setSource(QUrl(manualSource()), QTextDocument::MarkdownResource);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_browser);
    layout->addWidget(buttons);
    resize(820, 760);
}

QString ManualWindow::manualSource() {
    const QString language = QLocale().name().section(QLatin1Char('_'), 0, 0);
    const QString translated = QStringLiteral(":/manual/manual_%1.md").arg(language);
    return QFile::exists(translated) ? QStringLiteral("qrc") + translated
                                     : QStringLiteral("qrc:/manual/manual.md");
}

ShortcutsDialog::ShortcutsDialog(QMainWindow* window)
    : QDialog(window), m_table(new QTableWidget(0, 2, this)) {
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard Shortcuts"));
    setAttribute(Qt::WA_DeleteOnClose);
    m_table->setHorizontalHeaderLabels({tr("Keys"), tr("Command")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    for (QAction* top : window->menuBar()->actions()) {
        if (top->menu() != nullptr) {
            collect(top->menu(), plainText(top->text()), m_table);
        }
    }
    // What the views do with the mouse: gestures are not actions, so they are listed here.
    const QString mouse[][2] = {
        {tr("Click"), tr("Select a vertex, edge or patch (empty space clears)")},
        {tr("Shift+Click"), tr("Add to or remove from the selection")},
        {tr("Ctrl+Drag"), tr("Select the vertices in a rectangle (with Shift: add them)")},
        {tr("Left drag"), tr("3D view: rotate; development view: pan")},
        {tr("Middle drag"), tr("Pan")},
        {tr("Wheel or right drag"), tr("Zoom")},
    };
    for (const auto& entry : mouse) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_table->setItem(row, 0, new QTableWidgetItem(entry[0]));
        m_table->setItem(row, 1, new QTableWidgetItem(entry[1]));
    }
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(640, 620);
}

} // namespace devsurf::app
