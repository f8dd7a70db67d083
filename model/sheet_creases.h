#pragma once

// Creases confined to curves drawn in the sheet (§5: "crease vertices optionally confined to a
// curve drawn in the sheet", Fig. 12, 13). A designer draws the crease pattern on the flat
// sheet; every sample of a crease assigned to a curve (SheetDomain::creaseCurveOf) keeps its
// development on that curve, on the tangent line at its foot point as the sheet's boundary
// does, so the fold follows the drawn pattern.

#include "reference_curve.h"
#include "sheet_domain.h"

#include <map>
#include <vector>

namespace devsurf::model {

class CompositeSurface;
struct SampledMesh;

// The crease curves placed in the development's plane (by the domain's centre and angle),
// indexed like SheetDomain::creaseCurves; open curves have DomainLoop::open set.
std::vector<DomainLoop> creaseCurveLoops(const SheetDomain& domain);

// A sampled mesh vertex held on a crease curve.
struct OnCreaseCurve {
    int vertex = 0; // mesh vertex
    int curve = 0;  // index into creaseCurveLoops()
};
// Every sample (ends included) of every crease the domain assigns to a curve, once per curve.
std::vector<OnCreaseCurve> creaseSamplesOnCurves(const SheetDomain& domain,
                                                 const SampledMesh& mesh);

// Assigns the creases of `surface` (its S-edges between two faces) to the domain's curves: an
// edge goes to the curve its samples' development lies nearest to on average, when that mean
// distance is at most kCreaseCurveReach of the edge's developed length and no other crease lies
// nearer the curve there (for at least half of its samples, the sample is the nearest crease
// sample to its foot point on the curve). `mesh` is the surface sampled as `development` is.
inline constexpr double kCreaseCurveReach = 0.5;
// mm: a drawn crease curve is read this close to the exact curve (finer than a sheet's outline),
// so that its polygon turns by little at each vertex.
inline constexpr double kCreaseCurveTolerance = 0.001;
std::map<EdgeId, int> assignCreasesToCurves(const SheetDomain& domain,
                                            const CompositeSurface& surface,
                                            const SampledMesh& mesh,
                                            const std::vector<Vec2>& development);

// The largest distance (mm) of a held crease sample's development from its curve; 0 when none.
double largestCreaseCurveGap(const SheetDomain& domain, const SampledMesh& mesh,
                             const std::vector<Vec2>& development);

// The creases of `surface` (its S-edges between two faces) as they lie in `development` now
// (the development of sampleSurface(surface, kDevelopmentSamplesPerInterval)), as curves in the
// development's plane: drawn in a sheet (sheetFrameCurves), they keep the crease pattern while
// the rulings move in the sheet. Creases that continue one another through a vertex where no
// third crease meets form one curve, closed where they close up. Each is traced at
// kCreaseCurveSamples points per spline interval on a fresh unfolding laid onto `development`
// (the rigid motion that best maps its coarse vertices there). Empty for a surface without
// creases or one that does not unfold into one flat sheet.
inline constexpr int kCreaseCurveSamples = 32;
std::vector<SheetDomain::Curve> creaseCurvesAsTheyLie(const CompositeSurface& surface,
                                                      const std::vector<Vec2>& development);

// Curves in the development's plane moved into the own frame of `domain` (placed), where
// SheetDomain::creaseCurves are kept.
std::vector<SheetDomain::Curve> sheetFrameCurves(const SheetDomain& domain,
                                                 std::vector<SheetDomain::Curve> curves);

// Every curve of two points or more among `curves` seen from above (z dropped): closed when
// it ends where it starts (within 1e-6 of its length; the repeated point dropped), otherwise
// open. Moved by `shift` (into the sheet's frame).
std::vector<SheetDomain::Curve> sheetCurvesFromAbove(const std::vector<ReferenceCurve>& curves,
                                                     const Vec2& shift = {});

} // namespace devsurf::model
