#include "curve_reactions.h"

#include "model/curve_fit.h"
#include "model/document/commands/apply_surface_command.h"

#include "../workspace.h"
#include "background_read.h"
#include "io/curves/curve_import.h"
#include "model/document/commands/reference_curves_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>

#include <algorithm>
#include <limits>
#include <optional>

namespace devsurf::app {

// What the worker thread and the window share: the request, the progress as it goes, the
// cancel flag and the result (read by the window only after the thread finished).
struct ImportCurvesReaction::Job {
    QString path;
    io::CurveImportResult result;
};

namespace {

QString errorSentence(const io::CurveImportError& error, const QString& path) {
    using Code = io::CurveImportError::Code;
    const QString name = QFileInfo(path).fileName();
    switch (error.code) {
    case Code::UnknownFormat:
        return ImportCurvesReaction::
            tr("%1 is not a file DevSurf reads curves from; choose a DXF, SVG, STEP or IGES file.")
                .arg(name);
    case Code::NotAvailable:
        return ImportCurvesReaction::tr("This build of DevSurf reads curves from DXF and SVG files "
                                        "only; save the curves as DXF.");
    case Code::Unreadable:
        return ImportCurvesReaction::tr(
                   "%1 cannot be read; check that it exists and that you may read it.")
            .arg(name);
    case Code::TooLarge:
        return ImportCurvesReaction::tr("%1 is too large to import curves from.").arg(name);
    case Code::Damaged:
        return ImportCurvesReaction::tr(
                   "%1 is damaged or not a valid file of its type; nothing was imported.")
            .arg(name);
    case Code::NoCurves:
        return ImportCurvesReaction::tr(
                   "%1 holds no lines, polylines, splines, arcs or circles to import.")
            .arg(name);
    case Code::Cancelled:
        break;
    }
    return ImportCurvesReaction::tr("The curves of %1 could not be imported.").arg(name);
}

} // namespace

ImportCurvesReaction::ImportCurvesReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {}

ImportCurvesReaction::~ImportCurvesReaction() {
    // Closed while reading: the reader is stopped and waited for, nothing is applied.
    delete m_read;
}

void ImportCurvesReaction::onTriggered() {
    if (isBusy()) {
        return;
    }
    const QString path =
        m_chooser
            ? m_chooser()
            : QFileDialog::getOpenFileName(
                  workspace()->window(), tr("Import Curves"), workspace()->fileDialogDirectory(),
                  tr("Curve files (*.dxf *.svg *.step *.stp *.iges *.igs);;DXF (*.dxf);;"
                     "SVG (*.svg);;STEP (*.step *.stp);;IGES (*.iges *.igs)"));
    if (!path.isEmpty()) {
        importFile(path);
    }
}

void ImportCurvesReaction::importFile(const QString& path) {
    if (isBusy()) {
        return;
    }
    m_job = std::make_shared<Job>();
    m_job->path = path;
    std::shared_ptr<Job> job = m_job;
    m_read = new BackgroundRead(
        workspace()->window(), tr("Reading curves from %1…").arg(QFileInfo(path).fileName()),
        tr("Import Curves"), QStringLiteral("importCurvesProgress"),
        [job](const BackgroundRead::Progress& progress) {
            io::CurveImportOptions options;
            options.progress = progress;
            job->result = io::importCurveFile(job->path, options);
        },
        this);
    connect(m_read, &BackgroundRead::done, this, &ImportCurvesReaction::onRead);
}

void ImportCurvesReaction::onRead() {
    const bool cancelled = m_read->wasCancelled();
    m_read->deleteLater();
    m_read = nullptr;
    const std::shared_ptr<Job> job = std::move(m_job);
    if (cancelled && !job->result.error) {
        // Read before the cancel reached the reader: cancelled all the same.
        job->result = {};
        job->result.error = io::CurveImportError{io::CurveImportError::Code::Cancelled, {}};
    }
    bool imported = false;
    const QString name = QFileInfo(job->path).fileName();
    if (job->result.error) {
        if (job->result.error->code == io::CurveImportError::Code::Cancelled) {
            emit workspace()->statusMessage(tr("Import of curves from %1 cancelled").arg(name));
        } else {
            workspace()->showError(tr("Cannot import curves"),
                                   errorSentence(*job->result.error, job->path));
        }
    } else {
        imported = workspace()->apply(document::ReferenceCurvesCommand::createImport(
                                          *workspace()->document(), std::move(job->result.curves)),
                                      tr("Cannot import curves"));
        if (imported) {
            emit workspace()->statusMessage(tr("Imported the curves of %1").arg(name));
        }
    }
    emit finished(imported);
}

RemoveReferenceCurvesReaction::RemoveReferenceCurvesReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

void RemoveReferenceCurvesReaction::updateEnableState() {
    action()->setEnabled(!workspace()->document()->project().referenceCurves.empty());
}

void RemoveReferenceCurvesReaction::onTriggered() {
    workspace()->apply(document::ReferenceCurvesCommand::createRemoveAll(*workspace()->document()),
                       tr("Cannot remove the reference curves"));
}

namespace {

// The one spline edge selected (surface, edge), if exactly one edge is selected and it is one.
std::optional<std::pair<int, model::EdgeId>> selectedSplineEdge(Workspace* workspace) {
    std::optional<std::pair<int, model::EdgeId>> found;
    for (const document::Pick& pick : workspace->selection()->picks()) {
        if (pick.kind != document::Pick::Kind::Edge || found) {
            return std::nullopt;
        }
        found = std::make_pair(pick.surface, pick.id);
    }
    const document::Document* doc = workspace->document();
    if (!found || found->first < 0 || found->first >= doc->surfaceCount() ||
        !doc->surface(found->first).hasEdge(found->second) ||
        !doc->surface(found->first).edge(found->second).isSpline()) {
        return std::nullopt;
    }
    return found;
}

} // namespace

FitEdgeToCurveReaction::FitEdgeToCurveReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

void FitEdgeToCurveReaction::updateEnableState() {
    const bool curves = !workspace()->document()->project().referenceCurves.empty();
    const bool edge = selectedSplineEdge(workspace()).has_value();
    action()->setEnabled(curves && edge);
    const QString tip =
        !curves ? tr("Lay a crease or boundary onto a reference curve: import curves first "
                     "(File ▸ Import Curves…).")
        : !edge ? tr("Lay a crease or boundary onto a reference curve: select one spline edge.")
                : tr("Lay the selected crease or boundary onto the reference curve nearest it; "
                     "Solve then makes the surface developable again.");
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void FitEdgeToCurveReaction::onTriggered() {
    const auto selected = selectedSplineEdge(workspace());
    document::Document* doc = workspace()->document();
    const std::vector<model::ReferenceCurve>& curves = doc->project().referenceCurves;
    if (!selected || curves.empty()) {
        updateEnableState();
        return;
    }
    const auto [index, edge] = *selected;
    const model::CompositeSurface& surface = doc->surface(index);
    const std::size_t nearest = model::nearestCurve(surface, edge, curves);
    model::CompositeSurface changed = surface;
    const model::EdgeFit fit = model::fitEdgeToCurve(changed, edge, curves[nearest]);
    const QString curveName = QString::fromStdString(curves[nearest].name);
    if (fit.refused) {
        emit workspace()->statusMessage(
            fit.refused == model::EdgeFit::Refusal::EndsMeet
                ? tr("Edge %1 was not fitted: both its ends are nearest the same point of %2.")
                      .arg(edge)
                      .arg(curveName)
                : tr("Edge %1 was not fitted: %2 has too few points.").arg(edge).arg(curveName));
        return;
    }
    if (!workspace()->apply(document::ApplySurfaceCommand::create(*doc, index, std::move(changed),
                                                                  tr("Fit Edge to Curve"),
                                                                  document::Change::Geometry),
                            tr("Cannot fit the edge to the curve"))) {
        return;
    }
    const QLocale locale;
    emit workspace()->statusMessage(
        tr("Edge %1 lies on %2 within %3 mm; Solve (Ctrl+Return) makes the surface developable "
           "again.")
            .arg(edge)
            .arg(curveName, locale.toString(fit.largestDistance, 'g', 2)));
}

} // namespace devsurf::app
