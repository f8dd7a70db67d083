// RigidMotion (declared in topology_edits.h): the exact translations and rotations of the
// Move/Rotate edit.

#include "model_error.h"
#include "topology_edits.h"

#include <cmath>

namespace devsurf::model {

RigidMotion RigidMotion::translationBy(const Vec3& offset) {
    RigidMotion motion;
    motion.translation = offset;
    return motion;
}

RigidMotion RigidMotion::rotationAbout(const Vec3& point, const Vec3& direction, double angle) {
    const double length = direction.norm();
    if (!(length > 0.0) || !std::isfinite(length) || !point.isFinite() || !std::isfinite(angle)) {
        throw ModelError(problemOf(ProblemCode::InvalidRotation));
    }
    const Vec3 k = direction / length;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    const double t = 1.0 - c;
    RigidMotion motion;
    // Rodrigues: R = c I + s [k]x + (1 − c) k kᵀ.
    motion.rotation[0][0] = c + t * k.x * k.x;
    motion.rotation[0][1] = t * k.x * k.y - s * k.z;
    motion.rotation[0][2] = t * k.x * k.z + s * k.y;
    motion.rotation[1][0] = t * k.y * k.x + s * k.z;
    motion.rotation[1][1] = c + t * k.y * k.y;
    motion.rotation[1][2] = t * k.y * k.z - s * k.x;
    motion.rotation[2][0] = t * k.z * k.x - s * k.y;
    motion.rotation[2][1] = t * k.z * k.y + s * k.x;
    motion.rotation[2][2] = c + t * k.z * k.z;
    // p ↦ R (p − c) + c = R p + (c − R c).
    motion.translation = point - motion.apply(point);
    return motion;
}

Vec3 RigidMotion::apply(const Vec3& p) const {
    Vec3 result = translation;
    for (int i = 0; i < 3; ++i) {
        result[i] += rotation[i][0] * p.x + rotation[i][1] * p.y + rotation[i][2] * p.z;
    }
    return result;
}

} // namespace devsurf::model
