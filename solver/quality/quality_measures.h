#pragma once

#include "model/composite_surface.h"
#include "model/sampled_mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace devsurf::solver {

struct QualityOptions {
    // Samples per spline interval of the mesh (V,E,F) for flatness and curvature.
    int meshSamplesPerInterval = 8;
    // Parameter values per interval for the developability residual (≥ 50, docs/math.md §8).
    int developabilitySamplesPerInterval = 50;
};

// The quality measures of docs/math.md §8, computed from the geometry alone (never from a solver's
// residuals). All are scale-invariant ratios or angles.
struct QualityMeasures {
    // δ = dist(diagonal₁, diagonal₂) / mean(two shortest edge lengths) over the quads of (V,E,F).
    int quads = 0;
    double flatnessMean = 0.0;
    double flatnessMax = 0.0;
    // |K| = |2π − Σ angles| at the interior vertices of (V,E,F).
    int interiorVertices = 0;
    double curvatureMean = 0.0;
    double curvatureMax = 0.0;
    // |det(a−b, a′, b′)| / (|a−b| |a′| |b′|) over every strip, densely sampled.
    int developabilitySamples = 0;
    double developabilityMean = 0.0;
    double developabilityMax = 0.0;
};

// Throws model::ModelError if the surface is not valid.
QualityMeasures measureQuality(const model::CompositeSurface& surface,
                               const QualityOptions& options = {});

// The largest normalised developability residual of every strip patch, sampled as
// measureQuality does (samplesPerInterval midpoints per interval), worst first; cones and planar
// patches are developable by construction and are not listed. Empty for an invalid surface.
std::vector<std::pair<model::FaceId, double>>
developabilityByFace(const model::CompositeSurface& surface, int samplesPerInterval = 20);

// The largest of developabilityByFace's residuals (0 for a surface without strip patches).
double worstDevelopability(const model::CompositeSurface& surface);

// The developability of one strip patch as the Solver panel and the 3D view's colouring report it:
// the normalised residual at samplesPerInterval midpoints per spline interval; `worst` is their
// maximum (developabilityByFace's value), and segments[i] the maximum of the samples with u in
// [i, i+1) / (segmentsPerInterval · intervals), i.e. within the i-th quad of
// model::sampleSurface(surface, segmentsPerInterval). A segment that holds no sample takes the
// sample nearest its middle, so the maximum over the segments is `worst`.
struct PatchDevelopability {
    model::FaceId face = model::kInvalidId;
    double worst = 0.0;
    std::vector<double> segments;
};
// Every strip patch in face id order; cones and planar patches (developable by construction) are
// not listed. Empty for an invalid surface.
std::vector<PatchDevelopability> developabilityOfPatches(const model::CompositeSurface& surface,
                                                         int segmentsPerInterval,
                                                         int samplesPerInterval = 20);

// δ of every face of a sampled mesh: the distance of a quad's diagonal lines over the mean of its
// two shortest edges (docs/math.md §8); NaN where there is no quad to measure (triangles,
// quads whose diagonals are parallel or whose shortest edges vanish).
std::vector<double> faceFlatness(const model::SampledMesh& mesh);

// |K| = |2π − Σ angles| at every vertex of a sampled mesh (docs/math.md §8); NaN at vertices on
// the boundary or used by no face.
std::vector<double> vertexAngleDefects(const model::SampledMesh& mesh);

// The normalised developability residual of one ruled surface at u (docs/math.md §8, from (2)); 0
// if a factor vanishes.
double normalizedDevelopabilityResidual(const model::Vec3& aMinusB, const model::Vec3& aPrime,
                                        const model::Vec3& bPrime);

} // namespace devsurf::solver
