#pragma once

#include "model/composite_surface.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::solver {

// How a solve changed a surface, from the geometry of the start and the result (same
// combinatorics), for the degeneracy and noise figures of the benchmark and the tests.
struct ShapeChange {
    // Smallest |a(u) − b(u)| of the result over the same ruling's length in the start, over
    // every strip and sampled u (rulings of zero start length, SRS tips, are skipped).
    double shortestRuling = 1.0;
    // Smallest speed |c′(u)| of the result over the mean speed of the same S-edge in the
    // start, over every S-edge and sampled u.
    double slowestSpeed = 1.0;
    // Mean angle (radians) between the normals of the two sampled faces at a crease (an S-edge
    // between two faces) in the result, and between any two neighbouring sampled faces in the
    // start: a solve that crumples a noisy start raises the first above the second.
    double creaseFoldMean = 0.0;
    double startNormalAngleMean = 0.0;
    // Largest distance of a vertex or control point from its start position.
    double largestMove = 0.0;
    // Where the result folds over onto itself: foldOvers(result), from the same sampling.
    std::vector<std::pair<model::FaceId, int>> foldOvers;
    // The places of all of them.
    int foldOverPlaces() const;
};

// Throws model::ModelError if a surface is not valid; the two must share their combinatorics.
ShapeChange measureShapeChange(const model::CompositeSurface& start,
                               const model::CompositeSurface& result, int samplesPerInterval = 8);

// Where a patch folds over onto itself: the number of pairs of neighbouring sampled faces of
// the mesh (V,E,F) (samplesPerInterval per spline interval) that belong to the same face of
// the surface and whose normals turn by more than 90°, per face, most first. A developable
// patch's normal turns smoothly and never reverses between neighbouring samples; it does
// where the patch is folded back onto itself, e.g. a flat sheet pushed within its own plane
// until it overlaps itself. (Creases between two faces may fold by any angle and are not
// counted.) Empty for an invalid surface.
std::vector<std::pair<model::FaceId, int>> foldOvers(const model::CompositeSurface& surface,
                                                     int samplesPerInterval = 8);

// How many faces of foldOvers() a report names (the first ones, which it lists most places
// first); the rest are counted.
inline constexpr std::size_t kFoldOversNamed = 10;

} // namespace devsurf::solver
