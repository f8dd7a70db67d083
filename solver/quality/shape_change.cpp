#include "solver/quality/shape_change.h"
#include "model/derived_geometry.h"

#include "model/bspline_curve.h"
#include "model/model_error.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::solver {

using model::Vec3;

namespace {

Vec3 faceNormal(const model::SampledMesh& mesh, const std::vector<int>& face) {
    Vec3 normal;
    for (std::size_t i = 0; i < face.size(); ++i) {
        normal += cross(mesh.vertices[static_cast<std::size_t>(face[i])],
                        mesh.vertices[static_cast<std::size_t>(face[(i + 1) % face.size()])]);
    }
    const double length = normal.norm();
    return length > 0.0 ? normal / length : normal;
}

// The faces on either side of every mesh edge (an edge with one face maps to {f, -1}).
std::map<std::pair<int, int>, std::pair<int, int>> edgeFaces(const model::SampledMesh& mesh) {
    std::map<std::pair<int, int>, std::pair<int, int>> result;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const std::vector<int>& face = mesh.faces[f];
        for (std::size_t i = 0; i < face.size(); ++i) {
            const int a = face[i];
            const int b = face[(i + 1) % face.size()];
            if (a == b) {
                continue;
            }
            auto [it, inserted] =
                result.try_emplace({std::min(a, b), std::max(a, b)}, static_cast<int>(f), -1);
            if (!inserted) {
                it->second.second = static_cast<int>(f);
            }
        }
    }
    return result;
}

// Per face of the surface, the pairs of neighbouring sampled faces of it whose normals turn
// by more than 90° (see foldOvers).
std::map<model::FaceId, int>
foldOverPlaces(const model::SampledMesh& mesh,
               const std::map<std::pair<int, int>, std::pair<int, int>>& faces) {
    std::map<model::FaceId, int> places;
    for (const auto& [edge, pair] : faces) {
        (void)edge;
        if (pair.second < 0) {
            continue;
        }
        const auto first = static_cast<std::size_t>(pair.first);
        const auto second = static_cast<std::size_t>(pair.second);
        // Turned by more than 90°: the normals point to opposite half-spaces.
        if (mesh.faceOrigin[first] == mesh.faceOrigin[second] &&
            dot(faceNormal(mesh, mesh.faces[first]), faceNormal(mesh, mesh.faces[second])) < 0.0) {
            ++places[mesh.faceOrigin[first]];
        }
    }
    return places;
}

// foldOverPlaces as (face, places), most places first (see foldOvers).
std::vector<std::pair<model::FaceId, int>>
sortedFoldOvers(const model::SampledMesh& mesh,
                const std::map<std::pair<int, int>, std::pair<int, int>>& faces) {
    const std::map<model::FaceId, int> places = foldOverPlaces(mesh, faces);
    std::vector<std::pair<model::FaceId, int>> result(places.begin(), places.end());
    std::stable_sort(result.begin(), result.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    return result;
}

} // namespace

ShapeChange measureShapeChange(const model::CompositeSurface& start,
                               const model::CompositeSurface& result, int samplesPerInterval) {
    ShapeChange change;
    const int samples = std::max(1, samplesPerInterval);
    const std::vector<model::Strip> startStrips = model::stripsOf(start);
    const std::vector<model::Strip> resultStrips = model::stripsOf(result);
    if (startStrips.size() != resultStrips.size()) {
        throw model::ModelError(model::problemOf(model::ProblemCode::DifferentFaces));
    }
    for (std::size_t s = 0; s < startStrips.size(); ++s) {
        const model::Strip& a = startStrips[s];
        const model::Strip& b = resultStrips[s];
        if (a.isCone()) {
            continue;
        }
        const int intervals = start.edge(a.aSide.edge).space.intervals;
        for (int i = 0; i <= intervals * samples; ++i) {
            const double u = static_cast<double>(i) / (intervals * samples);
            const double before = distance(a.aPoint(u), a.bPoint(u));
            if (before > 1e-9 * (1.0 + a.aPoint(u).norm())) {
                change.shortestRuling =
                    std::min(change.shortestRuling, distance(b.aPoint(u), b.bPoint(u)) / before);
            }
        }
    }
    for (const auto& [id, record] : start.edges()) {
        if (!record.isSpline()) {
            continue;
        }
        const auto before = model::BSplineCurve::uniform(record.space, record.controlPoints);
        const auto after =
            model::BSplineCurve::uniform(result.edge(id).space, result.edge(id).controlPoints);
        const int count = record.space.intervals * samples;
        double mean = 0.0;
        for (int i = 0; i <= count; ++i) {
            mean += before.derivative(static_cast<double>(i) / count, 1).norm();
        }
        mean /= count + 1;
        for (int i = 0; i <= count && mean > 0.0; ++i) {
            change.slowestSpeed =
                std::min(change.slowestSpeed,
                         after.derivative(static_cast<double>(i) / count, 1).norm() / mean);
        }
        for (std::size_t k = 0; k < record.controlPoints.size(); ++k) {
            change.largestMove =
                std::max(change.largestMove,
                         distance(record.controlPoints[k], result.edge(id).controlPoints[k]));
        }
    }
    for (const auto& [id, position] : start.vertices()) {
        change.largestMove = std::max(change.largestMove, distance(position, result.position(id)));
    }

    const auto derivedBefore = model::DerivedGeometry::of(start, samples);
    const model::SampledMesh& before = derivedBefore->mesh();
    double sum = 0.0;
    int count = 0;
    for (const auto& [edge, faces] : edgeFaces(before)) {
        (void)edge;
        if (faces.second >= 0) {
            sum += angleBetween(
                faceNormal(before, before.faces[static_cast<std::size_t>(faces.first)]),
                faceNormal(before, before.faces[static_cast<std::size_t>(faces.second)]));
            ++count;
        }
    }
    change.startNormalAngleMean = count > 0 ? sum / count : 0.0;

    const auto derivedAfter = model::DerivedGeometry::of(result, samples);
    const model::SampledMesh& after = derivedAfter->mesh();
    const auto afterEdges = edgeFaces(after);
    sum = 0.0;
    count = 0;
    for (const model::SampledMesh::Polyline& line : after.splineEdges) {
        if (result.facesOfEdge(line.edge).size() != 2) {
            continue;
        }
        for (std::size_t i = 0; i + 1 < line.vertices.size(); ++i) {
            const int a = line.vertices[i];
            const int b = line.vertices[i + 1];
            const auto it = afterEdges.find({std::min(a, b), std::max(a, b)});
            if (it == afterEdges.end() || it->second.second < 0) {
                continue;
            }
            sum += angleBetween(
                faceNormal(after, after.faces[static_cast<std::size_t>(it->second.first)]),
                faceNormal(after, after.faces[static_cast<std::size_t>(it->second.second)]));
            ++count;
        }
    }
    change.creaseFoldMean = count > 0 ? sum / count : 0.0;
    change.foldOvers = sortedFoldOvers(after, afterEdges);
    return change;
}

std::vector<std::pair<model::FaceId, int>> foldOvers(const model::CompositeSurface& surface,
                                                     int samplesPerInterval) {
    std::shared_ptr<const model::DerivedGeometry> derived;
    try {
        derived = model::DerivedGeometry::of(surface, std::max(1, samplesPerInterval));
    } catch (const std::exception&) {
        return {}; // an invalid surface has no patches to measure
    }
    return sortedFoldOvers(derived->mesh(), edgeFaces(derived->mesh()));
}

int ShapeChange::foldOverPlaces() const {
    int sum = 0;
    for (const auto& [face, places] : foldOvers) {
        (void)face;
        sum += places;
    }
    return sum;
}

} // namespace devsurf::solver
