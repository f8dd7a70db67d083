#include "plane_motion.h"

#include <cmath>
#include <utility>

namespace devsurf::model {

Vec2 PlaneMotion::apply(const Vec2& p) const {
    const Vec2 q = (mirrored ? Vec2{-p.x, p.y} : p) - from;
    const double c = std::cos(angle), s = std::sin(angle);
    return Vec2{c * q.x - s * q.y, s * q.x + c * q.y} + to;
}

Vec2 PlaneMotion::applyInverse(const Vec2& p) const {
    const Vec2 q = p - to;
    const double c = std::cos(angle), s = std::sin(angle);
    const Vec2 r = Vec2{c * q.x + s * q.y, -s * q.x + c * q.y} + from;
    return mirrored ? Vec2{-r.x, r.y} : r;
}

namespace {

std::pair<PlaneMotion, double>
fitPlaneMotionMirrored(std::vector<Vec2> source, const std::vector<Vec2>& target, bool mirrored) {
    if (mirrored) {
        for (Vec2& p : source) {
            p.x = -p.x;
        }
    }
    Vec2 cs, ct;
    for (std::size_t i = 0; i < source.size(); ++i) {
        cs = cs + source[i];
        ct = ct + target[i];
    }
    const double n = static_cast<double>(source.size());
    cs = cs * (1.0 / n);
    ct = ct * (1.0 / n);
    double a = 0.0, b = 0.0;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const Vec2 s = source[i] - cs, t = target[i] - ct;
        a += dot2(s, t);
        b += cross2(s, t);
    }
    PlaneMotion motion;
    motion.angle = std::atan2(b, a);
    motion.to = ct;
    // `from` is in mirrored coordinates, as apply() mirrors before subtracting it; the
    // residual is measured on the already mirrored source, so without a second mirror.
    motion.from = cs;
    double squared = 0.0;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const Vec2 d = motion.apply(source[i]) - target[i];
        squared += dot2(d, d);
    }
    motion.mirrored = mirrored;
    return {motion, squared};
}

} // namespace

std::optional<PlaneMotion> fitPlaneMotion(const std::vector<Vec2>& from,
                                          const std::vector<Vec2>& to) {
    if (from.size() != to.size() || from.size() < 2) {
        return std::nullopt;
    }
    const auto straight = fitPlaneMotionMirrored(from, to, false);
    const auto mirrored = fitPlaneMotionMirrored(from, to, true);
    return mirrored.second < straight.second ? mirrored.first : straight.first;
}

} // namespace devsurf::model
