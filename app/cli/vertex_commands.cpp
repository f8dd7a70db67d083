#include "vertex_commands.h"
#include "model/derived_geometry.h"

#include "cli_output.h"
#include "command_line.h"
#include "curve_commands.h"
#include "problem_text.h"

#include "io/project_file.h"
#include "model/creases.h"
#include "model/development.h"
#include "model/sampled_mesh.h"
#include "model/sheet_creases.h"
#include "model/sheet_domain.h"
#include "model/strip.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace devsurf::app {

namespace {

std::set<model::VertexId> boundaryVertices(const model::CompositeSurface& surface) {
    std::set<model::VertexId> boundary;
    for (const auto& [id, edge] : surface.edges()) {
        if (surface.facesOfEdge(id).size() == 1) {
            boundary.insert(edge.from);
            boundary.insert(edge.to);
        }
    }
    return boundary;
}

// "crease" for an S-edge between two faces, "boundary" for an S-edge of one face, "" for rulings.
const char* curveKind(const model::CompositeSurface& surface, model::EdgeId id) {
    if (!surface.edge(id).isSpline()) {
        return "";
    }
    return surface.facesOfEdge(id).size() == 2 ? "crease" : "boundary";
}

// Every crease of the surface by edge id (mountain/valley and fold angle from the sampled mesh).
std::map<model::EdgeId, model::Crease> creasesById(const model::CompositeSurface& surface) {
    std::map<model::EdgeId, model::Crease> creases;
    for (const model::Crease& crease : model::DerivedGeometry::of(surface, 8)->creases()) {
        creases.emplace(crease.edge, crease);
    }
    return creases;
}

QJsonObject surfaceJson(const model::CompositeSurface& surface, const EntityListing& listing) {
    QJsonObject object;
    object["name"] = QString::fromStdString(surface.name());
    if (listing.vertices) {
        const std::set<model::VertexId> boundary = boundaryVertices(surface);
        QJsonArray vertices;
        for (const auto& [id, p] : surface.vertices()) {
            vertices.append(QJsonObject{{"id", static_cast<qint64>(id)},
                                        {"position", QJsonArray{p.x, p.y, p.z}},
                                        {"pinned", surface.isPinned(id)},
                                        {"boundary", boundary.count(id) != 0}});
        }
        object["vertices"] = vertices;
    }
    if (listing.edges) {
        QJsonArray edges;
        const auto creases = creasesById(surface);
        for (const auto& [id, edge] : surface.edges()) {
            QJsonObject e{{"id", static_cast<qint64>(id)},
                          {"label", edge.isSpline() ? "S" : "R"},
                          {"vertices", QJsonArray{static_cast<qint64>(edge.from),
                                                  static_cast<qint64>(edge.to)}}};
            if (edge.isSpline()) {
                e["kind"] = curveKind(surface, id);
                e["condition"] = model::creaseConditionName(edge.condition);
            } else if (surface.facesOfEdge(id).size() == 2) {
                e["smooth"] = edge.smooth;
            }
            if (const auto crease = creases.find(id); crease != creases.end()) {
                e["assignment"] = model::foldAssignmentLetter(crease->second.assignment);
                e["foldAngle"] = crease->second.foldAngleDegrees;
            }
            edges.append(e);
        }
        object["edges"] = edges;
    }
    return object;
}

void printSurfaceText(const model::CompositeSurface& surface, std::size_t index,
                      const EntityListing& listing, std::ostream& out) {
    out << "Surface " << index + 1 << ": " << surface.name() << "\n";
    if (listing.vertices) {
        const std::set<model::VertexId> boundary = boundaryVertices(surface);
        out << "  Vertices (id x y z, pinned, boundary):\n";
        const auto precision = out.precision(15);
        for (const auto& [id, p] : surface.vertices()) {
            out << "    " << id << " " << p.x << " " << p.y << " " << p.z
                << (surface.isPinned(id) ? " pinned" : " free")
                << (boundary.count(id) != 0 ? " boundary" : " interior") << "\n";
        }
        out.precision(precision);
    }
    if (listing.edges) {
        out << "  Edges (id label from to; curves: kind, condition; rulings between two patches: "
               "smooth or sharp; creases: mountain M, valley V or flat F, fold angle):\n";
        const auto creases = creasesById(surface);
        for (const auto& [id, edge] : surface.edges()) {
            out << "    " << id << " " << (edge.isSpline() ? "S" : "R") << " " << edge.from << " "
                << edge.to;
            if (edge.isSpline()) {
                out << " " << curveKind(surface, id) << " "
                    << model::creaseConditionName(edge.condition);
            } else if (surface.facesOfEdge(id).size() == 2) {
                out << (edge.smooth ? " smooth" : " sharp");
            }
            if (const auto crease = creases.find(id); crease != creases.end()) {
                char fold[64];
                std::snprintf(fold, sizeof fold, " %s %.2f deg",
                              model::foldAssignmentLetter(crease->second.assignment),
                              crease->second.foldAngleDegrees);
                out << fold;
            }
            out << "\n";
        }
    }
}

} // namespace

void printEntities(const model::Project& project, const EntityListing& listing, std::ostream& out) {
    if (listing.json) {
        QJsonArray surfaces;
        for (const model::CompositeSurface& surface : project.surfaces) {
            surfaces.append(surfaceJson(surface, listing));
        }
        const QJsonObject root{{"units", QString::fromStdString(project.units)},
                               {"surfaces", surfaces}};
        out << QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
        return;
    }
    for (std::size_t i = 0; i < project.surfaces.size(); ++i) {
        printSurfaceText(project.surfaces[i], i, listing, out);
    }
}

int runPinCommand(const SubcommandArguments& args) {
    const std::string input = args.onePositional("one project file");
    const std::string idsText =
        args.required("vertices", "the vertices are missing (use --vertices IDS)");
    const std::string output = args.required("o", kMissingOutput);
    const std::vector<model::VertexId> ids = parseIds(idsText, "--vertices", "vertex");
    const int surfaceNumber =
        args.isSet("surface")
            ? static_cast<int>(parseWhole(*args.value("surface"), "--surface", 1, 1000000))
            : 0;
    const bool unpin = args.isSet("unpin");
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    const std::size_t index = surfaceIndex(surfaceNumber, project, "pin vertices of");
    model::CompositeSurface& surface = project.surfaces[index];
    std::string unknown;
    for (model::VertexId id : ids) {
        if (!surface.hasVertex(id)) {
            unknown += (unknown.empty() ? "" : ", ") + std::to_string(id);
        }
    }
    if (!unknown.empty()) {
        std::cerr << "devsurf-cli: surface '" << surface.name() << "' has no vertex " << unknown
                  << " (list them with 'devsurf-cli info FILE --vertices').\n";
        return 2;
    }
    for (model::VertexId id : ids) {
        surface.setPinned(id, !unpin);
    }
    writeProject(project, output);
    std::cout << "Wrote " << output << " (" << surface.pinnedVertices().size() << " of "
              << surface.vertices().size() << " vertices pinned in '" << surface.name() << "')\n";
    return 0;
}

namespace {

std::string millimetres(double value) {
    return QString::number(value, 'g', 4).toStdString() + " mm";
}
std::string squareMillimetres(double value) {
    return QString::number(value, 'f', 0).toStdString() + " mm\u00b2";
}

// The closed curves of a DXF, SVG, STEP or IGES file, seen from above (z dropped), as a sheet's
// outline: the largest the outer boundary, the others holes. InputError if it has none.
std::vector<std::vector<model::Vec2>> outlineFrom(const std::string& path) {
    const io::CurveImportResult read = io::importCurveFile(QString::fromStdString(path));
    if (read.error) {
        throw InputError(curveImportSentence(*read.error, path));
    }
    std::vector<std::vector<model::Vec2>> loops = model::closedLoopsFromAbove(read.curves);
    model::SheetDomain check;
    check.shape = model::SheetShape::Outline;
    check.outline = loops;
    if (loops.empty() || model::domainProblem(check)) {
        throw InputError("'" + path +
                         "' holds no closed curve enclosing an area to be the sheet's "
                         "outline.");
    }
    return loops;
}

// Every curve of a DXF, SVG, STEP or IGES file seen from above, moved by `shift` into the
// sheet's frame, as crease curves. InputError if it has none.
std::vector<model::SheetDomain::Curve> creaseCurvesFrom(const std::string& path,
                                                        const model::Vec2& shift) {
    io::CurveImportOptions options;
    options.tolerance = model::kCreaseCurveTolerance;
    const io::CurveImportResult read = io::importCurveFile(QString::fromStdString(path), options);
    if (read.error) {
        throw InputError(curveImportSentence(*read.error, path));
    }
    std::vector<model::SheetDomain::Curve> curves = model::sheetCurvesFromAbove(read.curves, shift);
    if (curves.empty()) {
        throw InputError("'" + path + "' holds no curve of two points or more to hold creases.");
    }
    return curves;
}

// The sheet asked for on the command line: free (nullopt for --off) or a shape's sizes.
std::optional<model::SheetDomain> requestedSheet(const SubcommandArguments& args) {
    const char* const options[] = {"free", "rectangle", "disk", "annulus", "outline", "off"};
    int given = 0;
    for (const char* option : options) {
        given += args.isSet(option) ? 1 : 0;
    }
    if (given != 1) {
        throw UsageError{
            "give one of --free, --rectangle W,H, --disk R, --annulus R1,R2, --outline FILE and "
            "--off"};
    }
    model::SheetDomain domain;
    constexpr double kLargest = 1e6; // mm: a kilometre
    if (args.isSet("off")) {
        return std::nullopt;
    }
    if (args.isSet("rectangle")) {
        const std::vector<double> size =
            parseReals(*args.value("rectangle"), "--rectangle", 2, "300,200");
        domain.shape = model::SheetShape::Rectangle;
        domain.width = size[0];
        domain.height = size[1];
        for (double length : size) {
            if (!(length >= 1e-3 && length <= kLargest)) {
                throw UsageError{"--rectangle needs a width and a height in mm, such as 300,200"};
            }
        }
    } else if (args.isSet("disk")) {
        domain.shape = model::SheetShape::Disk;
        domain.radius = parseReal(*args.value("disk"), "--disk", 1e-3, kLargest, "a radius in mm");
    } else if (args.isSet("annulus")) {
        const std::vector<double> radii =
            parseReals(*args.value("annulus"), "--annulus", 2, "100,250");
        domain.shape = model::SheetShape::Annulus;
        domain.innerRadius = std::min(radii[0], radii[1]);
        domain.radius = std::max(radii[0], radii[1]);
        if (!(domain.innerRadius > 0.0) || !(domain.radius > domain.innerRadius) ||
            domain.radius > kLargest) {
            throw UsageError{"--annulus needs two different radii in mm, such as 100,250"};
        }
    } else if (args.isSet("outline")) {
        domain.shape = model::SheetShape::Outline;
        domain.outline = outlineFrom(*args.value("outline"));
    }
    return domain;
}

} // namespace

int runSheetCommand(const SubcommandArguments& args) {
    const std::string input = args.onePositional("one project file");
    const std::string output = args.required("o", kMissingOutput);
    std::optional<model::SheetDomain> requested = requestedSheet(args);
    const int surfaceNumber =
        args.isSet("surface")
            ? static_cast<int>(parseWhole(*args.value("surface"), "--surface", 1, 1000000))
            : 0;
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    const std::size_t index = surfaceIndex(surfaceNumber, project, "hold the sheet of");
    model::CompositeSurface& surface = project.surfaces[index];
    if (!requested) {
        surface.setKeepsDevelopment(false);
        surface.setSheetDomain({});
        writeProject(project, output);
        std::cout << "Wrote " << output << " ('" << surface.name()
                  << "' no longer keeps a development)\n";
        return 0;
    }
    // A development already kept is confined as it is; otherwise it is unfolded now.
    if (!surface.keepsDevelopment() || surface.development().empty()) {
        if (const auto problem = model::keepDevelopment(surface)) {
            throw InputError("cannot hold the sheet of '" + surface.name() +
                             "': " + withoutFinalPeriod(ProblemText::of(*problem).toStdString()));
        }
    }
    const model::SampledMesh mesh =
        model::sampleSurface(surface, model::kDevelopmentSamplesPerInterval);
    if (surface.sheetDomain().shape == model::SheetShape::Cylinder) {
        // Closed around: its sheet is the cylinder it unrolls from, never a flat shape.
        if (!requested->isFree()) {
            throw InputError("cannot confine '" + surface.name() +
                             "' to a flat sheet: it closes around a cylinder of radius " +
                             millimetres(surface.sheetDomain().radius));
        }
        requested = surface.sheetDomain();
    }
    model::SheetDomain domain = model::placeDomain(*requested, mesh, surface.development());
    std::size_t creases = 0;
    if (args.isSet("creases") && args.isSet("keep-creases")) {
        throw UsageError{"give --creases FILE or --keep-creases, not both"};
    }
    if (args.isSet("creases") || args.isSet("keep-creases")) {
        if (domain.isFree() || domain.shape == model::SheetShape::Cylinder) {
            throw UsageError{std::string(args.isSet("creases") ? "--creases" : "--keep-creases") +
                             " needs a sheet of a shape: --rectangle, --disk, --annulus or "
                             "--outline"};
        }
    }
    if (args.isSet("keep-creases")) {
        domain.creaseCurves = model::sheetFrameCurves(
            domain, model::creaseCurvesAsTheyLie(surface, surface.development()));
        domain.creaseCurveOf =
            model::assignCreasesToCurves(domain, surface, mesh, surface.development());
        creases = domain.creaseCurveOf.size();
        if (creases == 0) {
            throw InputError("'" + surface.name() + "' has no crease to keep");
        }
    }
    if (args.isSet("creases")) {
        // A rectangle is drawn from its corner at 0,0; the sheet's frame has its centre there.
        const model::Vec2 shift = domain.shape == model::SheetShape::Rectangle
                                      ? model::Vec2(-0.5 * domain.width, -0.5 * domain.height)
                                      : model::Vec2();
        const std::string path = *args.value("creases");
        domain.creaseCurves = creaseCurvesFrom(path, shift);
        domain.creaseCurveOf =
            model::assignCreasesToCurves(domain, surface, mesh, surface.development());
        creases = domain.creaseCurveOf.size();
        if (creases == 0) {
            throw InputError(
                "no crease of '" + surface.name() + "' lies near a curve of '" + path +
                "' (within half its length, no other crease nearer, where the sheet is placed)");
        }
    }
    surface.setSheetDomain(domain);
    writeProject(project, output);
    std::cout << "Wrote " << output << " ('" << surface.name()
              << "' keeps its development: " << surface.development().size() << " points, ";
    if (domain.shape == model::SheetShape::Cylinder) {
        std::cout << "periodic around a cylinder of radius " << millimetres(domain.radius) << ")\n";
        return 0;
    }
    if (domain.isFree()) {
        std::cout << "no boundary confined)\n";
        return 0;
    }
    const double gap = model::largestDomainGap(domain, mesh, surface.development());
    const double area = model::developedArea(mesh, surface.development());
    std::cout << "confined to the sheet; its boundary is " << millimetres(gap)
              << " from the sheet's)\n";
    double creaseGap = 0.0;
    if (creases > 0) {
        std::set<int> used;
        for (const auto& [edge, curve] : domain.creaseCurveOf) {
            used.insert(curve);
        }
        creaseGap = model::largestCreaseCurveGap(domain, mesh, surface.development());
        std::cout << creases << (creases == 1 ? " crease" : " creases") << " held on "
                  << used.size() << " of " << domain.creaseCurves.size()
                  << " crease curves; the farthest of their points is " << millimetres(creaseGap)
                  << " from its curve.\n";
    }
    if (area > model::domainArea(domain) * (1.0 + 1e-9)) {
        std::cout << "Note: the development (" << squareMillimetres(area)
                  << ") is larger than the sheet (" << squareMillimetres(model::domainArea(domain))
                  << "): no solve can fold the design from it without cutting.\n";
    } else if (gap > 1e-6 || creaseGap > 1e-6) {
        std::cout << "The next solve moves the development onto the sheet.\n";
    }
    return 0;
}

} // namespace devsurf::app
