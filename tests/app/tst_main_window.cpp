#include "autosaver.h"
#include "edit_refusal.h"
#include "example_dialog.h"
#include "example_text.h"
#include "io/project_file.h"
#include "main_window.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/commands/crease_condition_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "panels/patch_panel.h"
#include "panels/patch_tree_model.h"
#include "panels/properties_panel.h"
#include "surface_transform.h"
#include "test_registry.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLockFile>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include <QTimer>
#include <QTranslator>
#include <QTreeView>
#include <QUndoStack>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include <set>

using namespace devsurf;

namespace {

// Distinct colours in the central half of an image: a blank view has one (or a gradient),
// geometry adds patch colours and lines.
int coloursInCentre(const QImage& image) {
    std::set<QRgb> colours;
    const int w = image.width();
    const int h = image.height();
    for (int y = h / 4; y < 3 * h / 4; y += 2) {
        for (int x = w / 4; x < 3 * w / 4; x += 2) {
            colours.insert(image.pixel(x, y));
        }
    }
    return static_cast<int>(colours.size());
}

// Answers the next modal message box with the given button.
void answerNextMessageBox(QMessageBox::StandardButton button) {
    QTimer::singleShot(0, [button] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (box != nullptr && box->button(button) != nullptr) {
            box->button(button)->click();
        }
    });
}

} // namespace

class TstMainWindow : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void init() { QSettings().clear(); }

    void opensEveryExampleAndRendersBothViews() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        for (const model::ExampleInfo& info : model::builtInExamples()) {
            window.workspace()->newFromExample(QString::fromStdString(info.name), 0);
            QCOMPARE(window.workspace()->document()->project().surfaces.front().name(), info.name);
            const QImage view3d = window.surfaceView()->grabImage();
            const QImage development = window.developmentView()->grabImage();
            QVERIFY2(coloursInCentre(view3d) > 8, info.name.c_str());
            QVERIFY2(coloursInCentre(development) > 8, info.name.c_str());
        }
    }

    void newFromExampleHoldsTheSheetByDefault() {
        // File ▸ New from Example: an example that starts flat holds its sheet unless the
        // designer clears the box, which is remembered; others show why they cannot choose.
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* newAction = window.findChild<QAction*>(QStringLiteral("actionNew"));
        QVERIFY(newAction);
        // Runs the dialog: `check` sees it with `example` chosen, then it is accepted (also
        // when a check failed, so that the dialog never waits).
        auto runDialog = [&](const QString& example, const std::function<void(QCheckBox*)>& check) {
            bool seen = false;
            QTimer::singleShot(0, [&] {
                auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
                if (dialog == nullptr) {
                    return;
                }
                auto* examples = dialog->findChild<QComboBox*>();
                auto* box = dialog->findChild<QCheckBox*>(QStringLiteral("exampleHoldSheet"));
                if (examples != nullptr && box != nullptr) {
                    examples->setCurrentText(example);
                    check(box);
                    seen = !QTest::currentTestFailed();
                }
                dialog->accept();
            });
            newAction->trigger();
            QVERIFY(seen);
        };
        auto surface = [&] { return window.workspace()->document()->project().surfaces.front(); };
        // The description is the held example's while the box is checked.
        auto described = [](QCheckBox* box, const QString& text) {
            const QList<QLabel*> labels = box->window()->findChildren<QLabel*>();
            return std::any_of(labels.begin(), labels.end(),
                               [&](const QLabel* label) { return label->text().contains(text); });
        };
        runDialog(QStringLiteral("fig8"), [&](QCheckBox* box) {
            QVERIFY(box->isEnabled());
            QVERIFY(box->isChecked());
            const QString note = app::heldExampleDescription("fig8");
            QVERIFY(!note.isEmpty());
            QVERIFY(described(box, note));
            box->setChecked(false);
            QVERIFY(!described(box, note));
            box->setChecked(true);
            QVERIFY(described(box, note));
        });
        QCOMPARE(surface().name(), std::string("fig8"));
        QVERIFY(surface().keepsDevelopment());
        QCOMPARE(surface().sheetDomain().shape, model::SheetShape::Rectangle);
        QCOMPARE(surface().pinnedVertices().size(), std::size_t(1));

        runDialog(QStringLiteral("fig8"), [](QCheckBox* box) { box->setChecked(false); });
        QVERIFY(!surface().keepsDevelopment());
        QCOMPARE(surface().pinnedVertices().size(), std::size_t(2));
        QCOMPARE(app::ExampleDialog::rememberedSheet(), model::ExampleSheet::AsBuilt);
        runDialog(QStringLiteral("annulus"), [](QCheckBox* box) { QVERIFY(!box->isChecked()); });
        QVERIFY(!surface().keepsDevelopment());

        runDialog(QStringLiteral("torus"), [](QCheckBox* box) {
            QVERIFY(!box->isEnabled());
            QVERIFY(!box->isChecked());
            QVERIFY(!box->toolTip().isEmpty()); // why it cannot (in the test's language)
        });
        runDialog(QStringLiteral("column"), [](QCheckBox* box) {
            QVERIFY(!box->isEnabled());
            QVERIFY(box->isChecked());
        });
        QVERIFY(surface().keepsDevelopment()); // as built
        // A disabled box does not change what is remembered.
        QCOMPARE(app::ExampleDialog::rememberedSheet(), model::ExampleSheet::AsBuilt);
        runDialog(QStringLiteral("annulus"), [](QCheckBox* box) { box->setChecked(true); });
        QCOMPARE(surface().sheetDomain().shape, model::SheetShape::Annulus);
        QCOMPARE(app::ExampleDialog::rememberedSheet(), model::ExampleSheet::Held);
    }

    void pickingAVertexSelectsItEverywhere() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 3);
        const QPoint at = window.surfaceView()->projectVertexToWidget(0, 5);
        QTest::mouseClick(window.surfaceView()->glWidget(), Qt::LeftButton, {}, at);
        const document::Pick expected{document::Pick::Kind::Vertex, 0, 5};
        QVERIFY(window.workspace()->selection()->contains(expected));
        QVERIFY(window.developmentView()->highlightedPicks().count(expected) == 1);
        QVERIFY(window.propertiesPanel()->describedPick() == expected);
        QCOMPARE(window.propertiesPanel()->coordinateEditor(0)->value(), 100.0);
    }

    void aSelectedCreaseShowsItsSidesConditionAndFold() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 3);
        document::Document& doc = *window.workspace()->document();
        // Fold the part beyond y = 100 up by 30° (vertices and every control point): the
        // crease y = 100 becomes a valley.
        model::Project project = doc.project();
        model::CompositeSurface& surface = project.surfaces.front();
        devsurf::test::foldBeyond(surface, 100.0, 30.0 * M_PI / 180.0);
        doc.resetProject(project);
        const model::EdgeId crease = doc.surface(0).edgeBetween(4, 5);
        QVERIFY(crease != model::kInvalidId);
        window.workspace()->selection()->add({document::Pick::Kind::Edge, 0, crease});
        const app::PropertiesPanel* panel = window.propertiesPanel();
        const QString text = panel->summaryText();
        QVERIFY(panel->describedPick() == (document::Pick{document::Pick::Kind::Edge, 0, crease}));
        QVERIFY(panel->describedCrease().has_value());
        QCOMPARE(panel->describedCrease()->edge, crease);
        QCOMPARE(panel->describedCrease()->assignment, model::FoldAssignment::Valley);
        QCOMPARE(qRound(panel->describedCrease()->foldAngleDegrees * 10.0), -300);
        QVERIFY2(text.contains(QStringLiteral("30.0")), qPrintable(text));
        QCOMPARE(doc.surface(0).edge(crease).condition, model::CreaseCondition::None);
        QVERIFY2(text.contains(
                     document::CreaseConditionCommand::conditionText(model::CreaseCondition::None)),
                 qPrintable(text));
        // A boundary curve is described with no fold.
        window.workspace()->selection()->clear();
        const model::EdgeId boundary = doc.surface(0).edgeBetween(0, 1);
        QCOMPARE(doc.surface(0).facesOfEdge(boundary).size(), std::size_t(1));
        window.workspace()->selection()->add({document::Pick::Kind::Edge, 0, boundary});
        QVERIFY(panel->describedPick() ==
                (document::Pick{document::Pick::Kind::Edge, 0, boundary}));
        QVERIFY(!panel->describedCrease().has_value());
        QVERIFY(!panel->summaryText().isEmpty());
    }

    void patchTreeAndViewsShareTheSelection() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("mixed"), 2);
        app::PatchPanel* panel = window.patchPanel();
        const QModelIndex face2 = panel->model()->indexOfFace(0, 2);
        QVERIFY(face2.isValid());
        panel->treeView()->selectionModel()->select(face2, QItemSelectionModel::ClearAndSelect |
                                                               QItemSelectionModel::Rows);
        const document::Pick pick{document::Pick::Kind::Face, 0, 2};
        QVERIFY(window.workspace()->selection()->contains(pick));
        QVERIFY(window.surfaceView()->highlightedPicks().count(pick) == 1);
        window.workspace()->selection()->set({{document::Pick::Kind::Face, 0, 3}});
        const auto rows = panel->treeView()->selectionModel()->selectedRows();
        QCOMPARE(rows.size(), qsizetype(1));
        QCOMPARE(panel->model()->entityAt(rows.front()).second, model::FaceId(3));
    }

    void saveAsThenOpenReproducesTheDocument() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        const std::string original = io::encodeProject(window.workspace()->document()->project());
        const QString path = m_dir.filePath("roundtrip.devsurf");
        QVERIFY(window.workspace()->saveTo(path));
        QVERIFY(window.windowTitle().contains("roundtrip.devsurf"));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        QVERIFY(window.workspace()->open(path));
        QCOMPARE(io::encodeProject(window.workspace()->document()->project()), original);
        QVERIFY(window.workspace()->recentFiles().contains(QFileInfo(path).absoluteFilePath()));
    }

    void modifiedMarkerFollowsUndoAndRedo() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        document::Document* doc = window.workspace()->document();
        QVERIFY(!window.isWindowModified());
        const QString refusal = app::pushOrExplain(
            *doc, document::MoveVerticesCommand::createTranslation(*doc, 0, {5}, {0, 0, 10}));
        QVERIFY(refusal.isEmpty());
        QVERIFY(window.isWindowModified());
        QVERIFY(devsurf::test::undoCommand<document::MoveVerticesCommand>(*doc) != nullptr);
        QVERIFY(window.action("actionUndo")->isEnabled());
        QVERIFY(window.action("actionUndo")->text().contains(doc->undoStack()->undoText()));
        window.action("actionUndo")->trigger();
        QVERIFY(!window.isWindowModified());
        window.action("actionRedo")->trigger();
        QVERIFY(window.isWindowModified());
        QVERIFY(window.workspace()->saveTo(m_dir.filePath("marker.devsurf")));
        QVERIFY(!window.isWindowModified());
    }

    void editingACoordinatePushesAnUndoableMove() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        document::Document* doc = window.workspace()->document();
        window.workspace()->selection()->set({{document::Pick::Kind::Vertex, 0, 5}});
        const std::string before = io::encodeProject(doc->project());
        window.propertiesPanel()->coordinateEditor(2)->setValue(25.0);
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(doc->project().surfaces[0].position(5).z, 25.0);
        QVERIFY(doc->project().surfaces[0].validate().empty());
        doc->undoStack()->undo();
        QCOMPARE(io::encodeProject(doc->project()), before);
        QCOMPARE(window.propertiesPanel()->coordinateEditor(2)->value(), 0.0);
    }

    void toolActionsFollowTheSelection() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        QAction* subdivide = window.action("actionSubdivide");
        QAction* move = window.action("actionMoveRotate");
        QVERIFY(!subdivide->isEnabled());
        QVERIFY(!move->isEnabled());
        window.workspace()->selection()->set({{document::Pick::Kind::Face, 0, 4}});
        QVERIFY(subdivide->isEnabled());
        window.workspace()->selection()->set({{document::Pick::Kind::Vertex, 0, 1}});
        QVERIFY(move->isEnabled());
        QVERIFY(!window.action("actionDelete")->isEnabled());
        QVERIFY(!window.action("actionDelete")->toolTip().isEmpty());
    }

    void unsavedChangesPromptOnClose() {
        app::MainWindow window;
        window.show();
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        document::Document* doc = window.workspace()->document();
        app::pushOrExplain(
            *doc, document::MoveVerticesCommand::createTranslation(*doc, 0, {5}, {0, 0, 10}));
        answerNextMessageBox(QMessageBox::Cancel);
        QVERIFY(!window.close());
        QVERIFY(window.isVisible());
        answerNextMessageBox(QMessageBox::Discard);
        QVERIFY(window.close());
    }

    void droppingAProjectFileOpensIt() {
        const QString path = m_dir.filePath("dropped.devsurf");
        io::saveProjectFile(model::makeExample("cylinder"), path);
        app::MainWindow window;
        window.show();
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, {});
        QApplication::sendEvent(&window, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, {});
        QApplication::sendEvent(&window, &drop);
        QCOMPARE(window.workspace()->document()->project().surfaces.front().name(),
                 std::string("cylinder"));
    }

    void damagedFileShowsADialogAndKeepsTheDocument() {
        const QString path = m_dir.filePath("damaged.devsurf");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("DEVSURF this is not a project");
        file.close();
        app::MainWindow window;
        window.show();
        window.workspace()->newFromExample(QStringLiteral("mixed"), 0);
        const std::string before = io::encodeProject(window.workspace()->document()->project());
        QString shown;
        QTimer::singleShot(0, [&shown] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (box != nullptr) {
                shown = box->text();
                box->accept();
            }
        });
        QVERIFY(!window.workspace()->open(path));
        QVERIFY(shown.contains("damaged.devsurf"));
        QCOMPARE(io::encodeProject(window.workspace()->document()->project()), before);
    }

    // Issue 46, 3: a device without an end is refused after its first bytes: no growth to
    // gigabytes, no std::bad_alloc ending the application.
    void openingAnEndlessDeviceIsRefusedAtOnce() {
        if (!QFileInfo::exists(QStringLiteral("/dev/zero"))) {
            QSKIP("no /dev/zero");
        }
        app::MainWindow window;
        window.show();
        struct rusage before {};
        getrusage(RUSAGE_SELF, &before);
        QString shown;
        QTimer::singleShot(0, [&shown] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                shown = box->text();
                box->accept();
            }
        });
        QVERIFY(!window.workspace()->open(QStringLiteral("/dev/zero")));
        QVERIFY(shown.contains("/dev/zero"));
        struct rusage after {};
        getrusage(RUSAGE_SELF, &after);
        QVERIFY2(after.ru_maxrss - before.ru_maxrss < 256 * 1024,
                 qPrintable(QString::number(after.ru_maxrss - before.ru_maxrss) + " kB"));
    }

    void unsavedWorkSurvivesACrash() {
        const QString original = m_dir.filePath("crash.devsurf");
        QString leftover;
        std::string edited;
        {
            app::MainWindow window;
            app::Workspace* workspace = window.workspace();
            workspace->newFromExample(QStringLiteral("sheet"), 0);
            QVERIFY(workspace->saveTo(original));
            workspace->autosaver()->saveNow();
            QVERIFY(!QFile::exists(workspace->autosaver()->recoveryFile())); // nothing unsaved
            document::Document* doc = workspace->document();
            app::pushOrExplain(
                *doc, document::MoveVerticesCommand::createTranslation(*doc, 0, {5}, {0, 0, 7}));
            workspace->autosaver()->saveNow();
            const QString recovery = workspace->autosaver()->recoveryFile();
            QVERIFY(QFile::exists(recovery));
            edited = io::encodeProject(doc->project());
            QCOMPARE(io::encodeProject(io::loadProjectFile(recovery)), edited);
            // A crashed session leaves its file without a live lock: copy it as such a leftover.
            leftover = QFileInfo(recovery).dir().filePath("session-999999-1.devsurf");
            app::Autosaver::removeRecoveryFile(leftover); // from an earlier run that failed
            QVERIFY(QFile::copy(recovery, leftover));
            QVERIFY(QFile::copy(recovery + ".origin", leftover + ".origin"));
            answerNextMessageBox(QMessageBox::Discard);
            QVERIFY(window.close());
            QVERIFY(!QFile::exists(recovery)); // a clean exit leaves nothing behind
        }
        {
            // Saving removes the recovery copy at once: it is older than the saved file, and
            // a crash before the next interval must not offer it as unsaved work.
            app::MainWindow window;
            app::Workspace* workspace = window.workspace();
            QVERIFY(workspace->open(original));
            document::Document* doc = workspace->document();
            app::pushOrExplain(
                *doc, document::MoveVerticesCommand::createTranslation(*doc, 0, {6}, {0, 0, 3}));
            workspace->autosaver()->saveNow();
            const QString recovery = workspace->autosaver()->recoveryFile();
            QVERIFY(QFile::exists(recovery));
            QVERIFY(workspace->save());
            QVERIFY(!QFile::exists(recovery));
            QVERIFY(!QFile::exists(recovery + ".origin"));
            // Undoing back to the saved state after another edit removes it as well.
            app::pushOrExplain(
                *doc, document::MoveVerticesCommand::createTranslation(*doc, 0, {6}, {0, 0, 2}));
            workspace->autosaver()->saveNow();
            QVERIFY(QFile::exists(recovery));
            doc->undoStack()->undo();
            QVERIFY(!doc->isModified());
            QVERIFY(!QFile::exists(recovery));
            // The saved file is what the next start sees; put the file back as the crash left
            // it for the recovery below.
            QVERIFY(workspace->saveTo(original));
        }
        app::MainWindow next;
        next.show();
        QVERIFY(app::Autosaver::staleRecoveryFiles(app::Autosaver::defaultDirectory())
                    .contains(leftover));
        answerNextMessageBox(QMessageBox::Yes);
        next.workspace()->offerRecovery();
        document::Document* doc = next.workspace()->document();
        QCOMPARE(io::encodeProject(doc->project()), edited);
        QVERIFY(doc->isModified());
        QCOMPARE(doc->filePath(), QFileInfo(original).absoluteFilePath());
        QVERIFY(!QFile::exists(leftover));
        QVERIFY(next.workspace()->save());
        QCOMPARE(io::encodeProject(io::loadProjectFile(original)), edited);
    }

    // Issue 46, 1 in the application: File ▸ Export Interchange JSON never writes over the
    // design's own project file, also not through a link or a second name ending in .json; the
    // user is told, and the next name that is not the project works.
    void jsonExportRefusesTheProjectFile() {
        const QString design = m_dir.filePath(QStringLiteral("json-self.devsurf"));
        io::saveProjectFile(model::makeExample("annulus"), design, io::Backup::None);
        const auto bytesOf = [](const QString& path) {
            QFile file(path);
            return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
        };
        const QByteArray before = bytesOf(design);
        const QString link = m_dir.filePath(QStringLiteral("json-self-link.json"));
        const QString hard = m_dir.filePath(QStringLiteral("json-self-hard.json"));
        QVERIFY(QFile::link(design, link));
        QVERIFY(::link(QFile::encodeName(design).constData(),
                       QFile::encodeName(hard).constData()) == 0);
        const QString other = m_dir.filePath(QStringLiteral("json-self-export.json"));
        app::MainWindow window;
        window.show();
        QVERIFY(window.workspace()->open(design));
        for (const QString& target : {link, hard, other}) {
            // Answers the file dialog with the target, then counts the message boxes.
            int boxes = 0;
            bool chosen = false;
            QTimer driver;
            driver.setInterval(0);
            connect(&driver, &QTimer::timeout, &driver, [&] {
                QWidget* modal = QApplication::activeModalWidget();
                if (auto* files = qobject_cast<QFileDialog*>(modal); files && !chosen) {
                    chosen = true;
                    files->selectFile(target);
                    // Queued: its "replace it?" box runs a loop this timer must answer too.
                    QMetaObject::invokeMethod(files, "accept", Qt::QueuedConnection);
                } else if (auto* box = qobject_cast<QMessageBox*>(modal)) {
                    if (QAbstractButton* replace = box->button(QMessageBox::Yes)) {
                        replace->click(); // the file dialog's "replace it?"
                    } else {
                        ++boxes; // the refusal
                        box->accept();
                    }
                }
            });
            driver.start();
            window.action("actionExportJson")->trigger();
            driver.stop();
            QCOMPARE(bytesOf(design), before);
            if (target == other) {
                QCOMPARE(boxes, 0);
                QVERIFY(bytesOf(other).contains("devsurf-interchange"));
            } else {
                QCOMPARE(boxes, 1);
                QVERIFY(QFileInfo(link).isSymLink());
            }
        }
        QVERIFY(window.workspace()->open(design));
    }

    // Issue 46, 6: a session killed before it wrote a recovery file leaves only its lock; the
    // next start removes it (a running session's lock stays).
    void staleLocksWithoutRecoveryFileAreRemoved() {
        QTemporaryDir dir;
        // A lock as a session writes it, then given to a process that has ended.
        QProcess child;
        child.start(QStringLiteral("sh"), {QStringLiteral("-c"), QStringLiteral("echo $$")});
        QVERIFY(child.waitForFinished(30000));
        const QByteArray deadPid = child.readAllStandardOutput().trimmed();
        QVERIFY(!deadPid.isEmpty());
        QByteArray contents;
        {
            QLockFile own(dir.filePath(QStringLiteral("own.lock")));
            QVERIFY(own.tryLock(0));
            QFile file(dir.filePath(QStringLiteral("own.lock")));
            QVERIFY(file.open(QIODevice::ReadOnly));
            contents = file.readAll();
        }
        contents = deadPid + contents.mid(contents.indexOf('\n'));
        const QString dead = dir.filePath(QStringLiteral("session-1-2.devsurf.lock"));
        {
            QFile file(dead);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(contents);
        }
        document::Document document;
        app::Autosaver running(&document, dir.path(), 60000);
        QVERIFY(QFile::exists(running.recoveryFile() + QStringLiteral(".lock")));
        QVERIFY(app::Autosaver::staleRecoveryFiles(dir.path()).isEmpty());
        QVERIFY(!QFile::exists(dead));
        QVERIFY(QFile::exists(running.recoveryFile() + QStringLiteral(".lock")));
    }

    void germanTranslationCoversTheMenus() {
        QTranslator translator;
        QVERIFY(translator.load(QLocale(QLocale::German), QStringLiteral("devsurf"),
                                QStringLiteral("_"), QStringLiteral(":/i18n")));
        QApplication::installTranslator(&translator);
        {
            app::MainWindow window;
            QStringList titles;
            for (QAction* menu : window.menuBar()->actions()) {
                titles << menu->text();
            }
            QCOMPARE(titles.join(','),
                     QStringLiteral("&Datei,&Bearbeiten,&Ansicht,&Werkzeuge,&Hilfe"));
            QCOMPARE(window.action("actionSave")->text(), QStringLiteral("&Speichern"));
        }
        QApplication::removeTranslator(&translator);
    }
};

DEVSURF_REGISTER_TEST(TstMainWindow);
#include "tst_main_window.moc"
