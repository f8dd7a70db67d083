#include "lasso_marking.h"

#include <algorithm>
#include <cmath>

namespace devsurf::model::reference {

bool LassoCamera::project(const Vec3& point, Vec2& screen) const {
    const double* m = toScreen.data();
    const double x = m[0] * point.x + m[1] * point.y + m[2] * point.z + m[3];
    const double y = m[4] * point.x + m[5] * point.y + m[6] * point.z + m[7];
    const double w = m[12] * point.x + m[13] * point.y + m[14] * point.z + m[15];
    if (!(w > 0.0)) {
        return false;
    }
    screen = Vec2(x / w, y / w);
    return std::isfinite(screen.x) && std::isfinite(screen.y);
}

Vec3 LassoCamera::towardsCamera(const Vec3& point) const {
    return parallel ? -direction : eye - point;
}

bool insidePolygon(const std::vector<Vec2>& polygon, const Vec2& point) {
    if (polygon.size() < 3) {
        return false;
    }
    // Even–odd: count the edges a ray to the right of the point crosses.
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[j];
        if ((a.y > point.y) != (b.y > point.y) &&
            point.x < a.x + (point.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
            inside = !inside;
        }
    }
    return inside;
}

std::vector<Vec3> pointNormals(const ReferenceShape& shape) {
    if (shape.normals.size() == shape.points.size() && !shape.points.empty()) {
        return shape.normals;
    }
    if (shape.isPointCloud()) {
        return {};
    }
    std::vector<Vec3> normals(shape.points.size());
    const auto n = static_cast<int>(shape.points.size());
    for (const std::array<int, 3>& t : shape.triangles) {
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= n || t[1] >= n || t[2] >= n) {
            continue;
        }
        const Vec3& a = shape.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = shape.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = shape.points[static_cast<std::size_t>(t[2])];
        const Vec3 weighted = cross(b - a, c - a); // twice the area times the unit normal
        for (int corner : t) {
            normals[static_cast<std::size_t>(corner)] += weighted;
        }
    }
    return normals;
}

std::vector<std::size_t> pointsInLasso(const ReferenceShape& shape, const std::vector<Vec2>& lasso,
                                       const LassoCamera& camera) {
    std::vector<std::size_t> marked;
    if (lasso.size() < 3) {
        return marked;
    }
    // The lasso's bounds reject most points before the polygon test.
    Vec2 low = lasso.front();
    Vec2 high = lasso.front();
    for (const Vec2& p : lasso) {
        low = Vec2(std::min(low.x, p.x), std::min(low.y, p.y));
        high = Vec2(std::max(high.x, p.x), std::max(high.y, p.y));
    }
    const std::vector<Vec3> normals = pointNormals(shape);
    const bool mesh = !shape.isPointCloud();
    for (std::size_t i = 0; i < shape.points.size(); ++i) {
        const Vec3& point = shape.points[i];
        Vec2 screen;
        if (!camera.project(point, screen) || screen.x < low.x || screen.x > high.x ||
            screen.y < low.y || screen.y > high.y || !insidePolygon(lasso, screen)) {
            continue;
        }
        if (!normals.empty()) {
            const Vec3& normal = normals[i];
            if (normal.squaredNorm() == 0.0 ? mesh
                                            : dot(normal, camera.towardsCamera(point)) <= 0.0) {
                continue;
            }
        }
        marked.push_back(i);
    }
    return marked;
}

} // namespace devsurf::model::reference
