#pragma once

// The development in the solve (§5, eq. 12; docs/math.md §7): a flat copy of the sampled mesh
// as variables, isometric to the surface face by face.

#include "model/composite_surface.h"
#include "model/development.h"
#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"
#include "solver/core/fairness_term.h"
#include "solver/core/problem.h"
#include "solver/core/squared_distance_term.h"
#include "solver/core/target_term.h"

#include <map>
#include <vector>

namespace devsurf::solver {

// A coarse vertex's place in a held sheet pulled towards a target (mm, in the coordinates of
// the kept development, CompositeSurface::development()).
struct SheetHandle {
    model::VertexId vertex = model::kInvalidId;
    model::Vec2 target;
};

// Where the flat copy lives in the state, and how to read it back in millimetres.
struct DevelopmentVariables {
    model::SampledMesh mesh; // the sampled mesh the copy is of
    int offset = -1;         // block "development": v̄ of mesh vertex i at offset + 2 i
    model::Vec2 origin;      // a development point is origin + scale · (state values)
    double scale = 1.0;
    FairnessTerm* fairness = nullptr; // owned by the problem; null when the copy is fixed
    // Pulled points of the copy (DevelopmentOptions::pulls): their first row in `pulls`.
    TargetTerm* pulls = nullptr;
    std::map<model::VertexId, int> pullRow; // coarse vertex → row

    model::Development read(const std::vector<double>& x) const;
    // Moves a pulled point's target (mm); false if that vertex's place is not pulled.
    bool setPullTarget(model::VertexId vertex, const model::Vec2& target);
};

// How the flat copy enters a problem (FormulationOptions::development…).
struct DevelopmentOptions {
    int samplesPerInterval = 2;
    const std::vector<model::Vec2>* start = nullptr; // millimetres, indexed like the mesh
    bool fixed = false;   // the copy keeps its start values: the surface is folded from that sheet
    double weight = 1e-2; // FormulationOptions::developmentWeight
    double fairnessWeight = 0.01;
    // A copy that is not fixed is confined to this sheet (addDomain); free: unconfined.
    model::SheetDomain domain;
    // Coarse vertices' places pulled towards targets (mm): an energy of pullWeight
    // (family "sheetPulls", driving ε₁) that the surface follows as far as it can, the two-way
    // editing of a held sheet in the development view.
    std::vector<SheetHandle> pulls;
    double pullWeight = 100.0; // FormulationOptions::sheetHandleWeight
};

// Samples `surface` (model::sampleSurface) and appends to `problem` a block "development" with a
// 2D point v̄ per mesh vertex, starting at `options.start` or, without one, at the mesh's
// unfolding. Every mesh vertex v is a linear evaluation of the state: a coarse vertex's point,
// or a sample of an S-edge as the de Boor combination of its control points (`vertexOffsets`,
// `edgeOffsets`: state offsets, S-edge control points in stored orientation). A family
// "development" (constraints) gets (12) for every pair of vertices of every sampled face,
// ‖v̄ᵢ − v̄ⱼ‖² − ‖vᵢ − vⱼ‖² = 0, divided by the pair's squared length at the start; unless the
// copy is fixed, a family "developmentFairness" (an energy) gets the overfolding fairness
// Σ‖v̄ᵢ₊₁ − 2v̄ᵢ + v̄ᵢ₋₁‖² along every sampled S-edge and the copy is confined to
// `options.domain` (addDomain). State coordinates are model coordinates
// less the formulation's centre, divided by `scale`; `state` is resized and the block filled.
DevelopmentVariables addDevelopment(const model::CompositeSurface& surface,
                                    const DevelopmentOptions& options,
                                    const std::map<model::VertexId, int>& vertexOffsets,
                                    const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                                    double scale, Problem& problem, std::vector<double>& state);

} // namespace devsurf::solver
