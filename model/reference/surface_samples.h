#pragma once

#include "model/composite_surface.h"
#include "model/strip.h"

#include <cstdint>
#include <vector>

namespace devsurf::model::reference {

// A piece of a design on which the closest point to a given point is found exactly: a strip or
// cone (Newton on its (u,v)), or a triangle of a planar face (fanned from its first corner, as
// sampleSurface does).
struct SurfacePiece {
    std::size_t surface = 0; // index in the list of surfaces sampled
    FaceId face = kInvalidId;
    bool isStrip = false;
    Strip strip;        // if isStrip
    Vec3 triangle[3]{}; // otherwise
};

// Dense samples of one or more composite surfaces, as struct of arrays: sample i lies at
// positions[i] on pieces[piece[i]], at strip parameters (u[i], v[i]) (0 on triangles), and
// stands for area[i] of the surface (a quarter of each grid cell around it on strips, a third
// of each small triangle on planar faces). Every point of a piece lies within coveringRadius of
// a sample of that piece.
struct SurfaceSamples {
    std::vector<SurfacePiece> pieces;
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> piece;
    std::vector<double> u;
    std::vector<double> v;
    std::vector<double> area;
    double coveringRadius = 0.0;
};

// Samples every strip and cone on a (u,v) grid, samplesPerInterval steps in u per spline
// interval of its curves and as many steps along the rulings as keep the grid cells about
// square (at most 1000), and every planar face on a triangular grid no coarser than the
// strips'. The surfaces must be valid (ModelError otherwise, as sampleSurface throws);
// samplesPerInterval lies in [1, 1000] (ModelError otherwise).
SurfaceSamples sampleDensely(const std::vector<CompositeSurface>& surfaces, int samplesPerInterval);

} // namespace devsurf::model::reference
