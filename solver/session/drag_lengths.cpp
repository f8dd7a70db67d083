#include "solver/session/drag_lengths.h"

#include "model/pattern/cutting_pattern.h"
#include "solver/quality/shape_change.h"
#include "solver/quality/vertex_stars.h"

#include <algorithm>
#include <exception>
#include <stdexcept>

namespace devsurf::solver {

int DragOutcome::problems() const {
    return static_cast<int>(stopped) + static_cast<int>(residual > kDragConvergedResidual) +
           static_cast<int>(foldOverPlaces > 0) + static_cast<int>(!overlapping.empty()) +
           static_cast<int>(collapsed()) + static_cast<int>(!measurable);
}

DragOutcome judgeDrag(const model::CompositeSurface& start, const model::CompositeSurface& result,
                      double residual, bool stopped) {
    DragOutcome outcome;
    outcome.stopped = stopped;
    outcome.residual = residual;
    try {
        const ShapeChange change = measureShapeChange(start, result);
        outcome.foldOverPlaces = change.foldOverPlaces();
        outcome.shortestRuling = change.shortestRuling;
        outcome.slowestSpeed = change.slowestSpeed;
        outcome.overlapping = model::selfOverlappingPatches(result);
    } catch (const std::exception&) {
        outcome.measurable = false;
    }
    return outcome;
}

bool prefersStretched(const DragOutcome& kept, const DragOutcome& stretched) {
    return stretched.problems() < kept.problems();
}

std::vector<std::size_t> replayedMoves(std::size_t count, std::size_t limit) {
    std::vector<std::size_t> chosen;
    if (count == 0 || limit == 0) {
        return chosen;
    }
    const std::size_t n = std::min(count, limit);
    for (std::size_t k = 1; k <= n; ++k) {
        // The k-th of n evenly spaced moves, ending with the last (count − 1).
        chosen.push_back((k * count + n - 1) / n - 1);
    }
    return chosen;
}

ReplayedDrag replayStretching(const model::CompositeSurface& start,
                              const std::vector<DragMove>& moves, int after,
                              const std::atomic<bool>* cancel,
                              const std::function<void(const IterationStats&)>& perIteration) {
    return replayDrag(start, moves, SessionOptions{}, after, cancel, perIteration);
}

ReplayedDrag replayDrag(const model::CompositeSurface& start, const std::vector<DragMove>& moves,
                        const SessionOptions& options, int after, const std::atomic<bool>* cancel,
                        const std::function<void(const IterationStats&)>& perIteration) {
    ReplayedDrag replay;
    if (moves.empty()) {
        throw std::invalid_argument("there is no move to replay.");
    }
    // Pulled from where they were at the press, as the drag began.
    std::vector<VertexHandle> pulled;
    for (const VertexHandle& handle : moves.front().vertices) {
        pulled.push_back(
            {handle.vertex, false,
             start.hasVertex(handle.vertex) ? start.position(handle.vertex) : handle.target});
    }
    replay.session =
        std::make_unique<SolveSession>(start, pulled, moves.front().controlPoints, options);
    SolveSession& session = *replay.session;
    for (std::size_t index : replayedMoves(moves.size())) {
        for (const VertexHandle& handle : moves[index].vertices) {
            session.setHandleTarget(handle.vertex, handle.target);
        }
        for (const ControlPointHandle& point : moves[index].controlPoints) {
            session.setControlPointTarget(point.edge, point.index, point.target);
        }
        const Summary move = session.step(1, cancel, perIteration);
        replay.iterations += move.iterationsCompleted;
        if (move.status == Status::StoppedBeforeDegenerate || !move.succeeded() ||
            move.iterations.empty()) {
            replay.stopped = move.status == Status::StoppedBeforeDegenerate;
            replay.settling = move;
            return replay;
        }
    }
    session.settle();
    replay.settling = session.step(after, cancel, perIteration);
    replay.iterations += replay.settling.iterationsCompleted;
    replay.stopped = replay.settling.status == Status::StoppedBeforeDegenerate;
    return replay;
}

std::unique_ptr<SolveSession> secondSettling(const model::CompositeSurface& press,
                                             const model::CompositeSurface& last,
                                             const std::vector<VertexHandle>& handles,
                                             const std::vector<ControlPointHandle>& points,
                                             SessionOptions options) {
    options.holdFadeWhileResidualRises = true;
    double pressDefect = 0.0;
    for (const VertexAngleDefect& star : vertexAngleDefects(press)) {
        pressDefect = std::max(pressDefect, star.defect);
    }
    if (pressDefect <= options.formulation.vertexStartDefectLimit) {
        options.formulation.vertexStartDefectLimit = FormulationOptions{}.vertexStartDefectLimit;
    }
    auto session = std::make_unique<SolveSession>(last, handles, points, options);
    session->settle(true); // as the first settling gives up
    return session;
}

} // namespace devsurf::solver
