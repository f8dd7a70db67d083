#include "model/reference/initial_strip.h"

#include "model/bspline_curve.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace devsurf::model::reference {

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

// The unit direction of the frame's plane along which the normals turn most, if they turn
// clearly more along it than across it (kRulingAnisotropy) and by kRulingTurnMinimum at least
// over the points: a least-squares linear fit of the normals' tilt (their components in the
// plane, each normal turned to the side of axes[2]) against the points' position in the plane,
// whose larger singular direction that is.
std::optional<Vec3> mostTurningDirection(const std::vector<Vec3>& points,
                                         const std::vector<Vec3>& normals,
                                         const PrincipalFrame& frame) {
    if (normals.empty()) {
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
    const Eigen::Vector2d sigma = svd.singularValues();
    const double span = std::max(frame.high[0] - frame.low[0], frame.high[1] - frame.low[1]);
    if (!(sigma(0) * span >= kRulingTurnMinimum) || !(sigma(0) >= kRulingAnisotropy * sigma(1))) {
        return std::nullopt;
    }
    // Near the longest axis (within kRulingTurnAngle) the plain strip stays: turning it a
    // little gains nothing and changes what the strips of a shape meet with.
    const Eigen::Vector2d v = svd.matrixV().col(0);
    if (std::abs(v(0)) >= std::cos(kRulingTurnAngle) * v.norm()) {
        return std::nullopt;
    }
    const Vec3 direction = frame.axes[0] * v(0) + frame.axes[1] * v(1);
    return direction / direction.norm();
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

CompositeSurface initialStrip(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
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
    const PrincipalFrame frame = principalFrame(points);
    if (!(frame.high[1] - frame.low[1] > 1e-9 * (frame.high[0] - frame.low[0])) ||
        !(frame.high[0] - frame.low[0] > 0.0)) {
        throw std::invalid_argument("the points do not spread in two directions");
    }
    // The direction of a and b in the plane: the longest axis, or the direction of most turning.
    Vec3 along = frame.axes[0];
    if (const std::optional<Vec3> turning = mostTurningDirection(points, normals, frame)) {
        along = *turning;
    }
    const Vec3 across = cross(frame.axes[2], along); // along × across = axes[2]
    double low[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    double high[2] = {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
    for (const Vec3& p : points) {
        const double t[2] = {dot(p - frame.centroid, along), dot(p - frame.centroid, across)};
        for (int i = 0; i < 2; ++i) {
            low[i] = std::min(low[i], t[i]);
            high[i] = std::max(high[i], t[i]);
        }
    }
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

std::vector<std::vector<std::size_t>> clusterPoints(const std::vector<Vec3>& points, int count) {
    if (count < 1 || static_cast<std::size_t>(count) * 3 > points.size()) {
        throw std::invalid_argument("each group needs at least 3 points");
    }
    const auto k = static_cast<std::size_t>(count);
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
    std::vector<std::vector<std::size_t>> groups(k);
    for (std::size_t i = 0; i < points.size(); ++i) {
        groups[label[i]].push_back(i);
    }
    groups.erase(std::remove_if(groups.begin(), groups.end(),
                                [](const std::vector<std::size_t>& g) { return g.empty(); }),
                 groups.end());
    return groups;
}

} // namespace devsurf::model::reference
