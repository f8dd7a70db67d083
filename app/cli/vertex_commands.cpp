#include "vertex_commands.h"
#include "model/derived_geometry.h"

#include "cli_output.h"
#include "command_line.h"
#include "problem_text.h"

#include "io/project_file.h"
#include "model/creases.h"
#include "model/development.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <cstdio>
#include <iostream>
#include <map>
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
    const std::string output = args.required("o", "the output file is missing (use -o FILE)");
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

int runSheetCommand(const SubcommandArguments& args) {
    const std::string input = args.onePositional("one project file");
    const std::string output = args.required("o", "the output file is missing (use -o FILE)");
    const bool free = args.isSet("free");
    if (free == args.isSet("off")) {
        throw UsageError{"give one of --free (hold the sheet as it unfolds) and --off"};
    }
    const int surfaceNumber =
        args.isSet("surface")
            ? static_cast<int>(parseWhole(*args.value("surface"), "--surface", 1, 1000000))
            : 0;
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    const std::size_t index = surfaceIndex(surfaceNumber, project, "hold the sheet of");
    model::CompositeSurface& surface = project.surfaces[index];
    if (free) {
        if (const auto problem = model::keepDevelopment(surface)) {
            throw InputError("cannot hold the sheet of '" + surface.name() +
                             "': " + withoutFinalPeriod(ProblemText::of(*problem).toStdString()));
        }
    } else {
        surface.setKeepsDevelopment(false);
    }
    writeProject(project, output);
    std::cout << "Wrote " << output << " ('" << surface.name() << "' "
              << (free ? "keeps its development: " + std::to_string(surface.development().size()) +
                             " points, no boundary confined"
                       : std::string("no longer keeps a development"))
              << ")\n";
    return 0;
}

} // namespace devsurf::app
