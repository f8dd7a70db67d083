#include "shape_export_dialog.h"
#include "output_problem_text.h"
#include "problem_text.h"

#include "io/file_error.h"
#include "io/output_file.h"
#include "io/shape/cad_export.h"
#include "io/shape/mesh_export.h"
#include "io/shape/shape_export_error.h"
#include "model/model_error.h"
#include "model/project.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QVBoxLayout>

namespace devsurf::app {

namespace {

bool isMesh(ShapeExportDialog::Format format) {
    return format == ShapeExportDialog::Obj || format == ShapeExportDialog::Stl ||
           format == ShapeExportDialog::Ply;
}

QString shapeErrorText(const io::ShapeExportError& error) {
    switch (error.code()) {
    case io::ShapeExportError::Code::NoSurface:
        return ShapeExportDialog::tr("The design has no surface to export.");
    case io::ShapeExportError::Code::BadSurface:
        return ShapeExportDialog::tr("Patch %1 of surface %2 cannot be written as an exact "
                                     "surface.")
            .arg(error.face())
            .arg(error.surface());
    case io::ShapeExportError::Code::Translate:
        return ShapeExportDialog::tr("The shape could not be translated into this format. Try "
                                     "another format.");
    case io::ShapeExportError::Code::Cancelled:
        return QString();
    }
    return QString();
}

} // namespace

ShapeExportDialog::ShapeExportDialog(const model::Project& project, const QString& baseName,
                                     const QString& directory, QWidget* parent)
    : QDialog(parent), m_project(project), m_baseName(baseName), m_directory(directory) {
    setWindowTitle(tr("Export 3D Shape"));
    m_format = new QComboBox(this);
    m_format->setObjectName(QStringLiteral("shapeFormat"));
    m_format->addItems({tr("STEP AP242: exact surfaces"), tr("STEP AP214: exact surfaces"),
                        tr("IGES: exact surfaces"), tr("OBJ mesh: a group per patch"),
                        tr("STL mesh (binary)"), tr("PLY mesh (binary)")});
    m_tolerance = new QDoubleSpinBox(this);
    m_tolerance->setObjectName(QStringLiteral("shapeTolerance"));
    m_tolerance->setDecimals(4);
    m_tolerance->setRange(0.0001, 10.0);
    m_tolerance->setSingleStep(0.01);
    m_tolerance->setValue(0.01);
    m_tolerance->setSuffix(tr(" mm"));
    m_tolerance->setToolTip(tr("How far the mesh's triangles may stray from the exact surface."));
    m_thickness = new QDoubleSpinBox(this);
    m_thickness->setObjectName(QStringLiteral("shapeThickness"));
    m_thickness->setDecimals(3);
    m_thickness->setRange(0.0, 1000.0);
    m_thickness->setValue(0.0);
    m_thickness->setSuffix(tr(" mm"));
    m_thickness->setSpecialValueText(tr("none (the surface)"));
    m_thickness->setToolTip(
        tr("A sheet of this thickness for 3D printing: both sides offset by half of it, the rim "
           "closed."));
    m_note = new QLabel(this);
    m_note->setWordWrap(true);

    auto* form = new QFormLayout;
    form->addRow(tr("&Format:"), m_format);
    form->addRow(tr("Chord &tolerance:"), m_tolerance);
    form->addRow(tr("T&hickness:"), m_thickness);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton* exportButton = buttons->addButton(tr("&Export…"), QDialogButtonBox::AcceptRole);
    exportButton->setObjectName(QStringLiteral("shapeExportButton"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_note);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(exportButton, &QPushButton::clicked, this, &ShapeExportDialog::chooseFileAndExport);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ShapeExportDialog::updateEnabled);
    updateEnabled();
}

QString ShapeExportDialog::extensionFor(Format format) {
    switch (format) {
    case StepAP242:
    case StepAP214:
        return QStringLiteral("step");
    case Iges:
        return QStringLiteral("iges");
    case Obj:
        return QStringLiteral("obj");
    case Stl:
        return QStringLiteral("stl");
    case Ply:
        return QStringLiteral("ply");
    }
    return QString();
}

void ShapeExportDialog::updateEnabled() {
    const bool mesh = isMesh(static_cast<Format>(m_format->currentIndex()));
    m_tolerance->setEnabled(mesh);
    m_thickness->setEnabled(mesh);
    m_note->setText(mesh ? tr("A triangle mesh for renderers, slicers and mesh tools; watertight "
                              "wherever the design is.")
                         : tr("Every patch as its exact B-spline surface, sewn into one shell "
                              "per surface, in millimetres, faces named after their patches."));
}

void ShapeExportDialog::chooseFileAndExport() {
    const auto format = static_cast<Format>(m_format->currentIndex());
    const QString extension = extensionFor(format);
    const QString path =
        askExportPath(this, tr("Export 3D Shape"), m_directory, m_baseName, extension,
                      tr("%1 files (*.%2)").arg(extension.toUpper(), extension));
    if (!path.isEmpty() && exportTo(path)) {
        accept();
    }
}

bool ShapeExportDialog::exportTo(const QString& path) {
    const io::OutputProblem problem = io::outputProblem(
        path, m_projectFile.isEmpty() ? QStringList{} : QStringList{m_projectFile});
    if (problem != io::OutputProblem::None) {
        QMessageBox::critical(this, tr("Export failed"), outputProblemText(problem, path));
        return false;
    }
    const auto format = static_cast<Format>(m_format->currentIndex());
    try {
        return isMesh(format) ? exportMesh(path, format) : exportCad(path, format);
    } catch (const io::ShapeExportError& error) {
        if (error.code() != io::ShapeExportError::Code::Cancelled) {
            QMessageBox::critical(this, tr("Export failed"), shapeErrorText(error));
        }
    } catch (const model::ModelError& error) {
        QMessageBox::critical(this, tr("Export failed"), ProblemText::of(error.problem()));
    } catch (const io::FileError& error) {
        QMessageBox::critical(this, tr("Export failed"), QString::fromStdString(error.what()));
    }
    return false;
}

bool ShapeExportDialog::exportCad(const QString& path, Format format) {
    QProgressDialog progress(tr("Writing the 3D shape…"), tr("Cancel"), 0, 1000, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(400);
    io::CadExportOptions options;
    options.format = format == StepAP214 ? io::CadFormat::StepAP214
                     : format == Iges    ? io::CadFormat::Iges
                                         : io::CadFormat::StepAP242;
    options.progress = [&progress](double fraction) {
        progress.setValue(static_cast<int>(fraction * 1000.0));
        return !progress.wasCanceled();
    };
    const io::CadExportResult result = io::saveCadFile(m_project, path, options);
    progress.setValue(1000);
    std::size_t shells = 0;
    QStringList seams;
    for (const io::CadExportSurface& surface : result.surfaces) {
        shells += surface.shells;
        for (const io::UnsewnEdge& seam : surface.unsewn) {
            seams << tr("surface %1, edge %2 (%3 mm apart)")
                         .arg(surface.surface)
                         .arg(seam.edge)
                         .arg(seam.gap, 0, 'g', 3);
        }
    }
    m_summary = tr("faces: %1, shells: %2").arg(result.faces()).arg(shells);
    if (!seams.isEmpty()) {
        QMessageBox::warning(
            this, tr("Export 3D Shape"),
            tr("The shape was written, but some patches could not be sewn together and stay "
               "apart in the file: %1.")
                .arg(seams.join(QLatin1String("; "))));
    }
    return true;
}

bool ShapeExportDialog::exportMesh(const QString& path, Format format) {
    io::MeshExportOptions options;
    options.format = format == Obj   ? io::MeshFormat::Obj
                     : format == Ply ? io::MeshFormat::Ply
                                     : io::MeshFormat::Stl;
    options.tolerance = m_tolerance->value();
    options.thickness = m_thickness->value();
    QProgressDialog progress(tr("Writing the 3D shape…"), tr("Cancel"), 0, 1000, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(400);
    options.progress = [&progress](double fraction) {
        progress.setValue(static_cast<int>(fraction * 1000.0));
        return !progress.wasCanceled();
    };
    const io::ShapeMesh mesh = io::saveMeshFile(m_project, path, options);
    progress.setValue(1000);
    m_summary = tr("triangles: %1").arg(mesh.triangles.size());
    if (!mesh.toleranceMet) {
        QMessageBox::warning(this, tr("Export 3D Shape"),
                             tr("The mesh was written with %1 samples per curve interval, the "
                                "most DevSurf writes, and is coarser than the tolerance asked "
                                "for.")
                                 .arg(mesh.samplesPerInterval));
    }
    return true;
}

} // namespace devsurf::app
