#include "edit_refusal.h"
#include "help_dialogs.h"
#include "io/project_file.h"
#include "main_window.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/subdivide_strip_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "model/topology_edits.h"
#include "position_dialog.h"
#include "problem_text.h"
#include "reactions/file_reactions.h"
#include "test_registry.h"
#include "translations.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>

#include <cmath>
#include <functional>

using namespace devsurf;

namespace {

// Runs check on the next modal dialog once it is shown, then closes it with the given button
// (or rejects it).
void onNextModal(std::function<void(QWidget*)> check) {
    QTimer::singleShot(0, [check = std::move(check)] {
        QWidget* modal = QApplication::activeModalWidget();
        if (modal != nullptr) {
            check(modal);
        }
    });
}

QStringList menuTitles(const app::MainWindow& window) {
    QStringList titles;
    for (QAction* menu : window.menuBar()->actions()) {
        titles << menu->text();
    }
    return titles;
}

bool near(const model::Vec3& a, const model::Vec3& b) {
    return model::distance(a, b) < 1e-6;
}

// Restores the tests' interface language after a test that switched the language.
struct LanguageAfterwards {
    ~LanguageAfterwards() { test::installTestLanguage(); }
};

} // namespace

class TstUsability : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(test::installTestLanguage()); }
    void init() { QSettings().clear(); }

    void germanAndJapaneseMenusAndStandardButtons() {
        LanguageAfterwards restore;
        struct Case {
            QLocale locale;
            QString titles;
            QString save;
            QString standardSave;
        };
        const Case cases[] = {
            {QLocale(QLocale::German, QLocale::Germany),
             QStringLiteral("&Datei,&Bearbeiten,&Ansicht,&Werkzeuge,&Hilfe"),
             QStringLiteral("&Speichern"), QStringLiteral("Speichern")},
            {QLocale(QLocale::Japanese, QLocale::Japan),
             QStringLiteral("ファイル(&F),編集(&E),表示(&V),ツール(&T),ヘルプ(&H)"),
             QStringLiteral("保存(&S)"), QStringLiteral("保存")},
        };
        for (const Case& c : cases) {
            QLocale::setDefault(c.locale);
            QVERIFY(app::installTranslations(QLocale()));
            app::MainWindow window;
            window.show();
            QCOMPARE(menuTitles(window).join(','), c.titles);
            QCOMPARE(window.action("actionSave")->text(), c.save);
            // Qt's own translation: the standard buttons of the unsaved-changes question.
            QMessageBox box(QMessageBox::Question, QString(), QString(),
                            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
            QCOMPARE(box.button(QMessageBox::Save)->text(), c.standardSave);
        }
    }

    void everyTranslationIsFinished() {
        const QDir dir(QStringLiteral(DEVSURF_SOURCE_DIR "/translations"));
        const QStringList files = dir.entryList({QStringLiteral("devsurf_*.ts")});
        for (const char* language : {"de", "ja", "en"}) {
            QVERIFY(files.contains(QStringLiteral("devsurf_%1.ts").arg(language)));
        }
        for (const QString& name : files) {
            QFile file(dir.filePath(name));
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(file.readAll());
            QVERIFY2(!text.contains(QStringLiteral("type=\"unfinished\"")), qPrintable(name));
            QVERIFY2(text.contains(QStringLiteral("<message")), qPrintable(name));
        }
    }

    void pluralFormsForOneAndTwo() {
        LanguageAfterwards restore;
        document::Document doc;
        doc.resetProject(model::makeExample("sheet", 2));
        const std::pair<const char*, QStringList> cases[] = {
            {"en", {"Move 1 vertex", "Move 2 vertices"}},
            {"de", {"1 Ecke verschieben", "2 Ecken verschieben"}},
            {"ja", {"1 個の頂点を移動", "2 個の頂点を移動"}},
        };
        for (const auto& [language, expected] : cases) {
            QLocale::setDefault(QLocale(QString::fromLatin1(language)));
            QVERIFY(app::installTranslations(QLocale()));
            const auto one =
                document::MoveVerticesCommand::createTranslation(doc, 0, {0}, {0, 0, 1});
            const auto two =
                document::MoveVerticesCommand::createTranslation(doc, 0, {0, 1}, {0, 0, 1});
            QVERIFY(one && two);
            QCOMPARE(one.command()->text(), expected[0]);
            QCOMPARE(two.command()->text(), expected[1]);
        }
    }

    void toolbarShowsEveryActionAt1280Pixels() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* toolbar = window.findChild<QToolBar*>(QStringLiteral("MainToolBar"));
        QVERIFY(toolbar != nullptr);
        QCOMPARE(toolbar->toolButtonStyle(), Qt::ToolButtonIconOnly);
        int buttons = 0;
        for (QAction* action : toolbar->actions()) {
            if (action->isSeparator()) {
                continue;
            }
            QWidget* widget = toolbar->widgetForAction(action);
            QVERIFY2(widget != nullptr && widget->isVisible(), qPrintable(action->objectName()));
            QVERIFY2(!action->icon().isNull(), qPrintable(action->objectName()));
            QVERIFY2(!action->toolTip().isEmpty(), qPrintable(action->objectName()));
            QVERIFY(toolbar->rect().contains(widget->geometry()));
            ++buttons;
        }
        QVERIFY(buttons >= 15);
        auto* chevron = toolbar->findChild<QToolButton*>(QStringLiteral("qt_toolbar_ext_button"));
        QVERIFY(chevron == nullptr || !chevron->isVisible());

        // Undo's button keeps its place and width while its text changes.
        QWidget* undo = toolbar->widgetForAction(window.action("actionUndo"));
        const QRect before = undo->geometry();
        document::Document* doc = window.workspace()->document();
        app::pushOrExplain(
            *doc, document::MoveVerticesCommand::createTranslation(*doc, 0, {0, 1, 2}, {0, 0, 1}));
        QVERIFY(window.action("actionUndo")->isEnabled());
        QCOMPARE(undo->geometry(), before);
    }

    void resetLayoutRestoresDocksAndViews() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* toolbar = window.findChild<QToolBar*>(QStringLiteral("MainToolBar"));
        window.findChild<QDockWidget*>(QStringLiteral("PatchesDock"))->hide();
        toolbar->hide();
        window.action("actionView3D")->trigger();
        QVERIFY(!window.developmentView()->isVisible());
        window.action("actionResetLayout")->trigger();
        QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("PatchesDock"))->isVisible());
        QVERIFY(toolbar->isVisible());
        QVERIFY(window.developmentView()->isVisible());
        QVERIFY(window.surfaceView()->isVisible());
    }

    void standardViewsScaleBarAndTriad() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        views::SurfaceView* view = window.surfaceView();
        QVERIFY(view->hasOrientationTriad());
        QVERIFY(!window.developmentView()->hasOrientationTriad());
        window.action("actionViewTop")->trigger();
        QVERIFY(near(view->viewDirection(), {0, 0, -1}));
        window.action("actionViewFront")->trigger();
        QVERIFY(near(view->viewDirection(), {0, 1, 0}));
        window.action("actionViewRight")->trigger();
        QVERIFY(near(view->viewDirection(), {-1, 0, 0}));
        window.action("actionViewIsometric")->trigger();
        const double third = 1.0 / std::sqrt(3.0);
        QVERIFY(near(view->viewDirection(), {-third, third, -third}));
        window.action("actionResetView")->trigger();
        const model::Vec3 start = model::Vec3(-1.0, 1.6, -1.2) / model::Vec3(1, 1.6, 1.2).norm();
        QVERIFY(near(view->viewDirection(), start));

        // Both views: a bar of a round length, 40–120 px long, its text in mm.
        for (views::SceneView* scene : {static_cast<views::SceneView*>(view),
                                        static_cast<views::SceneView*>(window.developmentView())}) {
            scene->grabImage(); // renders
            QTRY_VERIFY(scene->scaleBarPixels() > 0.0);
            QVERIFY(scene->scaleBarPixels() >= 40.0 && scene->scaleBarPixels() <= 120.0);
            const double length = scene->scaleBarLength();
            const double mantissa = length / std::pow(10.0, std::floor(std::log10(length)));
            QVERIFY(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                    std::abs(mantissa - 5) < 1e-9);
            QVERIFY2(scene->scaleBarText().endsWith(QStringLiteral(" mm")),
                     qPrintable(scene->scaleBarText()));
        }
        // The development view's bar: its pixels are the distance two points so far apart are
        // drawn at.
        views::DevelopmentView* dev = window.developmentView();
        const double length = dev->scaleBarLength();
        const QPoint a = dev->projectToWidget({0, 0, 0});
        const QPoint b = dev->projectToWidget({length, 0, 0});
        QVERIFY(std::abs(std::abs(b.x() - a.x()) - dev->scaleBarPixels()) <= 1.5);

        // Patch numbers: off by default, every patch's number in the development view when on.
        QVERIFY(dev->patchLabelTexts().isEmpty());
        window.action("actionPatchLabels")->trigger();
        dev->grabImage();
        QTRY_COMPARE(dev->patchLabelTexts().size(), qsizetype(9));
        view->grabImage();
        window.action("actionViewTop")->trigger();
        view->grabImage();
        QTRY_COMPARE(view->patchLabelTexts().size(), qsizetype(9)); // all seen from above
        window.action("actionPatchLabels")->trigger();
        QVERIFY(dev->patchLabelTexts().isEmpty());
    }

    void patchColoursStayWhenAnotherPatchIsSubdivided() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 3);
        window.action("actionViewTop")->trigger();
        document::Document* doc = window.workspace()->document();
        const model::CompositeSurface before = doc->project().surfaces[0];
        const std::vector<model::FaceId> row = model::stripRow(before, 0);
        // The centre of every patch outside the subdivided row, and its colour on screen.
        views::SurfaceView* view = window.surfaceView();
        const QImage imageBefore = view->grabImage();
        const double dpr = imageBefore.devicePixelRatio();
        std::map<model::FaceId, QRgb> colours;
        for (const auto& [face, loop] : before.faces()) {
            if (std::find(row.begin(), row.end(), face) != row.end()) {
                continue;
            }
            model::Vec3 centre;
            for (model::VertexId v : loop) {
                centre += before.position(v);
            }
            const QPoint at = view->projectToWidget(centre / static_cast<double>(loop.size()));
            colours[face] = imageBefore.pixel(
                QPoint(static_cast<int>(at.x() * dpr), static_cast<int>(at.y() * dpr)));
        }
        QCOMPARE(colours.size(), before.faces().size() - row.size());
        window.workspace()->selection()->set({{document::Pick::Kind::Face, 0, 0}});
        onNextModal([](QWidget* modal) {
            auto* dialog = qobject_cast<app::PositionDialog*>(modal);
            if (dialog != nullptr) {
                dialog->accept();
            }
        });
        window.action("actionSubdivide")->trigger();
        QCOMPARE(doc->undoStack()->count(), 1);
        QVERIFY(doc->project().surfaces[0].faces().size() > before.faces().size());
        const QImage imageAfter = view->grabImage();
        for (const auto& [face, colour] : colours) {
            model::Vec3 centre;
            const auto& loop = before.faceLoop(face);
            for (model::VertexId v : loop) {
                centre += before.position(v);
            }
            const QPoint at = view->projectToWidget(centre / static_cast<double>(loop.size()));
            QCOMPARE(imageAfter.pixel(
                         QPoint(static_cast<int>(at.x() * dpr), static_cast<int>(at.y() * dpr))),
                     colour);
            QCOMPARE(views::SurfaceView::patchColor(face).rgb(),
                     views::SurfaceView::patchColor(face).rgb());
        }
    }

    void creaseIsPreviewedBeforeOk() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        document::Document* doc = window.workspace()->document();
        window.workspace()->selection()->set({{document::Pick::Kind::Face, 0, 5}});
        int shownLines = 0;
        int linesAfterMove = 0;
        onNextModal([&](QWidget* modal) {
            auto* dialog = qobject_cast<app::PositionDialog*>(modal);
            if (dialog == nullptr) {
                return;
            }
            shownLines = window.surfaceView()->previewLineCount();
            dialog->percentBox()->setValue(30.0);
            linesAfterMove = window.surfaceView()->previewLineCount();
            dialog->reject();
        });
        window.action("actionSubdivide")->trigger();
        QVERIFY(shownLines > 0);
        QCOMPARE(linesAfterMove, shownLines);
        QCOMPARE(window.surfaceView()->previewLineCount(), 0);
        QCOMPARE(doc->undoStack()->count(), 0);

        onNextModal([](QWidget* modal) {
            if (auto* dialog = qobject_cast<app::PositionDialog*>(modal)) {
                dialog->percentBox()->setValue(25.0);
                dialog->accept();
            }
        });
        window.action("actionSubdivide")->trigger();
        QCOMPARE(doc->undoStack()->count(), 1);
        QVERIFY(dynamic_cast<const document::SubdivideStripCommand*>(doc->undoStack()->command(0)));
        QVERIFY(doc->undoStack()->text(0).contains(QStringLiteral("5"))); // the patch
        QCOMPARE(window.surfaceView()->previewLineCount(), 0);
    }

    void relabelOnTheCylinderIsDisabledAndSaysWhy() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("cylinder"), 0);
        const model::CompositeSurface& s = window.workspace()->document()->project().surfaces[0];
        QAction* relabel = window.action("actionRelabel");
        window.workspace()->selection()->clear();
        const QString selectFirst = relabel->toolTip();
        for (const auto& [id, record] : s.edges()) {
            window.workspace()->selection()->set({{document::Pick::Kind::Edge, 0, id}});
            QVERIFY(!relabel->isEnabled());
            // Why this edge cannot be relabelled, not the general hint.
            QVERIFY(!relabel->toolTip().isEmpty());
            QVERIFY2(relabel->toolTip() != selectFirst, qPrintable(relabel->toolTip()));
        }
        // Where relabelling works (the planar patch of the mixed example), it is offered.
        window.workspace()->newFromExample(QStringLiteral("mixed"), 0);
        const model::CompositeSurface& mixed =
            window.workspace()->document()->project().surfaces[0];
        bool someEnabled = false;
        for (const auto& [id, record] : mixed.edges()) {
            window.workspace()->selection()->set({{document::Pick::Kind::Edge, 0, id}});
            someEnabled = someEnabled || relabel->isEnabled();
        }
        QVERIFY(someEnabled);
    }

    void openingDegenerateGeometryListsTheProblems() {
        model::Project project = model::makeExample("sheet", 2);
        model::CompositeSurface& surface = project.surfaces[0];
        const model::CompositeSurface original = surface;
        for (const auto& [id, p] : original.vertices()) {
            surface.moveVertex(id, {0, 0, 0});
        }
        for (const auto& [id, record] : original.edges()) {
            if (record.isSpline()) {
                surface.setControlPoints(
                    id, std::vector<model::Vec3>(record.controlPoints.size(), model::Vec3{}));
            }
        }
        const QString path = m_dir.filePath("zeros.devsurf");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        const std::string bytes = io::encodeProject(project);
        file.write(bytes.data(), static_cast<qint64>(bytes.size()));
        file.close();

        app::MainWindow window;
        window.show();
        QString text;
        QString details;
        onNextModal([&](QWidget* modal) {
            if (auto* box = qobject_cast<QMessageBox*>(modal)) {
                text = box->text();
                details = box->detailedText();
                box->accept();
            }
        });
        QVERIFY(!window.workspace()->open(path));
        QVERIFY2(text.contains(QStringLiteral("zeros.devsurf")), qPrintable(text));
        // Every problem under the details, at least one a face; the first eight in the message
        // and the count of the others.
        const qsizetype problems = details.split(QLatin1Char('\n')).size();
        QVERIFY2(problems >= qsizetype(surface.faces().size()), qPrintable(details));
        QVERIFY(problems > 8);
        QCOMPARE(text.count(QStringLiteral("\n• ")), 8);
        QVERIFY2(text.contains(QString::number(problems - 8)), qPrintable(text));
        // Each patch's zero area, worded as the application words it (in any language).
        for (const auto& [face, loop] : surface.faces()) {
            QVERIFY(details.contains(
                app::ProblemText::of(model::faceProblem(model::ProblemCode::ZeroArea, face))));
        }
    }

    void interchangeJsonKeepsItsExtension() {
        using app::ExportJsonReaction;
        QCOMPARE(ExportJsonReaction::jsonPathFor("/tmp/a.json", nullptr), QString("/tmp/a.json"));
        QCOMPARE(ExportJsonReaction::jsonPathFor("/tmp/a.JSON", nullptr), QString("/tmp/a.JSON"));
        QCOMPARE(ExportJsonReaction::jsonPathFor("/tmp/a", nullptr), QString("/tmp/a.json"));
        QString asked;
        for (const char* answer : {"rename", "cancel"}) {
            const bool rename = QByteArray(answer) == "rename";
            onNextModal([&asked, rename](QWidget* modal) {
                auto* box = qobject_cast<QMessageBox*>(modal);
                if (box == nullptr) {
                    return;
                }
                asked = box->text();
                for (QAbstractButton* button : box->buttons()) {
                    if (rename == (box->buttonRole(button) == QMessageBox::AcceptRole)) {
                        button->click();
                        return;
                    }
                }
            });
            const QString result = ExportJsonReaction::jsonPathFor("/tmp/pattern.svg", nullptr);
            QVERIFY(asked.contains(QStringLiteral("pattern.svg")));
            QCOMPARE(result, rename ? QString("/tmp/pattern.json") : QString());
        }
    }

    void manualAndShortcutsFromTheHelpMenu() {
        app::MainWindow window;
        window.show();
        window.action("actionManual")->trigger();
        auto* manual = window.findChild<app::ManualWindow*>();
        QVERIFY(manual != nullptr);
        QTextDocument* text = manual->browser()->document();
        // The manual of the interface's language, its seven chapters.
        QCOMPARE(manual->browser()->source(), QUrl(app::ManualWindow::manualSource()));
        int chapters = 0;
        for (QTextBlock block = text->begin(); block.isValid(); block = block.next()) {
            chapters += block.blockFormat().headingLevel() == 2 ? 1 : 0;
        }
        QVERIFY2(chapters >= 7, qPrintable(QString::number(chapters)));
        // Every picture the manual shows is there.
        int images = 0;
        for (QTextBlock block = text->begin(); block.isValid(); block = block.next()) {
            for (auto it = block.begin(); !it.atEnd(); ++it) {
                const QTextCharFormat format = it.fragment().charFormat();
                if (format.isImageFormat()) {
                    const QString name = format.toImageFormat().name();
                    const QVariant image = text->resource(QTextDocument::ImageResource, QUrl(name));
                    QVERIFY2(image.isValid(), qPrintable(name));
                    ++images;
                }
            }
        }
        QVERIFY(images >= 2);
        manual->close();
        {
            // The Japanese manual for a Japanese interface.
            LanguageAfterwards restore;
            QLocale::setDefault(QLocale(QLocale::Japanese, QLocale::Japan));
            QCOMPARE(app::ManualWindow::manualSource(), QStringLiteral("qrc:/manual/manual_ja.md"));
            QVERIFY(QFile::exists(QStringLiteral(":/manual/manual_ja.md")));
            // The English one for English.
            QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
            QCOMPARE(app::ManualWindow::manualSource(), QStringLiteral("qrc:/manual/manual.md"));
        }

        window.action("actionShortcuts")->trigger();
        auto* dialog = window.findChild<app::ShortcutsDialog*>();
        QVERIFY(dialog != nullptr);
        QStringList listed;
        for (int row = 0; row < dialog->table()->rowCount(); ++row) {
            listed << dialog->table()->item(row, 0)->text();
        }
        for (QAction* action : window.findChildren<QAction*>()) {
            const bool inMenu = !action->associatedObjects().isEmpty();
            if (inMenu && !action->shortcut().isEmpty()) {
                QVERIFY2(listed.contains(action->shortcut().toString(QKeySequence::NativeText)),
                         qPrintable(action->objectName()));
            }
        }
        const QKeySequence save = window.action("actionSave")->shortcut();
        QCOMPARE(save, QKeySequence(Qt::CTRL | Qt::Key_S));
        QVERIFY(listed.contains(save.toString(QKeySequence::NativeText)));
        QVERIFY(listed.contains(QStringLiteral("0")));
    }
};

DEVSURF_REGISTER_TEST(TstUsability);
#include "tst_usability.moc"
