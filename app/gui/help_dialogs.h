#pragma once

#include <QDialog>

class QMainWindow;
class QTextBrowser;
class QTableWidget;

namespace devsurf::app {

// Help ▸ User Manual: docs/manual/manual.md (compiled in as a resource, with its pictures) in a
// browser window that stays open beside the main window.
class ManualWindow : public QDialog {
    Q_OBJECT
public:
    explicit ManualWindow(QWidget* parent);
    QTextBrowser* browser() const { return m_browser; }
    // The manual in the interface language if there is one (manual_de.md, ...), else English.
    static QString manualSource();

private:
    QTextBrowser* m_browser;
};

// Help ▸ Keyboard Shortcuts: every action of the window's menus that has a shortcut, read from
// the actions themselves so that the list is always true, plus the mouse gestures of the views.
class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ShortcutsDialog(QMainWindow* window);
    QTableWidget* table() const { return m_table; }

private:
    QTableWidget* m_table;
};

} // namespace devsurf::app
