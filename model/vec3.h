#pragma once

#include <cmath>

namespace devsurf::model {

// A point or vector in 3-space. Deliberately tiny so that model headers stay cheap to
// include; numeric code converts to Eigen where it needs linear algebra.
struct Vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    Vec3& operator+=(const Vec3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    Vec3& operator-=(const Vec3& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    Vec3& operator*=(double s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
    constexpr bool operator!=(const Vec3& o) const { return !(*this == o); }

    double norm() const { return std::sqrt(x * x + y * y + z * z); }
    constexpr double squaredNorm() const { return x * x + y * y + z * z; }
    bool isFinite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
};

constexpr Vec3 operator*(double s, const Vec3& v) {
    return v * s;
}
constexpr double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double det(const Vec3& a, const Vec3& b, const Vec3& c) {
    return dot(a, cross(b, c));
}
inline double distance(const Vec3& a, const Vec3& b) {
    return (a - b).norm();
}
// The angle between two vectors in [0, π], accurate also near 0 and π.
inline double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(cross(a, b).norm(), dot(a, b));
}

// A point of the plane (developments).
struct Vec2 {
    double x = 0.0;
    double y = 0.0;
    constexpr Vec2() = default;
    constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}
    constexpr Vec2 operator+(const Vec2& o) const { return {x + o.x, y + o.y}; }
    constexpr Vec2 operator-(const Vec2& o) const { return {x - o.x, y - o.y}; }
    constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
    double norm() const { return std::sqrt(x * x + y * y); }
    constexpr bool operator==(const Vec2& o) const { return x == o.x && y == o.y; }
};

constexpr double cross2(const Vec2& a, const Vec2& b) {
    return a.x * b.y - a.y * b.x;
}
constexpr double dot2(const Vec2& a, const Vec2& b) {
    return a.x * b.x + a.y * b.y;
}

} // namespace devsurf::model
