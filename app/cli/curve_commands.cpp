#include "curve_commands.h"

#include "model/curve_fit.h"

#include "cli_output.h"
#include "io/curves/curve_import.h"
#include "io/file_error.h"
#include "io/output_file.h"
#include "io/project_file.h"

#include <QString>

#include <iostream>
#include <limits>

namespace devsurf::app {

// One sentence for the terminal (the application words the same codes with tr()).
std::string curveImportSentence(const io::CurveImportError& error, const std::string& path) {
    using Code = io::CurveImportError::Code;
    const std::string detail = error.detail.empty() ? std::string() : " (" + error.detail + ")";
    switch (error.code) {
    case Code::UnknownFormat:
        return "cannot import curves from '" + path +
               "': use a DXF (.dxf), SVG (.svg), STEP (.step, .stp) or IGES (.iges, .igs) file.";
    case Code::NotAvailable:
        return "cannot import curves from '" + path +
               "': this build has no OpenCASCADE to read STEP and IGES; use DXF or SVG.";
    case Code::Unreadable:
        return "cannot read '" + path + "'" + detail + ".";
    case Code::TooLarge:
        return "cannot import curves from '" + path + "': it is too large" + detail + ".";
    case Code::Damaged:
        return "cannot import curves from '" + path + "': its contents are damaged" + detail + ".";
    case Code::NoCurves:
        return "'" + path + "' holds no lines, polylines, splines, arcs or circles to import.";
    case Code::Cancelled:
        return "the import of '" + path + "' was cancelled.";
    }
    return "cannot import curves from '" + path + "'.";
}

int runImportCurvesCommand(const SubcommandArguments& args) {
    const std::vector<std::string> files = args.positionals(2, "a project file and a curve file");
    const std::string& input = files[0];
    const std::string& curveFile = files[1];
    const std::string output = args.required("o", kMissingOutput);
    io::CurveImportOptions options;
    if (const std::optional<std::string> text = args.value("tolerance")) {
        options.tolerance = parseReal(*text, "--tolerance", 1e-6, 1e3, "a length in mm");
    }
    if (!io::curveFormatOf(QString::fromStdString(curveFile))) {
        throw io::FileError(
            curveImportSentence({io::CurveImportError::Code::UnknownFormat, {}}, curveFile));
    }
    // The curve file is an input that is not a project: never written over.
    if (io::outputProblem(QString::fromStdString(output), {QString::fromStdString(curveFile)}) ==
        io::OutputProblem::SameAsInput) {
        throw io::FileError("Refusing to write the project to '" + output +
                            "': it is the curve file being read, which would be lost. Choose "
                            "another output file.");
    }
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    const io::CurveImportResult result =
        io::importCurveFile(QString::fromStdString(curveFile), options);
    if (result.error) {
        std::cerr << "devsurf-cli: " << curveImportSentence(*result.error, curveFile) << "\n";
        return 2;
    }
    project.referenceCurves.insert(project.referenceCurves.end(), result.curves.begin(),
                                   result.curves.end());
    writeProject(project, output);
    std::size_t points = 0;
    for (const model::ReferenceCurve& curve : result.curves) {
        points += curve.points.size();
    }
    std::cout << "Wrote " << output << " (" << result.curves.size() << " reference curve"
              << (result.curves.size() == 1 ? "" : "s") << " imported, " << points << " points";
    if (result.skipped > 0) {
        std::cout << "; " << result.skipped << " other entit" << (result.skipped == 1 ? "y" : "ies")
                  << " skipped";
    }
    std::cout << "; " << project.referenceCurves.size() << " in the project)\n";
    return 0;
}

int runFitEdgeCommand(const SubcommandArguments& args) {
    const std::string input = args.onePositional("one project file");
    const std::string edgeText = args.required("edge", "the edge is missing (use --edge ID)");
    const std::string output = args.required("o", kMissingOutput);
    const auto edge = static_cast<model::EdgeId>(parseWhole(edgeText, "--edge", 0, 4294967294L));
    const std::optional<std::string> curveText = args.value("curve");
    const std::optional<std::string> surfaceText = args.value("surface");
    const int surfaceNumber =
        surfaceText ? static_cast<int>(parseWhole(*surfaceText, "--surface", 1, 1000000)) : 0;
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    const std::size_t index = surfaceIndex(surfaceNumber, project, "fit an edge of");
    model::CompositeSurface& surface = project.surfaces[index];
    const std::vector<model::ReferenceCurve>& curves = project.referenceCurves;
    if (curves.empty()) {
        std::cerr << "devsurf-cli: '" << input
                  << "' has no reference curves (add some with 'devsurf-cli import-curves').\n";
        return 2;
    }
    if (!surface.hasEdge(edge) || !surface.edge(edge).isSpline()) {
        std::cerr << "devsurf-cli: surface '" << surface.name() << "' has no spline edge " << edge
                  << " (list the edges with 'devsurf-cli info FILE --edges').\n";
        return 2;
    }
    const std::size_t chosen =
        curveText ? static_cast<std::size_t>(
                        parseWhole(*curveText, "--curve", 1, static_cast<long>(curves.size()))) -
                        1
                  : model::nearestCurve(surface, edge, curves);
    const model::ReferenceCurve& curve = curves[chosen];
    const model::EdgeFit fit = model::fitEdgeToCurve(surface, edge, curve);
    if (fit.refused) {
        std::cerr << "devsurf-cli: edge " << edge << " was not fitted to '" << curve.name << "': "
                  << (fit.refused == model::EdgeFit::Refusal::EndsMeet
                          ? "both its ends are nearest the same point of the curve"
                          : "the curve has too few points")
                  << ".\n";
        return 2;
    }
    writeProject(project, output);
    std::cout << "Wrote " << output << " (edge " << edge << " laid onto reference curve "
              << chosen + 1 << " '" << curve.name << "' within " << fit.largestDistance
              << " mm; solve to make the surface developable again)\n";
    return 0;
}

} // namespace devsurf::app
