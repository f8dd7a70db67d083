#include "main_window.h"

#include "autosaver.h"
#include "camera_actions.h"
#include "eliding_status_bar.h"
#include "help_dialogs.h"
#include "language_menu.h"
#include "mark_region_tool.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "panels/patch_panel.h"
#include "panels/pins_panel.h"
#include "panels/properties_panel.h"
#include "panels/solver_panel.h"
#include "reactions/approximate_reaction.h"
#include "reactions/crease_reactions.h"
#include "reactions/curve_reactions.h"
#include "reactions/edit_reactions.h"
#include "reactions/file_reactions.h"
#include "reactions/join_reaction.h"
#include "reactions/pattern_reactions.h"
#include "reactions/pin_reactions.h"
#include "reactions/reference_shape_reactions.h"
#include "reactions/shape_reactions.h"
#include "reactions/sheet_reactions.h"
#include "reactions/tool_reactions.h"
#include "reactions/view_reactions.h"
#include "solve_controller.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "workspace.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

namespace devsurf::app {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), m_workspace(new Workspace(this)) {
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
    setStatusBar(new ElidingStatusBar(this)); // before anything adds to it
    document::Document* doc = m_workspace->document();
    document::Selection* selection = m_workspace->selection();

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_surfaceView = new views::SurfaceView(doc, selection, m_splitter);
    m_developmentView = new views::DevelopmentView(doc, selection, m_splitter);
    m_splitter->addWidget(m_surfaceView);
    m_splitter->addWidget(m_developmentView);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);
    setCentralWidget(m_splitter);

    createDocks();
    createMenus();

    m_countsLabel = new QLabel(this);
    m_hoverLabel = new QLabel(this);
    // The hover text never widens the bar into the counts: it is cut at the label's width.
    m_hoverLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_hoverLabel->setMinimumWidth(0);
    statusBar()->addWidget(m_hoverLabel, 1);
    statusBar()->addPermanentWidget(m_countsLabel);
    connect(m_surfaceView, &views::SurfaceView::hoverChanged, m_hoverLabel, &QLabel::setText);
    connect(m_developmentView, &views::DevelopmentView::hoverChanged, m_hoverLabel,
            &QLabel::setText);
    connect(m_workspace, &Workspace::statusMessage, this,
            [this](const QString& text) { statusBar()->showMessage(text, 5000); });

    connect(doc, &document::Document::modifiedChanged, this, &QWidget::setWindowModified);
    connect(doc, &document::Document::filePathChanged, this, &MainWindow::updateTitle);
    connect(doc, &document::Document::changed, this, &MainWindow::updateCounts);
    connect(selection, &document::Selection::selectionChanged, this, &MainWindow::updateCounts);
    connect(doc, &document::Document::projectReset, this, [this] {
        m_surfaceView->fitAll();
        m_developmentView->fitAll();
    });
    updateTitle();
    updateCounts();

    // What View ▸ Reset Layout returns to.
    m_defaultLayout = saveState();
    QSettings settings;
    if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray())) {
        resize(1400, 860);
    }
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    m_splitter->restoreState(settings.value(QStringLiteral("window/splitter")).toByteArray());
}

MainWindow::~MainWindow() = default;

QAction* MainWindow::addAction(QMenu* menu, const QString& name, const QString& text,
                               const QKeySequence& shortcut) {
    auto* action = new QAction(text, this);
    action->setObjectName(name);
    if (!shortcut.isEmpty()) {
        action->setShortcut(shortcut);
    }
    menu->addAction(action);
    return action;
}

QAction* MainWindow::action(const QString& name) const {
    return findChild<QAction*>(name);
}

void MainWindow::createDocks() {
    document::Document* doc = m_workspace->document();
    document::Selection* selection = m_workspace->selection();
    m_patchPanel = new PatchPanel(doc, selection, this);
    auto* patches = new QDockWidget(tr("Patches"), this);
    patches->setObjectName(QStringLiteral("PatchesDock"));
    patches->setWidget(m_patchPanel);
    addDockWidget(Qt::LeftDockWidgetArea, patches);

    m_propertiesPanel = new PropertiesPanel(doc, selection, this);
    auto* properties = new QDockWidget(tr("Properties"), this);
    properties->setObjectName(QStringLiteral("PropertiesDock"));
    properties->setWidget(m_propertiesPanel);
    addDockWidget(Qt::LeftDockWidgetArea, properties);

    m_pinsPanel = new PinsPanel(doc, selection, this);
    auto* pins = new QDockWidget(tr("Pins"), this);
    pins->setObjectName(QStringLiteral("PinsDock"));
    pins->setWidget(m_pinsPanel);
    addDockWidget(Qt::LeftDockWidgetArea, pins);
    tabifyDockWidget(properties, pins); // a tab beside Properties: the left column stays readable
    properties->raise();

    m_solveController = new SolveController(m_workspace, this);
    m_solverPanel = new SolverPanel(this);
    m_solverPanel->follow(doc);
    auto* solverDock = new QDockWidget(tr("Solver"), this);
    solverDock->setObjectName(QStringLiteral("SolverDock"));
    solverDock->setWidget(m_solverPanel);
    addDockWidget(Qt::LeftDockWidgetArea, solverDock);
    connect(m_solveController, &SolveController::reportReady, m_solverPanel,
            &SolverPanel::showReport);
    // Both views write the verdict of the report the panel shows (it follows the undo state).
    connect(m_solverPanel, &SolverPanel::verdictChanged, this,
            [this](const QString& brief, solver::VerdictKind kind) {
                const QColor colour = SolverPanel::verdictColour(kind);
                m_surfaceView->setVerdict(brief, colour);
                m_developmentView->setVerdict(brief, colour);
            });
    connect(m_solverPanel, &SolverPanel::selectPatches, this,
            [this](const std::set<document::Pick>& patches) {
                m_workspace->selection()->set(patches);
            });
}

void MainWindow::createMenus() {
    QToolBar* toolbar = addToolBar(tr("Main"));
    toolbar->setObjectName(QStringLiteral("MainToolBar"));
    // Icons only: buttons keep their width when a text changes (Undo Move 3 vertices), and
    // the whole bar fits a 1280 px wide window; the texts are in the tooltips.
    toolbar->setToolButtonStyle(Qt::ToolButtonIconOnly);

    // File
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* newAction =
        addAction(file, QStringLiteral("actionNew"), tr("&New from Example…"), QKeySequence::New);
    new NewFromExampleReaction(newAction, m_workspace);
    QAction* open = addAction(file, QStringLiteral("actionOpen"), tr("&Open…"), QKeySequence::Open);
    new OpenReaction(open, m_workspace);
    QMenu* recent = file->addMenu(tr("Open &Recent"));
    recent->setObjectName(QStringLiteral("menuRecent"));
    new OpenRecentReaction(recent, m_workspace);
    file->addSeparator();
    QAction* save = addAction(file, QStringLiteral("actionSave"), tr("&Save"), QKeySequence::Save);
    new SaveReaction(save, m_workspace);
    QAction* saveAs =
        addAction(file, QStringLiteral("actionSaveAs"), tr("Save &As…"), QKeySequence::SaveAs);
    new SaveAsReaction(saveAs, m_workspace);
    file->addSeparator();
    QAction* importCurves =
        addAction(file, QStringLiteral("actionImportCurves"), tr("Import &Curves…"));
    importCurves->setStatusTip(
        tr("Add the curves of a DXF, SVG, STEP or IGES file as reference curves"));
    new ImportCurvesReaction(importCurves, m_workspace);
    QAction* importShape = addAction(file, QStringLiteral("actionImportReferenceShape"),
                                     tr("Import Reference S&hape…"));
    importShape->setStatusTip(tr("Add a mesh (OBJ, PLY, STL, OFF) or a point cloud (XYZ, PTS) "
                                 "the design is to follow, as a reference shape"));
    new ImportReferenceShapeReaction(importShape, m_workspace);
    QAction* exportJson = addAction(file, QStringLiteral("actionExportJson"),
                                    tr("&Export Interchange JSON…"), QKeySequence(tr("Ctrl+E")));
    new ExportJsonReaction(exportJson, m_workspace);
    QAction* exportShape =
        addAction(file, QStringLiteral("actionExportShape"), tr("Export &3D Shape…"));
    new ExportShapeReaction(exportShape, m_workspace);
    addCuttingPatternActions(file, m_workspace);
    file->addSeparator();
    QAction* quit = addAction(file, QStringLiteral("actionQuit"), tr("&Quit"), QKeySequence::Quit);
    connect(quit, &QAction::triggered, this, &QWidget::close);

    // Edit
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->setToolTipsVisible(true);
    QUndoStack* stack = m_workspace->document()->undoStack();
    QAction* undo = stack->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("actionUndo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = stack->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("actionRedo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    QAction* deleteAction =
        addAction(edit, QStringLiteral("actionDelete"), tr("&Delete"), QKeySequence::Delete);
    new DeleteSelectionReaction(deleteAction, m_workspace);
    QAction* removeCurves = addAction(edit, QStringLiteral("actionRemoveReferenceCurves"),
                                      tr("Remove Reference &Curves"));
    new RemoveReferenceCurvesReaction(removeCurves, m_workspace);
    QAction* removeShapes = addAction(edit, QStringLiteral("actionRemoveReferenceShapes"),
                                      tr("Remove Reference S&hapes"));
    new RemoveReferenceShapesReaction(removeShapes, m_workspace);
    QAction* selectNone = addAction(edit, QStringLiteral("actionSelectNone"), tr("Select &None"),
                                    QKeySequence(tr("Esc")));
    connect(selectNone, &QAction::triggered, m_workspace->selection(), &document::Selection::clear);

    // View
    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* only3d =
        addAction(view, QStringLiteral("actionView3D"), tr("&3D View"), QKeySequence(tr("Ctrl+1")));
    QAction* onlyDev = addAction(view, QStringLiteral("actionViewDevelopment"),
                                 tr("&Development View"), QKeySequence(tr("Ctrl+2")));
    QAction* both = addAction(view, QStringLiteral("actionViewBoth"), tr("3D &and Development"),
                              QKeySequence(tr("Ctrl+3")));
    new ViewLayoutReaction(only3d, onlyDev, both, m_surfaceView, m_developmentView);
    view->addSeparator();
    QAction* polygons = addAction(view, QStringLiteral("actionControlPolygons"),
                                  tr("&Control Polygons"), QKeySequence(tr("Ctrl+Shift+P")));
    QAction* vertices = addAction(view, QStringLiteral("actionVertices"), tr("&Vertices"),
                                  QKeySequence(tr("Ctrl+Shift+V")));
    new ToggleDisplayReaction(polygons, vertices, m_surfaceView);
    // The held sheet behind the development: on unless turned off (remembered).
    QAction* sheet = addAction(view, QStringLiteral("actionShowSheet"), tr("S&heet Outline"));
    sheet->setCheckable(true);
    sheet->setChecked(QSettings().value(QStringLiteral("view/sheet"), true).toBool());
    sheet->setToolTip(tr("Draw the sheet a held development is confined to behind it in the "
                         "development view (Tools ▸ Sheet Shape…)."));
    sheet->setStatusTip(sheet->toolTip());
    m_developmentView->setShowSheet(sheet->isChecked());
    connect(sheet, &QAction::toggled, m_developmentView, [this](bool on) {
        m_developmentView->setShowSheet(on);
        QSettings().setValue(QStringLiteral("view/sheet"), on);
    });
    // The reference shapes in the 3D view: on unless turned off (remembered).
    QAction* shapes =
        addAction(view, QStringLiteral("actionShowReferenceShapes"), tr("&Reference Shapes"));
    shapes->setCheckable(true);
    shapes->setChecked(QSettings().value(QStringLiteral("view/referenceShapes"), true).toBool());
    shapes->setToolTip(tr("Draw the imported meshes and point clouds in the 3D view (File ▸ "
                          "Import Reference Shape…)."));
    shapes->setStatusTip(shapes->toolTip());
    m_surfaceView->setShowReferenceShapes(shapes->isChecked());
    connect(shapes, &QAction::toggled, m_surfaceView, [this](bool on) {
        m_surfaceView->setShowReferenceShapes(on);
        QSettings().setValue(QStringLiteral("view/referenceShapes"), on);
    });
    // The reference shapes coloured by their distance to the design: off unless turned on
    // (remembered); measured in the background while on.
    QAction* byDistance = addAction(view, QStringLiteral("actionColourReferenceByDistance"),
                                    tr("Colour Reference by Dis&tance"));
    byDistance->setCheckable(true);
    byDistance->setChecked(
        QSettings().value(QStringLiteral("view/referenceDistances"), false).toBool());
    byDistance->setToolTip(tr("Colour the points of the reference shapes by their distance to "
                              "the design, in mm, with a legend (green: within the coverage "
                              "tolerance of Tools ▸ Distance to Reference…)."));
    byDistance->setStatusTip(byDistance->toolTip());
    m_surfaceView->setColourReferenceByDistance(byDistance->isChecked());
    connect(byDistance, &QAction::toggled, m_surfaceView, [this](bool on) {
        m_surfaceView->setColourReferenceByDistance(on);
        QSettings().setValue(QStringLiteral("view/referenceDistances"), on);
    });
    createColourActions(view);
    QAction* fit =
        addAction(view, QStringLiteral("actionFitAll"), tr("&Fit All"), QKeySequence(tr("F")));
    connect(fit, &QAction::triggered, m_surfaceView, &views::SurfaceView::fitAll);
    connect(fit, &QAction::triggered, m_developmentView, &views::DevelopmentView::fitAll);
    auto* camera = new CameraActions(view, m_surfaceView, m_developmentView, this);
    view->addSeparator();
    QAction* resetLayout =
        addAction(view, QStringLiteral("actionResetLayout"), tr("Reset &Layout"));
    connect(resetLayout, &QAction::triggered, this, &MainWindow::resetLayout);
    view->addSeparator();

    // Tools
    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    tools->setToolTipsVisible(true);
    QAction* relabel = addAction(tools, QStringLiteral("actionRelabel"),
                                 tr("&Relabel Edge (R ↔ S)"), QKeySequence(tr("Ctrl+L")));
    new RelabelEdgeReaction(relabel, m_workspace);
    QAction* subdivide = addAction(tools, QStringLiteral("actionSubdivide"), tr("Add &Crease…"),
                                   QKeySequence(tr("Ctrl+D")));
    new SubdivideStripReaction(subdivide, m_workspace, m_surfaceView);
    QAction* split = addAction(tools, QStringLiteral("actionSplitAtRuling"), tr("Add R&uling…"),
                               QKeySequence(tr("Ctrl+R")));
    new SplitAtRulingReaction(split, m_workspace, m_surfaceView);
    QAction* removeRuling = addAction(tools, QStringLiteral("actionRemoveRuling"),
                                      tr("Remove Rulin&g"), QKeySequence(tr("Ctrl+Alt+R")));
    new RemoveRulingReaction(removeRuling, m_workspace);
    QAction* refine = addAction(tools, QStringLiteral("actionRefine"), tr("Re&fine Curves"),
                                QKeySequence(tr("Ctrl+Shift+R")));
    new RefineCurvesReaction(refine, m_workspace);
    QMenu* creaseMenu = createCreaseMenu(tools, m_workspace);
    tools->addMenu(creaseMenu);
    tools->addSeparator();
    QAction* move = addAction(tools, QStringLiteral("actionMoveRotate"),
                              tr("&Move or Rotate Vertices…"), QKeySequence(tr("Ctrl+M")));
    new MoveVerticesReaction(move, m_workspace, m_solveController);
    tools->addSeparator();
    QAction* pin = addAction(tools, QStringLiteral("actionPinVertices"), tr("&Pin Vertices"),
                             QKeySequence(tr("Ctrl+K")));
    new PinVerticesReaction(pin, m_workspace, true);
    QAction* unpin = addAction(tools, QStringLiteral("actionUnpinVertices"), tr("U&npin Vertices"),
                               QKeySequence(tr("Ctrl+Shift+K")));
    new PinVerticesReaction(unpin, m_workspace, false);
    m_pinsPanel->setUnpinAction(unpin);
    QAction* holdSheet = addAction(tools, QStringLiteral("actionHoldSheet"), tr("Hold the &Sheet"),
                                   QKeySequence(tr("Ctrl+Shift+H")));
    new HoldSheetReaction(holdSheet, m_workspace);
    QAction* sheetShape =
        addAction(tools, QStringLiteral("actionSheetShape"), tr("Sheet S&hape…"), QKeySequence());
    new SheetShapeReaction(sheetShape, m_workspace);
    tools->addSeparator();
    QAction* distance = addAction(tools, QStringLiteral("actionDistanceToReference"),
                                  tr("Dis&tance to Reference…"));
    new DistanceReportReaction(distance, m_workspace);
    QAction* approximate = addAction(tools, QStringLiteral("actionApproximateReference"),
                                     tr("A&pproximate Reference Shape…"));
    auto* approximation = new ApproximateReaction(approximate, m_workspace, m_solveController);
    // New strips unfold beside the sheets, out of the development view's frame: show them all.
    connect(approximation, &ApproximateReaction::finished, m_developmentView, [this](bool applied) {
        if (applied) {
            m_developmentView->fitAll();
        }
    });
    QAction* join = addAction(tools, QStringLiteral("actionJoinSurfaces"), tr("&Join Surfaces"),
                              QKeySequence(tr("Ctrl+J")));
    new JoinReaction(join, m_workspace, m_solveController);
    // Issue 42: a region of the reference shape marked by hand, a flat strip over it.
    QAction* markRegion = addAction(tools, QStringLiteral("actionMarkRegion"),
                                    tr("Mar&k Region of Reference Shape"), QKeySequence(tr("L")));
    QAction* stripOverMark = addAction(tools, QStringLiteral("actionAddStripOverMark"),
                                       tr("Add Strip O&ver Marked Region"));
    auto* markTool = new MarkRegionTool(markRegion, stripOverMark, m_workspace, m_surfaceView);
    connect(markTool, &MarkRegionTool::statusMessage, this,
            [this](const QString& text) { statusBar()->showMessage(text); });
    connect(markTool, &MarkRegionTool::stripAdded, m_developmentView,
            &views::DevelopmentView::fitAll);
    tools->addSeparator();
    const QList<QAction*> solverActions = createSolverActions(tools, selectNone);
    // One tool at a time (createSolverActions groups the others).
    if (QActionGroup* group = action(QStringLiteral("actionMeasureTool"))->actionGroup()) {
        group->addAction(markRegion);
    }
    // A right click in either view offers what applies to the entity under the cursor.
    for (views::SceneView* sceneView : {static_cast<views::SceneView*>(m_surfaceView),
                                        static_cast<views::SceneView*>(m_developmentView)}) {
        connect(sceneView, &views::SceneView::contextMenuRequested, this,
                [this, sceneView, pin, unpin, move, creaseMenu](const QPoint& pos) {
                    QMenu menu(sceneView);
                    menu.setObjectName(QStringLiteral("viewContextMenu"));
                    menu.setToolTipsVisible(true);
                    menu.addAction(pin);
                    menu.addAction(unpin);
                    // Over an edge: its crease condition, or smooth / sharp for a ruling.
                    for (const document::Pick& pick : m_workspace->selection()->picks()) {
                        if (pick.kind == document::Pick::Kind::Edge) {
                            menu.addSeparator();
                            menu.addMenu(creaseMenu);
                            break;
                        }
                    }
                    menu.addSeparator();
                    menu.addAction(move);
                    menu.exec(sceneView->glWidget()->mapToGlobal(pos));
                });
    }

    // Help
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* manual = addAction(help, QStringLiteral("actionManual"), tr("&User Manual"),
                                QKeySequence::HelpContents);
    connect(manual, &QAction::triggered, this, [this] {
        auto* window = new ManualWindow(this);
        window->show();
    });
    QAction* shortcuts =
        addAction(help, QStringLiteral("actionShortcuts"), tr("&Keyboard Shortcuts"));
    connect(shortcuts, &QAction::triggered, this, [this] {
        auto* dialog = new ShortcutsDialog(this);
        dialog->show();
    });
    help->addSeparator();
    QAction* about = addAction(help, QStringLiteral("actionAbout"), tr("&About DevSurf"));
    connect(about, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About DevSurf"),
                           tr("<b>DevSurf %1</b><p>Design of developable surfaces and "
                              "curved-crease origami with spline developables (Tang, Bo, "
                              "Wallner, Pottmann 2015).</p>")
                               .arg(QApplication::applicationVersion()));
    });

    // Panels can be hidden; their toggles live in the View menu.
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        view->addAction(dock->toggleViewAction());
    }
    view->addSeparator();
    addLanguageMenu(view, m_workspace);

    const std::pair<QAction*, const char*> icons[] = {
        {newAction, "new"},       {open, "open"},   {save, "save"},
        {undo, "undo"},           {redo, "redo"},   {relabel, "relabel"},
        {subdivide, "subdivide"}, {split, "split"}, {refine, "refine"},
        {move, "move"},           {pin, "pin"},     {polygons, "control-polygon"},
        {fit, "fit-all"}};
    for (const auto& [action, icon] : icons) {
        action->setIcon(actionIcon(QString::fromLatin1(icon)));
    }
    for (QAction* a : {newAction, open, save}) {
        toolbar->addAction(a);
    }
    toolbar->addSeparator();
    toolbar->addAction(undo);
    toolbar->addAction(redo);
    toolbar->addSeparator();
    for (QAction* a : {relabel, subdivide, split, refine, move, pin}) {
        toolbar->addAction(a);
    }
    toolbar->addSeparator();
    toolbar->addActions(solverActions);
    toolbar->addSeparator();
    toolbar->addAction(polygons);
    toolbar->addAction(camera->patchLabelsAction());
    toolbar->addSeparator();
    toolbar->addAction(fit);
    toolbar->addActions(camera->toolbarActions());
    // A tooltip names the command and its key; those of the tools explain themselves.
    for (QAction* a : toolbar->actions()) {
        if (!a->isSeparator() && !a->shortcut().isEmpty() &&
            a->toolTip() == QString(a->text()).remove(QLatin1Char('&')).remove(QChar(0x2026))) {
            a->setToolTip(
                tr("%1 (%2)").arg(a->toolTip(), a->shortcut().toString(QKeySequence::NativeText)));
        }
    }
}

void MainWindow::resetLayout() {
    restoreState(m_defaultLayout);
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        dock->show();
    }
    for (QToolBar* bar : findChildren<QToolBar*>()) {
        bar->show();
    }
    if (QAction* both = action(QStringLiteral("actionViewBoth"))) {
        both->trigger();
    }
    const int width = m_splitter->width();
    m_splitter->setSizes({width * 3 / 5, width - width * 3 / 5});
}

void MainWindow::updateTitle() {
    const QString path = m_workspace->document()->filePath();
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(tr("%1[*] — DevSurf").arg(name));
    setWindowFilePath(path);
}

void MainWindow::updateCounts() {
    const auto& surfaces = m_workspace->document()->project().surfaces;
    std::size_t faces = 0;
    std::size_t controlPoints = 0;
    for (const auto& surface : surfaces) {
        faces += surface.faces().size();
        controlPoints += surface.controlPointCount();
    }
    const auto selected = m_workspace->selection()->picks().size();
    m_countsLabel->setText(
        QStringList{tr("%n surface(s)", nullptr, static_cast<int>(surfaces.size())),
                    tr("%n patch(es)", nullptr, static_cast<int>(faces)),
                    tr("%n control point(s)", nullptr, static_cast<int>(controlPoints)),
                    tr("%n selected", nullptr, static_cast<int>(selected))}
            .join(QStringLiteral(" · ")));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_workspace->maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    settings.setValue(QStringLiteral("window/splitter"), m_splitter->saveState());
    m_workspace->autosaver()->discard();
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.front().isLocalFile() &&
        urls.front().toLocalFile().endsWith(QStringLiteral(".devsurf"), Qt::CaseInsensitive)) {
        event->acceptProposedAction();
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.isEmpty() || !urls.front().isLocalFile()) {
        return;
    }
    event->acceptProposedAction();
    if (m_workspace->maybeSave()) {
        m_workspace->open(urls.front().toLocalFile());
    }
}

} // namespace devsurf::app
