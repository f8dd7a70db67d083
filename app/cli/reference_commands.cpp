#include "reference_commands.h"

#include "cli_output.h"
#include "io/file_error.h"
#include "io/output_file.h"
#include "io/project_file.h"
#include "model/reference/distance_report.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <limits>

namespace devsurf::app {

namespace {

std::string plainMillimetres(double value) {
    return QString::number(value, 'g', 6).toStdString();
}

} // namespace

std::string referenceImportSentence(const io::ReferenceImportError& error,
                                    const std::string& path) {
    using Code = io::ReferenceImportError::Code;
    const std::string detail = error.detail.empty() ? std::string() : " (" + error.detail + ")";
    const std::string cannot = "cannot import a reference shape from '" + path + "': ";
    switch (error.code) {
    case Code::UnknownFormat:
        return cannot + "use a mesh (.obj, .ply, .stl, .off) or a point cloud (.xyz, .pts).";
    case Code::Unreadable:
        return "cannot read '" + path + "'" + detail + ".";
    case Code::TooLarge:
        return cannot + "it is too large" + detail + "; DevSurf takes up to " +
               std::to_string(io::kMaxReferencePoints) + " points and " +
               std::to_string(io::kMaxReferenceTriangles) + " triangles.";
    case Code::Damaged:
        return cannot + "its contents are damaged" + detail + ".";
    case Code::Truncated:
        return cannot + "it is truncated" + detail + "; copy or export it again.";
    case Code::NotANumber:
        return cannot + "it holds a coordinate that is not a finite number of sensible size" +
               detail + ".";
    case Code::BadFaces:
        return cannot + "a face names a point the file does not have" + detail + ".";
    case Code::NoPoints:
        return "'" + path + "' holds no points to import.";
    case Code::Cancelled:
        return "the import of '" + path + "' was cancelled.";
    }
    return cannot + "it cannot be read.";
}

void checkReferenceTarget(const std::string& target, const std::string& output) {
    if (!io::referenceFormatOf(target)) {
        throw io::FileError(
            referenceImportSentence({io::ReferenceImportError::Code::UnknownFormat, {}}, target));
    }
    // The target is an input that is not a project: never written over.
    if (!output.empty() &&
        io::outputProblem(QString::fromStdString(output), {QString::fromStdString(target)}) ==
            io::OutputProblem::SameAsInput) {
        throw io::FileError("Refusing to write the project to '" + output +
                            "': it is the reference shape being read, which would be lost. "
                            "Choose another output file.");
    }
}

int runImportReferenceCommand(const SubcommandArguments& args) {
    const std::vector<std::string> files = args.positionals(2, "a project file and a mesh or "
                                                               "point cloud file");
    const std::string& input = files[0];
    const std::string& target = files[1];
    const std::string output = args.required("o", kMissingOutput);
    const std::optional<std::string> name = args.value("name");
    if (name && (name->empty() || name->size() > 4096)) {
        throw UsageError{"option '--name' needs a name of 1 to 4096 characters"};
    }
    checkReferenceTarget(target, output);
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    io::ReferenceImportResult result = io::readReferenceShape(target);
    if (result.error) {
        std::cerr << "devsurf-cli: " << referenceImportSentence(*result.error, target) << "\n";
        return 2;
    }
    model::ReferenceShape& shape = result.shape;
    if (name) {
        shape.name = *name;
    }
    model::Vec3 low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                    std::numeric_limits<double>::max()};
    model::Vec3 high = -low;
    for (const model::Vec3& p : shape.points) {
        for (int k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], p[k]);
            high[k] = std::max(high[k], p[k]);
        }
    }
    const std::size_t points = shape.points.size();
    const std::size_t triangles = shape.triangles.size();
    const std::string shapeName = shape.name;
    project.referenceShapes.push_back(std::move(shape));
    writeProject(project, output);
    std::cout << "Wrote " << output << " (reference shape '" << shapeName << "': " << points
              << " point" << (points == 1 ? "" : "s") << ", " << triangles << " triangle"
              << (triangles == 1 ? "" : "s") << ", " << plainMillimetres(high.x - low.x) << " x "
              << plainMillimetres(high.y - low.y) << " x " << plainMillimetres(high.z - low.z)
              << " mm; " << project.referenceShapes.size() << " in the project)\n";
    return 0;
}

namespace {

QJsonObject oneSidedJson(const model::reference::OneSidedDistance& d) {
    QJsonObject o;
    o[QStringLiteral("mean")] = d.mean;
    o[QStringLiteral("p95")] = d.percentile95;
    o[QStringLiteral("max")] = d.max;
    o[QStringLiteral("meanPercent")] = d.meanPercent;
    o[QStringLiteral("p95Percent")] = d.percentile95Percent;
    o[QStringLiteral("maxPercent")] = d.maxPercent;
    return o;
}

std::string oneSidedLine(const model::reference::OneSidedDistance& d) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "mean %.4g mm (%.3g %%), 95th percentile %.4g mm (%.3g %%), max %.4g mm "
                  "(%.3g %%)",
                  d.mean, d.meanPercent, d.percentile95, d.percentile95Percent, d.max,
                  d.maxPercent);
    return line;
}

} // namespace

void printDistanceReport(const model::reference::DistanceReport& report, std::size_t targetPoints) {
    std::cout << "Target: " << targetPoints << " points, bounding-box diagonal "
              << plainMillimetres(report.diagonal) << " mm\n"
              << "Target to surface: " << oneSidedLine(report.targetToSurface) << "\n"
              << "Surface to target: " << oneSidedLine(report.surfaceToTarget)
              << (report.toMesh ? " (to the mesh, sampled every "
                                : " (to the nearest point, "
                                  "sampled every ")
              << plainMillimetres(report.surfaceSpacing) << " mm)\n";
    char line[200];
    std::snprintf(line, sizeof line,
                  "Two-sided (Hausdorff) %.4g mm; coverage %.1f %% of the target within %.4g "
                  "mm of the surface.\n",
                  report.hausdorff(), 100.0 * report.coverage, report.tolerance);
    std::cout << line;
}

int runDistanceCommand(const SubcommandArguments& args) {
    const std::vector<std::string> files =
        args.positionals(2, "a project file and a mesh or point cloud file");
    const std::string& input = files[0];
    const std::string& target = files[1];
    model::reference::DistanceOptions options;
    if (const auto tolerance = args.value("tolerance")) {
        options.tolerance = parseReal(*tolerance, "tolerance", 1e-9, 1e9, "a length in mm");
    }
    checkReferenceTarget(target);
    const model::Project project = io::loadProjectFile(QString::fromStdString(input));
    if (project.surfaces.empty()) {
        throw io::FileError("'" + input + "' has no surface to measure.");
    }
    const io::ReferenceImportResult read = io::readReferenceShape(target);
    if (read.error) {
        std::cerr << "devsurf-cli: " << referenceImportSentence(*read.error, target) << "\n";
        return 2;
    }
    options.triangles = &read.shape.triangles; // a mesh: to its triangles
    const model::reference::DistanceReport report =
        model::reference::measureDistance(project.surfaces, read.shape.points, options);
    if (args.isSet("json")) {
        QJsonObject o;
        o[QStringLiteral("targetPoints")] = static_cast<double>(read.shape.points.size());
        o[QStringLiteral("diagonal")] = report.diagonal;
        o[QStringLiteral("targetToSurface")] = oneSidedJson(report.targetToSurface);
        o[QStringLiteral("surfaceToTarget")] = oneSidedJson(report.surfaceToTarget);
        o[QStringLiteral("hausdorff")] = report.hausdorff();
        o[QStringLiteral("tolerance")] = report.tolerance;
        o[QStringLiteral("coverage")] = report.coverage;
        o[QStringLiteral("surfaceSamples")] = static_cast<double>(report.surfaceSamples);
        o[QStringLiteral("surfaceSpacing")] = report.surfaceSpacing;
        o[QStringLiteral("surfaceToMesh")] = report.toMesh;
        std::cout << QJsonDocument(o).toJson(QJsonDocument::Indented).toStdString();
        return 0;
    }
    printDistanceReport(report, read.shape.points.size());
    return 0;
}

} // namespace devsurf::app
