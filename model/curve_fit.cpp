#include "curve_fit.h"

#include "bspline_curve.h"
#include "edge_measure.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace devsurf::model {

namespace {

// A polyline measured by arc length.
struct Measured {
    std::vector<Vec3> points;
    std::vector<double> at; // arc length at each point
    double length() const { return at.empty() ? 0.0 : at.back(); }
    bool closed() const {
        return points.size() > 3 && distance(points.front(), points.back()) <= 1e-9 * length();
    }

    explicit Measured(const std::vector<Vec3>& curve) {
        for (const Vec3& p : curve) {
            if (!points.empty() && distance(points.back(), p) == 0.0) {
                continue; // repeated points carry no length
            }
            at.push_back(points.empty() ? 0.0 : at.back() + distance(points.back(), p));
            points.push_back(p);
        }
    }

    // The point at arc length s (clamped).
    Vec3 point(double s) const {
        s = std::clamp(s, 0.0, length());
        const auto it = std::upper_bound(at.begin(), at.end(), s);
        const std::size_t i = std::min<std::size_t>(
            static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - at.begin(), 1)),
            points.size() - 1);
        const double span = at[i] - at[i - 1];
        const double t = span > 0.0 ? (s - at[i - 1]) / span : 0.0;
        return points[i - 1] + (points[i] - points[i - 1]) * t;
    }

    // The arc length of the point nearest p, and its distance.
    std::pair<double, double> nearest(const Vec3& p) const {
        double best = std::numeric_limits<double>::infinity(), where = 0.0;
        for (std::size_t i = 1; i < points.size(); ++i) {
            const Vec3 d = points[i] - points[i - 1];
            const double len2 = dot(d, d);
            const double t =
                len2 > 0.0 ? std::clamp(dot(p - points[i - 1], d) / len2, 0.0, 1.0) : 0.0;
            const double gap = distance(p, points[i - 1] + d * t);
            if (gap < best) {
                best = gap;
                where = at[i - 1] + t * (at[i] - at[i - 1]);
            }
        }
        return {where, best};
    }
};

BSplineCurve splineOf(const EdgeRecord& record) {
    return BSplineCurve::uniform(record.space, record.controlPoints);
}

} // namespace

double edgeCurveDistance(const CompositeSurface& surface, EdgeId edge,
                         const ReferenceCurve& curve) {
    if (!surface.hasEdge(edge) || !surface.edge(edge).isSpline()) {
        return std::numeric_limits<double>::infinity();
    }
    const Measured measured(curve.points);
    if (measured.points.size() < 2) {
        return std::numeric_limits<double>::infinity();
    }
    const BSplineCurve spline = splineOf(surface.edge(edge));
    constexpr int kSamples = 32;
    double sum = 0.0;
    for (int i = 0; i <= kSamples; ++i) {
        const double u = spline.domainBegin() +
                         (spline.domainEnd() - spline.domainBegin()) * i / double(kSamples);
        sum += measured.nearest(spline.evaluate(u)).second;
    }
    return sum / (kSamples + 1);
}

std::size_t nearestCurve(const CompositeSurface& surface, EdgeId edge,
                         const std::vector<ReferenceCurve>& curves) {
    std::size_t nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const double d = edgeCurveDistance(surface, edge, curves[c]);
        if (d < best) {
            best = d;
            nearest = c;
        }
    }
    return nearest;
}

EdgeFit fitEdgeToCurve(CompositeSurface& surface, EdgeId edge, const ReferenceCurve& curve) {
    EdgeFit fit;
    if (!surface.hasEdge(edge) || !surface.edge(edge).isSpline()) {
        fit.refused = EdgeFit::Refusal::NotSpline;
        return fit;
    }
    const Measured measured(curve.points);
    if (measured.points.size() < 2 || !(measured.length() > 0.0)) {
        fit.refused = EdgeFit::Refusal::TooFewPoints;
        return fit;
    }
    const EdgeRecord record = surface.edge(edge);
    const int n = static_cast<int>(record.controlPoints.size());
    // The ends: unpinned ones onto the curve; the piece between their nearest points.
    Vec3 ends[2] = {record.controlPoints.front(), record.controlPoints.back()};
    double at[2];
    const VertexId vertices[2] = {record.from, record.to};
    for (int k = 0; k < 2; ++k) {
        at[k] = measured.nearest(ends[k]).first;
        if (!surface.isPinned(vertices[k])) {
            ends[k] = measured.point(at[k]);
        }
    }
    double s0 = at[0], s1 = at[1];
    if (std::abs(s1 - s0) <= 1e-9 * measured.length()) {
        fit.refused = EdgeFit::Refusal::EndsMeet;
        return fit;
    }
    const double total = measured.length();
    if (measured.closed()) {
        // Two pieces join the ends: the one whose length is nearest the edge's.
        const double length = edgeLength(surface, edge);
        const double direct = std::abs(s1 - s0);
        const double around = total - direct;
        if (std::abs(around - length) < std::abs(direct - length)) {
            s1 = s1 > s0 ? s1 - total : s1 + total; // run the other way, wrapping
        }
    }
    const auto pieceAt = [&](double fraction) {
        double s = s0 + (s1 - s0) * fraction;
        if (measured.closed()) {
            s = std::fmod(s + 2 * total, total);
        }
        return measured.point(s);
    };

    // Least squares for the inner control points, the parameter proportional to arc length.
    const int inner = n - 2;
    std::vector<Vec3> points = record.controlPoints;
    points.front() = ends[0];
    points.back() = ends[1];
    if (inner > 0) {
        const int samples = std::max(8 * n, 64);
        Eigen::MatrixXd basis(samples + 1, n);
        std::vector<Vec3> unit(static_cast<std::size_t>(n), Vec3(0, 0, 0));
        for (int j = 0; j < n; ++j) {
            unit[static_cast<std::size_t>(j)] = Vec3(1, 0, 0);
            const BSplineCurve b = BSplineCurve::uniform(record.space, unit);
            unit[static_cast<std::size_t>(j)] = Vec3(0, 0, 0);
            for (int i = 0; i <= samples; ++i) {
                const double u = b.domainBegin() + (b.domainEnd() - b.domainBegin()) * i / samples;
                basis(i, j) = b.evaluate(u).x;
            }
        }
        Eigen::MatrixXd rhs(samples + 1, 3);
        for (int i = 0; i <= samples; ++i) {
            const Vec3 target = pieceAt(static_cast<double>(i) / samples) - ends[0] * basis(i, 0) -
                                ends[1] * basis(i, n - 1);
            rhs.row(i) << target.x, target.y, target.z;
        }
        const Eigen::MatrixXd a = basis.middleCols(1, inner);
        const Eigen::MatrixXd x = (a.transpose() * a).ldlt().solve(a.transpose() * rhs);
        for (int j = 0; j < inner; ++j) {
            points[static_cast<std::size_t>(j + 1)] = Vec3(x(j, 0), x(j, 1), x(j, 2));
        }
    }
    for (std::size_t j = 0; j < points.size(); ++j) {
        if (!std::isfinite(points[j].x) || !std::isfinite(points[j].y) ||
            !std::isfinite(points[j].z)) {
            fit.refused = EdgeFit::Refusal::TooFewPoints;
            return fit;
        }
        fit.moved = std::max(fit.moved, distance(points[j], record.controlPoints[j]));
    }
    std::vector<std::pair<VertexId, Vec3>> moves;
    for (int k = 0; k < 2; ++k) {
        if (!surface.isPinned(vertices[k])) {
            moves.emplace_back(vertices[k], ends[k]);
        }
    }
    surface.moveVertices(moves);
    surface.setControlPoints(edge, points);
    const BSplineCurve fitted = splineOf(surface.edge(edge));
    for (int i = 0; i <= 200; ++i) {
        const double u =
            fitted.domainBegin() + (fitted.domainEnd() - fitted.domainBegin()) * i / 200.0;
        fit.largestDistance =
            std::max(fit.largestDistance, measured.nearest(fitted.evaluate(u)).second);
    }
    return fit;
}

} // namespace devsurf::model
