// View ▸ Language: the interface language is chosen in the application, remembered in the
// settings, and the next window comes up in it.
#include "main_window.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "test_registry.h"
#include "translations.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QMessageBox>
#include <QSettings>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

using namespace devsurf;

namespace {

// Answers the next message box "Later" (its reject button; never restarts) and records whether
// it offered to restart now.
void answerLater(bool& shown, bool& offeredRestart) {
    QTimer::singleShot(0, [&shown, &offeredRestart] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (box == nullptr) {
            return;
        }
        shown = true;
        offeredRestart = false;
        QAbstractButton* later = nullptr;
        for (QAbstractButton* button : box->buttons()) {
            const QMessageBox::ButtonRole role = box->buttonRole(button);
            offeredRestart = offeredRestart || role == QMessageBox::AcceptRole;
            if (role == QMessageBox::RejectRole) {
                later = button;
            }
        }
        if (later != nullptr) {
            later->click();
        } else {
            box->reject();
        }
    });
}

} // namespace

class TstLanguage : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }
    void cleanup() {
        QSettings().clear();
        test::installTestLanguage(); // the language this run of the tests uses
    }

    void choosingGermanIsRememberedAndTheNextWindowIsGerman() {
        app::installTranslations(QLocale(QLocale::English, QLocale::UnitedStates));
        app::MainWindow first;
        first.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        QAction* system = first.action(QStringLiteral("actionLanguageSystem"));
        QAction* german = first.action(QStringLiteral("actionLanguageGerman"));
        QVERIFY(system != nullptr && german != nullptr);
        QVERIFY(system->isChecked() && !german->isChecked());
        const QString english = first.action(QStringLiteral("actionSolve"))->text();

        bool shown = false;
        bool offeredRestart = false;
        answerLater(shown, offeredRestart);
        german->trigger();
        QVERIFY(shown);
        QVERIFY(offeredRestart); // nothing unsaved: restarting now loses nothing
        QVERIFY(german->isChecked());
        QCOMPARE(QSettings().value(QStringLiteral("interface/language")).toString(),
                 QStringLiteral("de"));
        QCOMPARE(app::chosenLanguage(), QStringLiteral("de"));

        // The next start: translations from the setting, then the window.
        QVERIFY(app::installInterfaceTranslations());
        QCOMPARE(QLocale().language(), QLocale::German);
        app::MainWindow next;
        QVERIFY(next.action(QStringLiteral("actionLanguageGerman"))->isChecked());
        const QString solve = next.action(QStringLiteral("actionSolve"))->text();
        QVERIFY(solve != english);
        QCOMPARE(solve, QCoreApplication::translate("devsurf::app::MainWindow", "&Solve"));
    }

    void withUnsavedChangesNoRestartIsOffered() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        document::Document* doc = window.workspace()->document();
        doc->undoStack()->push(
            document::PinVerticesCommand::create(*doc, 0, {0}, true).takeCommand().release());
        QVERIFY(doc->isModified());
        bool shown = false;
        bool offeredRestart = true;
        answerLater(shown, offeredRestart);
        window.action(QStringLiteral("actionLanguageJapanese"))->trigger();
        QVERIFY(shown);
        QVERIFY(!offeredRestart);
        QCOMPARE(app::chosenLanguage(), QStringLiteral("ja"));
        QVERIFY(doc->isModified());

        // Back to the system's language: the setting goes.
        answerLater(shown, offeredRestart);
        window.action(QStringLiteral("actionLanguageSystem"))->trigger();
        QVERIFY(!QSettings().contains(QStringLiteral("interface/language")));
        QCOMPARE(app::chosenLanguage(), QString());
    }
};

DEVSURF_REGISTER_TEST(TstLanguage);
#include "tst_language.moc"
