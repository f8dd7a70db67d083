#include "shape_commands.h"

#include "cli_output.h"

#include "io/file_error.h"
#include "io/project_file.h"
#include "io/shape/mesh_export.h"
#include "io/shape/shape_export_error.h"
#ifdef DEVSURF_CAD_EXPORT
#include "io/shape/cad_export.h"
#endif
#include "model/project.h"

#include <QFileInfo>
#include <QString>

#include <iostream>

namespace devsurf::app {

namespace {

// The sentence for a stopped export (the command line is English only).
std::string shapeErrorText(const io::ShapeExportError& error, const std::string& file) {
    switch (error.code()) {
    case io::ShapeExportError::Code::NoSurface:
        return "'" + file + "' has no surface to export.";
    case io::ShapeExportError::Code::BadSurface:
        return "Patch " + std::to_string(error.face()) + " of surface " +
               std::to_string(error.surface()) +
               " cannot be written as an exact surface (OpenCASCADE refused it).";
    case io::ShapeExportError::Code::Translate:
        return "The shape of '" + file + "' could not be translated into the format.";
    case io::ShapeExportError::Code::Cancelled:
        return "The export was cancelled.";
    }
    return "The export failed.";
}

void refusePatternOptions(const SubcommandArguments& args) {
    for (const char* option : {"sheet", "paper", "seam", "rulings", "splines", "r12"}) {
        if (args.isSet(option)) {
            throw UsageError{"option '" + optionText(option) +
                             "' is for cutting patterns (dxf, svg, pdf, fold), not 3D shapes"};
        }
    }
}

#ifdef DEVSURF_CAD_EXPORT
int writeCad(const model::Project& project, const std::string& output, io::CadFormat format,
             const std::string& formatText) {
    io::CadExportOptions options;
    options.format = format;
    const io::CadExportResult result =
        io::saveCadFile(project, QString::fromStdString(output), options);
    std::size_t shells = 0;
    for (const io::CadExportSurface& surface : result.surfaces) {
        shells += surface.shells;
        for (const io::UnsewnEdge& seam : surface.unsewn) {
            std::cerr << "devsurf-cli: warning: surface " << surface.surface
                      << ": the patches at edge " << seam.edge << " are " << seam.gap
                      << " mm apart, more than the sewing tolerance " << result.sewingTolerance
                      << " mm; they are written unsewn there.\n";
        }
    }
    std::cout << "Wrote " << output << " (" << formatText << ", " << result.faces()
              << (result.faces() == 1 ? " face" : " faces") << " in " << shells
              << (shells == 1 ? " shell" : " shells")
              << (result.sewn() ? ", sewn" : ", not sewn everywhere") << ")\n";
    return kExitOk;
}
#endif

} // namespace

bool isShapeFormat(const std::string& name) {
    io::MeshFormat mesh;
    return name == "step" || name == "step214" || name == "step242" || name == "stp" ||
           name == "iges" || name == "igs" || io::meshFormatFromName(name, mesh);
}

int runExportShapeCommand(const SubcommandArguments& args, const std::string& format) {
    const std::string file = args.onePositional("one project file");
    const std::string output = args.required("o", kMissingOutput);
    refusePatternOptions(args);
    if (output == "-") {
        throw UsageError{"a 3D shape is written to a file, not to standard output ('-')"};
    }
    io::MeshFormat meshFormat = io::MeshFormat::Stl;
    const bool mesh = io::meshFormatFromName(format, meshFormat);
    const bool iges = format == "iges" || format == "igs";
    std::string extension = mesh ? format : iges ? "iges" : "step";
    const std::string suffix =
        QFileInfo(QString::fromStdString(output)).suffix().toLower().toStdString();
    if ((extension == "step" && suffix == "stp") || (extension == "iges" && suffix == "igs")) {
        extension = suffix;
    }
    std::string upper = mesh ? format : iges ? "IGES" : "STEP";
    for (char& c : upper) {
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    checkOutput(output, {file}, OutputKind::Other, "the " + upper + " shape");
    checkExtension(output, extension, upper);
    io::MeshExportOptions options;
    if (const std::optional<std::string> text = args.value("tolerance")) {
        options.tolerance = parseReal(*text, "--tolerance", 1e-4, 10.0, "a length in mm");
        if (!mesh) {
            throw UsageError{"option '--tolerance' is for meshes (obj, stl, ply): STEP and "
                             "IGES hold the exact surfaces"};
        }
    }
    if (const std::optional<std::string> text = args.value("thickness")) {
        options.thickness = parseReal(*text, "--thickness", 0.0, 1000.0, "a length in mm");
        if (!mesh) {
            throw UsageError{"option '--thickness' is for meshes (obj, stl, ply) only"};
        }
    }
    const model::Project project = io::loadProjectFile(QString::fromStdString(file));
    try {
        if (mesh) {
            options.format = meshFormat;
            const io::ShapeMesh written =
                io::saveMeshFile(project, QString::fromStdString(output), options);
            if (!written.toleranceMet) {
                std::cerr << "devsurf-cli: warning: the mesh has " << written.samplesPerInterval
                          << " samples per spline interval, the most it takes, and is coarser "
                             "than --tolerance.\n";
            }
            std::cout << "Wrote " << output << " (" << upper << ", " << written.triangles.size()
                      << " triangles, " << written.samplesPerInterval
                      << " samples per spline interval)\n";
            return kExitOk;
        }
#ifdef DEVSURF_CAD_EXPORT
        io::CadFormat cadFormat = io::CadFormat::StepAP242;
        io::cadFormatFromName(format, cadFormat);
        const std::string formatText = cadFormat == io::CadFormat::Iges        ? "IGES"
                                       : cadFormat == io::CadFormat::StepAP214 ? "STEP AP214"
                                                                               : "STEP AP242";
        return writeCad(project, output, cadFormat, formatText);
#else
        throw InputError("This devsurf-cli was built without STEP and IGES export "
                         "(OpenCASCADE); meshes (obj, stl, ply) can be written.");
#endif
    } catch (const io::ShapeExportError& error) {
        throw InputError(shapeErrorText(error, file));
    }
}

} // namespace devsurf::app
