// Every dialog and window the main window opens shows its texts as meant: no literal '&' where
// a mnemonic was written for a label without a buddy (Qt shows those as they are).
#include "main_window.h"
#include "model/document/selection.h"
#include "test_registry.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QGroupBox>
#include <QLabel>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QTabWidget>
#include <QTest>
#include <QTextDocument>
#include <QTimer>

using namespace devsurf;
using document::Pick;

namespace {

// The text Qt draws for a text with mnemonics: "&x" draws "x", "&&" draws "&".
QString withoutMnemonics(const QString& text) {
    QString shown;
    for (int i = 0; i < text.size(); ++i) {
        if (text[i] == QLatin1Char('&') && i + 1 < text.size()) {
            ++i; // the next character is drawn (underlined, or the second '&')
        }
        shown += text[i];
    }
    return shown;
}

// What a label draws: rich text as its plain text, a plain label's mnemonic only when it has a
// buddy.
QString shownText(const QLabel* label) {
    const bool rich = label->textFormat() == Qt::RichText ||
                      (label->textFormat() == Qt::AutoText && Qt::mightBeRichText(label->text()));
    if (rich) {
        QTextDocument document;
        document.setHtml(label->text());
        return document.toPlainText();
    }
    return label->buddy() != nullptr ? withoutMnemonics(label->text()) : label->text();
}

// "class 'text'" for every label, button, group box and tab of `top` that draws a literal '&'.
QStringList literalAmpersands(const QWidget* top) {
    QStringList found;
    auto check = [&found](const QObject* widget, const QString& shown, const QString& text) {
        if (shown.contains(QLatin1Char('&'))) {
            found << QStringLiteral("%1 '%2'").arg(
                QString::fromLatin1(widget->metaObject()->className()), text);
        }
    };
    for (const QLabel* label : top->findChildren<QLabel*>()) {
        check(label, shownText(label), label->text());
    }
    for (const QAbstractButton* button : top->findChildren<QAbstractButton*>()) {
        check(button, withoutMnemonics(button->text()), button->text());
    }
    for (const QGroupBox* box : top->findChildren<QGroupBox*>()) {
        check(box, withoutMnemonics(box->title()), box->title());
    }
    for (const QTabWidget* tabs : top->findChildren<QTabWidget*>()) {
        for (int i = 0; i < tabs->count(); ++i) {
            check(tabs, withoutMnemonics(tabs->tabText(i)), tabs->tabText(i));
        }
    }
    return found;
}

} // namespace

class TstDialogTexts : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void noDialogShowsALiteralAmpersand() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("fig8")));
        // The actions that open a dialog or a window: "…" by convention, and Help's.
        QList<QAction*> opening;
        const QStringList help{QStringLiteral("actionManual"), QStringLiteral("actionShortcuts"),
                               QStringLiteral("actionAbout")};
        for (QAction* action : window.findChildren<QAction*>()) {
            if (action->text().endsWith(QChar(0x2026)) || help.contains(action->objectName())) {
                opening << action;
            }
        }
        QVERIFY(opening.size() >= 10);
        // Selections under which the actions that need one are enabled.
        const std::set<Pick> selections[] = {
            {},
            {{Pick::Kind::Vertex, 0, 5}},
            {{Pick::Kind::Vertex, 0, 5}, {Pick::Kind::Vertex, 0, 6}},
            {{Pick::Kind::Face, 0, 1}}};
        QStringList problems;
        QStringList seen;
        QStringList notOpened;
        for (QAction* action : opening) {
            for (const std::set<Pick>& picks : selections) {
                if (action->isEnabled()) {
                    break;
                }
                window.workspace()->selection()->set(picks);
            }
            if (!action->isEnabled()) {
                notOpened << action->objectName();
                continue;
            }
            const QList<QWidget*> before = QApplication::topLevelWidgets();
            QWidget* opened = nullptr;
            // A modal dialog runs its own event loop: a timer checks it there and closes it.
            QTimer poll;
            connect(&poll, &QTimer::timeout, &poll, [&] {
                QWidget* modal = QApplication::activeModalWidget();
                if (modal == nullptr || !modal->isVisible()) {
                    return;
                }
                opened = modal;
                problems << literalAmpersands(modal).replaceInStrings(
                    QRegularExpression(QStringLiteral("^")), modal->windowTitle() + ": ");
                seen << QString::fromLatin1(modal->metaObject()->className());
                if (auto* dialog = qobject_cast<QDialog*>(modal)) {
                    dialog->reject();
                } else {
                    modal->close();
                }
            });
            poll.start(20);
            action->trigger();
            poll.stop();
            // A window shown without a modal loop (the manual, the shortcuts) is there now.
            for (QWidget* top : QApplication::topLevelWidgets()) {
                if (opened == nullptr && !before.contains(top) && top->isVisible() &&
                    top->isWindow() && top != &window) {
                    opened = top;
                    problems << literalAmpersands(top);
                    seen << QString::fromLatin1(top->metaObject()->className());
                    top->close();
                }
            }
            if (opened == nullptr) {
                notOpened << action->objectName();
            }
        }
        qInfo("checked: %s; opened nothing: %s", qPrintable(seen.join(QStringLiteral(", "))),
              qPrintable(notOpened.join(QStringLiteral(", "))));
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("; "))));
        // The dialogs of our own that carry forms were among them.
        for (const char* name :
             {"devsurf::app::PatternExportDialog", "devsurf::app::ShapeExportDialog",
              "devsurf::app::ExampleDialog", "devsurf::app::MoveDialog"}) {
            QVERIFY2(seen.contains(QString::fromLatin1(name)), name);
        }
    }
};

DEVSURF_REGISTER_TEST(TstDialogTexts);
#include "tst_dialog_texts.moc"
