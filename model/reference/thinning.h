#pragma once

#include "model/vec3.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace devsurf::model::reference {

// One point kept by the thinning of §4.2 (MATH.md §6): q_j, a point of the reference, and m_j,
// the unit normal of the plane fitted (PCA) to the reference points in its ball.
struct ThinnedPoint {
    Vec3 position;
    Vec3 normal;
    std::size_t source = 0;    // the index of q_j in the reference
    std::size_t ballCount = 0; // how many reference points the plane was fitted to
};

struct ThinningResult {
    std::vector<ThinnedPoint> points; // in the order of their index in the reference
    double radius = 0.0;              // ρ
    // Reference points dropped because their ball held fewer than 3 points or only collinear
    // ones: no plane to fit (isolated scan noise, a stray point far from the shape).
    std::size_t isolated = 0;
    std::size_t nonFinite = 0; // reference points with a NaN or infinite coordinate, skipped
    bool cancelled = false;    // the progress callback asked to stop; `points` is then partial
};

// Called now and then with the points visited so far and the total; returning false cancels.
using ThinningProgress = std::function<bool(std::size_t done, std::size_t total)>;

// Poisson-like thinning: visits the reference in index order; a point not yet discarded whose
// ball of radius ρ holds at least 3 points that are not all collinear is kept as q_j, with the
// normal m_j of a PCA plane fit to every reference point in the ball (discarded ones included,
// so the normal does not depend on the order of visits), and the ball's points are discarded.
// A point without such a plane is dropped alone, so its neighbours still get their turn. Any
// two kept points are at least ρ apart. m_j points away from the centroid of the reference
// (outwards on a closed scan); eq. (10), which uses it, does not depend on its sign. Non-finite
// points are skipped. ρ ≤ 0 means defaultThinningRadius (found on the same KD-tree, which saves
// building a second one); a non-finite ρ throws std::invalid_argument.
ThinningResult thinReference(const std::vector<Vec3>& points, double rho,
                             const ThinningProgress& progress = {});

// ρ for a reference: 1 % of its bounding-box diagonal, at least 3 times the median spacing of
// its points (the distance of a point to its nearest neighbour, over up to 1000 evenly spread
// points) so that a ball holds some 25 points to fit a plane to even in a sparse cloud; 0 for
// fewer than 2 distinct points. Why 1 %: a scanned object such as the bunny then keeps a few
// thousand points q_j (tens per strip of Fig. 10's 94), enough to guide the strips without
// making each iteration's closest-point projection dominate, while features of a curvature
// radius above a few ρ keep a reliable normal.
double defaultThinningRadius(const std::vector<Vec3>& points);

} // namespace devsurf::model::reference
