#include "model/reference/initial_strip.h"

#include "model/bspline_curve.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
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

// How the normals turn over the points: a least-squares linear fit of their tilt (their
// components in the frame's plane, each normal turned to the side of axes[2]) against the
// points' position in the plane; its singular values (rad per mm, larger first) and the unit
// direction in the plane of the larger one. None for a missing or zero normal.
struct Turning {
    double most = 0.0;
    double least = 0.0;
    Vec3 direction;
    double alongLongest = 0.0; // |cos| of its angle to axes[0]
};

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

namespace {

// The arguments of an initial strip checked (std::invalid_argument as initialStrip documents),
// the points' frame, and the direction of a and b in its plane: the longest axis, or the
// direction of most turning.
struct StripPlane {
    PrincipalFrame frame;
    Vec3 along;
};

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

// The smallest and largest projection of the points, from `origin`, on `along` (index 0) and
// on `across` (index 1).
void extents(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& along,
             const Vec3& across, double low[2], double high[2]) {
    for (int i = 0; i < 2; ++i) {
        low[i] = std::numeric_limits<double>::max();
        high[i] = std::numeric_limits<double>::lowest();
    }
    for (const Vec3& p : points) {
        const double t[2] = {dot(p - origin, along), dot(p - origin, across)};
        for (int i = 0; i < 2; ++i) {
            low[i] = std::min(low[i], t[i]);
            high[i] = std::max(high[i], t[i]);
        }
    }
}

} // namespace

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

bool isPatchOverPlane(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                      double rho) {
    if (points.size() < 3 || normals.size() != points.size() || !(rho > 0.0)) {
        return false;
    }
    PrincipalFrame frame;
    try {
        frame = principalFrame(points);
    } catch (const std::invalid_argument&) {
        return false;
    }
    const Vec3& up = frame.axes[2];
    const double cosLimit = std::cos(kPatchNormalAngle);
    std::size_t facing = 0;
    // Per cell of side 2ρ: the lowest and highest height and the steepest normal's slope.
    struct Cell {
        double low = std::numeric_limits<double>::max();
        double high = std::numeric_limits<double>::lowest();
        double slope = 0.0;
    };
    std::map<std::pair<long, long>, Cell> cells;
    const double side = 2.0 * rho;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double length = normals[i].norm();
        if (!(length > 0.0) || !std::isfinite(length)) {
            return false;
        }
        const double c = std::min(1.0, std::abs(dot(normals[i], up)) / length);
        facing += c >= cosLimit ? 1 : 0;
        const Vec3 d = points[i] - frame.centroid;
        const std::pair<long, long> key{std::lround(std::floor(dot(d, frame.axes[0]) / side)),
                                        std::lround(std::floor(dot(d, frame.axes[1]) / side))};
        Cell& cell = cells[key];
        const double h = dot(d, up);
        cell.low = std::min(cell.low, h);
        cell.high = std::max(cell.high, h);
        cell.slope =
            std::max(cell.slope, std::sqrt(std::max(0.0, 1.0 - c * c)) / std::max(c, cosLimit));
    }
    if (static_cast<double>(facing) < kPatchNormalShare * static_cast<double>(points.size())) {
        return false;
    }
    const double diagonal = side * std::sqrt(2.0);
    return std::all_of(cells.begin(), cells.end(), [&](const auto& entry) {
        const Cell& cell = entry.second;
        return cell.high - cell.low <= diagonal * cell.slope + rho;
    });
}

namespace {

// The strips' sheet over direction `along` of the frame's plane: the rectangle of the points
// (enlarged by the margin) and their height over the plane as h(u, w) = f(u) + g(w), f a cubic
// without a constant term, g piecewise linear between the strips' lines w0 + k (w1 − w0) /
// count, by least squares (u scaled for the conditioning; g's second differences held a little
// towards 0 so that a line no point lies near stays determined). nullopt where the points do
// not spread both ways.
struct SheetFit {
    Vec3 along;
    Vec3 across;
    double u0 = 0.0, u1 = 0.0, w0 = 0.0, w1 = 0.0;
    double scale = 1.0;
    Eigen::VectorXd c; // f's 3 coefficients, then g at the count + 1 lines
    double squaredError = 0.0;

    double area() const { return (u1 - u0) * (w1 - w0); }

    Vec3 at(const PrincipalFrame& frame, double u, int k, int count) const {
        const double x = u / scale;
        const double height = x * (c(0) + x * (c(1) + x * c(2))) + c(3 + k);
        return frame.centroid + along * u + across * (w0 + (w1 - w0) * k / count) +
               frame.axes[2] * height;
    }
};

std::optional<SheetFit> fitSheet(const std::vector<Vec3>& points, const PrincipalFrame& frame,
                                 const Vec3& along, int count, double margin) {
    SheetFit fit;
    fit.along = along;
    fit.across = cross(frame.axes[2], along);
    double low[2];
    double high[2];
    extents(points, frame.centroid, fit.along, fit.across, low, high);
    const double length = high[0] - low[0];
    const double width = high[1] - low[1];
    if (!(width > 1e-9 * length) || !(length > 1e-9 * width)) {
        return std::nullopt;
    }
    fit.u0 = low[0] - margin * length;
    fit.u1 = high[0] + margin * length;
    fit.w0 = low[1] - margin * width;
    fit.w1 = high[1] + margin * width;
    fit.scale = std::max(length, width);
    const auto hat = [&](double w, int k) {
        const double x = (w - fit.w0) / (fit.w1 - fit.w0) * count - k;
        return std::max(0.0, 1.0 - std::abs(x));
    };
    const auto n = static_cast<Eigen::Index>(points.size());
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + std::max(0, count - 1), 3 + count + 1);
    Eigen::VectorXd h = Eigen::VectorXd::Zero(a.rows());
    for (Eigen::Index i = 0; i < n; ++i) {
        const Vec3 d = points[static_cast<std::size_t>(i)] - frame.centroid;
        const double x = dot(d, fit.along) / fit.scale;
        const double w = dot(d, fit.across);
        a(i, 0) = x;
        a(i, 1) = x * x;
        a(i, 2) = x * x * x;
        for (int k = 0; k <= count; ++k) {
            a(i, 3 + k) = hat(w, k);
        }
        h(i) = dot(d, frame.axes[2]);
    }
    const double smooth = 1e-3 * std::sqrt(static_cast<double>(n) / (count + 1));
    for (int k = 1; k < count; ++k) {
        const Eigen::Index row = n + k - 1;
        a(row, 3 + k - 1) = smooth;
        a(row, 3 + k) = -2.0 * smooth;
        a(row, 3 + k + 1) = smooth;
    }
    fit.c = a.colPivHouseholderQr().solve(h);
    fit.squaredError = (a.topRows(n) * fit.c - h.head(n)).squaredNorm();
    return fit;
}

} // namespace

CompositeSurface initialStripSheet(const std::vector<Vec3>& points,
                                   const std::vector<Vec3>& normals, int count,
                                   const SplineSpace& space, double margin) {
    if (count < 1) {
        throw std::invalid_argument("lay at least one strip");
    }
    const StripPlane plane = stripPlane(points, normals, space, margin);
    const PrincipalFrame& frame = plane.frame;
    // Curves where the normals turn most (a cylinder's run around it), else along the longest
    // axis; another of kCylinderDirections evenly turned directions where its sheet fits
    // clearly better (kCylinderDirectionGain): a saddle's principal directions, which the
    // normals' turning does not tell apart. Only directions whose rectangle is at most
    // kSheetAreaSlack times the smallest: a rectangle turned against its patch's footprint
    // (a square turned 45°) stands off it at its corners.
    Vec3 first = frame.axes[0];
    if (const std::optional<Turning> t = normalTurning(points, normals, frame);
        t && t->most >= kRulingAnisotropy * t->least) {
        first = t->direction;
    }
    std::vector<SheetFit> fits;
    if (std::optional<SheetFit> fit = fitSheet(points, frame, first, count, margin)) {
        fits.push_back(std::move(*fit));
    } else {
        throw std::invalid_argument("the points do not spread in two directions");
    }
    for (int k = 0; k < kCylinderDirections; ++k) {
        const double angle = M_PI * k / kCylinderDirections;
        const Vec3 along = frame.axes[0] * std::cos(angle) + frame.axes[1] * std::sin(angle);
        if (std::optional<SheetFit> fit = fitSheet(points, frame, along, count, margin)) {
            fits.push_back(std::move(*fit));
        }
    }
    double smallest = std::numeric_limits<double>::max();
    for (const SheetFit& fit : fits) {
        smallest = std::min(smallest, fit.area());
    }
    const auto eligible = [&](const SheetFit& fit) {
        return fit.area() <= kSheetAreaSlack * smallest;
    };
    const SheetFit* best = eligible(fits.front()) ? &fits.front() : nullptr;
    double bar = best != nullptr ? kCylinderDirectionGain * best->squaredError
                                 : std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < fits.size(); ++i) {
        if (eligible(fits[i]) && fits[i].squaredError < bar) {
            best = &fits[i];
            bar = fits[i].squaredError;
        }
    }
    CompositeSurface s;
    s.setName("strips");
    std::vector<VertexId> start;
    std::vector<VertexId> end;
    for (int k = 0; k <= count; ++k) {
        start.push_back(s.addVertex(best->at(frame, best->u0, k, count)));
        end.push_back(s.addVertex(best->at(frame, best->u1, k, count)));
    }
    // Strip k: curve a the k-th line, b the next; the loop a0, a1, b1, b0 as initialStrip's.
    for (int k = 0; k < count; ++k) {
        s.addFace({start[k], end[k], end[k + 1], start[k + 1]});
    }
    // Each line k the cubic u ↦ at(u, k), exact in the cubic space: strip k is the general
    // cylinder over it along across + g's slope there · normal (b a translate of a).
    for (int k = 0; k <= count; ++k) {
        std::vector<Vec3> controls = fitControlPoints(space, [&](double t) {
            return best->at(frame, best->u0 + (best->u1 - best->u0) * t, k, count);
        });
        controls.front() = s.position(start[k]); // as the fit gives them, to the last bit
        controls.back() = s.position(end[k]);
        s.setSpline(start[k], end[k], space, controls);
    }
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
