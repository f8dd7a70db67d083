#pragma once

#include "solver/core/guided_projection.h"
#include "solver/core/options.h"
#include "solver/core/summary.h"
#include "solver/formulation/surface_formulation.h"

#include <atomic>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace devsurf::solver {

// The damping ε₂ of interactive solving and of the command line (one iteration per call).
Options defaultSessionSolverOptions();
// The formulation of every session: vertex developability on at the stars where it holds at
// the start (FormulationOptions::vertexStartDefectLimit 1e-6 rad).
FormulationOptions defaultSessionFormulationOptions();

// A start whose sampled developability and crease-condition residuals are at most this: a design
// that satisfies its conditions up to a small error (the end of a drag), not a rough start
// (docs/tuning.md).
constexpr double kNearlyValidResidual = 1e-4;
bool nearlyValid(const model::CompositeSurface& surface);

// FormulationOptions::controlSpacingUnit of every session: a design whose control polygons are
// finer than this fraction of its diameter is regularised as if they were that coarse (just
// below the finest example, the annulus at 0.039). Measurements: docs/tuning.md.
constexpr double kSessionControlSpacingUnit = 0.035;

// FormulationOptions::vertexStartDefectLimit of a Solve of a nearly valid design: only stars
// that hold to this are imposed (a nearly flat star has almost no Jacobian, and closing it took
// huge steps).
constexpr double kValidSolveStarDefectLimit = 1e-9;

// A Solve of a rough start pulls every point towards where it was (Options::proximityFactor,
// proximityThreshold), fading as the constraints converge, so the result stays near the design.
constexpr double kRoughSolveProximity = 0.3;
constexpr double kRoughSolveProximityThreshold = 0.1;

// The same Solve damps changes of the control nets' lengths (FormulationOptions::
// lengthDampingWeight) so that the first long steps bend rather than stretch; once the largest
// residual first falls to kRoughSolveLengthDampingUntil the weight fades by
// kRoughSolveLengthDampingFade per iteration.
constexpr double kRoughSolveLengthDamping = 10.0;
constexpr double kRoughSolveLengthDampingUntil = 1e-3;
constexpr double kRoughSolveLengthDampingFade = 0.5;

// FormulationOptions::isometryWeight of a drag that keeps lengths (the sheet bends instead of
// stretching), and the factor by which it shrinks per iteration after the release so that the
// conditions converge where the net had to give a little.
constexpr double kKeepLengthsWeight = 30.0;
constexpr double kKeepLengthsFade = 0.5;

// Iterations after a vertex drag's release (a limit: they stop once settled): 10 as the paper
// does, 20 when keeping lengths, whose energy fades over them, 60 when the surface holds its
// sheet, whose low-weight development pulls the last digits in slowly (docs/tuning.md).
constexpr int kIterationsAfterDrag = 10;
constexpr int kIterationsAfterDragKeepingLengths = 20;
constexpr int kIterationsAfterDragHoldingSheet = 60;
constexpr int iterationsAfterDrag(bool keepLengths, bool holdsSheet = false) {
    return holdsSheet    ? kIterationsAfterDragHoldingSheet
           : keepLengths ? kIterationsAfterDragKeepingLengths
                         : kIterationsAfterDrag;
}

// Options::reuseFactorization while a drag moves on a model whose factorisation takes at least
// kDragFactorizationReuseFlops: up to five moves in a row (step(1) calls) solve with an earlier
// move's factorisation, and a step that such a reuse throws off is undone and factorised afresh
// (Options::reusedStepMeritRise); the iterations after the release factorise every time.
constexpr int kDragFactorizationReuse = 5;
// And up to five more while the next factorisation is being made beside, instead of making one
// in the worker (docs/tuning.md, "More chord steps while the next factorisation is made").
constexpr int kDragReuseWhileFactorizingBeside = 5;
constexpr double kDragFactorizationReuseFlops = 1e7;
constexpr double kDragReusedStepMeritRise = 100.0;

// A move of a drag on a surface that holds its sheet, whose pulled points jump farther than
// kMoveStepLimit × the surface's diameter since the last move, is split into as many iterations
// (at most kMoveSplitLimit), their targets evenly along the jump: one linearised step that long
// can fold a thin part over, which the held sheet then keeps (docs/tuning.md).
constexpr double kMoveStepLimit = 0.003;
constexpr int kMoveSplitLimit = 8;
// On a model of more than kLargeMoveVariables variables a move is not split: split moves there
// fell behind the mouse, and the next move's jump grew longer still (docs/tuning.md).
constexpr int kLargeMoveVariables = 15000;

// The pull of a dragged vertex of a surface that holds its sheet (pulledHandleWeight); the lag
// does not depend on it (docs/tuning.md, "Holding the sheet").
constexpr double kSheetPullWeight = 1.0;

// A drag's settling after its release (settle(true)) whose largest constraint residual stays
// above kHopelessSettlingResidual for kHopelessSettlingIterations iterations in a row stops there
// (SolveSession::gaveUp), so that a drag too far reaches its second settling and its partway
// search sooner (docs/tuning.md).
constexpr double kHopelessSettlingResidual = 1e-2;
constexpr int kHopelessSettlingIterations = 4;
// On a held sheet a settling can rise that high and still converge (one rose to 0.019 … 0.5 for
// six iterations, then to 1e-15), so there it is hopeless once above kHopelessHeldSettlingResidual
// for kHopelessHeldSettlingIterations iterations in a row (docs/tuning.md).
constexpr double kHopelessHeldSettlingResidual = 0.1;
constexpr int kHopelessHeldSettlingIterations = 6;

// A settling on a held sheet can stall: its residual wanders within a band it no longer leaves
// (fig12 dragged: between 3e-6 and 2e-5 for 45 of its 60 iterations). It stops, as if at its
// iteration limit, once kStalledSettlingIterations iterations in a row all stayed within
// kStalledSettlingResidual, their best not below half the best before them and their median
// not below half that of the iterations before them, at an iterate no worse than that median
// (docs/tuning.md, "A stalled held settling stops").
constexpr int kStalledSettlingIterations = 12;
constexpr double kStalledSettlingResidual = 1e-4; // kDragConvergedResidual (drag_lengths.h)

// An approximation (§4.2) runs its iterations with eqs. (9)–(11) at their weights; from
// SessionOptions::approximationFadeAfter on, every iteration multiplies those weights by
// kApproximationFade, so that the hard conditions converge exactly at the end while the surface
// stays where the target pulled it.
constexpr double kApproximationFade = 0.3;
constexpr int kApproximationFadeIterations = 10;

// The damped recipe of an approximation, for a target that a developable strip cannot follow
// closely (a doubly curved part of a scan): eqs. (9)–(11) at kDampedApproximationWeightScale of
// their weights, and ε₂ at least kDampedApproximationEps2 while they pull, fading by
// kApproximationFade with them (SessionOptions::approximationDamping). It converges only
// linearly, so the solve job runs it only where the usual pull failed (docs/tuning.md).
constexpr double kDampedApproximationWeightScale = 0.01;
constexpr double kDampedApproximationEps2 = 1.0;

struct SessionOptions {
    // Its `handles` are extended by the session: every pinned vertex becomes a fixed handle,
    // every pulled vertex a pulled one.
    FormulationOptions formulation = defaultSessionFormulationOptions();
    // maxIterations, scheduleOffset, cancel and progress are ignored: step(n) decides.
    Options solver = defaultSessionSolverOptions();
    // step(n) ends early, with Status::Converged, after the first iteration whose largest
    // constraint residual is at most this (0: it always runs n iterations).
    double stopResidual = 0.0;
    // With FormulationOptions::approximation: the iterations (over all step() calls) after
    // which the approximation weights fade (kApproximationFade); negative: never.
    int approximationFadeAfter = -1;
    // With FormulationOptions::approximation: the floor of ε₂ while the target pulls, fading
    // with it (0: none; kDampedApproximationEps2).
    double approximationDamping = 0.0;
    // After settle(): the keep-lengths energy fades (kKeepLengthsFade) only after iterations
    // whose residual did not rise, so that it fades more slowly where the iterates alternate
    // (a drag's second settling, docs/tuning.md "Settled again").
    bool holdFadeWhileResidualRises = false;
    // After settle(): the pulls of places in the held sheet fade as well (kCreaseDragFade), as
    // the partway search needs; a release keeps them at the mouse (docs/tuning.md).
    bool fadeSheetPulls = false;
    // A drag's moves (step(1) before settle()) factorise on another thread beside their steps
    // (Options::backgroundFactorization), on a model whose factorisation takes at least
    // kDragFactorizationReuseFlops.
    bool backgroundFactorization = false;
    // After settle(), on a surface that holds its sheet, each iteration holds the guards (the
    // spokes of crease vertices' stars, rulings, curve speeds) that its linear step would cross
    // at their bounds and makes the step again (Options::engageCrossedGuards). Without, a guard
    // pulled through in one step and pushed back in the next makes the settling swing until the
    // move is taken back (fig8's held 30° turn; docs/tuning.md, "Guards held in a settling").
    // Off only to study the settlings that swing without it.
    bool engageCrossedGuards = true;
};

// A settling on a held sheet within kSolveStopResidual stops once its distance from its sheet
// (model::keptSheetStretch) falls by less than this factor in an iteration.
constexpr double kSettledStretchRatio = 0.99;

// A Solve stops once its largest residual is at most kSolveStopResidual; its iterations
// (kSolveIterations unless the user sets another count) are a limit.
constexpr double kSolveStopResidual = 1e-12;
constexpr int kSolveIterations = 30;

// The options of a drag that keeps lengths: the isometry energy at kKeepLengthsWeight instead of
// the fairness of points and of normals next to creases with a condition, which pull curves
// straight and strips flat.
SessionOptions keepLengthsSessionOptions();

// A crease drag pulls its unpinned ends as constraints and its interior control points as an
// energy (kCreaseDragPointWeight) with a weak pull of every point towards the press
// (kCreaseDragStartPull); after the release both fade by kCreaseDragFade per iteration.
constexpr double kCreaseDragPointWeight = 1.0;
constexpr double kCreaseDragStartPull = 0.03;
constexpr double kCreaseDragFade = 0.5;

// The options of a crease drag: the energies above, no fairness next to crease conditions.
SessionOptions creaseDragSessionOptions();

// One surface being solved across calls: the formulation, the state vector and the
// GuidedProjection (with its cached structure and factorisation choice) stay alive between
// step() calls, so a drag's mouse moves and the iterations after release continue one solve.
// SolveJob runs it for the command line and the desktop application alike.
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
    // The same with interior control points of S-edges pulled too (a dragged crease).
    SolveSession(const model::CompositeSurface& surface, const std::vector<VertexHandle>& pulled,
                 const std::vector<ControlPointHandle>& pulledControlPoints,
                 const SessionOptions& options = {});
    SolveSession(const SolveSession&) = delete;
    SolveSession& operator=(const SolveSession&) = delete;
    ~SolveSession();

    // The drag is released: every iteration fades the keep-lengths energy (kKeepLengthsFade),
    // and step() stops (Converged) once settled: within kSolveStopResidual, on a held sheet
    // also no longer nearing it (kSettledStretchRatio). Idempotent. With `giveUpWhenHopeless`
    // it stops once the settling is hopeless (gaveUp()).
    void settle(bool giveUpWhenHopeless = false) {
        m_settling = true;
        m_giveUpWhenHopeless = giveUpWhenHopeless;
    }

    // Moves a pulled handle's target (model coordinates); false if the vertex is not pulled
    // or the target is not finite.
    bool setHandleTarget(model::VertexId vertex, const model::Vec3& target);
    // The same for a pulled control point.
    bool setControlPointTarget(model::EdgeId edge, int index, const model::Vec3& target);
    // The same for a vertex's place in the held sheet (SessionOptions::formulation.
    // sheetHandles; mm, in the coordinates of the kept development).
    bool setSheetHandleTarget(model::VertexId vertex, const model::Vec2& target);

    // Runs n iterations continuing the ε₁ schedule (step(1) ten times equals step(10) bit for
    // bit); writes the result into surface(). A long
    // move of a drag first runs iterations of its own along the way (kMoveStepLimit), counted
    // in Summary::iterationsCompleted. `cancel` is checked between iterations, `perIteration`
    // called after each on this thread. A failed or cancelled iteration leaves surface() at
    // the last good state.
    Summary step(int n, const std::atomic<bool>* cancel = nullptr,
                 const std::function<void(const IterationStats&)>& perIteration = {});
    // Builds what the first step() would build (structure, ordering, symbolic analysis, and in
    // a drag the first move's factorisation) and runs no iteration, changing nothing else: a
    // drag prepared before its press.
    Summary prepare();
    // GuidedProjection::waitForBackgroundFactorization (SessionOptions::backgroundFactorization).
    void waitForBackgroundFactorization() { m_projection.waitForBackgroundFactorization(); }

    const model::CompositeSurface& surface() const { return m_surface; }
    // Whether a settling stopped early, its residual above kHopelessSettlingResidual in
    // kHopelessSettlingIterations iterations in a row (on a held sheet: the Held pair).
    bool gaveUp() const { return m_gaveUp; }
    // Whether a settling on a held sheet stopped because it stalled (kStalledSettlingIterations).
    bool stalled() const { return m_stalled; }
    const SurfaceFormulation& formulation() const { return *m_formulation; }
    // The solver's state (normalised coordinates, see SurfaceFormulation).
    const std::vector<double>& state() const { return m_x; }
    // Iterations completed over all step() calls (the position in the ε₁ schedule).
    int iterationsDone() const { return m_iterationsDone; }
    // The pulled vertices (pinned ones excluded).
    const std::vector<model::VertexId>& pulledVertices() const { return m_pulled; }
    // Why the last step() stopped with Status::StoppedBeforeDegenerate: the first problem of
    // the iterate it refused (model::degenerateGeometryProblems). Empty otherwise.
    const std::optional<model::Problem>& refusedIterate() const { return m_refused; }

    // Faces worst first at the current state (SurfaceFormulation::faceResiduals).
    std::vector<SurfaceFormulation::FaceResidual> worstFaces() const;

    // A Solve (nothing pulled) goes back to its iterate of smallest residual over all step()
    // calls if the current one's is larger, and returns its iteration (from 1) and residual;
    // otherwise, and in a drag, {0, residual}. `summary` (of the last step()) follows it.
    struct BestIterate {
        int iteration = 0;
        double residual = 0.0;
    };
    BestIterate returnToBestIterate(Summary* summary = nullptr);

private:
    // The factorisation reuse of a drag's step(n) while it moves (kDragFactorizationReuse).
    void reuseFactorizations(Options& options, int n) const;

    SessionOptions m_options;
    model::CompositeSurface m_surface;
    std::unique_ptr<SurfaceFormulation> m_formulation;
    GuidedProjection m_projection;
    std::vector<double> m_x;
    std::vector<model::VertexId> m_pulled;
    int m_iterationsDone = 0;
    std::optional<model::Problem> m_refused;
    bool m_dragging = false; // something is pulled
    bool m_settling = false;
    bool m_giveUpWhenHopeless = false;
    int m_hopelessRun = 0; // settling iterations in a row above the hopeless residual
    bool m_gaveUp = false;
    bool m_stalled = false;
    std::vector<double> m_settlingResiduals; // of a settling on a held sheet, in order
    bool stallsAt(double residual);          // whether the settling stalled (kStalled…)
    // The pulled points' targets now and at the last step().
    struct Targets {
        std::map<model::VertexId, model::Vec3> vertices;
        std::map<std::pair<model::EdgeId, int>, model::Vec3> controlPoints;
    };
    Targets m_targets;
    Targets m_targetsStepped;
    double m_diameter = 0.0; // 0: moves are not split
    // The iterations the next move takes (kMoveStepLimit); the targets of the k-th (from 1).
    int moveSplits() const;
    void aimPartway(int k, int splits);
    bool m_lengthDampingFades = false; // the residual has fallen to kRoughSolveLengthDampingUntil
    double m_residual = std::numeric_limits<double>::infinity();        // at the last iterate
    double m_settledResidual = std::numeric_limits<double>::infinity(); // at the last settling
    double m_settledStretch = -1.0; // distance from the sheet at the last settled iterate
    bool settled(double residual);  // whether an iterate at `residual` ends the settling
    // The iterate of smallest residual of a Solve (returnToBestIterate).
    std::vector<double> m_bestX;
    double m_bestResidual = std::numeric_limits<double>::infinity();
    int m_bestIteration = 0;
};

} // namespace devsurf::solver
