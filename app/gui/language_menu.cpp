#include "language_menu.h"

#include "model/document/document.h"
#include "translations.h"
#include "workspace.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QMenu>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QWidget>

namespace devsurf::app {

namespace {

// The translation context of the menu's texts.
class LanguageMenu {
    Q_DECLARE_TR_FUNCTIONS(LanguageMenu)
};

// Says when the choice takes effect; restarts now if asked (the design is saved or unchanged:
// the new process opens its file, or starts as DevSurf always does).
void announce(Workspace* workspace) {
    QWidget* window = workspace->window();
    const document::Document* doc = workspace->document();
    QMessageBox box(QMessageBox::Information, LanguageMenu::tr("Language"),
                    LanguageMenu::tr("The interface will use this language from the next start of "
                                     "DevSurf."),
                    QMessageBox::NoButton, window);
    box.setObjectName(QStringLiteral("languageChangedBox"));
    QPushButton* restart = nullptr;
    if (!doc->isModified()) {
        restart = box.addButton(LanguageMenu::tr("&Restart Now"), QMessageBox::AcceptRole);
    } else {
        box.setInformativeText(
            LanguageMenu::tr("Save your changes and restart DevSurf to use it now."));
    }
    box.addButton(restart != nullptr ? LanguageMenu::tr("&Later") : LanguageMenu::tr("OK"),
                  QMessageBox::RejectRole);
    box.exec();
    if (restart == nullptr || box.clickedButton() != restart) {
        return;
    }
    QStringList arguments;
    if (!doc->filePath().isEmpty()) {
        arguments << doc->filePath();
    }
    if (QProcess::startDetached(QCoreApplication::applicationFilePath(), arguments)) {
        window->close();
    }
}

} // namespace

void addLanguageMenu(QMenu* view, Workspace* workspace) {
    QMenu* menu = view->addMenu(LanguageMenu::tr("&Language"));
    menu->setObjectName(QStringLiteral("menuLanguage"));
    auto* group = new QActionGroup(menu);
    // Each language also in its own words, so that anyone finds theirs.
    const struct {
        const char* name;
        const char* code;
        QString text;
    } entries[] = {{"actionLanguageSystem", "", LanguageMenu::tr("&System Language")},
                   {"actionLanguageEnglish", "en", LanguageMenu::tr("&English")},
                   {"actionLanguageGerman", "de", LanguageMenu::tr("&German (Deutsch)")},
                   {"actionLanguageJapanese", "ja", LanguageMenu::tr("&Japanese (日本語)")}};
    const QString chosen = chosenLanguage();
    for (const auto& entry : entries) {
        QAction* action = menu->addAction(entry.text);
        action->setObjectName(QString::fromLatin1(entry.name));
        action->setCheckable(true);
        const QString code = QString::fromLatin1(entry.code);
        action->setChecked(code == chosen);
        group->addAction(action);
        QObject::connect(action, &QAction::triggered, menu, [workspace, code] {
            if (code == chosenLanguage()) {
                return;
            }
            setChosenLanguage(code);
            announce(workspace);
        });
    }
}

} // namespace devsurf::app
