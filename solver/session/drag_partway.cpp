#include "solver/session/drag_partway.h"

#include "model/geometry_checks.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/job_assessment.h"
#include "solver/session/verdict.h"

#include <algorithm>
#include <exception>

namespace devsurf::solver {

namespace {

// How much a drag whose release would end broken may spend on finding how far it can follow
// (SolveJob::run's release): at most kPartwayProbes settlings of a state the drag passed
// through, each halving the range of moves still in question, all stopped at kPartwayBudget
// (docs/tuning.md, "A drag too far follows part of the way").
constexpr int kPartwayProbes = 6;
constexpr std::chrono::milliseconds kPartwayBudget{1500};
// States a drag passed through that are kept for that (evenly spread over the drag; the
// latest always).
constexpr std::size_t kReachedKept = 32;
// A state passed through is settled with this many times the release's iterations: it starts
// farther from converged than the drag's own last state.
constexpr int kPartwaySettleFactor = 3;
// The angle defect (rad) a star may end with where the press's were smaller, as the sessions'
// vertexStartDefectLimit.
constexpr double kPartwayStarDefect = 1e-6;
// The largest sampled developability residual (normalised, worstDevelopability) a state may end
// with where the press was better: a partial drag is kept only if it ends developable.
constexpr double kPartwayDevelopability = 1e-5;

} // namespace

bool partwayFits(std::chrono::steady_clock::duration releaseStep) {
    return 2 * kPartwaySettleFactor * releaseStep < kPartwayBudget;
}

void keepReached(std::vector<Reached>& reached, Reached state) {
    reached.push_back(std::move(state));
    if (reached.size() > kReachedKept) {
        std::vector<Reached> thinned;
        for (std::size_t i = 0; i < reached.size(); ++i) {
            if (i % 2 == 1 || i + 1 == reached.size()) {
                thinned.push_back(std::move(reached[i]));
            }
        }
        reached = std::move(thinned);
    }
}

std::optional<Partway>
followPartway(const model::CompositeSurface& press, const SurfaceAssessment& atPress,
              const std::vector<Reached>& reached, const std::vector<DragMove>& moves,
              const SessionOptions& options, int after, const std::vector<VertexHandle>& handles,
              const std::vector<ControlPointHandle>& points, const std::atomic<bool>* cancel) {
    const auto start = std::chrono::steady_clock::now();
    // Vertex developability where it held at the press, also at stars a state passed through
    // has opened (a fresh session would impose it only where it holds at its start).
    SessionOptions settleOptions = options;
    if (atPress.largestVertexDefect <= settleOptions.formulation.vertexStartDefectLimit) {
        settleOptions.formulation.vertexStartDefectLimit =
            FormulationOptions{}.vertexStartDefectLimit;
    }
    // Ends well: not broken, no star opened beyond the press's (or kPartwayStarDefect), and
    // sampled as developable as the press within kPartwayDevelopability (or 10 times it).
    const double defectLimit = std::max(atPress.largestVertexDefect, kPartwayStarDefect);
    const double developabilityLimit =
        std::max(10.0 * atPress.summary.finalMaxConstraintResidual, kPartwayDevelopability);
    std::optional<Partway> best;
    // reached[good] known to end well (-1: the press), reached[bad] known to end broken.
    long good = -1;
    long bad = static_cast<long>(reached.size());
    if (!reached.empty() && reached.back().moves >= moves.size()) {
        --bad; // the release itself
    }
    for (int probe = 0; probe < kPartwayProbes && bad - good > 1; ++probe) {
        if (std::chrono::steady_clock::now() - start > kPartwayBudget ||
            (cancel != nullptr && cancel->load())) {
            break;
        }
        const long index = good + (bad - good + 1) / 2;
        const Reached& state = reached[static_cast<std::size_t>(index)];
        const DragMove& move = moves.at(state.moves - 1);
        std::unique_ptr<SolveSession> session;
        Summary settling;
        try {
            session = std::make_unique<SolveSession>(state.surface, move.vertices,
                                                     move.controlPoints, settleOptions);
            session->settle();
            // Stopped where the budget runs out, even within a settling.
            std::atomic<bool> stop{false};
            settling =
                session->step(kPartwaySettleFactor * after, &stop, [&](const IterationStats&) {
                    if ((cancel != nullptr && cancel->load()) ||
                        std::chrono::steady_clock::now() - start > kPartwayBudget) {
                        stop = true;
                    }
                });
        } catch (const std::exception&) {
            break;
        }
        if (settling.status == Status::Cancelled) {
            break;
        }
        SurfaceAssessment a;
        const model::CompositeSurface& surface = session->surface();
        bool ended = settling.succeeded() && model::allCoordinatesFinite(surface);
        if (ended) {
            a.solved = true;
            a.summary = settling;
            measureHandleGaps(a, surface, handles, points);
            a.sheetHeld = surface.keepsDevelopment();
            measureSettled(a, surface, &press, std::nullopt);
            ended = !broken(a) && a.largestVertexDefect <= defectLimit &&
                    worstDevelopability(surface) <= developabilityLimit;
        }
        if (ended) {
            good = index;
            a.followed = static_cast<double>(state.moves) / static_cast<double>(moves.size());
            best = Partway{std::move(session), std::move(a)};
        } else {
            bad = index;
        }
    }
    return best;
}

} // namespace devsurf::solver
