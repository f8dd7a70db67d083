#pragma once

#include "solver/core/guided_projection.h"
#include "solver/core/options.h"
#include "solver/core/summary.h"
#include "solver/formulation/surface_formulation.h"

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace devsurf::solver {

// The damping ε₂ of interactive solving and of the command line (one iteration per call).
Options defaultSessionSolverOptions();
// The formulation of interactive solving and of the command line: vertex developability on
// (FormulationOptions::vertexDevelopability; with defaultSessionSolverOptions it takes the
// scripted Fig. 8 lift to an angle defect of 0 at its crease vertices instead of 4e-2 rad) at
// the stars where it holds at the start (vertexStartDefectLimit 1e-6 rad).
FormulationOptions defaultSessionFormulationOptions();

// A start whose sampled developability residual and crease-condition residual (measureQuality,
// measureCreaseQuality) are at most kNearlyValidResidual: a design that satisfies its
// conditions up to a small error, such as the end of a drag, not a rough start. Invalid
// surfaces are not.
constexpr double kNearlyValidResidual = 1e-6;
bool nearlyValid(const model::CompositeSurface& surface);

// FormulationOptions::controlSpacingUnit of every session: a design whose control polygons are
// finer than 0.035 of its diameter is regularised as if they were that coarse. 0.035 lies just
// below the finest example (the annulus, 0.039), so the examples are solved exactly as before.
// Measured with devsurf-bench --study large-annulus --session (the annulus of size 30, control
// segments 0.0078 of the diameter; 10 seeds) from 10 % edge noise, diameter as unit → this:
// det worst 2.2e-4 after 20 iterations (3 seeds), rulings 0.000, every development
// overlapping → 8.1e-12 (1.7e-7 after 10), rulings 0.69, speeds 0.55, none overlapping. (With
// the linear start normals of noisy strips, kNoisyStartNormals, and the floor a failed
// factorisation leaves on ε₂ at twice the failed value: median 9.8e-14, worst 1.9e-13.)
// From 1 % of its diameter (noise 1.3 times its control spacing) it crumples either way.
constexpr double kSessionControlSpacingUnit = 0.035;

// FormulationOptions::vertexStartDefectLimit of a session in which nothing is pulled and whose
// start is nearlyValid (Tools ▸ Solve of a valid design): only stars that hold to this are
// imposed. At a nearly flat vertex the angle sum is stationary, so its rows have almost no
// Jacobian, and closing a star with a defect near the sessions' 1e-6 rad took steps of a tenth
// of the diameter: Solve of the annulus that Solve had just made developable from 0.1 % noise
// (det 5e-15, one star at 1.3e-6 rad) alternated for 30 iterations between 1e-6 and 0.5.
// With this limit it converges in one iteration.
constexpr double kValidSolveStarDefectLimit = 1e-9;

// Options::proximityFactor and proximityThreshold of a session in which nothing is pulled and
// whose start is not nearlyValid (a Solve after a vertex was moved by hand, of a noisy import):
// the pull of every point towards the start, fading as the constraints converge, leads the
// iteration to a developable surface near the start instead of a distant, crumpled one.
// Measured with devsurf-cli solve (10 iterations, no pins, 10 seeds of Gaussian noise; det
// worst, seeds whose development overlaps itself, seeds folding over), without → with it:
//   sheet 1 % of the diameter   8.7e-4, 5, 4    → 3.1e-5, 0, 0
//   annulus 0.1 %               1.0, 2, 2       → 1.0e-14, 0, 0
//   annulus 1 %                 0.76, 10, 10    → 1.3e-3, 6, 6
//   cylinder 0.1 %              2.8e-5, 2, 0    → 1.6e-15, 0, 0
//   cylinder 1 %                1.6e-3, 8, 3    → 2.6e-8, 0, 0
//   mixed 1 %                   2.7e-5, 5, 1    → 1.5e-5, 0, 0
// (the sheet and mixed from 0.1 % reach 3e-16 … 1e-11 either way). An annulus vertex lifted
// 30 mm by hand and solved: residual 1.8 with rulings at 0.05 of their length, 3 fold-overs,
// the development overlapping itself and 112 mm moved → 3e-2 with rulings at 0.65, none of
// those, 30 mm moved (the vertex goes most of the way back; a second Solve: 3e-8). Factors 0.5
// and 1 (threshold 1e-2) left worse worst cases (det 7e-4 and 6e-3 on the annulus from 1 %),
// 3 and 10 held the start too firmly (up to 0.95); with the threshold 1e-2 the pull slowed the
// last iterations (a perturbed curved fold, tst_crease_conditions, ended at 3e-4 instead of
// 2e-14 after 10).
constexpr double kRoughSolveProximity = 0.3;
constexpr double kRoughSolveProximityThreshold = 0.1;

// FormulationOptions::lengthDampingWeight of the same sessions (a rough start, nothing pulled):
// a step changes a length of a strip's control net (polygons, rungs, diagonals) as reluctantly
// as ε₂ makes it move a variable by as much, times this weight. The long first steps then bend
// the net rather than stretch it, and the iteration does not drift within the plane of a nearly
// flat result: without it, once the pull towards the start had faded, fairness drew the control
// points of a nearly flat sheet along their curves (speeds down to 0.03) and let the annulus's
// rulings collapse. Once the largest constraint residual first falls to
// kRoughSolveLengthDampingUntil the weight is multiplied by kRoughSolveLengthDampingFade before
// every further iteration, so the last iterations converge nearly as fast as without it.
// Measured with devsurf-bench --study MODEL --session (10 seeds, 10 iterations, three boundary
// vertices fixed; worst det, shortest ruling and slowest speed relative to the start, mean
// crease fold over the start's normal angles), without → with:
//   sheet, 1 % of the diameter     5.1e-6, 0.89, 0.031, 0.27 → 7.4e-13, 0.88, 0.59, 0.10
//   annulus, 10 % of an edge       1.6e-13, 0.10, 0.53, 0.19 → 2.2e-13, 0.70, 0.59, 0.10
//   annulus, 1 % of the diameter   2.4e-4, 0.001, 0.40, 0.75 → 3.8e-4, 0.34, 0.41, 0.07
//                                  (seeds overlapping in the development: 7 → 1; after 30
//                                  iterations, as Tools ▸ Solve runs: 1.2e-14, 0.34)
//   fig13, 10 % / 1 %              fold over start 1.20 / 1.14 → 0.45 / 0.40
//   cylinder, 1 %                  det 2e-15 → 2e-10 (10 %: 3e-11; mixed, fig6, fig8 ≤ 3e-12)
// and the curved fold of tst_crease_conditions from 1 % (20 seeds): 4 seeds above 1e-8 (worst
// 1.3e-6) → none (worst 2.6e-9). Stopping the damping at once instead of fading it: the annulus
// from 1 % at 7.9e-5 after 10 iterations but rulings at 0.015 and 2 seeds overlapping, and
// after 30 one seed at 4e-7 with a ruling of length 0.000; fading by 0.3: rulings at 0.11.
// With that stop, weights 3, 15, 20, 30 left the sheet from 1 % at 5e-6 (3), the annulus from
// 1 % at 2.7e-5, 1.7e-3, 1.8e-3, 1.0e-4, and the curved fold from 1 % with 3, 0, 0 and 16
// seeds above 1e-8; a limit of 3e-4 or 3e-3 instead of 1e-3 changed little. Measured before
// the rows were scaled to lengths: the same rows as an energy (weighted by ε₁, never stopped)
// left the annulus from 1 % at 1e-3 with curve speeds at 0.01.
constexpr double kRoughSolveLengthDamping = 10.0;
constexpr double kRoughSolveLengthDampingUntil = 1e-3;
constexpr double kRoughSolveLengthDampingFade = 0.5;

// FormulationOptions::isometryWeight of a drag that keeps lengths (the desktop application's
// Tools ▸ Lengths While Dragging ▸ Keep Lengths, `devsurf-cli drag --keep-lengths`): the sheet
// bends instead of stretching. Measured (20 moves, 10 iterations after): lifting the annulus's
// inner vertex 0 by 100 mm with its outer rim pinned ends at a constraint residual of 2e-6,
// angle defects 6e-8 rad, rulings at 0.97 of their start length (without: 2.4, 3.4 rad,
// 0.06); a 1 mm lift of fig6's vertex 2 turns the sheet about its pinned edge (the far
// corners move 1.0 and 2.0 mm; without: 16–20 mm, the curved crease pulled straight). Held
// at this weight it stalls where the net must give a little (the lifted Fig. 8 at a residual
// of 1e-4 with curved creases folded 45°), hence kKeepLengthsFade after the release; a
// dragged crease would no longer reach the mouse. 10: annulus residual 3e-5; 100: 9e-5 and
// the handles 0.08 mm short (both without the fade).
constexpr double kKeepLengthsWeight = 30.0;
// The factor by which that weight shrinks with every iteration once a drag is released
// (SolveSession::settle()), so that the conditions converge exactly where the net had to give
// a little. Measured (20 moves, then 10 and 20 iterations): the lifted Fig. 8 at a residual of
// 1.7e-5 and 1.1e-7 with its creases still curved (0.3: 6e-4, 1e-5; no fade: 4e-4 for ever);
// the annulus at 1e-14; fig6 folded 67° at 1e-11.
//
// What limits the lifted Fig. 8: after the release its residual alternates between iterates
// some 1000× apart (2e-6, 8e-3, 4e-7, 5e-3, 5e-8, 5e-5, …). The large steps come where ε₂ has
// followed a small residual down (clamp(r, 1e-6, 1e-3)); they are gone with vertex
// developability off (2e-10 after 20, but the sheet does not fold: 1.5°) and remain with
// ε₁ = 0 after the schedule. Measured and not better (after 10 / 20 iterations): a floor
// under the faded weight (0.3 … 10: 1.4e-5 … 1.1e-4 / 1.3e-6 with 1); ε₂ floors of 1e-5 or
// 1e-4, or ε₂ = 10 r or 100 r (still alternating, or linear at 5e-6 … 7e-6 after 20); ε₂ ≥
// 10 r only while settling (residuals up to 0.9); Levenberg–Marquardt acceptance (stalls at
// 4e-6) or halving a step that raises the residual (stalls at 3e-4); the crease-vertex
// ratio λ frozen per iteration (still alternating); relative fairness (1e-3 and worse);
// ε₁ ≤ r while settling (1.5e-8 / 1e-8, but the curved-fold residual between collocation
// values rises to 1e-3 and curves slow to 0.35 of their mean speed); keeping the iterate of
// smallest residual (after 20 det 2.6e-6 against 5e-7 for the last iterate).
constexpr double kKeepLengthsFade = 0.5;

// Iterations after a vertex drag's release (the desktop application's Drag and Rotate tools,
// `devsurf-cli drag` without --after, the drag benchmark): 10, as the paper does; 20 when
// keeping lengths, whose energy fades over them (kKeepLengthsFade): the lifted Fig. 8 then
// reaches a residual of 1e-7 after 20 of them, 2e-5 after 10.
constexpr int kIterationsAfterDrag = 10;
constexpr int kIterationsAfterDragKeepingLengths = 20;
constexpr int iterationsAfterDrag(bool keepLengths) {
    return keepLengths ? kIterationsAfterDragKeepingLengths : kIterationsAfterDrag;
}

// Options::reuseFactorization while a drag moves (a session with pulled handles, until
// settle()) on a model whose factorisation takes at least kDragFactorizationReuseFlops: every
// other move solves with the factorisation of the move before, which costs the evaluation and
// the triangular solves only (the matrix changes little between moves); the iterations after
// the release factorise every time. Measured with devsurf-bench --drag on the annulus of size
// 14 (18,164 variables, 7.7e7 flops per factorisation): results applied per second 41 → 59,
// median 37 → 28 ms (2 and 3 reuses in a row: 76 and 80 per second); a step that reuses costs
// 2.7 ms against 9.4 ms on the sheet of size 12 (2.2e7 flops). The moves in between are less
// converged: lifting fig8's middle 85 mm in 20 moves, the residual after the moves that reuse
// was about 3× that after the others (after the 20 iterations that follow: 8e-16, without
// reuse 1e-14).
// Below the threshold drags are fast enough, and their delicate cases (a fold turned after a
// lift, tst_crease_conditions) end elsewhere when their moves reuse: fig8 (1.9e6 flops), fig6,
// the annulus of size 6 (6.7e6) factorise in every move.
constexpr int kDragFactorizationReuse = 1;
constexpr double kDragFactorizationReuseFlops = 1e7;

struct SessionOptions {
    // Its `handles` are extended by the session: every pinned vertex becomes a fixed handle,
    // every pulled vertex a pulled one.
    FormulationOptions formulation = defaultSessionFormulationOptions();
    // maxIterations, scheduleOffset, cancel and progress are ignored: step(n) decides.
    Options solver = defaultSessionSolverOptions();
    // step(n) ends early, with Status::Converged, after the first iteration whose largest
    // constraint residual is at most this (0: it always runs n iterations). Tools ▸ Solve uses
    // kSolveStopResidual.
    double stopResidual = 0.0;
};

// SessionOptions::stopResidual of Tools ▸ Solve, whose iterations (kSolveIterations by default)
// are then a limit rather than a count: a design that converges stops there, one that does not
// gets them all. Measured with devsurf-cli solve on the annulus shaken by 1 % of its diameter
// (10 seeds): after 10 iterations 4 of them were within 1e-8; given 30, 7 reached 1e-16 (the
// other 3 stopped before a ruling collapsed, see SolveSession::step), all 7 below 1e-12
// within 10 to 12 iterations. A valid design stops after one iteration.
constexpr double kSolveStopResidual = 1e-12;
constexpr int kSolveIterations = 30;

// The options of a drag that keeps lengths: the isometry energy at kKeepLengthsWeight, and
// neither fairness of the points nor of the normals next to creases with a condition, which
// pull curves straight and strips flat (see FormulationOptions::
// normalFairnessAtCreaseConditions); the isometry energy is the regularisation instead.
// Measured on the lifted Fig. 8 after 20 moves and 20 iterations: with the point fairness
// (0.1) the creases ended straight (bow 0.0 mm), without it they keep bows of 2–8 mm and fold
// 46°; the annulus with its outer rim pinned reaches 1e-14 instead of 3e-7.
SessionOptions keepLengthsSessionOptions();

// The energies of a crease drag (creaseDragSessionOptions) and the factor by which their
// weights shrink before every iteration after the release. A crease drag pulls its interior
// control points and its unpinned ends (CreaseDrag). Held at every control point, a curved
// crease of a folded design fixes a cubic boundary of both its strips, and each strip's other
// curve has fewer free coordinates than (4) has rows on it: as constraints, the handles and the
// conditions met at a least-squares compromise. So the ends stay constraints and the interior
// points are an energy (FormulationOptions::controlPointHandleWeight) that follows the mouse
// while the drag moves, together with a weak pull of every point towards the press
// (proximityEnergyWeight) that keeps the rest of the design where it was; after the release
// both let go and the conditions converge where the crease can be.
constexpr double kCreaseDragPointWeight = 1.0;
constexpr double kCreaseDragStartPull = 0.03;
constexpr double kCreaseDragFade = 0.5;

// The options of a crease drag (the Drag tool on a crease, `devsurf-cli drag --crease`): the
// energies above and, as when keeping lengths, neither fairness of the points nor of the
// normals next to creases with a condition, which pulled a folded crease straight and fought
// the handles (absolute fairness 0.1: fig8's crease 6 slid 15 mm ended at 7e-2 with curve
// speeds at 0.03; normal fairness: the folds relaxed from 46° to 22°). Measured with
// devsurf-cli drag --crease (20 moves, 10 iterations) on fig6 folded 15° (its free edge lifted
// 60 mm keeping lengths) and fig8 lifted 85 mm keeping lengths (the README picture):
//   fig6, crease slid 15 mm   residual 3.0e-4 for ever, det 4.6e-3 → 1.2e-12, fold kept (15.3°)
//   fig8, crease 6 slid 15 mm residual alternating 1.6e-4 ↔ 0.5 (the spoke guard), det 4.7e-3,
//                             57 mm moved after the release → 2.4e-8, det 1.3e-6, fold 49°
//   fig8, creases 2, 6 (±15 and 30 mm), 14: residuals 2.4e-8 … 2.2e-7, crease rows ≤ 7.4e-7,
//                             folds 46° … 54° (46° before), rulings ≥ 0.82 of their length
//   flat fig6, fig8, sheet    residual ≤ 4e-16 as before, the crease within 0.014 mm of the
//                             mouse, curve speeds 0.99 of their start instead of 0.4 (fairness
//                             slid the control points along the curves)
// Without the pull towards the press the iterations after the release let the free boundary
// curves of fig8 (two pinned corners) wander: one bent by 70 mm where it bends by 7 mm with it
// (0.01: 21 mm; 0.1: stalls at 2e-4); fading it faster than the handles (0.25, 0.1) let them
// wander again (17 and 28 mm). Relative fairness instead kept fig8's curves (4 mm) but let
// fig6's free strip swing open (fold 15° → 4°); the isometry energy (0.3) moved the far strip of
// a flat sheet rather than shrink it (curve speeds 0.07).
SessionOptions creaseDragSessionOptions();

// One surface being solved across calls: the formulation, the state vector and the
// GuidedProjection (with its cached structure and factorisation choice) stay alive between
// step() calls, so a drag's mouse moves and the iterations after release continue one solve.
// This is the one solve loop of the product: the command line's `solve` and `drag` and the
// desktop application's worker all run it.
//
// Not thread-safe; one thread at a time.
class SolveSession {
public:
    // Every pinned vertex of `surface` (CompositeSurface::pinnedVertices()) becomes a fixed
    // handle; `pulled` adds handles pulled towards a target (VertexHandle{v, false, target}).
    // A pinned vertex stays fixed even if it is also pulled. Throws std::invalid_argument with
    // a sentence if the surface cannot be solved (invalid, a non-finite coordinate, an unknown
    // or non-finite handle).
    SolveSession(const model::CompositeSurface& surface, const std::vector<VertexHandle>& pulled,
                 const SessionOptions& options = {});
    // The same with interior control points of S-edges pulled too (a dragged crease). Throws
    // std::invalid_argument for a control point that does not exist or a non-finite target.
    SolveSession(const model::CompositeSurface& surface, const std::vector<VertexHandle>& pulled,
                 const std::vector<ControlPointHandle>& pulledControlPoints,
                 const SessionOptions& options = {});
    SolveSession(const SolveSession&) = delete;
    SolveSession& operator=(const SolveSession&) = delete;
    ~SolveSession();

    // The drag is released: from now on every iteration multiplies the weight of the
    // keep-lengths energy (if any) by kKeepLengthsFade. Idempotent.
    void settle() { m_settling = true; }

    // Moves a pulled handle's target (model coordinates); false if the vertex is not pulled
    // or the target is not finite.
    bool setHandleTarget(model::VertexId vertex, const model::Vec3& target);
    // The same for a pulled control point.
    bool setControlPointTarget(model::EdgeId edge, int index, const model::Vec3& target);

    // Runs n iterations continuing the ε₁ schedule where the last call stopped; writes the
    // result into surface(). step(1) ten times equals step(10) bit for bit. `cancel` is
    // checked between iterations; `perIteration` is called after each (on this thread, with
    // IterationStats::iteration counted within this call). A failed or cancelled iteration
    // leaves surface() at the last good state.
    Summary step(int n, const std::atomic<bool>* cancel = nullptr,
                 const std::function<void(const IterationStats&)>& perIteration = {});

    const model::CompositeSurface& surface() const { return m_surface; }
    const SurfaceFormulation& formulation() const { return *m_formulation; }
    // The solver's state (normalised coordinates, see SurfaceFormulation).
    const std::vector<double>& state() const { return m_x; }
    // Iterations completed over all step() calls (the position in the ε₁ schedule).
    int iterationsDone() const { return m_iterationsDone; }
    // The pulled vertices (pinned ones excluded).
    const std::vector<model::VertexId>& pulledVertices() const { return m_pulled; }

    // Faces worst first at the current state (SurfaceFormulation::faceResiduals).
    std::vector<SurfaceFormulation::FaceResidual> worstFaces() const;

    // A Solve (nothing pulled) remembers, over all step() calls, the iterate whose largest
    // constraint residual was the smallest. If the current iterate's is larger, this goes back
    // to that one (state and surface()) and returns its iteration (counted from 1 over all
    // calls) and residual; otherwise, and in a drag, it stays and returns {0, residual}. With
    // `summary` (of the last step()), its final residual and toleranceReached follow the
    // iterate returned to.
    // Measured: Solve of the lifted Fig. 8 kept at its lengths cycles between 2.6e-8,
    // 1.7e-6 and 1.8e-6, so where it ended depended on the iteration count (10 iterations:
    // sampled det 1.3e-6 from 6.6e-7; 30: 6.3e-7).
    struct BestIterate {
        int iteration = 0;
        double residual = 0.0;
    };
    BestIterate returnToBestIterate(Summary* summary = nullptr);

private:
    SessionOptions m_options;
    model::CompositeSurface m_surface;
    std::unique_ptr<SurfaceFormulation> m_formulation;
    GuidedProjection m_projection;
    std::vector<double> m_x;
    std::vector<model::VertexId> m_pulled;
    int m_iterationsDone = 0;
    bool m_dragging = false; // something is pulled
    bool m_settling = false;
    bool m_lengthDampingFades = false; // the residual has fallen to kRoughSolveLengthDampingUntil
    double m_residual = std::numeric_limits<double>::infinity(); // at the last iterate
    // The iterate of smallest residual of a Solve (returnToBestIterate).
    std::vector<double> m_bestX;
    double m_bestResidual = std::numeric_limits<double>::infinity();
    int m_bestIteration = 0;
};

} // namespace devsurf::solver
