#include "patch_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace devsurf::test {

namespace {

using model::Vec3;

double pointSegmentDistance3(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 d = b - a;
    const double length2 = d.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp(model::dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
    return (a + d * t - p).norm();
}

double rulingDistance(const Vec3& p, const io::PatchSurface& patch, double u) {
    return pointSegmentDistance3(p, patch.a.evaluate(u), patch.b.evaluate(u));
}

double ruledDistance(const Vec3& p, const io::PatchSurface& patch) {
    constexpr int kScan = 400;
    int best = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= kScan; ++i) {
        const double d = rulingDistance(p, patch, static_cast<double>(i) / kScan);
        if (d < bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    double low = std::max(0, best - 1) / static_cast<double>(kScan);
    double high = std::min(kScan, best + 1) / static_cast<double>(kScan);
    for (int iteration = 0; iteration < 200 && high - low > 1e-15; ++iteration) {
        const double m1 = low + (high - low) / 3.0;
        const double m2 = high - (high - low) / 3.0;
        if (rulingDistance(p, patch, m1) < rulingDistance(p, patch, m2)) {
            high = m2;
        } else {
            low = m1;
        }
    }
    return std::min(bestDistance, rulingDistance(p, patch, 0.5 * (low + high)));
}

double planarDistance(const Vec3& p, const io::PatchSurface& patch) {
    Vec3 normal;
    const std::size_t n = patch.corners.size();
    for (std::size_t i = 0; i < n; ++i) {
        normal += model::cross(patch.corners[i], patch.corners[(i + 1) % n]);
    }
    normal = normal / normal.norm();
    const double height = model::dot(p - patch.corners.front(), normal);
    const Vec3 q = p - normal * height;
    // Inside: the angles the polygon's sides subtend at q add up to ±2π.
    double winding = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 a = patch.corners[i] - q;
        const Vec3 b = patch.corners[(i + 1) % n] - q;
        winding += std::atan2(model::dot(model::cross(a, b), normal), model::dot(a, b));
    }
    if (std::abs(winding) > 3.0) {
        return std::abs(height);
    }
    double edge = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
        edge =
            std::min(edge, pointSegmentDistance3(p, patch.corners[i], patch.corners[(i + 1) % n]));
    }
    return edge;
}

// A lower bound of the distance: to the box around the patch's poles or corners (a B-spline
// lies in the convex hull of its poles).
double boxDistance(const Vec3& p, const io::PatchSurface& patch) {
    std::vector<Vec3> points = patch.corners;
    points.insert(points.end(), patch.a.controlPoints().begin(), patch.a.controlPoints().end());
    points.insert(points.end(), patch.b.controlPoints().begin(), patch.b.controlPoints().end());
    Vec3 outside;
    for (int k = 0; k < 3; ++k) {
        double low = std::numeric_limits<double>::infinity();
        double high = -low;
        for (const Vec3& q : points) {
            low = std::min(low, q[k]);
            high = std::max(high, q[k]);
        }
        outside[k] = std::max({low - p[k], 0.0, p[k] - high});
    }
    return outside.norm();
}

} // namespace

double distanceToPatches(const Vec3& p, const std::vector<io::PatchSurface>& patches) {
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        order.emplace_back(boxDistance(p, patches[i]), i);
    }
    std::sort(order.begin(), order.end());
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [bound, i] : order) {
        if (bound > best) {
            break;
        }
        const io::PatchSurface& patch = patches[i];
        best =
            std::min(best, patch.isPlanar() ? planarDistance(p, patch) : ruledDistance(p, patch));
    }
    return best;
}

} // namespace devsurf::test
