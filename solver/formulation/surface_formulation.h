#pragma once

#include "model/composite_surface.h"
#include "model/strip.h"
#include "solver/core/options.h"
#include "solver/core/problem.h"
#include "solver/formulation/approximation_terms.h"
#include "solver/formulation/curve_pairing.h"
#include "solver/formulation/development_terms.h"
#include "solver/formulation/normal_spline_start.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace devsurf::solver {

struct StripNormalSpline; // crease_conditions.h

class BilinearTerm;
class BisectorTerm;
class FairnessTerm;
class MinimumLengthTerm;
class SquaredDistanceTerm;
class TargetTerm;
class UnitNormTerm;

// A user handle on a coarse vertex: fixed where it is, or pulled towards a target (weight 1).
struct VertexHandle {
    model::VertexId vertex = model::kInvalidId;
    bool fixed = true;
    model::Vec3 target; // only used when !fixed, in model coordinates
};

// A user handle on an interior control point of an S-edge (a dragged crease): pulled towards
// a target with the weight of the vertex handles.
struct ControlPointHandle {
    model::EdgeId edge = model::kInvalidId;
    int index = 1;      // among the edge's control points, 1 … n − 2 (its ends are vertices)
    model::Vec3 target; // model coordinates
};

// The choices of a formulation. The defaults are the configuration the benchmark times (the
// paper's, but with the exact normal space); the sessions (solver/session) and
// useRoughStartConfiguration change them. The measurements behind them: docs/tuning.md.
struct FormulationOptions {
    // (4) with the first-derivative points a¹₀, a¹₁, b¹₀, b¹₁ of every collocation value as
    // auxiliary variables tied to the control points by linear relations (as the paper does),
    // instead of substituting those relations into (4). Off: slower at equal quality.
    bool auxiliaryDerivativePoints = false;
    // Collocation values of (4) per interval; 0 means 3m − 2, which makes the strip exactly
    // developable (det(a−b, a′, b′) has degree 3m − 3 per interval, docs/math.md §2).
    int developabilityValuesPerInterval = 0;

    // Scale every row of (4), of planar faces, of cone normals and of the crease conditions
    // (docs/math.md §5) by 1/(|n| |d|) of its two sides at the reference state
    // (BilinearTerm::scaleRowsAt): near it a row then measures the cosine of an angle, so a
    // residual of 1e-8 means the same on every strip whatever its size. Off by default (the
    // cylinder stalls with it); part of useRoughStartConfiguration.
    bool normalizedRows = false;

    // The state's unit: the diameter, or the mean control segment divided by this where that
    // is shorter (stateUnit), so a finer design is not regularised more weakly. 0: the
    // diameter; sessions use kSessionControlSpacingUnit.
    double controlSpacingUnit = 0.0;

    // Noisy unit normals of a strip that is not developable at the start are replaced by their
    // best linear field (fitStartNormals, kNoisyStartNormals). Off by default; sessions turn it
    // on.
    bool linearNoisyStartNormals = false;

    // One-sided guards relative to the reference state: every sampled ruling stays at least
    // rulingGuard times its reference length, every curve speed at least speedGuard times the
    // smaller of its reference and mean reference speed. Inactive while satisfied; 0: off.
    double rulingGuard = 0.0;
    double speedGuard = 0.0;
    double guardWeight = 1.0;

    // Fairness of the change x − x_ref (x_ref: the reference state) instead of fairness of x,
    // and the soft length of the normal spline's control normals kept at their reference
    // lengths. Meant for drags re-based with setReferenceState. Off by default: it leaves a
    // rough start's noise in place and its rulings can collapse.
    bool relativeFairness = false;

    // Weight of the pull of every point towards the reference state, further multiplied by μ
    // (Options::proximityFactor; μ = 0 skips the rows). 0 removes the rows.
    double proximityWeight = 1.0;
    // Above 0: that pull is instead an energy of this weight (times ε₁, acting whatever μ is)
    // that a drag fades after its release (SurfaceFormulation::fadeDragEnergies); a crease
    // drag keeps the rest of the design where it was with it (creaseDragSessionOptions).
    double proximityEnergyWeight = 0.0;
    // The same for the control normals of the normal splines (towards their reference values).
    // Off: anchored normals make the iteration satisfy (4) by collapsing rulings.
    double normalProximityWeight = 0.0;

    // The normal spline of a strip in S(2m − 1, k − 1) of its curves' space S(m, k) (quintic C¹
    // for cubic C² curves), which contains the normal of every developable strip of the
    // design space, instead of the paper's cubic C² (see the Builder).
    bool exactNormalSpace = true;
    // The largest normalised det(a − b, a′, b′) at which a strip counts as developable at the
    // start (isDevelopableStart): such a strip gets the exact normal space and the exact fit of
    // its normal, so the iteration starts at its residual. Solve of a nearly valid design
    // (SolveSession) raises it to kNearlyValidResidual, so that it does not start at a cubic
    // fit's larger residual.
    double developableStartLimit = kDevelopableStartLimit;

    // Constraint weights (the W of (6)).
    double developabilityWeight = 1.0;
    double normalWeight = 1.0; // n(0)ᵀn(0) = 1, cone and plane normals, their definitions
    double planarityWeight = 1.0;
    double creaseWeight = 1.0; // crease conditions (7), (8), straight when unfolded (§5)
    double smoothnessWeight = 1.0;
    double handleWeight = 1.0;
    // Energy weights (multiplied by ε₁ in the iteration, so they act in the first iterations
    // only). Fairness of the point sequences is low: it pulls every curve towards a straight
    // line, which deforms curved designs.
    double fairnessWeight = 0.1;
    // Weight of the energy keeping the lengths of every strip's control net (addStripIsometry)
    // at their values before each iteration (rebaseIsometry): the net bends rather than
    // stretches. 0 removes it; a drag that keeps lengths uses kKeepLengthsWeight.
    double isometryWeight = 0.0;
    // Where isometryWeight is 0: the same rows as damping, weighted by this times ε₂. 0
    // removes them; Solve from a rough start uses kRoughSolveLengthDamping.
    double lengthDampingWeight = 0.0;
    // Fairness of the normal splines' control normals is high: it keeps neighbouring control
    // normals from flipping against each other, a degenerate way of satisfying (4) where n(u)
    // vanishes between them.
    double normalFairnessWeight = 10.0;
    // false: no normal fairness on the strips next to a crease with a condition. Fairness of
    // the control normals pulls a strip towards a plane, and two planar strips meet in a
    // straight line, so a drag that keeps lengths pulled curved folds straight
    // (keepLengthsSessionOptions uses false).
    bool normalFairnessAtCreaseConditions = true;
    // true: the two normals of every crease row are weighed by their lengths at the reference
    // state (BisectorTerm::weighSidesAt), so the rows state (7) and (8) with unit normals and
    // a valid fold stays put. false (while something is pulled): weights 1.
    bool weighCreaseNormals = true;
    double unitControlNormalWeight = 0.1;

    // R-edges between two faces across which the unit normals must agree (smooth transition),
    // in addition to those the surface marks smooth (model::EdgeRecord::smooth).
    std::vector<model::EdgeId> smoothRulings;

    // Vertex developability (docs/math.md §7): at every interior vertex where a crease meets,
    // the angles between consecutive edges sum to 2π, through a flat copy of the star of its
    // edges' tangent points (see addVertexDevelopability). The rows vanish on an exactly
    // developable design, so valid designs stay put with it. Off by default (it slows the
    // convergence from rough starts); SolveSession turns it on with the limits below
    // (defaultSessionFormulationOptions).
    bool vertexDevelopability = false;
    double vertexDevelopabilityWeight = 1.0;
    // Every spoke of such a star (from the vertex to its edge's tangent point) stays at least
    // this fraction of its start length (a one-sided guard, inactive while satisfied; 0: none),
    // so that the iteration does not close a star by shrinking one spoke to a point.
    double vertexSpokeGuard = 0.5;
    // Where a crease passes through such a star straight to within this angle (radians), it is
    // made tangent-continuous there (G¹) instead of the flat copy; it stays below the
    // examples' kinks (docs/tuning.md). 0: flat copies everywhere.
    double vertexSmoothCreaseAngle = 0.05;
    // The same for a crease without a condition (CreaseCondition::None), whose kink is part of
    // the design: smoothed only where it is straight to this (docs/tuning.md).
    double vertexSmoothPlainCreaseAngle = 1e-3;
    // Only stars whose angle defect at the start is at most this (radians) get rows (the
    // others keep rows scaled to zero): vertex developability is then kept where it holds
    // rather than imposed on a rough start. The default imposes it everywhere.
    double vertexStartDefectLimit = 1e9;

    // The development in the solve (addDevelopment): a flat copy of the surface sampled at this
    // many values per interval (0: none), starting at developmentStart (mm) or the unfolding;
    // fixedDevelopment keeps it there, so the surface is folded from that sheet.
    // developmentWeight is low because the sampled mesh matches a developable spline only up to
    // its sampling (docs/tuning.md); the development is judged apart, in mm
    // (Verdict::sheetStretchMm).
    int developmentSamplesPerInterval = 0;
    double developmentWeight = 1e-2;
    double developmentFairnessWeight = 0.01;
    std::vector<model::Vec2> developmentStart;
    bool fixedDevelopment = false;
    // A development that is not fixed is confined to this sheet (addDomain); free: unconfined.
    model::SheetDomain developmentDomain;
    // Coarse vertices whose place in the development is pulled (two-way editing: a point of
    // the held sheet dragged in the development view); needs developmentSamplesPerInterval.
    // At weight 1 the point lagged 16 mm behind a 20 mm drag until the release; at 100 it
    // follows each move to 0.01 mm (tests/solver/tst_development.cpp's two-way drag).
    std::vector<SheetHandle> sheetHandles;
    double sheetHandleWeight = 100.0;

    std::vector<VertexHandle> handles;
    std::vector<ControlPointHandle> controlPointHandles;
    // 0: the control-point handles are constraints, as the vertex handles are. Above 0: an
    // energy of this weight (times ε₁, family "creaseHandles") that the iteration follows as
    // far as the conditions let it, for a dragged crease whose every control point is pulled
    // (see creaseDragSessionOptions).
    double controlPointHandleWeight = 0.0;
    // Above 0: pulled vertex handles are an energy of this weight ("pulls", driving ε₁, faded by
    // fadeDragEnergies) instead of constraints, so a vertex lags where the sheet cannot follow.
    double pulledHandleWeight = 0.0;

    // Approximation of a reference shape (§4.2, eqs. 9–11): the strips are pulled towards
    // these points through their closest points, refreshed before every iteration
    // (refreshApproximation). Null: none.
    std::shared_ptr<const ApproximationTarget> approximation;
    ApproximationWeights approximationWeights;

    // Pairs of boundary edges of one kind (two S-edges, or two R-edges as straight segments)
    // pulled together (§4.2, "Composite"; CurvePairingFit), their
    // closest points refreshed before every iteration with the approximation's. A constraint
    // judged apart, not faded: the curves end on each other, ready to be welded.
    std::vector<CurvePair> curvePairs;
    double curvePairingWeight = 1.0;
};

// The configuration for rough starts (a design dragged far, a noisy import): proximity to the
// start (Options::proximityFactor 1, threshold 1e-2), rows of (4) normalised to angles
// (normalizedRows), ε₂ floor 3e-4, ruling and speed guards (0.3, 0.15, weight 0.1). It keeps
// rulings long and ends near the start where the paper's configuration degenerates; not the
// default, since with a small ε₂ the paper's configuration converges further on mild noise
// (docs/tuning.md).
void useRoughStartConfiguration(FormulationOptions& formulation, Options& solver);

// The unit of the state's coordinates for `surface`, whose diameter is `diameter`: the
// diameter, or the mean control segment over `controlSpacingUnit` where that is shorter
// (FormulationOptions::controlSpacingUnit). 1 for a surface of no extent.
double stateUnit(const model::CompositeSurface& surface, double diameter,
                 double controlSpacingUnit);

// Turns a composite surface into a guided-projection problem (§3.1, §3.2) and writes solutions
// back. Variables, all in coordinates normalised to the surface's diameter (centre at the
// origin, diameter 1; on fine designs to their control spacing, see controlSpacingUnit) so that
// weights and ε₂ do not depend on the model's units:
//   "points"            every coarse vertex and every interior S-edge control point, once;
//   "normalControls"    a cubic C² normal spline per strip (SRSR, SRS);
//   "coneNormals"       unit normals of every cone at its interval ends;
//   "planeNormals"      one unit normal per planar face;
//   "derivativePoints"  a¹₀, a¹₁, b¹₀, b¹₁ per collocation value (auxiliary variant only).
// Fixed handles are fixed variables (they keep their value exactly).
class SurfaceFormulation {
public:
    // Throws std::invalid_argument (with a sentence naming the entity) when the surface is
    // not valid or an option refers to something that does not exist or cannot be used.
    SurfaceFormulation(const model::CompositeSurface& surface, const FormulationOptions& options);

    const Problem& problem() const { return m_problem; }
    Problem& problem() { return m_problem; }
    // The state of the given surface (the one passed to the constructor).
    const std::vector<double>& initialState() const { return m_initialState; }

    // Makes x the reference state: the row scales of (4), the weights of the crease
    // conditions' normals (weighCreaseNormals) and the guards' minimum ruling
    // lengths and curve speeds are taken from x (and, with relativeFairness, fairness
    // measures the change from x). The constructor uses the
    // initial state. Values only (the problem's structure is unchanged), so an interactive
    // caller can re-base between drags without a new symbolic analysis.
    void setReferenceState(const std::vector<double>& x);
    // Sets the lengths the isometry energy (FormulationOptions::isometryWeight) keeps to
    // those at x.
    void rebaseIsometry(const std::vector<double>& x);
    // Measures the development's overfolding fairness from x: the energy then damps how much
    // the next step bends the development's curves and vanishes once the iteration stands
    // still, instead of pulling the curves of a development confined to a sheet straight
    // against its boundary (docs/tuning.md, "A sheet of a given shape").
    void rebaseDevelopmentFairness(const std::vector<double>& x);
    // Multiplies the weight of that energy (or damping) by `factor` (nothing without it).
    void scaleIsometryWeight(double factor);
    // Multiplies the weights of a drag's energies by `factor`: the control-point handles'
    // (controlPointHandleWeight), the soft vertex pulls (pulledHandleWeight) and the pull
    // towards the reference state where it is an energy (proximityEnergyWeight), and with
    // `sheetPulls` the pulls of places in the held sheet (sheetHandleWeight); from now on ε₁
    // follows the constraint residual alone. Nothing without them.
    void fadeDragEnergies(double factor, bool sheetPulls = false);
    // Finds the closest points of the approximation target (FormulationOptions::approximation)
    // and of the paired curves (curvePairs) on `current`, the surface at the state about to be
    // iterated from. No-op without them.
    void refreshApproximation(const model::CompositeSurface& current);
    // Multiplies the weights of eqs. (9)–(11) and of the control normals' unit length by
    // `factor`: the approximation fades out so that the hard conditions converge exactly.
    void scaleApproximationWeights(double factor);
    // The closest points of the target; null without one.
    const ApproximationFit* approximationFit() const { return m_approximation.get(); }
    // The paired curves' samples and closest points; null without pairs.
    const CurvePairingFit* curvePairing() const { return m_pairing.get(); }
    // Whether those rows damp length changes (lengthDampingWeight) rather than keep lengths.
    bool isometryDamps() const {
        return m_isometryFamily >= 0 &&
               m_problem.family(m_isometryFamily).role == TermRole::Damping;
    }

    // Developability, planarity and crease-condition residual of every face at state x (a
    // crease counts towards its left strip): the largest |row|
    // of the face's rows, worst first. Where a solve did not reach its tolerance, these are the
    // faces to show.
    struct FaceResidual {
        model::FaceId face = model::kInvalidId;
        double residual = 0.0;
    };
    std::vector<FaceResidual> faceResiduals(const std::vector<double>& x) const;

    // Moves the target of a pulled handle (model coordinates). Returns false if the vertex has
    // no pulled handle.
    bool setHandleTarget(model::VertexId vertex, const model::Vec3& target);
    // The same for a pulled control point (false if it has no handle).
    bool setControlPointTarget(model::EdgeId edge, int index, const model::Vec3& target);
    // Moves a pulled point of the development (FormulationOptions::sheetHandles; mm, in the
    // development's own coordinates); false if that vertex's place is not pulled.
    bool setSheetHandleTarget(model::VertexId vertex, const model::Vec2& target);

    // Writes the vertices and control points of state x into `surface` (which must have the
    // combinatorics of the formulated surface). Refuses a state of the wrong size or with a
    // non-finite value: `surface` is then untouched and `error` says why. Coordinates that
    // the solver did not change are restored bit for bit.
    bool writeBack(const std::vector<double>& x, model::CompositeSurface& surface,
                   std::string* error = nullptr) const;

    // Model coordinates of a coarse vertex in state x.
    model::Vec3 vertexPosition(const std::vector<double>& x, model::VertexId vertex) const;

    // The development at state x (mm) and its mesh; null and empty without one.
    const model::SampledMesh* developmentMesh() const {
        return m_development.offset >= 0 ? &m_development.mesh : nullptr;
    }
    model::Development development(const std::vector<double>& x) const {
        return m_development.offset >= 0 ? m_development.read(x) : model::Development{};
    }

    int stripCount() const { return m_stripCount; }
    int coneCount() const { return m_coneCount; }
    int planarFaceCount() const { return m_planarCount; }
    int pointCount() const { return m_pointCount; }
    double scale() const { return m_scale; }

    // Scales the unit normals of planar faces and cones and the osculating normals of
    // "straight when unfolded" to unit length at x. Every other row of those normals is
    // homogeneous in them, so this satisfies the unit rows exactly and leaves the others'
    // zeros. The strips' normal splines are left alone: their rows mix both sides of a crease
    // (docs/tuning.md).
    void normaliseUnitNormals(double* x) const;

private:
    struct Builder;
    // Fixes the fixed vertex handles and adds the rows of the pulled ones to `handles`, those
    // of the control-point handles to `controlPointHandles` (throws std::invalid_argument for
    // a handle on something the surface does not have).
    void addHandles(TargetTerm& handles, TargetTerm& controlPointHandles);
    int pointOffset(int point) const { return m_pointsOffset + 3 * point; }
    model::Vec3 toModel(const double* p) const;
    // Point indices of a strip side's curve in the order the strip traverses it.
    std::vector<int> sidePoints(const model::StripSide& side) const;
    // The closest points of the approximation target (§4.2) on the strips (not cones), with
    // each strip's normal spline (surface_formulation_approximation.cpp).
    void addApproximationFit(const model::CompositeSurface& surface,
                             const std::vector<model::Strip>& strips,
                             const std::map<model::FaceId, StripNormalSpline>& stripNormals);
    // The pairing of FormulationOptions::curvePairs (throws std::invalid_argument for an edge
    // that is not a boundary S-edge of the surface).
    void addCurvePairs(const model::CompositeSurface& surface);

    FormulationOptions m_options;
    Problem m_problem;
    std::vector<double> m_initialState;
    model::Vec3 m_centre;
    double m_scale = 1.0;
    int m_pointsOffset = 0;
    int m_pointCount = 0;
    int m_stripCount = 0;
    int m_coneCount = 0;
    int m_planarCount = 0;
    std::map<model::VertexId, int> m_vertexPoint;
    std::map<model::EdgeId, std::vector<int>> m_edgePoints; // stored orientation, ends included
    // The normal of a face at one of its R-edges, keyed by (face, edge): a combination of
    // normal variables oriented like the face loop (filled while adding faces, used for smooth
    // transitions).
    std::map<std::pair<model::FaceId, model::EdgeId>, PointCombination> m_rulingNormals;
    std::map<model::VertexId, int> m_handleRow; // first TargetTerm row of a pulled handle
    std::map<std::pair<model::EdgeId, int>, int> m_controlHandleRow; // the same per point
    TargetTerm* m_handleTerm = nullptr;
    TargetTerm* m_controlHandleTerm = nullptr; // m_handleTerm, or the energy's own term
    FamilyId m_controlHandleEnergy = -1;       // the family of that energy, if any
    FamilyId m_pullEnergy = -1;                // soft vertex handles (pulledHandleWeight)
    FamilyId m_proximityEnergy = -1;           // the pull towards the reference, as an energy
    TargetTerm* m_proximity = nullptr;         // every point towards the reference state
    TargetTerm* m_normalProximity = nullptr;   // every control normal towards the reference state
    int m_normalControlsOffset = 0;
    FairnessTerm* m_pointFairness = nullptr;
    FairnessTerm* m_normalFairness = nullptr;
    DevelopmentVariables m_development;
    UnitNormTerm* m_unitControlNormals = nullptr;
    SquaredDistanceTerm* m_isometry = nullptr;
    FamilyId m_isometryFamily = -1;
    MinimumLengthTerm* m_rulingGuard = nullptr;
    MinimumLengthTerm* m_speedGuard = nullptr;
    // Row ranges of m_speedGuard per curve (the mean speed is taken per curve).
    std::vector<int> m_speedCurveStart;
    // The face of every row of the developability and planarity terms.
    BilinearTerm* m_developability = nullptr;
    BilinearTerm* m_planarity = nullptr;
    BilinearTerm* m_coneNormals = nullptr;
    BisectorTerm* m_creaseConditions = nullptr; // curved folds and geodesics
    BilinearTerm* m_straightCreases = nullptr;  // straight when unfolded
    std::vector<model::FaceId> m_developabilityFaces;
    std::vector<model::FaceId> m_planarityFaces;
    // The left strip of every row of m_creaseConditions and of m_straightCreases.
    std::vector<model::FaceId> m_creaseFaces;
    std::vector<model::FaceId> m_straightCreaseFaces;
    std::vector<model::Vec3> m_originalPoints; // model coordinates of the given surface
    std::unique_ptr<ApproximationFit> m_approximation;
    std::vector<FamilyId> m_approximationFamilies;
    std::unique_ptr<CurvePairingFit> m_pairing;
};

} // namespace devsurf::solver
