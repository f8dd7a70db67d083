#include "model/reference/initial_strip.h"

#include "model/reference/strip_plane.h"

#include "model/bspline_curve.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>

namespace devsurf::model::reference {

using detail::extents;
using detail::normalTurning;
using detail::stripPlane;
using detail::StripPlane;
using detail::Turning;

namespace {

// Control points of the straight spline from p to q in `space` at its Greville abscissae:
// the line, uniformly parametrised (as model/examples.cpp builds its sheet).
std::vector<Vec3> straightControlPoints(const SplineSpace& space, const Vec3& p, const Vec3& q) {
    const std::vector<double> knots = space.knots(false);
    const int count = space.controlPointCount(false);
    std::vector<Vec3> points(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        double greville = 0.0;
        for (int j = 1; j <= space.degree; ++j) {
            greville += knots[static_cast<std::size_t>(i + j)];
        }
        greville /= space.degree;
        points[static_cast<std::size_t>(i)] = p * (1.0 - greville) + q * greville;
    }
    points.front() = p;
    points.back() = q;
    return points;
}

} // namespace

namespace detail {

std::optional<Turning> normalTurning(const std::vector<Vec3>& points,
                                     const std::vector<Vec3>& normals,
                                     const PrincipalFrame& frame) {
    if (normals.empty() || normals.size() != points.size()) {
        return std::nullopt;
    }
    Eigen::MatrixXd positions(static_cast<Eigen::Index>(points.size()), 3);
    Eigen::MatrixXd tilts(static_cast<Eigen::Index>(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i) {
        Vec3 n = normals[i];
        const double length = n.norm();
        if (!(length > 0.0) || !std::isfinite(length)) {
            return std::nullopt;
        }
        n = n / length;
        if (dot(n, frame.axes[2]) < 0.0) {
            n = -n;
        }
        const auto row = static_cast<Eigen::Index>(i);
        const Vec3 d = points[i] - frame.centroid;
        positions.row(row) << dot(d, frame.axes[0]), dot(d, frame.axes[1]), 1.0;
        tilts.row(row) << dot(n, frame.axes[0]), dot(n, frame.axes[1]);
    }
    // tilt ≈ position · X; the 2 × 2 gradient G = X's first two rows, tilt change = Gᵀ · step.
    const Eigen::MatrixXd x = positions.colPivHouseholderQr().solve(tilts);
    const Eigen::Matrix2d gradient = x.topRows(2).transpose(); // rows: tilt, columns: step
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(gradient, Eigen::ComputeFullV);
    const Eigen::Vector2d v = svd.matrixV().col(0);
    const Vec3 direction = frame.axes[0] * v(0) + frame.axes[1] * v(1);
    if (!(direction.norm() > 0.0)) {
        return std::nullopt;
    }
    Turning t;
    t.most = svd.singularValues()(0);
    t.least = svd.singularValues()(1);
    t.direction = direction / direction.norm();
    t.alongLongest = std::abs(v(0)) / v.norm();
    return t;
}

} // namespace detail

namespace {

// The unit direction of the frame's plane along which the normals turn most, if they turn
// clearly more along it than across it (kRulingAnisotropy) and by kRulingTurnMinimum at least
// over the points.
std::optional<Vec3> mostTurningDirection(const std::vector<Vec3>& points,
                                         const std::vector<Vec3>& normals,
                                         const PrincipalFrame& frame) {
    const std::optional<Turning> t = normalTurning(points, normals, frame);
    if (!t) {
        return std::nullopt;
    }
    const double span = std::max(frame.high[0] - frame.low[0], frame.high[1] - frame.low[1]);
    if (!(t->most * span >= kRulingTurnMinimum) || !(t->most >= kRulingAnisotropy * t->least)) {
        return std::nullopt;
    }
    // Near the longest axis (within kRulingTurnAngle) the plain strip stays: turning it a
    // little gains nothing and changes what the strips of a shape meet with.
    if (t->alongLongest >= std::cos(kRulingTurnAngle)) {
        return std::nullopt;
    }
    return t->direction;
}

// k-means labels of `points` into `count` groups (at most 50 rounds) from a deterministic
// farthest-point start.
std::vector<std::size_t> kMeansLabels(const std::vector<Vec3>& points, std::size_t k) {
    const PrincipalFrame frame = principalFrame(points);
    // Farthest-point start: deterministic and spread over the shape.
    std::vector<Vec3> centres;
    std::vector<double> nearest(points.size(), std::numeric_limits<double>::max());
    Vec3 next = frame.centroid;
    for (std::size_t c = 0; c < k; ++c) {
        std::size_t farthest = 0;
        double best = -1.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double d = c == 0 ? (points[i] - next).norm() : nearest[i];
            if (d > best) {
                best = d;
                farthest = i;
            }
        }
        centres.push_back(points[farthest]);
        for (std::size_t i = 0; i < points.size(); ++i) {
            nearest[i] = std::min(nearest[i], (points[i] - centres.back()).norm());
        }
    }
    std::vector<std::size_t> label(points.size(), 0);
    for (int round = 0; round < 50; ++round) {
        bool changed = false;
        for (std::size_t i = 0; i < points.size(); ++i) {
            std::size_t best = 0;
            for (std::size_t c = 1; c < k; ++c) {
                if ((points[i] - centres[c]).squaredNorm() <
                    (points[i] - centres[best]).squaredNorm()) {
                    best = c;
                }
            }
            changed = changed || best != label[i];
            label[i] = best;
        }
        if (!changed && round > 0) {
            break;
        }
        std::vector<Vec3> sum(k);
        std::vector<std::size_t> members(k, 0);
        for (std::size_t i = 0; i < points.size(); ++i) {
            sum[label[i]] += points[i];
            ++members[label[i]];
        }
        for (std::size_t c = 0; c < k; ++c) {
            if (members[c] > 0) {
                centres[c] = sum[c] / static_cast<double>(members[c]);
            }
        }
    }
    return label;
}

std::vector<std::vector<std::size_t>> groupsOf(const std::vector<std::size_t>& label,
                                               std::size_t k) {
    std::vector<std::vector<std::size_t>> groups(k);
    for (std::size_t i = 0; i < label.size(); ++i) {
        groups[label[i]].push_back(i);
    }
    groups.erase(std::remove_if(groups.begin(), groups.end(),
                                [](const std::vector<std::size_t>& g) { return g.empty(); }),
                 groups.end());
    return groups;
}

// The direction a group's band runs, for a group whose normals turn both ways (by
// kRulingTurnMinimum at least across its points): where they turn clearly more one way
// (kBandAnisotropy), that way; otherwise its longest axis. None for a group that curves one way
// or not at all (a developable strip fits it at any width) or spreads in fewer than two
// directions: it stays compact.
std::optional<Vec3> bandDirection(const std::vector<Vec3>& points,
                                  const std::vector<Vec3>& normals) {
    if (points.size() < 3) {
        return std::nullopt;
    }
    const PrincipalFrame frame = principalFrame(points);
    if (!(frame.high[1] - frame.low[1] > 0.0)) {
        return std::nullopt;
    }
    const std::optional<Turning> t = normalTurning(points, normals, frame);
    const double span = std::max(frame.high[0] - frame.low[0], frame.high[1] - frame.low[1]);
    if (!t || !(t->least * span >= kRulingTurnMinimum)) {
        return std::nullopt;
    }
    return t->most > kBandAnisotropy * t->least ? t->direction : frame.axes[0];
}

} // namespace

PrincipalFrame principalFrame(const std::vector<Vec3>& points) {
    if (points.size() < 3) {
        throw std::invalid_argument("a plane needs at least 3 points");
    }
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Vec3& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw std::invalid_argument("a point is not finite");
        }
        centroid += Eigen::Vector3d(p.x, p.y, p.z);
    }
    centroid /= static_cast<double>(points.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Vec3& p : points) {
        const Eigen::Vector3d d = Eigen::Vector3d(p.x, p.y, p.z) - centroid;
        covariance += d * d.transpose();
    }
    // Eigenvalues in increasing order: the longest axis is the last column.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    PrincipalFrame frame;
    frame.centroid = Vec3(centroid.x(), centroid.y(), centroid.z());
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d axis = solver.eigenvectors().col(2 - i);
        frame.axes[i] = Vec3(axis.x(), axis.y(), axis.z());
    }
    // A right-handed frame, so that axes[0] × axes[1] = axes[2].
    frame.axes[2] = cross(frame.axes[0], frame.axes[1]);
    for (int i = 0; i < 3; ++i) {
        frame.low[i] = std::numeric_limits<double>::max();
        frame.high[i] = std::numeric_limits<double>::lowest();
    }
    for (const Vec3& p : points) {
        for (int i = 0; i < 3; ++i) {
            const double t = dot(p - frame.centroid, frame.axes[i]);
            frame.low[i] = std::min(frame.low[i], t);
            frame.high[i] = std::max(frame.high[i], t);
        }
    }
    return frame;
}

CompositeSurface initialStrip(const std::vector<Vec3>& points, const SplineSpace& space,
                              double margin) {
    return initialStrip(points, {}, space, margin);
}

namespace detail {

StripPlane stripPlane(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                      const SplineSpace& space, double margin) {
    if (!space.isValid()) {
        throw std::invalid_argument("the spline space is not valid");
    }
    if (!(margin >= 0.0) || !std::isfinite(margin)) {
        throw std::invalid_argument("the margin must be a finite number of at least 0");
    }
    if (!normals.empty() && normals.size() != points.size()) {
        throw std::invalid_argument("give one normal per point or none");
    }
    StripPlane plane{principalFrame(points), Vec3()};
    const PrincipalFrame& frame = plane.frame;
    if (!(frame.high[1] - frame.low[1] > 1e-9 * (frame.high[0] - frame.low[0])) ||
        !(frame.high[0] - frame.low[0] > 0.0)) {
        throw std::invalid_argument("the points do not spread in two directions");
    }
    plane.along = mostTurningDirection(points, normals, frame).value_or(frame.axes[0]);
    return plane;
}

void extents(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& along,
             const Vec3& across, double low[2], double high[2]) {
    for (int i = 0; i < 2; ++i) {
        low[i] = std::numeric_limits<double>::max();
        high[i] = std::numeric_limits<double>::lowest();
    }
    for (const Vec3& p : points) {
        const double t[2] = {dot(p - origin, along), dot(p - origin, across)};
        if (!std::isfinite(t[0]) || !std::isfinite(t[1])) {
            continue;
        }
        for (int i = 0; i < 2; ++i) {
            low[i] = std::min(low[i], t[i]);
            high[i] = std::max(high[i], t[i]);
        }
    }
}

} // namespace detail

CompositeSurface initialStrip(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                              const SplineSpace& space, double margin) {
    const StripPlane plane = stripPlane(points, normals, space, margin);
    const PrincipalFrame& frame = plane.frame;
    const Vec3 along = plane.along;
    const Vec3 across = cross(frame.axes[2], along); // along × across = axes[2]
    double low[2];
    double high[2];
    extents(points, frame.centroid, along, across, low, high);
    const double length = high[0] - low[0];
    const double width = high[1] - low[1];
    if (!(width > 1e-9 * length) || !(length > 1e-9 * width)) {
        throw std::invalid_argument("the points do not spread in two directions");
    }
    // Each curve spans the points of its half of the strip (never empty: the extreme points lie
    // in it). A rectangle over a footprint that narrows to one side (a cone patch) overhung it
    // there, and the strip slid off the wide side's corners while its rulings turned.
    double sideLow[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    double sideHigh[2] = {std::numeric_limits<double>::lowest(),
                          std::numeric_limits<double>::lowest()};
    const double middle = 0.5 * (low[1] + high[1]);
    for (const Vec3& p : points) {
        const double u = dot(p - frame.centroid, along);
        const double w = dot(p - frame.centroid, across);
        for (int side : {0, 1}) {
            if (side == 0 ? w <= middle : w >= middle) {
                sideLow[side] = std::min(sideLow[side], u);
                sideHigh[side] = std::max(sideHigh[side], u);
            }
        }
    }
    const double w0 = low[1] - margin * width;
    const double w1 = high[1] + margin * width;
    auto at = [&](double u, double w) { return frame.centroid + along * u + across * w; };
    CompositeSurface s;
    s.setName("strip");
    // a from a0 to a1 along `along`, b from b0 to b1 beside it along `across`: the face loop
    // a0, a1, b1, b0 runs like the sheet example's faces, so its normal is axes[2].
    const VertexId a0 = s.addVertex(at(sideLow[0] - margin * length, w0));
    const VertexId a1 = s.addVertex(at(sideHigh[0] + margin * length, w0));
    const VertexId b1 = s.addVertex(at(sideHigh[1] + margin * length, w1));
    const VertexId b0 = s.addVertex(at(sideLow[1] - margin * length, w1));
    s.addFace({a0, a1, b1, b0});
    s.setSpline(a0, a1, space, straightControlPoints(space, s.position(a0), s.position(a1)));
    s.setSpline(b0, b1, space, straightControlPoints(space, s.position(b0), s.position(b1)));
    return s;
}

namespace {

// The general cylinder over direction `along` of the frame's plane: the height h over the plane
// as f(u) + tilt · w, f a cubic of u (along) and w across, fitted by least squares; u and w
// from the centroid, scaled by `scale` inside the fit for its conditioning.
struct CylinderFit {
    Vec3 along;
    Vec3 across;
    double coefficients[4] = {0.0, 0.0, 0.0, 0.0}; // f(u) = Σ cₖ (u / scale)ᵏ
    double tilt = 0.0;
    double scale = 1.0;
    double squaredError = 0.0;

    double height(double u, double w) const {
        const double s = u / scale;
        return coefficients[0] +
               s * (coefficients[1] + s * (coefficients[2] + s * coefficients[3])) + tilt * w;
    }
};

CylinderFit fitCylinder(const std::vector<Vec3>& points, const PrincipalFrame& frame,
                        const Vec3& along) {
    CylinderFit fit;
    fit.along = along;
    fit.across = cross(frame.axes[2], along);
    fit.scale = std::max({frame.high[0] - frame.low[0], frame.high[1] - frame.low[1], 1e-300});
    Eigen::MatrixXd a(static_cast<Eigen::Index>(points.size()), 5);
    Eigen::VectorXd h(static_cast<Eigen::Index>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 d = points[i] - frame.centroid;
        const double s = dot(d, fit.along) / fit.scale;
        const auto row = static_cast<Eigen::Index>(i);
        a.row(row) << 1.0, s, s * s, s * s * s, dot(d, fit.across) / fit.scale;
        h(row) = dot(d, frame.axes[2]);
    }
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(h);
    for (int k = 0; k < 4; ++k) {
        fit.coefficients[k] = c(k);
    }
    fit.tilt = c(4) / fit.scale;
    fit.squaredError = (a * c - h).squaredNorm();
    return fit;
}

} // namespace

std::vector<Vec3> fitControlPoints(const SplineSpace& space,
                                   const std::function<Vec3(double)>& at) {
    const int count = space.controlPointCount(false);
    const int samples = 4 * count;
    Eigen::MatrixXd basis(samples, count);
    for (int i = 0; i < count; ++i) {
        std::vector<Vec3> unit(static_cast<std::size_t>(count));
        unit[static_cast<std::size_t>(i)] = Vec3(1.0, 0.0, 0.0);
        const BSplineCurve curve = BSplineCurve::uniform(space, unit);
        for (int k = 0; k < samples; ++k) {
            basis(k, i) = curve.evaluate(static_cast<double>(k) / (samples - 1)).x;
        }
    }
    Eigen::MatrixXd values(samples, 3);
    for (int k = 0; k < samples; ++k) {
        const Vec3 p = at(static_cast<double>(k) / (samples - 1));
        values.row(k) << p.x, p.y, p.z;
    }
    const Eigen::MatrixXd c = basis.colPivHouseholderQr().solve(values);
    std::vector<Vec3> points(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        points[static_cast<std::size_t>(i)] = Vec3(c(i, 0), c(i, 1), c(i, 2));
    }
    return points;
}

CompositeSurface stripOfCurves(const std::string& name, const SplineSpace& space,
                               const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    CompositeSurface s;
    s.setName(name);
    const VertexId a0 = s.addVertex(a.front());
    const VertexId a1 = s.addVertex(a.back());
    const VertexId b1 = s.addVertex(b.back());
    const VertexId b0 = s.addVertex(b.front());
    s.addFace({a0, a1, b1, b0});
    s.setSpline(a0, a1, space, a);
    s.setSpline(b0, b1, space, b);
    return s;
}

CompositeSurface initialCylinderStrip(const std::vector<Vec3>& points,
                                      const std::vector<Vec3>& normals, const SplineSpace& space,
                                      double margin) {
    const StripPlane plane = stripPlane(points, normals, space, margin);
    const PrincipalFrame& frame = plane.frame;
    CylinderFit best = fitCylinder(points, frame, plane.along);
    const double firstError = best.squaredError;
    for (int k = 0; k < kCylinderDirections; ++k) {
        const double angle = M_PI * k / kCylinderDirections;
        const Vec3 along = frame.axes[0] * std::cos(angle) + frame.axes[1] * std::sin(angle);
        const CylinderFit fit = fitCylinder(points, frame, along);
        if (fit.squaredError < kCylinderDirectionGain * firstError &&
            fit.squaredError < best.squaredError) {
            best = fit;
        }
    }
    double low[2];
    double high[2];
    extents(points, frame.centroid, best.along, best.across, low, high);
    const double length = high[0] - low[0];
    const double width = high[1] - low[1];
    const double w0 = low[1] - margin * width;
    const double w1 = high[1] + margin * width;
    const double u0 = low[0] - margin * length;
    const double u1 = high[0] + margin * length;
    const auto curveAt = [&](double w) {
        return [&, w](double t) {
            const double u = u0 + (u1 - u0) * t;
            return frame.centroid + best.along * u + best.across * w +
                   frame.axes[2] * best.height(u, w);
        };
    };
    const std::vector<Vec3> aPoints = fitControlPoints(space, curveAt(w0));
    const std::vector<Vec3> bPoints = fitControlPoints(space, curveAt(w1));
    const auto finite = [](const Vec3& p) { return p.isFinite(); };
    if (!(width > 1e-9 * length) || !(length > 1e-9 * width) ||
        !std::all_of(aPoints.begin(), aPoints.end(), finite) ||
        !std::all_of(bPoints.begin(), bPoints.end(), finite)) {
        throw std::invalid_argument("the points do not spread in two directions");
    }
    // The face loop a0, a1, b1, b0 as the flat strip's: its normal is near axes[2].
    return stripOfCurves("strip", space, aPoints, bPoints);
}

std::vector<std::vector<std::size_t>> clusterPoints(const std::vector<Vec3>& points, int count) {
    if (count < 1 || static_cast<std::size_t>(count) * 3 > points.size()) {
        throw std::invalid_argument("each group needs at least 3 points");
    }
    const auto k = static_cast<std::size_t>(count);
    return groupsOf(kMeansLabels(points, k), k);
}

std::vector<std::vector<std::size_t>> clusterPoints(const std::vector<Vec3>& points,
                                                    const std::vector<Vec3>& normals, int count,
                                                    double aspect) {
    if (count < 1 || static_cast<std::size_t>(count) * 3 > points.size()) {
        throw std::invalid_argument("each group needs at least 3 points");
    }
    if (!(aspect >= 1.0) || !std::isfinite(aspect)) {
        throw std::invalid_argument("the aspect must be a finite number of at least 1");
    }
    if (normals.size() != points.size()) {
        throw std::invalid_argument("give one normal per point");
    }
    const auto k = static_cast<std::size_t>(count);
    std::vector<std::size_t> label = kMeansLabels(points, k);
    if (aspect == 1.0) {
        return groupsOf(label, k);
    }
    // From the compact groups, rounds of: each group's centre and band direction t, then each
    // point to the group nearest in that group's metric |d|² + (s − 1) (|d|² − (d · t)²), s =
    // aspect² for a band, 1 for a group that stays compact (no t).
    const double stretch = aspect * aspect;
    std::vector<Vec3> centres(k);
    std::vector<Vec3> along(k);
    std::vector<double> groupStretch(k, 1.0);
    std::vector<bool> alive(k, false);
    for (int round = 0; round < 50; ++round) {
        std::vector<std::vector<Vec3>> members(k);
        std::vector<std::vector<Vec3>> memberNormals(k);
        for (std::size_t i = 0; i < points.size(); ++i) {
            members[label[i]].push_back(points[i]);
            memberNormals[label[i]].push_back(normals[i]);
        }
        for (std::size_t c = 0; c < k; ++c) {
            alive[c] = !members[c].empty();
            if (!alive[c]) {
                continue;
            }
            Vec3 sum;
            for (const Vec3& p : members[c]) {
                sum += p;
            }
            centres[c] = sum / static_cast<double>(members[c].size());
            const std::optional<Vec3> t = bandDirection(members[c], memberNormals[c]);
            along[c] = t.value_or(Vec3());
            groupStretch[c] = t ? stretch : 1.0;
        }
        bool changed = false;
        for (std::size_t i = 0; i < points.size(); ++i) {
            std::size_t best = label[i];
            double bestDistance = std::numeric_limits<double>::max();
            for (std::size_t c = 0; c < k; ++c) {
                if (!alive[c]) {
                    continue;
                }
                const Vec3 d = points[i] - centres[c];
                const double t = dot(d, along[c]);
                const double distance =
                    d.squaredNorm() + (groupStretch[c] - 1.0) * (d.squaredNorm() - t * t);
                if (distance < bestDistance) {
                    bestDistance = distance;
                    best = c;
                }
            }
            changed = changed || best != label[i];
            label[i] = best;
        }
        if (!changed) {
            break;
        }
    }
    return groupsOf(label, k);
}

} // namespace devsurf::model::reference
