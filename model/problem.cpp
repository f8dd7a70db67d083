#include "problem.h"

#include <sstream>

namespace devsurf::model {

namespace {

const char* codeName(ProblemCode code) {
    switch (code) {
#define DEVSURF_CODE(name)                                                                         \
    case ProblemCode::name:                                                                        \
        return #name;
        DEVSURF_CODE(NoFaces)
        DEVSURF_CODE(IdUsedTwice)
        DEVSURF_CODE(Missing)
        DEVSURF_CODE(EdgeEndsInvalid)
        DEVSURF_CODE(DuplicateEdge)
        DEVSURF_CODE(FaceTooFewVertices)
        DEVSURF_CODE(FaceRepeatsVertex)
        DEVSURF_CODE(FaceMissingVertex)
        DEVSURF_CODE(FaceOrientation)
        DEVSURF_CODE(FaceNonManifold)
        DEVSURF_CODE(NoEdgeBetween)
        DEVSURF_CODE(CurveCannotBeSmooth)
        DEVSURF_CODE(Unused)
        DEVSURF_CODE(BeyondIdCounter)
        DEVSURF_CODE(RulingWithSplineData)
        DEVSURF_CODE(SmoothNotShared)
        DEVSURF_CODE(CurveMarkedSmooth)
        DEVSURF_CODE(InvalidSplineSpace)
        DEVSURF_CODE(ControlPointCount)
        DEVSURF_CODE(ControlPointNotFinite)
        DEVSURF_CODE(CurveNotAtVertex)
        DEVSURF_CODE(ConditionNotShared)
        DEVSURF_CODE(InvalidFaceLabel)
        DEVSURF_CODE(SplineSpacesDiffer)
        DEVSURF_CODE(DevelopmentSize)
        DEVSURF_CODE(DevelopmentNotFinite)
        DEVSURF_CODE(SheetDomainInvalid)
        DEVSURF_CODE(PositionNotFinite)
        DEVSURF_CODE(PositionTooFar)
        DEVSURF_CODE(ControlPointTooFar)
        DEVSURF_CODE(CurveZeroLength)
        DEVSURF_CODE(CurvePinched)
        DEVSURF_CODE(RulingZeroLength)
        DEVSURF_CODE(CoincidentVertices)
        DEVSURF_CODE(ZeroArea)
        DEVSURF_CODE(CreaseNeedsStrip)
        DEVSURF_CODE(CreaseBlocked)
        DEVSURF_CODE(RowClosesSwapped)
        DEVSURF_CODE(CreasePositionOutside)
        DEVSURF_CODE(NothingToRelabel)
        DEVSURF_CODE(NotACurve)
        DEVSURF_CODE(RulingNeedsStrip)
        DEVSURF_CODE(SingleInterval)
        DEVSURF_CODE(RulingPosition)
        DEVSURF_CODE(CurvesMeetReversed)
        DEVSURF_CODE(CurveSpaceDiffers)
        DEVSURF_CODE(RefineFactorTooSmall)
        DEVSURF_CODE(TooManyIntervals)
        DEVSURF_CODE(NothingToMove)
        DEVSURF_CODE(InvalidRotation)
        DEVSURF_CODE(UnknownExample)
        DEVSURF_CODE(ExampleSize)
        DEVSURF_CODE(SampleCount)
        DEVSURF_CODE(NotAStrip)
        DEVSURF_CODE(DifferentFaces)
        DEVSURF_CODE(ConditionOnBoundary)
        DEVSURF_CODE(ConditionBesideNonStrip)
        DEVSURF_CODE(ConditionNeedsDegree)
        DEVSURF_CODE(NotOneSheet)
        DEVSURF_CODE(WeldNeedsBoundaryEdges)
        DEVSURF_CODE(EdgesTooFarApart)
        DEVSURF_CODE(MergeNeedsStrips)
        DEVSURF_CODE(Internal)
#undef DEVSURF_CODE
    }
    return "Unknown";
}

} // namespace

bool Problem::operator==(const Problem& o) const {
    return code == o.code && element == o.element && id == o.id && vertex == o.vertex &&
           otherVertex == o.otherVertex && edge == o.edge && otherEdge == o.otherEdge &&
           face == o.face && otherFace == o.otherFace && faces == o.faces &&
           faceType == o.faceType && count == o.count && expected == o.expected &&
           value == o.value && limit == o.limit && space == o.space && otherSpace == o.otherSpace &&
           name == o.name && detail == o.detail;
}

std::string technicalKey(const Problem& problem) {
    std::ostringstream out;
    out << codeName(problem.code);
    auto id = [&out](const char* what, std::uint32_t value) {
        if (value != kInvalidId) {
            out << ' ' << what << '=' << value;
        }
    };
    if (problem.id != kInvalidId) {
        static const char* const elements[] = {"vertex", "edge", "face"};
        id(elements[static_cast<int>(problem.element)], problem.id);
    }
    id("vertex", problem.vertex);
    id("other-vertex", problem.otherVertex);
    id("edge", problem.edge);
    id("other-edge", problem.otherEdge);
    id("face", problem.face);
    id("other-face", problem.otherFace);
    if (!problem.name.empty()) {
        out << " name=" << problem.name;
    }
    if (!problem.detail.empty()) {
        out << " (" << problem.detail << ')';
    }
    return out.str();
}

} // namespace devsurf::model
