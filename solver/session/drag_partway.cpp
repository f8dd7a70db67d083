#include "solver/session/drag_partway.h"

#include "model/geometry_checks.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/approximation_recipe.h"
#include "solver/session/job_assessment.h"
#include "solver/session/verdict.h"

#include <algorithm>
#include <exception>
#include <limits>

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
// PartwaySearch::Brief: at most this many states, each settled as long as the release (the one
// kept once more where it ends short of the tolerance), among those before the first move whose
// iteration ended at more than kPartwayResidualJump times the lowest residual of the moves
// before it (the drag was then asking for more than the sheet allows; docs/tuning.md, "A drag
// too far follows part of the way").
constexpr int kBriefPartwayProbes = 3;
constexpr double kPartwayResidualJump = 10.0;
// A state whose dragged points came less than this share of the way (shown as 0 %) is the
// press to the designer: the press is kept instead, exactly as it was.
constexpr double kLeastFollowedShare = 0.005;

// Whether every dragged vertex of `surface` is nearer its target than at the press: a state
// settled with soft pulls may slide back past the press, which is no part of the drag.
bool nearerThanAtPress(const model::CompositeSurface& press, const model::CompositeSurface& surface,
                       const DragMove& release) {
    const bool vertices =
        std::all_of(release.vertices.begin(), release.vertices.end(), [&](const VertexHandle& h) {
            return model::distance(surface.position(h.vertex), h.target) <
                   model::distance(press.position(h.vertex), h.target);
        });
    return vertices &&
           std::all_of(release.sheet.begin(), release.sheet.end(), [&](const SheetHandle& h) {
               const std::optional<model::Vec2> now = sheetPlace(surface, h.vertex);
               const std::optional<model::Vec2> before = sheetPlace(press, h.vertex);
               return now && before && (*now - h.target).norm() < (*before - h.target).norm();
           });
}

// The iterate of smallest residual within the tolerance that a settling passed through. A
// settling of a state the drag passed through can cycle (residuals 7e-10, 4e-5, 4e-8, 4e-5 on
// the annulus of size 14 lifted too far), and its last iterate is then a poor one.
struct BestSeen {
    std::optional<model::CompositeSurface> surface;
    double residual = std::numeric_limits<double>::infinity();

    void see(const SolveSession& session, const IterationStats& stats, double tolerance) {
        if (stats.maxConstraintResidual <= tolerance && stats.maxConstraintResidual < residual) {
            surface = session.surface();
            residual = stats.maxConstraintResidual;
        }
    }
};

// How much of the drag a state follows: the share of the way its dragged points came from the
// press towards the release's targets (1 − largest gap now / `pressGap`, the largest at the
// press), so that a state that settled back near the press is not said to follow the share of
// the moves it was reached after; that share (`ofMoves`) where there is no gap at the press
// (nothing dragged is a vertex or control point). Below 1: the state is not the whole drag.
double followedShare(double pressGap, const SurfaceAssessment& state, double ofMoves) {
    const double share = pressGap > 0.0 ? 1.0 - state.largestHandleGap / pressGap : ofMoves;
    return std::clamp(share, 0.0, 0.999);
}

} // namespace

bool partwayFits(std::chrono::steady_clock::duration releaseStep) {
    return 2 * kPartwaySettleFactor * releaseStep < kPartwayBudget;
}

void keepReached(std::vector<Reached>& reached, std::size_t& stride, Reached state) {
    stride = std::max<std::size_t>(stride, 1);
    if (!reached.empty() && reached.back().moves % stride != 0) {
        reached.pop_back(); // kept only as the latest
    }
    reached.push_back(std::move(state));
    while (reached.size() > kReachedKept) {
        stride *= 2;
        std::vector<Reached> thinned;
        for (std::size_t i = 0; i < reached.size(); ++i) {
            if (reached[i].moves % stride == 0 || i + 1 == reached.size()) {
                thinned.push_back(std::move(reached[i]));
            }
        }
        reached = std::move(thinned);
    }
}

void PassedThrough::moved(std::size_t moves, const model::CompositeSurface& surface,
                          double residual) {
    if (!m_states.empty() && m_states.back().moves == moves) {
        return;
    }
    if (moves % m_stride == 0) {
        m_latestPending = false;
        keepReached(m_states, m_stride, {moves, surface, residual});
        return;
    }
    m_latestPending = true;
    m_latestMoves = moves;
    m_latestResidual = residual;
}

void PassedThrough::keepLatest(const model::CompositeSurface& surface) {
    if (m_latestPending) {
        m_latestPending = false;
        keepReached(m_states, m_stride, {m_latestMoves, surface, m_latestResidual});
    }
}

void PassedThrough::clear() {
    m_states.clear();
    m_stride = 1;
    m_latestPending = false;
}

int partwayIterationLimit(PartwaySearch search, int after) {
    return search != PartwaySearch::Brief ? kPartwayProbes * kPartwaySettleFactor * after
                                          : (kBriefPartwayProbes + 1) * after;
}

std::optional<Partway>
followPartway(const model::CompositeSurface& press, const SurfaceAssessment& atPress,
              const std::vector<Reached>& reached, const std::vector<DragMove>& moves,
              const SessionOptions& options, int after, const DragMove& release,
              const std::atomic<bool>* cancel, PartwaySearch search,
              const std::function<void(const IterationStats&)>& onIteration) {
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
    // How far the dragged points are from the release's targets at the press (followedShare).
    SurfaceAssessment pressGaps;
    measureHandleGaps(pressGaps, press, release.vertices, release.controlPoints);
    const double pressGap = pressGaps.largestHandleGap;
    std::optional<Partway> best;
    const DragMove* bestMove = nullptr; // the move best was released at
    // reached[good] known to end well (-1: the press), reached[bad] known to end broken.
    long good = -1;
    long bad = static_cast<long>(reached.size());
    if (!reached.empty() && reached.back().moves >= moves.size()) {
        --bad; // the release itself
    }
    const bool timed = search == PartwaySearch::Thorough;
    const bool thorough = timed || search == PartwaySearch::Untimed;
    if (!thorough) {
        // Only states before the drag asked for more than the sheet allows: its moves'
        // residual jumped there.
        double lowest = std::numeric_limits<double>::infinity();
        for (long i = 0; i < bad; ++i) {
            const double residual = reached[static_cast<std::size_t>(i)].residual;
            if (residual > kPartwayResidualJump * lowest) {
                bad = i;
                break;
            }
            lowest = std::min(lowest, residual);
        }
    }
    if (!thorough && settleOptions.formulation.pulledHandleWeight == 0.0) {
        // The pulls soft, as on a held sheet: a state passed through settles where the sheet
        // lets the dragged points go, not fighting their targets (docs/tuning.md).
        settleOptions.formulation.pulledHandleWeight = kSheetPullWeight;
    }
    // Ends well: as above, and every dragged vertex nearer its target than at the press. (A
    // development that only overlaps itself is reported, not refused, as after any release.)
    auto judge = [&](const SolveSession& session, const Summary& settling, SurfaceAssessment& a) {
        const model::CompositeSurface& surface = session.surface();
        if (!settling.succeeded() || !model::allCoordinatesFinite(surface)) {
            return false;
        }
        a.solved = true;
        a.summary = settling;
        measureHandleGaps(a, surface, release.vertices, release.controlPoints);
        measureSheetGaps(a, surface, release.sheet);
        a.sheetHeld = surface.keepsDevelopment();
        measureSettled(a, surface, &press, std::nullopt);
        return !broken(a) && a.largestVertexDefect <= defectLimit &&
               worstDevelopability(surface) <= developabilityLimit &&
               nearerThanAtPress(press, surface, release);
    };
    // Places pulled in the held sheet let go as the settling goes on: one pulled off the
    // sheet's boundary would keep the boundary's rows from converging.
    settleOptions.fadeSheetPulls = true;
    // A state is released with its move's targets: there the dragged points stay.
    auto sessionAt = [&settleOptions](const model::CompositeSurface& surface,
                                      const DragMove& move) {
        SessionOptions probe = settleOptions;
        probe.formulation.sheetHandles = move.sheet;
        return std::make_unique<SolveSession>(surface, move.vertices, move.controlPoints, probe);
    };
    // A settling whose last iterate missed the tolerance ends on the best it passed through
    // that reached it, where that one is sampled developable within the limit above (or at
    // least as developable as the last). The residual that misses is often not
    // developability's: on the annulus of size 14 lifted too far, an iterate at 6.6e-10 is
    // sampled 5.2e-8 from developable, the last, at 4.0e-5, 3.2e-8.
    const double tolerance = settleOptions.solver.reportTolerance;
    auto backToBestSeen = [&](std::unique_ptr<SolveSession>& session, Summary& settling,
                              const BestSeen& seen, const DragMove& move) {
        if (!seen.surface || settling.toleranceReached || !settling.succeeded()) {
            return;
        }
        const double developability = worstDevelopability(*seen.surface);
        if (developability > developabilityLimit &&
            developability > worstDevelopability(session->surface())) {
            return;
        }
        try {
            session = sessionAt(*seen.surface, move);
        } catch (const std::exception&) {
            return; // stays on its last iterate
        }
        settling.finalMaxConstraintResidual = seen.residual;
        settling.toleranceReached = true;
    };
    const int probes = thorough ? kPartwayProbes : kBriefPartwayProbes;
    const int settleFactor = thorough ? kPartwaySettleFactor : 1;
    for (int probe = 0; probe < probes && bad - good > 1; ++probe) {
        if ((timed && std::chrono::steady_clock::now() - start > kPartwayBudget) ||
            (cancel != nullptr && cancel->load())) {
            break;
        }
        const long index = good + (bad - good + 1) / 2;
        const Reached& state = reached[static_cast<std::size_t>(index)];
        const DragMove& move = moves.at(state.moves - 1);
        std::unique_ptr<SolveSession> session;
        Summary settling;
        BestSeen seen;
        try {
            session = sessionAt(state.surface, move);
            session->settle();
            // Stopped where the budget runs out, even within a settling.
            std::atomic<bool> stop{false};
            settling = session->step(settleFactor * after, &stop, [&](const IterationStats& stats) {
                seen.see(*session, stats, tolerance);
                if (onIteration) {
                    onIteration(stats);
                }
                if ((cancel != nullptr && cancel->load()) ||
                    (timed && std::chrono::steady_clock::now() - start > kPartwayBudget)) {
                    stop = true;
                }
            });
        } catch (const std::exception&) {
            break;
        }
        if (settling.status == Status::Cancelled) {
            break;
        }
        backToBestSeen(session, settling, seen, move);
        SurfaceAssessment a;
        bool ended = judge(*session, settling, a);
        if (ended) {
            good = index;
            a.followed = followedShare(
                pressGap, a, static_cast<double>(state.moves) / static_cast<double>(moves.size()));
            best = Partway{std::move(session), std::move(a)};
            bestMove = &move;
        } else {
            bad = index;
        }
    }
    if (best && !thorough && !best->assessment.summary.toleranceReached &&
        !(cancel != nullptr && cancel->load())) {
        // A brief probe settles only as long as the release: the state kept gets as many
        // iterations once more to reach the tolerance, and stays as it was if they spoil it.
        const model::CompositeSurface settled = best->session->surface();
        BestSeen seen;
        Summary more = best->session->step(after, cancel, [&](const IterationStats& stats) {
            seen.see(*best->session, stats, tolerance);
            if (onIteration) {
                onIteration(stats);
            }
        });
        SurfaceAssessment a;
        if (more.status == Status::Cancelled) {
            return std::nullopt;
        }
        backToBestSeen(best->session, more, seen, *bestMove);
        if (judge(*best->session, more, a)) {
            continueSummary(best->assessment.summary, more);
            a.summary = best->assessment.summary;
            a.followed = followedShare(pressGap, a, best->assessment.followed);
            best->assessment = std::move(a);
        } else {
            try {
                best->session = sessionAt(settled, *bestMove);
            } catch (const std::exception&) {
                best.reset();
            }
        }
    }
    if (best && pressGap > 0.0 && best->assessment.followed < kLeastFollowedShare) {
        return std::nullopt;
    }
    return best;
}

} // namespace devsurf::solver
