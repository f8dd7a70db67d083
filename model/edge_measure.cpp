#include "edge_measure.h"

#include "bspline_curve.h"

#include <algorithm>
#include <cmath>

namespace devsurf::model {

namespace {

// The unit tangent of an edge at one of its ends, pointing into the edge.
Vec3 tangentAway(const CompositeSurface& surface, EdgeId edge, VertexId at) {
    const EdgeRecord& record = surface.edge(edge);
    const bool atFrom = record.from == at;
    Vec3 direction;
    if (record.isSpline() && record.controlPoints.size() >= 2) {
        // A clamped spline leaves its ends along its first and last control legs.
        const std::vector<Vec3>& p = record.controlPoints;
        std::size_t next = atFrom ? 1 : p.size() - 2;
        const Vec3& end = atFrom ? p.front() : p.back();
        // A zero leg (a repeated control point) has no direction: the next one has.
        while (distance(p[next], end) == 0.0 && next > 0 && next + 1 < p.size()) {
            next = atFrom ? next + 1 : next - 1;
        }
        direction = p[next] - end;
    } else {
        direction = surface.position(atFrom ? record.to : record.from) - surface.position(at);
    }
    const double length = direction.norm();
    return length > 0.0 ? direction * (1.0 / length) : direction;
}

} // namespace

double edgeLength(const CompositeSurface& surface, EdgeId edge) {
    const EdgeRecord& record = surface.edge(edge);
    if (!record.isSpline()) {
        return distance(surface.position(record.from), surface.position(record.to));
    }
    const BSplineCurve spline = BSplineCurve::uniform(record.space, record.controlPoints);
    constexpr int kChords = 1000;
    double length = 0.0;
    Vec3 last = spline.evaluate(spline.domainBegin());
    for (int i = 1; i <= kChords; ++i) {
        const Vec3 p = spline.evaluate(spline.domainBegin() +
                                       (spline.domainEnd() - spline.domainBegin()) * i / kChords);
        length += distance(last, p);
        last = p;
    }
    return length;
}

std::optional<EdgeAngle> edgeAngle(const CompositeSurface& surface, EdgeId a, EdgeId b) {
    if (a == b || !surface.hasEdge(a) || !surface.hasEdge(b)) {
        return std::nullopt;
    }
    const EdgeRecord& ra = surface.edge(a);
    const EdgeRecord& rb = surface.edge(b);
    VertexId shared = kInvalidId;
    for (VertexId v : {ra.from, ra.to}) {
        if (v == rb.from || v == rb.to) {
            shared = v;
        }
    }
    if (shared == kInvalidId) {
        return std::nullopt;
    }
    const Vec3 ta = tangentAway(surface, a, shared);
    const Vec3 tb = tangentAway(surface, b, shared);
    // atan2 of |cross| and dot: accurate near 0° and 180° alike.
    const double degrees = std::atan2(cross(ta, tb).norm(), dot(ta, tb)) * 180.0 / M_PI;
    return EdgeAngle{shared, degrees};
}

} // namespace devsurf::model
