#include "reference_shape_reactions.h"

#include "../distance_report_dialog.h"
#include "../workspace.h"
#include "background_read.h"
#include "io/reference/reference_import.h"
#include "model/document/commands/reference_shapes_command.h"
#include "model/document/document.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>

#include <algorithm>

namespace devsurf::app {

// What the worker thread and the window share: the request, the progress as it goes, the
// cancel flag and the result (read by the window only after the thread finished).
struct ImportReferenceShapeReaction::Job {
    QString path;
    io::ReferenceImportResult result;
};

namespace {

QString errorSentence(const io::ReferenceImportError& error, const QString& path) {
    using Code = io::ReferenceImportError::Code;
    using R = ImportReferenceShapeReaction;
    const QString name = QFileInfo(path).fileName();
    switch (error.code) {
    case Code::UnknownFormat:
        return R::tr("%1 is not a file DevSurf reads shapes from; choose a mesh (OBJ, PLY, STL, "
                     "OFF) or a point cloud (XYZ, PTS).")
            .arg(name);
    case Code::Unreadable:
        return R::tr("%1 cannot be read; check that it exists and that you may read it.").arg(name);
    case Code::TooLarge:
        return R::tr("%1 is too large; DevSurf takes up to %2 points and %3 triangles.")
            .arg(name, QLocale().toString(static_cast<qulonglong>(io::kMaxReferencePoints)),
                 QLocale().toString(static_cast<qulonglong>(io::kMaxReferenceTriangles)));
    case Code::Damaged:
        return R::tr("%1 is damaged or not a valid file of its type; nothing was imported.")
            .arg(name);
    case Code::Truncated:
        return R::tr("%1 ends before its last point or triangle; copy or export it again.")
            .arg(name);
    case Code::NotANumber:
        return R::tr("%1 holds a coordinate that is not a finite number of sensible size; nothing "
                     "was imported.")
            .arg(name);
    case Code::BadFaces:
        return R::tr("A face of %1 names a point the file does not have; nothing was imported.")
            .arg(name);
    case Code::NoPoints:
        return R::tr("%1 holds no points to import.").arg(name);
    case Code::Cancelled:
        break;
    }
    return R::tr("No reference shape could be imported from %1.").arg(name);
}

} // namespace

ImportReferenceShapeReaction::ImportReferenceShapeReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {}

ImportReferenceShapeReaction::~ImportReferenceShapeReaction() {
    // Closed while reading: the reader is stopped and waited for, nothing is applied.
    delete m_read;
}

void ImportReferenceShapeReaction::onTriggered() {
    if (isBusy()) {
        return;
    }
    const QString path =
        m_chooser ? m_chooser()
                  : QFileDialog::getOpenFileName(
                        workspace()->window(), tr("Import Reference Shape"),
                        workspace()->fileDialogDirectory(),
                        tr("Meshes and point clouds (*.obj *.ply *.stl *.off *.xyz *.pts);;"
                           "Meshes (*.obj *.ply *.stl *.off);;Point clouds (*.xyz *.pts)"));
    if (!path.isEmpty()) {
        importFile(path);
    }
}

void ImportReferenceShapeReaction::importFile(const QString& path) {
    if (isBusy()) {
        return;
    }
    m_job = std::make_shared<Job>();
    m_job->path = path;
    std::shared_ptr<Job> job = m_job;
    m_read = new BackgroundRead(
        workspace()->window(), tr("Reading reference shape %1…").arg(QFileInfo(path).fileName()),
        tr("Import Reference Shape"), QStringLiteral("importReferenceShapeProgress"),
        [job](const BackgroundRead::Progress& progress) {
            job->result = io::readReferenceShape(job->path.toStdString(), progress);
        },
        this);
    connect(m_read, &BackgroundRead::done, this, &ImportReferenceShapeReaction::onRead);
}

void ImportReferenceShapeReaction::onRead() {
    const bool cancelled = m_read->wasCancelled();
    m_read->deleteLater();
    m_read = nullptr;
    const std::shared_ptr<Job> job = std::move(m_job);
    if (cancelled && !job->result.error) {
        // Read before the cancel reached the reader: cancelled all the same.
        job->result = {};
        job->result.error = io::ReferenceImportError{io::ReferenceImportError::Code::Cancelled, {}};
    }
    bool imported = false;
    const QString fileName = QFileInfo(job->path).fileName();
    if (job->result.error) {
        if (job->result.error->code == io::ReferenceImportError::Code::Cancelled) {
            emit workspace()->statusMessage(
                tr("Import of reference shape %1 cancelled").arg(fileName));
        } else {
            workspace()->showError(tr("Cannot import the reference shape"),
                                   errorSentence(*job->result.error, job->path));
        }
    } else {
        const QString name = QString::fromStdString(job->result.shape.name);
        const int points = static_cast<int>(job->result.shape.points.size());
        const int triangles = static_cast<int>(job->result.shape.triangles.size());
        imported = workspace()->apply(document::ReferenceShapesCommand::createImport(
                                          *workspace()->document(), std::move(job->result.shape)),
                                      tr("Cannot import the reference shape"));
        if (imported) {
            emit workspace()->statusMessage(tr("Imported reference shape %1: %2, %3")
                                                .arg(name, tr("%n point(s)", nullptr, points),
                                                     tr("%n triangle(s)", nullptr, triangles)));
        }
    }
    emit finished(imported);
}

RemoveReferenceShapesReaction::RemoveReferenceShapesReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

void RemoveReferenceShapesReaction::updateEnableState() {
    action()->setEnabled(!workspace()->document()->project().referenceShapes.empty());
}

void RemoveReferenceShapesReaction::onTriggered() {
    workspace()->apply(document::ReferenceShapesCommand::createRemoveAll(*workspace()->document()),
                       tr("Cannot remove the reference shapes"));
}

DistanceReportReaction::DistanceReportReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

DistanceReportDialog* DistanceReportReaction::dialog() const {
    return m_dialog;
}

void DistanceReportReaction::updateEnableState() {
    const model::Project& project = workspace()->document()->project();
    const bool shapes = !project.referenceShapes.empty();
    const bool surface =
        std::any_of(project.surfaces.begin(), project.surfaces.end(),
                    [](const model::CompositeSurface& s) { return !s.faces().empty(); });
    action()->setEnabled(shapes && surface);
    const QString tip =
        !shapes    ? tr("Measure how far the design is from a reference shape: import one first "
                           "(File ▸ Import Reference Shape…).")
        : !surface ? tr("Measure how far the design is from the reference shapes: the design "
                        "has no surface yet.")
                   : tr("Show how far the design is from each reference shape, both ways (mean, "
                        "95th percentile, largest), and how much of the shape it covers.");
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void DistanceReportReaction::onTriggered() {
    if (m_dialog == nullptr) {
        m_dialog = new DistanceReportDialog(workspace()->document(), workspace()->window());
        m_dialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_dialog->show();
    m_dialog->raise();
    m_dialog->activateWindow();
}

} // namespace devsurf::app
