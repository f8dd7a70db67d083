#include "outcome_text.h"
#include "problem_text.h"

#include "solver/quality/shape_change.h"
#include "solver/session/drag_lengths.h"
#include "solver/session/verdict.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace devsurf::app {

namespace {

std::string faceList(const std::vector<model::FaceId>& faces) {
    constexpr std::size_t kShown = 8;
    std::string text;
    for (std::size_t i = 0; i < std::min(faces.size(), kShown); ++i) {
        text += (i == 0 ? "" : ", ") + std::to_string(faces[i]);
    }
    return faces.size() > kShown ? text + ", …" : text;
}

std::string places(int count) {
    return std::to_string(count) + (count == 1 ? " place" : " places");
}

// "a, b and c".
std::string joinParts(const std::vector<std::string>& parts) {
    std::string sentence;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        sentence += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    }
    return sentence;
}

} // namespace

std::string describeFoldOvers(const std::vector<std::pair<model::FaceId, int>>& foldOvers) {
    if (foldOvers.empty()) {
        return "No face folds over onto itself.";
    }
    std::string text = "Folded over onto itself:";
    const std::size_t named = std::min(foldOvers.size(), solver::kFoldOversNamed);
    for (std::size_t i = 0; i < named; ++i) {
        text += (i == 0 ? " face " : ", face ") + std::to_string(foldOvers[i].first) + " (" +
                places(foldOvers[i].second) + ")";
    }
    if (named < foldOvers.size()) {
        int rest = 0;
        for (std::size_t i = named; i < foldOvers.size(); ++i) {
            rest += foldOvers[i].second;
        }
        const std::size_t more = foldOvers.size() - named;
        text += " and " + std::to_string(more) + (more == 1 ? " more face (" : " more faces (") +
                places(rest) + ")";
    }
    return text + ".";
}

std::string describeSelfOverlap(const std::vector<model::FaceId>& patches) {
    if (patches.empty()) {
        return "The development does not overlap itself.";
    }
    return std::string("The development overlaps itself at ") +
           (patches.size() == 1 ? "patch " : "patches ") + faceList(patches) +
           " and cannot be cut from one sheet.";
}

std::string describeHeld(const model::HeldVertex& held) {
    std::ostringstream text;
    text << "Vertex " << held.vertex;
    if (held.pins.size() == 2) {
        text << " lies on the straight line between the pinned vertices " << held.pins[0] << " and "
             << held.pins[1];
    } else {
        text << " lies inside the triangle of the pinned vertices " << held.pins[0] << ", "
             << held.pins[1] << " and " << held.pins[2];
    }
    text << ", which are as far apart as in the flat sheet, so bending cannot move it; only "
            "stretching can.";
    return text.str();
}

std::string describeOutcome(const solver::DragOutcome& outcome) {
    std::vector<std::string> parts;
    char text[160];
    if (outcome.stopped) {
        parts.push_back("stopped before a degenerate shape");
    }
    if (outcome.residual > solver::kDragConvergedResidual) {
        std::snprintf(text, sizeof text, "did not converge (residual %.1e)", outcome.residual);
        parts.push_back(text);
    }
    if (outcome.foldOverPlaces > 0) {
        parts.push_back("folded over in " + places(outcome.foldOverPlaces));
    }
    if (!outcome.overlapping.empty()) {
        std::snprintf(text, sizeof text, "left a development overlapping itself at %zu patch%s",
                      outcome.overlapping.size(), outcome.overlapping.size() == 1 ? "" : "es");
        parts.push_back(text);
    }
    if (outcome.collapsed()) {
        std::snprintf(text, sizeof text,
                      "collapsed strips (rulings at %.2f of their length, curve speeds at %.2f of "
                      "their mean)",
                      outcome.shortestRuling, outcome.slowestSpeed);
        parts.push_back(text);
    }
    if (!outcome.measurable) {
        parts.push_back("left a shape too degenerate to measure");
    }
    return parts.empty() ? "ended without a problem" : joinParts(parts);
}

std::string describeTakenBack(const solver::SurfaceAssessment& refused) {
    const solver::BrokenBy by = solver::brokenBy(refused);
    std::vector<std::string> parts;
    char text[200];
    if (by.worstFace) {
        std::snprintf(text, sizeof text,
                      "did not reach the tolerance (residual %.1e; patch %d sampled %.1e from "
                      "developable)",
                      refused.summary.finalMaxConstraintResidual,
                      static_cast<int>(by.worstFace->first), by.worstFace->second);
        parts.push_back(text);
    }
    if (by.offSheet) {
        std::snprintf(text, sizeof text, "left its kept sheet by %.2g mm", refused.sheetStretchMm);
        parts.push_back(text);
    }
    if (by.foldOverPlaces > 0) {
        parts.push_back("folded over in " + places(by.foldOverPlaces));
    }
    if (!refused.overlapping.empty()) {
        std::snprintf(text, sizeof text, "left a development overlapping itself at %zu patch%s",
                      refused.overlapping.size(), refused.overlapping.size() == 1 ? "" : "es");
        parts.push_back(text);
    }
    if (!refused.summary.toleranceReached &&
        refused.edgeLengthError > solver::kDragConvergedResidual) {
        std::snprintf(text, sizeof text, "would stretch its sheet by %.2g %% to lie flat",
                      100.0 * refused.edgeLengthError);
        parts.push_back(refused.edgeLengthError < 1.0 ? text : "would not lie flat as one sheet");
    }
    return parts.empty() ? "ended not developable" : joinParts(parts);
}

std::string describeCreaseRefusal(const solver::CreaseDragRefused& refused) {
    const std::string name = "edge " + std::to_string(refused.edge());
    switch (refused.reason()) {
    case solver::CreaseDragRefusal::NoSuchEdge:
        return "there is no " + name + ".";
    case solver::CreaseDragRefusal::NotACrease:
        return name +
               " is not a crease (a curve between two patches); only creases can be dragged.";
    case solver::CreaseDragRefusal::Immovable:
        break;
    }
    return name + " cannot move: both its ends are pinned and it has no other control point.";
}

std::string describeQuality(const solver::QualityMeasures& q) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer,
                  "flatness mean %.2e max %.2e, |K| mean %.2e max %.2e, det mean %.2e max %.2e",
                  q.flatnessMean, q.flatnessMax, q.curvatureMean, q.curvatureMax,
                  q.developabilityMean, q.developabilityMax);
    return buffer;
}

std::string refusedText(const solver::SurfaceAssessment& assessment) {
    if (!assessment.refusedIterate) {
        return std::string();
    }
    return ", before the next iteration broke it: " +
           ProblemText::of(*assessment.refusedIterate).toStdString();
}

std::string describeFailure(const solver::JobFailure& failure) {
    const std::string surface = "surface " + std::to_string(failure.surface + 1);
    std::string text;
    switch (failure.error) {
    case solver::JobError::None:
    case solver::JobError::Cancelled:
        return "cancelled";
    case solver::JobError::CannotSolve:
        text = surface + " cannot be solved";
        if (failure.problem) {
            text += ": " + withoutFinalPeriod(ProblemText::of(*failure.problem).toStdString());
        }
        break;
    case solver::JobError::TargetNotFinite:
        text = failure.vertex != model::kInvalidId
                   ? "the target of vertex " + std::to_string(failure.vertex) + " is not finite"
                   : "the target of control point " + std::to_string(failure.index) + " of edge " +
                         std::to_string(failure.edge) + " is not finite";
        break;
    case solver::JobError::SolverFailed:
        text = surface + " could not be solved: " + solver::toString(failure.status);
        break;
    case solver::JobError::NotFinite:
        text = surface + " could not be solved: the solver produced a value that is not finite";
        break;
    }
    if (!failure.detail.empty()) {
        text += ": " + withoutFinalPeriod(failure.detail);
    }
    return text;
}

} // namespace devsurf::app
