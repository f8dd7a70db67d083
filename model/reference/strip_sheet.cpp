#include "model/reference/strip_sheet.h"

#include "model/reference/strip_plane.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

namespace devsurf::model::reference {

using detail::extents;
using detail::normalTurning;
using detail::stripPlane;
using detail::StripPlane;
using detail::Turning;

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
                                 const Vec3& along, int count, double margin,
                                 const std::vector<Vec3>& whole) {
    SheetFit fit;
    fit.along = along;
    fit.across = cross(frame.axes[2], along);
    double low[2];
    double high[2];
    extents(whole.empty() ? points : whole, frame.centroid, fit.along, fit.across, low, high);
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
                                   const SplineSpace& space, double margin,
                                   const std::vector<Vec3>& whole) {
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
    if (std::optional<SheetFit> fit = fitSheet(points, frame, first, count, margin, whole)) {
        fits.push_back(std::move(*fit));
    } else {
        throw std::invalid_argument("the points do not spread in two directions");
    }
    for (int k = 0; k < kCylinderDirections; ++k) {
        const double angle = M_PI * k / kCylinderDirections;
        const Vec3 along = frame.axes[0] * std::cos(angle) + frame.axes[1] * std::sin(angle);
        if (std::optional<SheetFit> fit = fitSheet(points, frame, along, count, margin, whole)) {
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

} // namespace devsurf::model::reference
