#include "strip.h"

#include "model_error.h"

namespace devsurf::model {

namespace {

// The curve of the loop side i (loop[i] → loop[i+1]) as it runs along the loop, or against it.
BSplineCurve sideCurve(const CompositeSurface& surface, const std::vector<VertexId>& loop,
                       std::size_t side, bool againstLoop, StripSide& info) {
    const VertexId from = loop[side];
    const VertexId to = loop[(side + 1) % loop.size()];
    info.edge = surface.edgeBetween(from, to);
    const EdgeRecord& record = surface.edge(info.edge);
    const VertexId start = againstLoop ? to : from;
    info.reversed = record.from != start;
    std::vector<Vec3> points = surface.controlPointsFrom(start, againstLoop ? from : to);
    return BSplineCurve::uniform(record.space, std::move(points), false);
}

} // namespace

Strip stripOfFace(const CompositeSurface& surface, FaceId face) {
    const auto& loop = surface.faceLoop(face);
    const std::string labels = surface.labelString(face);
    Strip strip;
    strip.face = face;
    strip.type = surface.faceType(face);
    const std::size_t sides = loop.size();
    switch (strip.type) {
    case FaceType::StripSRSR: {
        const auto edges = surface.faceEdges(face);
        std::size_t aIndex = labels[0] == 'S' ? 0 : 1;
        if (edges[aIndex + 2] < edges[aIndex]) {
            aIndex += 2;
        }
        strip.a = sideCurve(surface, loop, aIndex, false, strip.aSide);
        strip.b = sideCurve(surface, loop, (aIndex + 2) % sides, true, strip.bSide);
        break;
    }
    case FaceType::StripSRS: {
        const std::size_t ruling = labels.find('R');
        strip.a = sideCurve(surface, loop, (ruling + 1) % 3, false, strip.aSide);
        strip.b = sideCurve(surface, loop, (ruling + 2) % 3, true, strip.bSide);
        break;
    }
    case FaceType::ConeSRR: {
        const std::size_t spline = labels.find('S');
        strip.a = sideCurve(surface, loop, spline, false, strip.aSide);
        strip.apexVertex = loop[(spline + 2) % 3];
        strip.apex = surface.position(strip.apexVertex);
        break;
    }
    case FaceType::Planar:
    case FaceType::Invalid:
        throw ModelError(faceProblem(ProblemCode::NotAStrip, face));
    }
    return strip;
}

std::vector<Strip> stripsOf(const CompositeSurface& surface) {
    std::vector<Strip> strips;
    for (const auto& entry : surface.faces()) {
        const FaceType type = surface.faceType(entry.first);
        if (type == FaceType::StripSRSR || type == FaceType::StripSRS ||
            type == FaceType::ConeSRR) {
            strips.push_back(stripOfFace(surface, entry.first));
        }
    }
    return strips;
}

} // namespace devsurf::model
