#include "thinning.h"

#include "bounding_box.h"
#include "point_index.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace devsurf::model::reference {

namespace {

// How often the progress callback is called: every this many visited points.
constexpr std::size_t kProgressStride = 1u << 16;

// Eigenvalue ratio below which the ball's points count as collinear: no plane through them.
constexpr double kCollinear = 1e-10;

struct PlaneFit {
    bool valid = false;
    Vec3 normal;
};

// The least-squares plane through the ball (PCA): its normal is the eigenvector of the smallest
// eigenvalue of the covariance. Coordinates are taken relative to `origin` (the ball's centre)
// so that a shape far from the origin loses no digits.
PlaneFit fitPlane(const std::vector<Vec3>& points, const std::vector<PointIndex::Neighbour>& ball,
                  const Vec3& origin) {
    PlaneFit fit;
    if (ball.size() < 3) {
        return fit;
    }
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& n : ball) {
        const Vec3 d = points[n.index] - origin;
        mean += Eigen::Vector3d(d.x, d.y, d.z);
    }
    mean /= static_cast<double>(ball.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const auto& n : ball) {
        const Vec3 d = points[n.index] - origin;
        const Eigen::Vector3d centred = Eigen::Vector3d(d.x, d.y, d.z) - mean;
        covariance.noalias() += centred * centred.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    if (solver.info() != Eigen::Success) {
        return fit;
    }
    const Eigen::Vector3d values = solver.eigenvalues(); // ascending
    if (!(values(1) > kCollinear * values(2))) {
        return fit;
    }
    const Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
    fit.valid = true;
    fit.normal = Vec3(normal(0), normal(1), normal(2));
    return fit;
}

// The finite points and their indices in the reference.
void finitePoints(const std::vector<Vec3>& points, std::vector<Vec3>& finite,
                  std::vector<std::size_t>& source) {
    finite.reserve(points.size());
    source.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (points[i].isFinite()) {
            finite.push_back(points[i]);
            source.push_back(i);
        }
    }
}

// defaultThinningRadius on the KD-tree of the finite points.
double defaultRadiusOf(const PointIndex& index) {
    const double diagonal = boundingBoxDiagonal(index.points());
    if (!(diagonal > 0.0)) {
        return 0.0;
    }
    // A point's nearest neighbour at a positive distance (duplicates in a scan do not count).
    constexpr std::size_t kSamples = 1000;
    constexpr std::size_t kNeighbours = 8;
    const std::size_t stride = std::max<std::size_t>(1, index.size() / kSamples);
    std::vector<double> spacing;
    for (std::size_t i = 0; i < index.size(); i += stride) {
        for (const auto& n : index.nearest(index.points()[i], kNeighbours)) {
            if (n.squaredDistance > 0.0) {
                spacing.push_back(std::sqrt(n.squaredDistance));
                break;
            }
        }
    }
    double median = 0.0;
    if (!spacing.empty()) {
        auto middle = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
        std::nth_element(spacing.begin(), middle, spacing.end());
        median = *middle;
    }
    return std::max(0.01 * diagonal, 3.0 * median);
}

} // namespace

ThinningResult thinReference(const std::vector<Vec3>& points, double rho,
                             const ThinningProgress& progress) {
    if (!std::isfinite(rho)) {
        throw std::invalid_argument("thinReference: the radius must be finite");
    }
    ThinningResult result;
    std::vector<Vec3> finite;
    std::vector<std::size_t> source;
    finitePoints(points, finite, source);
    result.nonFinite = points.size() - finite.size();
    Vec3 centroid;
    for (const Vec3& p : finite) {
        centroid += p;
    }
    if (!finite.empty()) {
        centroid = centroid / static_cast<double>(finite.size());
    }
    const PointIndex index(std::move(finite));
    result.radius = rho > 0.0 ? rho : defaultRadiusOf(index);
    if (!(result.radius > 0.0)) { // fewer than two distinct points: nothing to fit a plane to
        result.isolated = index.size();
        return result;
    }
    rho = result.radius;
    const std::vector<Vec3>& cloud = index.points();
    const std::size_t count = cloud.size();
    std::vector<char> discarded(count, 0);
    std::vector<PointIndex::Neighbour> ball;
    for (std::size_t i = 0; i < count; ++i) {
        if (progress && i % kProgressStride == 0 && !progress(i, count)) {
            result.cancelled = true;
            return result;
        }
        if (discarded[i]) {
            continue;
        }
        index.withinRadius(cloud[i], rho, ball);
        const PlaneFit fit = fitPlane(cloud, ball, cloud[i]);
        if (!fit.valid) {
            ++result.isolated;
            discarded[i] = 1;
            continue;
        }
        const Vec3 normal = dot(fit.normal, cloud[i] - centroid) < 0.0 ? -fit.normal : fit.normal;
        result.points.push_back({cloud[i], normal, source[i], ball.size()});
        for (const auto& n : ball) {
            discarded[n.index] = 1;
        }
    }
    if (progress) {
        progress(count, count);
    }
    return result;
}

double defaultThinningRadius(const std::vector<Vec3>& points) {
    std::vector<Vec3> finite;
    std::vector<std::size_t> source;
    finitePoints(points, finite, source);
    return defaultRadiusOf(PointIndex(std::move(finite)));
}

} // namespace devsurf::model::reference
