#include "sampled_mesh.h"

#include "model_error.h"
#include "strip.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace devsurf::model {

SampledMesh sampleSurface(const CompositeSurface& surface, int samplesPerInterval) {
    if (samplesPerInterval < 1 || samplesPerInterval > 1000) {
        Problem problem = problemOf(ProblemCode::SampleCount);
        problem.count = samplesPerInterval;
        problem.expected = 1000;
        throw ModelError(problem);
    }
    const auto problems = surface.validate();
    if (!problems.empty()) {
        throw ModelError(problems.front());
    }
    SampledMesh mesh;
    std::map<VertexId, int> vertexIndex;
    for (const auto& [id, position] : surface.vertices()) {
        vertexIndex[id] = static_cast<int>(mesh.vertices.size());
        mesh.vertices.push_back(position);
        mesh.coarseVertexIds.push_back(id);
    }
    std::map<EdgeId, std::vector<int>> edgeSamples;
    for (const auto& [id, record] : surface.edges()) {
        if (!record.isSpline()) {
            continue;
        }
        const BSplineCurve curve = BSplineCurve::uniform(record.space, record.controlPoints);
        const int count = record.space.intervals * samplesPerInterval;
        std::vector<int> indices{vertexIndex.at(record.from)};
        for (int i = 1; i < count; ++i) {
            indices.push_back(static_cast<int>(mesh.vertices.size()));
            mesh.vertices.push_back(curve.evaluate(static_cast<double>(i) / count));
        }
        indices.push_back(vertexIndex.at(record.to));
        mesh.splineEdges.push_back({id, indices});
        edgeSamples.emplace(id, std::move(indices));
    }
    auto sideSamples = [&edgeSamples](const StripSide& side) {
        std::vector<int> samples = edgeSamples.at(side.edge);
        if (side.reversed) {
            std::reverse(samples.begin(), samples.end());
        }
        return samples;
    };
    auto addFace = [&mesh](std::vector<int> corners, FaceId origin) {
        // Drop corners repeated by a collapsed side (SRS strips end in a point).
        std::vector<int> distinct;
        for (int c : corners) {
            if (std::find(distinct.begin(), distinct.end(), c) == distinct.end()) {
                distinct.push_back(c);
            }
        }
        if (distinct.size() >= 3) {
            mesh.faces.push_back(std::move(distinct));
            mesh.faceOrigin.push_back(origin);
        }
    };
    for (const auto& [faceId, loop] : surface.faces()) {
        const FaceType type = surface.faceType(faceId);
        if (type == FaceType::Planar) {
            std::vector<int> corners;
            for (VertexId v : loop) {
                corners.push_back(vertexIndex.at(v));
            }
            if (corners.size() <= 4) {
                addFace(corners, faceId);
            } else {
                for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
                    addFace({corners[0], corners[i], corners[i + 1]}, faceId);
                }
            }
            continue;
        }
        const Strip strip = stripOfFace(surface, faceId);
        const std::vector<int> a = sideSamples(strip.aSide);
        if (strip.isCone()) {
            const int apex = vertexIndex.at(strip.apexVertex);
            for (std::size_t i = 0; i + 1 < a.size(); ++i) {
                addFace({a[i], a[i + 1], apex}, faceId);
            }
            for (int sample : a) {
                mesh.rulings.emplace_back(sample, apex);
            }
            continue;
        }
        const std::vector<int> b = sideSamples(strip.bSide);
        for (std::size_t i = 0; i + 1 < a.size(); ++i) {
            addFace({a[i], a[i + 1], b[i + 1], b[i]}, faceId);
        }
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (a[i] != b[i]) {
                mesh.rulings.emplace_back(a[i], b[i]);
            }
        }
    }
    return mesh;
}

std::size_t sampledVertexCount(const CompositeSurface& surface, int samplesPerInterval) {
    std::size_t count = surface.vertices().size();
    for (const auto& [id, record] : surface.edges()) {
        if (record.isSpline() && record.space.intervals > 0) {
            count += static_cast<std::size_t>(record.space.intervals * samplesPerInterval - 1);
        }
    }
    return count;
}

SidesByEdge groupSidesByEdge(const std::vector<std::pair<int, int>>& edges) {
    SidesByEdge grouped;
    grouped.order.resize(edges.size());
    std::iota(grouped.order.begin(), grouped.order.end(), std::size_t{0});
    std::stable_sort(grouped.order.begin(), grouped.order.end(),
                     [&edges](std::size_t x, std::size_t y) { return edges[x] < edges[y]; });
    grouped.run.resize(edges.size());
    for (std::size_t begin = 0; begin < grouped.order.size();) {
        std::size_t end = begin + 1;
        while (end < grouped.order.size() &&
               edges[grouped.order[end]] == edges[grouped.order[begin]]) {
            ++end;
        }
        for (std::size_t i = begin; i < end; ++i) {
            grouped.run[grouped.order[i]] = {begin, end};
        }
        begin = end;
    }
    return grouped;
}

} // namespace devsurf::model
