#pragma once

#include "model/composite_surface.h"
#include "model/held_by_pins.h"
#include "model/problem.h"
#include "model/reference/strip_trim.h"
#include "model/reference/thinning.h"
#include "solver/core/summary.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/crease_quality.h"
#include "solver/session/drag_lengths.h"
#include "solver/session/shared_surfaces.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace devsurf::solver {

// What a solve is for. The job chooses the options, the iteration count and the guards from it.
enum class JobKind {
    Solve,       // Tools ▸ Solve, `devsurf-cli solve`: every surface, stops once converged
    VertexDrag,  // the Drag tool on vertices, `devsurf-cli drag --vertices`
    CreaseDrag,  // the Drag tool on a crease, `devsurf-cli drag --crease`
    Rotate,      // the Rotate tool, `devsurf-cli drag --rotate` (a vertex drag along an arc)
    Edit,        // an exact move or rotation kept developable (Tools ▸ Move or Rotate Vertices)
    Approximate, // strips pulled towards a reference shape (§4.2), `devsurf-cli approximate`
    Join,        // surfaces joined into one composite (§4.2), Tools ▸ Join Surfaces, `--join`
};

// Drags and rotations come as many requests (one per mouse move) and a settling one (the
// release); Solve and Edit are one request each.
constexpr bool isDrag(JobKind kind) {
    return kind == JobKind::VertexDrag || kind == JobKind::CreaseDrag || kind == JobKind::Rotate;
}

struct JobRequest {
    JobKind kind = JobKind::Solve;
    // Requests of one drag share a non-zero id: the job continues that drag's sessions. A new
    // id, or any other kind, starts afresh from `surfaces`.
    std::uint64_t drag = 0;
    // A drag's release: the iterations after it, the keep-lengths replay and the full
    // assessment. Solve and Edit always settle.
    bool settle = false;
    // A drag about to start (the pointer resting on a vertex with the Drag tool): the job builds
    // the drag's sessions with the pulled points where they are and the solver's analysis of
    // their structure, runs no iteration and returns the surfaces unchanged (JobOutcome::
    // prepared). The drag's first move with the same id and pulled points continues them.
    // Only for drags; it overrides `settle`, and other kinds ignore it.
    bool prepare = false;
    SharedSurfaces surfaces;                         // every surface of the project (pins inside)
    std::map<int, std::vector<VertexHandle>> pulled; // per surface index
    std::map<int, std::vector<ControlPointHandle>> pulledControlPoints; // a dragged crease
    // Vertices' places in a held sheet pulled in the development view (a VertexDrag of
    // surfaces that keep their development): the surface follows its sheet.
    std::map<int, std::vector<SheetHandle>> pulledSheet;
    // Solve: vertices held where they are without pinning them in the document.
    std::map<int, std::vector<model::VertexId>> fixed;
    // Iterations of this request; unset: defaultIterations(kind, settle, lengths, holdsSheet).
    std::optional<int> iterations;
    // Vertex drags and rotations: whether the sheet bends or stretches (crease drags stretch).
    DragLengths lengths = DragLengths::Automatic;
    // Approximate: per surface index, the (thinned) reference points it is pulled towards;
    // surfaces without an entry stay as they are. The iterations are those of the pull; the
    // job adds kApproximationFadeIterations in which the pull fades (solve_session.h).
    std::map<int, std::shared_ptr<const ApproximationTarget>> targets;
    // Approximate (or Solve): per surface index, boundary curves pulled together
    // (FormulationOptions::curvePairs), to be welded afterwards (model::weldEdges).
    std::map<int, std::vector<CurvePair>> curvePairs;
    // Join: the thinned reference points that the joined surface is pulled towards while its
    // facing edges are paired and once more after the weld, and the radius they were thinned
    // with; none: the pairing and the last step run as Solves.
    std::shared_ptr<const model::reference::ThinningResult> joinTarget;
    double joinRho = 0.0;
    // A drag too far: the thorough partway search, run to its end instead of within its time
    // budget (followPartway), so that what it follows does not depend on the machine's speed
    // (tests; the front ends keep the budget).
    bool untimedPartway = false;
    // A drag's moves factorise on another thread beside their steps
    // (SessionOptions::backgroundFactorization). The solver worker asks for it (the front
    // ends' drags); the command line and the tests that run jobs themselves step
    // synchronously, reproducibly.
    bool backgroundFactorization = false;
};

// The iterations of an approximation's pull when the request does not say.
constexpr int kApproximationIterations = 30;
// At most this many more iterations, of the hard conditions alone, for an approximation whose
// strip is short of the tolerance when its pull has faded (docs/tuning.md).
constexpr int kApproximationFinishIterations = 20;
// ... or whose sampled developability (worstDevelopability) exceeds this fraction of the
// tolerance: between its samples it may lie above the tolerance (a sphere cap pulled damped from
// its cylinder: within it as sampled there, 1.1e-8 at 50 values per interval).
constexpr double kApproximationFinishSampledFraction = 0.1;

// The iterations a request runs when it does not say: Solve kSolveIterations (a limit, it stops
// once converged), a drag's move 1, its release iterationsAfterDrag() (longer when a surface
// holds its sheet), an edit 1 + iterationsAfterDrag(false, holdsSheet), an approximation
// kApproximationIterations (plus its fading).
int defaultIterations(JobKind kind, bool settle, DragLengths lengths, bool holdsSheet = false);

// How far a handle ended from its target (model units).
struct HandleGap {
    model::VertexId vertex = model::kInvalidId; // a pulled vertex, or
    model::EdgeId edge = model::kInvalidId;     // a pulled control point of this edge
    int index = -1;
    double distance = 0.0;
};

// An Automatic drag that failed keeping lengths and was replayed letting the sheet stretch.
struct LengthsReplay {
    DragOutcome keepingLengths;
    DragOutcome stretching;
    bool taken = false; // the stretched result is the outcome's
};

// A vertex held back by the sheet by less than this (mm) has followed the mouse.
inline constexpr double kNegligibleLag = 0.01;

// Everything the front ends say about one surface of an outcome. Measured once, here.
struct SurfaceAssessment {
    bool solved = false; // false: left as it was (a drag's surfaces without handles)
    Summary summary;
    // Status::StoppedBeforeDegenerate: what the refused iterate would have broken.
    std::optional<model::Problem> refusedIterate;
    // Solve: ended on this earlier iterate of smallest residual (0: on the last).
    int bestIteration = 0;
    // Solve: the result sampled less developable than the start, which is returned instead.
    struct LessDevelopable {
        double before = 0.0; // largest normalised developability residual
        double after = 0.0;
    };
    std::optional<LessDevelopable> keptAsItWas;
    std::optional<LengthsReplay> replay;
    // A vertex drag keeping lengths whose release ended with problems, settled once more from
    // its last state with the keep-lengths energy fading more slowly, and kept so.
    bool settledAgain = false;
    // The iterations the first settling ran before that (fewer than asked where it gave up,
    // SolveSession::gaveUp).
    int firstSettlingIterations = 0;
    // A drag's settling on a held sheet that stopped after this many iterations because its
    // residual no longer fell (SolveSession::stalled); 0 otherwise.
    int stalledAfter = 0;
    // A vertex drag keeping lengths whose pins hold a dragged vertex where the sheet cannot bend.
    std::optional<model::HeldVertex> held;
    std::vector<HandleGap> handleGaps;
    double largestHandleGap = 0.0;
    // The surface keeps its development: a dragged vertex goes only as far as the sheet lets
    // it, and largestHandleGap says how far it lags behind the mouse.
    bool sheetHeld = false;
    // A drag's release that lags on a held sheet: the pinned vertices that hold a straight line
    // of the sheet between them (model::findTautPinLines), where a curved crease cannot fold.
    std::vector<std::pair<model::VertexId, model::VertexId>> tautPins;

    // The rest is measured on settled outcomes only (Solve, Edit, a drag's release).
    bool measured = false;
    std::vector<std::pair<model::FaceId, int>> foldOvers; // patch, places
    std::vector<model::FaceId> overlapping;               // the development overlaps itself
    CreaseQuality creases; // sampled along every crease (residuals of those with a condition)
    int vertexStars = 0;   // interior crease vertices
    double largestVertexDefect = 0.0; // rad
    // Drags: the shortest ruling and slowest curve speed relative to the press.
    double shortestRuling = 1.0;
    double slowestSpeed = 1.0;
    // Up to kWorstFaces patches by sampled developability, worst first, when the tolerance was
    // not reached.
    std::vector<std::pair<model::FaceId, double>> worstFaces;
    // The unfolded sampled mesh (kVerdictSamples per interval): its largest relative edge-length
    // error, its largest extent (mm) and how far from isometric that makes the sheet (mm): the
    // error times the extent, or the unfolding's closure gap if larger. -1: not measured.
    double edgeLengthError = -1.0;
    double sheetExtent = 0.0;
    double isometryMm = -1.0;
    // A drag's release (or an Edit) that would have ended broken (verdict.h: folded over, off
    // its kept sheet or not developable patch by patch; on a held sheet also not developable
    // as the verdict judges it) from a press that was not: the surface stays as at the press,
    // for an Edit as before it (the last developable state; this assessment measures it, its
    // summary's residual the press's sampled developability), and this is how the refused
    // result measured.
    std::shared_ptr<const SurfaceAssessment> takenBack;
    // With takenBack: how much of the drag (0 < followed < 1) the surface follows instead of
    // the press, when a state the drag passed through settles developable: the share of the
    // way from the press to the release's targets that its dragged vertices came (they lag
    // behind the mouse by largestHandleGap), or for a drag in the sheet the share of the moves
    // before that state. 0: the surface is as at the press.
    double followed = 0.0;
    // A surface that keeps its development: how far it is from it (model::keptSheetStretch,
    // mm), measured from the geometry. The development is held as a constraint judged apart
    // (a sampled mesh matches a developable spline only up to its sampling), so this is what
    // says whether the sheet held. -1: the surface keeps none.
    double sheetStretchMm = -1.0;
    // An approximation whose pull failed (stopped, not developable or run away from its
    // points) and ran again with the damped recipe (kDampedApproximationWeightScale): the
    // target is farther from developable than the strip can follow closely.
    bool dampedApproximation = false;
    // An approximation that stayed short of developable even after its finishing Solve and
    // kept its strip as it was laid (developable), solved.
    bool approximationKeptStart = false;
    // A strip the automatic path laid, trimmed back where it overhung the shape once pulled
    // (approximation_recipe.h), and solved: the part of its parameters it keeps.
    std::optional<model::reference::StripTrim> approximationTrim;
};

// Samples per spline interval of the development the verdict measures (as the views draw it).
inline constexpr int kVerdictSamples = 8;

constexpr std::size_t kWorstFaces = 5;

// A Solve whose result is this many times less developable than its start made it worse.
inline constexpr double kLessDevelopableFactor = 10.0;
// Below this normalised developability residual a surface counts as developable either way.
inline constexpr double kNegligibleDevelopability = 1e-8;

// Why a job failed: a code with its data. The front ends word it; `detail` is the solver's
// own technical note, for logs and the command line.
enum class JobError {
    None,
    Cancelled,
    CannotSolve,     // the surface cannot be set up (invalid, an unknown handle)
    TargetNotFinite, // a handle's target is not a finite point
    SolverFailed,    // an iteration failed (Summary::status says how)
    NotFinite,       // the solver produced a value that is not finite
};

struct JobFailure {
    JobError error = JobError::None;
    int surface = -1;
    model::VertexId vertex = model::kInvalidId; // TargetNotFinite: the vertex, or
    model::EdgeId edge = model::kInvalidId;     // the control point's edge and index
    int index = -1;
    Status status = Status::IterationLimit; // SolverFailed
    std::optional<model::Problem> problem;  // CannotSolve: what the model found wrong
    std::string detail;                     // a technical note for a bug report, not for the user
};

// What a Join did (join_job.h): the facing boundary edges (two curves or two rulings) it
// paired and which pairs it welded.
struct JoinReport {
    std::vector<int> joined;             // the request's surfaces now one (ascending indices)
    std::vector<double> separations;     // per pair of facing edges, mm apart before the pairing
    double largestGap = 0.0;             // mm apart after the pairing, over the pairs welded
    int welded = 0;                      // pairs now one shared edge
    std::vector<model::Problem> refused; // why the other pairs were not welded
    int parts = 0;                       // connected parts of the joined surface
    bool pulledToReference = false;      // pulled towards joinTarget, not solved alone
};

struct JobOutcome {
    JobKind kind = JobKind::Solve;
    std::uint64_t drag = 0;
    bool settled = false;  // answers a Solve, an Edit or a drag's release
    bool prepared = false; // answers JobRequest::prepare: nothing moved, nothing to show
    bool ok = false;       // false: failure says why, surfaces is empty
    JobFailure failure;
    // Every surface, valid: a session starts only from a valid surface, changes only positions
    // and refuses an iterate with degenerate geometry, so the front ends apply these without
    // validating them again on their thread (ApplySurfaceCommand::createValidated).
    std::vector<model::CompositeSurface> surfaces;
    std::vector<SurfaceAssessment> assessments; // per surface
    double elapsedMs = 0.0;
    // Every iteration the job ran, over all its surfaces: settlings, a second settling, a
    // replay and a partway search included (the assessments' summaries hold only some of them).
    int iterationsRun = 0;
    // Join: what was paired and welded; `surfaces` is then the one surface that the surfaces
    // JoinReport::joined became (the others are left as they are), or the request's surfaces
    // unchanged when no two face each other (separations empty).
    std::shared_ptr<const JoinReport> join;

    bool cancelled() const { return failure.error == JobError::Cancelled; }
    // The largest final constraint residual and iteration count over the solved surfaces.
    double largestResidual() const;
    int largestIterationCount() const;
};

struct JobProgress {
    int surface = 0;
    int done = 0;  // iterations of this request so far, over all surfaces
    int total = 0; // as planned (a replay adds more)
    bool replaying = false;
    // The release ended broken: a state the drag passed through is settled (followPartway).
    bool followingPartway = false;
    int variables = 0; // of the surface's problem
    int rows = 0;
    const IterationStats* stats = nullptr;
    const model::CompositeSurface* current = nullptr; // the surface after this iteration
};
using JobProgressFn = std::function<void(const JobProgress&)>;

// The one place where a solve is decided: options, iteration counts, the keep-lengths replay,
// the best iterate, the guards and the assessment. The desktop application's worker and the
// command line run it, so the same requests give the same bits. A drag's moves continue the
// sessions of its earlier requests. Not thread-safe; one thread at a time.
class SolveJob {
public:
    SolveJob();
    ~SolveJob();
    SolveJob(const SolveJob&) = delete;
    SolveJob& operator=(const SolveJob&) = delete;

    // `cancel` is checked between iterations; `progress` is called after each (this thread).
    JobOutcome run(const JobRequest& request, const std::atomic<bool>* cancel = nullptr,
                   const JobProgressFn& progress = {});
    // Forgets a drag's sessions.
    void reset();

private:
    struct Drag;
    std::unique_ptr<Drag> m_drag;
};

} // namespace devsurf::solver
