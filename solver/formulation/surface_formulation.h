#pragma once

#include "model/composite_surface.h"
#include "solver/core/options.h"
#include "solver/core/problem.h"
#include "solver/formulation/normal_spline_start.h"

#include <map>
#include <string>
#include <vector>

namespace devsurf::solver {

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

struct FormulationOptions {
    // (4) with the first-derivative points a¹₀, a¹₁, b¹₀, b¹₁ of every collocation value as
    // auxiliary variables tied to the control points by linear relations (as the paper does),
    // instead of substituting those relations into (4). Measured slower at equal quality (see
    // the benchmark), so off by default.
    bool auxiliaryDerivativePoints = false;
    // Collocation values of (4) per interval; 0 means 3m − 2, which makes the strip exactly
    // developable (det(a−b, a′, b′) has degree 3m − 3 per interval, docs/math.md §2).
    int developabilityValuesPerInterval = 0;

    // Scale every row of (4), of planar faces, of cone normals and of the crease conditions
    // (docs/math.md §5) by 1/(|n| |d|) of its two
    // sides at the reference state (BilinearTerm::scaleRowsAt): near it a row then measures
    // the cosine of an angle, so a residual of 1e-8 means the same on every strip whatever its
    // width, control spacing or the model's size. Off by default: measured from 0.1 % noise
    // (3 seeds, 10 iterations) it helped the sheet (det 2e-15 against 2e-11) and the annulus
    // (9e-14 against 1e-7) and kept rulings longer, but the cylinder stalled at 1e-5 (against
    // 5e-15) and one seed of the mixed example degenerated. Together with the proximity to the
    // start it is part of useRoughStartConfiguration: without it that configuration ended at
    // det 0.40 on the annulus from 1 % of the diameter (5.5e-3 with it) and 2.2e-6 on the
    // cylinder from 0.1 % (3e-8 with it).
    bool normalizedRows = false;

    // The unit of the state's coordinates, as a fraction of the diameter for the mean segment
    // of the control polygons. The constraint rows are dimensionless, so their Jacobian grows
    // as one over the control spacing; fairness, ε₂ and the pull towards the start are
    // measured in the state's unit. With the diameter as the unit, a design whose control
    // polygons are five times finer has a regularisation 25 times weaker against its
    // constraints. So the unit is the diameter, or, where the mean control segment
    // (meanControlSpacing) is shorter than this fraction of the diameter, that segment
    // divided by it: a finer design is regularised like one whose segments are this fraction
    // of its diameter. 0 (the default, the paper's configuration the benchmark times) keeps
    // the diameter; sessions use kSessionControlSpacingUnit.
    double controlSpacingUnit = 0.0;

    // Noisy unit normals of a strip that is not developable at the start are replaced by their
    // best linear field (fitStartNormals, kNoisyStartNormals). Off by default, the paper's
    // configuration the benchmark times; sessions turn it on.
    bool linearNoisyStartNormals = false;

    // Guards against degenerate solutions, relative to the reference state (the start of the
    // solve, see setReferenceState): every sampled ruling |a(u) − b(u)| stays at least
    // rulingGuard times its reference length, and every sampled curve speed |a′(u)| at least
    // speedGuard times the smaller of its reference speed and the curve's mean reference
    // speed. Inactive (zero rows) while satisfied, so a valid design is not moved; 0 disables.
    // Off by default: measured with 0.5 on the sheet and the annulus from 1 % noise, they keep
    // the rulings above half their length but the iteration then does not converge in 10
    // iterations (normalised det 0.56–0.99 instead of 1e-5 on the sheet). With the proximity
    // to the start (useRoughStartConfiguration: 0.3, 0.15, weight 0.1) they are inactive on
    // every start measured except the annulus from 1 % of the diameter, where they keep the
    // rulings at 0.30 of their length instead of 0.005 (det 1.9e-2 instead of 5.5e-3; weight
    // 0.3: rulings 0.17, 0.03: 0.11, speed guard 0.3: rulings 0.19).
    double rulingGuard = 0.0;
    double speedGuard = 0.0;
    double guardWeight = 1.0;

    // Fairness of the change x − x_ref (x_ref: the reference state) instead of fairness of x,
    // and the soft length of the normal spline's control normals kept at their reference
    // lengths. Off by default: it leaves a rough start's noise in place, and measured from
    // 0.1 % noise on the sheet the rulings then collapsed (det 6e-3 instead of 1e-13). Valid
    // designs stay put either way, because ε₁ is capped by the constraint residual
    // (Options::eps1ResidualFactor). Meant for drags re-based with setReferenceState.
    bool relativeFairness = false;

    // Weight of the pull of every point towards the reference state (a family of role
    // Proximity: its weight is further multiplied by μ, which GuidedProjection ties to the
    // constraint residual, Options::proximityFactor; with μ = 0, the default, the rows are
    // skipped). 0 removes the rows.
    double proximityWeight = 1.0;
    // Above 0: that pull is instead an energy of this weight (times ε₁, acting whatever μ is)
    // that a drag fades after its release (SurfaceFormulation::fadeDragEnergies); a crease
    // drag keeps the rest of the design where it was with it (creaseDragSessionOptions).
    double proximityEnergyWeight = 0.0;
    // The same for the control normals of the normal splines (towards their reference values).
    // Off: measured, anchoring the normals makes the iteration satisfy (4) by moving the
    // points into the planes of the stuck normals, i.e. by collapsing rulings (weight 1: the
    // sheet from 10 % edge noise ended at det 0.12 with rulings at 5 % of their length; 0.1
    // lost the annulus, det 0.83).
    double normalProximityWeight = 0.0;

    // The normal spline of a strip in S(2m − 1, k − 1) of its curves' space S(m, k) (quintic C¹
    // for cubic C² curves), which contains the normal of every developable strip of the
    // design space, instead of the paper's cubic C² (see the Builder).
    bool exactNormalSpace = true;
    // The largest normalised det(a − b, a′, b′) at which a strip counts as developable at the
    // start (isDevelopableStart): such a strip gets the exact normal space and the exact fit of
    // its normal, so the iteration starts at its residual. Solve of a nearly valid design
    // (SolveSession) raises it to kNearlyValidResidual: with the default, the cubic fit of the
    // curved fold a drag keeping lengths leaves on the lifted Fig. 8 (sampled det 6.6e-7)
    // started Solve at 1.1e-4 instead of 3e-8, and its steps wrecked the design (1.1e-2 after
    // 30 iterations, a point moved by 116 mm); with it, 2.6e-8 after 30 (0.08 mm).
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
    // line, which deforms curved designs (measured: 10 bent the developable cylinder example
    // to det 0.19, 0.1 keeps it at 1e-15). Fairness of the normal splines' control normals is
    // high: 10 × ε₁ = 1 → 0.59 keeps neighbouring control normals from flipping against each
    // other, a degenerate way of satisfying (4) where n(u) vanishes between them.
    double fairnessWeight = 0.1;
    // Weight of the energy that keeps the lengths of every strip's control net (its two
    // control polygons, the segments aᵢbᵢ and the diagonals aᵢbᵢ₊₁; see addStripIsometry)
    // at their values before the iteration: SolveSession re-bases it before every iteration
    // (rebaseIsometry), so it damps stretching of the net in each step and lets the net bend.
    // 0 (the default) removes it; a drag that keeps lengths uses kKeepLengthsWeight.
    double isometryWeight = 0.0;
    // Where isometryWeight is 0: the same rows as damping (TermRole::Damping), weighted by
    // this times ε₂, so that a step changes the net's lengths as reluctantly as ε₂ makes it
    // move any variable, times this weight. 0 (the default) removes them; Solve from a rough
    // start uses kRoughSolveLengthDamping (see there for the measurements).
    double lengthDampingWeight = 0.0;
    double normalFairnessWeight = 10.0;
    // false: no normal fairness on the strips next to a crease with a condition. Fairness of
    // the control normals pulls a strip towards a plane, and two planar strips meet in a
    // straight line: a drag that keeps lengths (keepLengthsSessionOptions) then still pulled
    // every curved fold straight as the isometry energy faded (fig6 lifted 60 mm: bow 0.0 mm
    // with weight 0.1, 33 mm without).
    bool normalFairnessAtCreaseConditions = true;
    // The normal splines of the two strips beside a curved fold or a geodesic have unit length
    // at u = 0 only, so the bilinear rows ⟨d, n_L ± n_R⟩ state (7) and (8) only where the two
    // have equal lengths. true: setReferenceState weighs the two normals of every row by their
    // lengths at the reference state (BisectorTerm::weighSidesAt), so that there the rows are
    // (7) and (8) with unit normals and a valid fold stays where it is (measured: Solve moved
    // fig6, lifted 60 mm keeping lengths and saved, by 18 % of its diameter; with SolveSession's
    // relative fairness for nearly valid starts now 3.4e-6). false:
    // weights 1. SolveSession uses false while something is pulled: over a drag the lengths at
    // its start go stale, and measured with them fig6 lifted keeping lengths lost its crease's
    // bow (12 of 30 mm, against 33 with weights 1); weighed again before every iteration the
    // weights feed back into the lengths, and a valid fold without pins drifted away
    // (residual 3e-13, 1e-8, 1e-2 over five iterations).
    bool weighCreaseNormals = true;
    double unitControlNormalWeight = 0.1;

    // R-edges between two faces across which the unit normals must agree (smooth transition),
    // in addition to those the surface marks smooth (model::EdgeRecord::smooth).
    std::vector<model::EdgeId> smoothRulings;

    // Vertex developability (docs/math.md §7): at every interior vertex where a crease meets,
    // the angles between consecutive edges sum to 2π, through a flat copy of the star of its
    // edges' tangent points (see addVertexDevelopability). The rows vanish on an exactly
    // developable design, so valid designs stay put with it (tst_vertex_developability). Off by
    // default: measured on the examples from 0.1 % noise (tst_formulation, ε₂ = 1e-3, 10
    // iterations) it kept det at 1e-8 … 6e-4 instead of ≤ 1e-8 (weight 1; 0.1 and 0.01 did not
    // help), the rough annulus ended at det 1.7e-2 instead of ≤ 1e-6, and a star lifted to an
    // angle defect of 0.05 needs ε₂ = 1e-3 (10 iterations: defect 4e-12) or 30 iterations at
    // ε₂ = 0.01 (4e-15; 10 iterations: 0.8). SolveSession turns it on (with the limits below,
    // see defaultSessionFormulationOptions).
    bool vertexDevelopability = false;
    double vertexDevelopabilityWeight = 1.0;
    // Every spoke of such a star (from the vertex to its edge's tangent point) stays at least
    // this fraction of its start length (a one-sided guard, inactive while satisfied; 0: none).
    // Without it the iteration closed a lifted star by shrinking one spoke to a point (defect
    // 1e-2 left, measured by the angles of the control points).
    double vertexSpokeGuard = 0.5;
    // Where a crease passes through such a star almost straight (a four-spoke star whose two
    // S-edge spokes leave the vertex within this angle, in radians, of opposite directions at
    // the start), the crease is made tangent-continuous there (G¹, see
    // addVertexDevelopability) instead of the star's flat copy; that implies the angle sum 2π.
    // Measured on the scripted Fig. 8 lift (SolveSession, 20 moves + 10 iterations; the
    // example's creases then kinked by 0.026 rad at its four crease vertices, now they are
    // tangent-continuous there, so Solve leaves the flat example put): with flat copies the
    // drag did not converge (residual 0.36, defect 2.5e-2 … 2.5 rad; with the session's final
    // ε₁ det 3e-14, defect 1e-13, but rulings at 3 % of their start length); with tangent
    // continuity det 5e-15, defect 0, rulings 0.78. 0.05 stays below the annulus example's
    // kinks (0.087 rad; the cylinder's are 0.175), which it keeps through flat copies: valid
    // designs stay put. 0: flat copies everywhere.
    double vertexSmoothCreaseAngle = 0.05;
    // Only stars whose angle defect at the start is at most this (radians) get rows (the
    // others keep rows scaled to zero): vertex developability is then kept where it holds
    // rather than imposed on a rough start. See defaultSessionFormulationOptions for measured
    // values; the default imposes it everywhere.
    double vertexStartDefectLimit = 1e9;

    std::vector<VertexHandle> handles;
    std::vector<ControlPointHandle> controlPointHandles;
    // 0: the control-point handles are constraints, as the vertex handles are. Above 0: an
    // energy of this weight (times ε₁, family "creaseHandles") that the iteration follows as
    // far as the conditions let it, for a dragged crease whose every control point is pulled
    // (see creaseDragSessionOptions).
    double controlPointHandleWeight = 0.0;
};

// The configuration for rough starts (a design dragged far, a noisy import): proximity to the
// start (Options::proximityFactor 1, threshold 1e-2), rows of (4) normalised to angles
// (normalizedRows), ε₂ floor 3e-4, ruling and speed guards (0.3, 0.15, weight 0.1). Measured over
// 10 seeds, 10 iterations, three boundary vertices fixed: det worst, paper's configuration → this
// one (in brackets: worst shortest ruling and slowest speed relative to the start, paper's → this
// one):
//   10 % of the mean edge length
//     sheet     2.8e-4 → 1.2e-7  (0.65 → 0.95, 0.62 → 0.70)
//     annulus   0.15   → 2.4e-7  (0.00 → 0.66, 0.00 → 0.67)
//     cylinder  5.2e-4 → 2.2e-7  (0.69 → 0.90, 0.85 → 0.84)
//     mixed     2.6e-6 → 7.0e-8  (0.47 → 0.82, 0.32 → 0.59)
//   1 % of the diameter
//     sheet     6.6e-3 → 6.2e-7  (0.00 → 0.92, 0.05 → 0.27)
//     annulus   0.98   → 1.9e-2  (0.00 → 0.30, 0.00 → 0.03)
//     cylinder  1.2e-3 → 5.2e-7  (0.43 → 0.90, 0.78 → 0.83)
//     mixed     3.9e-6 → 8.1e-8  (0.37 → 0.83, 0.30 → 0.59)
// and crease folds over the start's noise angle at most 0.20 (paper's: up to 13.5). The
// guards act only on the annulus from 1 %: without them 5.5e-3 (0.005, 0.015). From
// 0.1 % of the diameter (4 seeds) it ends at 3e-9 / 5e-9 / 3e-8 / 1e-16 on the four examples,
// where the paper's configuration with the same ε₂ = 0.01 ends at 6e-6 / 2e-3 / 7e-5 / 3e-16.
// Not the default: with ε₂ = 1e-3, which tst_formulation uses from 0.1 %, the paper's
// configuration reaches 2e-11 … 5e-15 there (the cylinder by shrinking its rulings to 31 %)
// but this one only 2.6e-4 on the cylinder; with ε₂ = 1e-3 the paper's configuration
// degenerates on every rough start above (det up to 1, rulings at 0).
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
    // Multiplies the weight of that energy (or damping) by `factor` (nothing without it).
    void scaleIsometryWeight(double factor);
    // Multiplies the weights of a drag's energies by `factor`: the control-point handles'
    // (controlPointHandleWeight) and the pull towards the reference state where it is an
    // energy (proximityEnergyWeight); from now on ε₁ follows the constraint residual alone.
    // Nothing without them.
    void fadeDragEnergies(double factor);
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

    // Writes the vertices and control points of state x into `surface` (which must have the
    // combinatorics of the formulated surface). Refuses a state of the wrong size or with a
    // non-finite value: `surface` is then untouched and `error` says why. Coordinates that
    // the solver did not change are restored bit for bit.
    bool writeBack(const std::vector<double>& x, model::CompositeSurface& surface,
                   std::string* error = nullptr) const;

    // Model coordinates of a coarse vertex in state x.
    model::Vec3 vertexPosition(const std::vector<double>& x, model::VertexId vertex) const;

    int stripCount() const { return m_stripCount; }
    int coneCount() const { return m_coneCount; }
    int planarFaceCount() const { return m_planarCount; }
    int pointCount() const { return m_pointCount; }
    double scale() const { return m_scale; }

    // Scales the unit normals of planar faces and cones and the osculating normals of
    // "straight when unfolded" to unit length at x. Every other row of those normals is
    // homogeneous in them, so this satisfies the unit rows exactly and leaves the others'
    // zeros; the step's second-order error in the unit rows (|δn|²) is gone. (The strips'
    // normal splines are left alone: their rows mix both sides of a crease, and normalised
    // they made rough starts worse, the sheet from 10 % edge noise 4e-16 → 8e-6.)
    void normaliseUnitNormals(double* x) const;

private:
    struct Builder;
    // Fixes the fixed vertex handles and adds the rows of the pulled ones to `handles`, those
    // of the control-point handles to `controlPointHandles` (throws std::invalid_argument for
    // a handle on something the surface does not have).
    void addHandles(TargetTerm& handles, TargetTerm& controlPointHandles);
    int pointOffset(int point) const { return m_pointsOffset + 3 * point; }
    model::Vec3 toModel(const double* p) const;

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
    FamilyId m_proximityEnergy = -1;           // the pull towards the reference, as an energy
    TargetTerm* m_proximity = nullptr;         // every point towards the reference state
    TargetTerm* m_normalProximity = nullptr;   // every control normal towards the reference state
    int m_normalControlsOffset = 0;
    FairnessTerm* m_pointFairness = nullptr;
    FairnessTerm* m_normalFairness = nullptr;
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
};

} // namespace devsurf::solver
