#pragma once

#include "ids.h"
#include "spline_space.h"

#include <cstdint>
#include <string>
#include <vector>

namespace devsurf::model {

enum class FaceType : std::uint8_t;

// What is wrong with a design, or why an edit or a construction step is refused: a code with
// the ids and numbers it concerns. model/ never words it; the front ends in app/ do (the
// desktop application with tr(), the command line for a terminal).
enum class ProblemCode {
    // The structure of a design (a damaged file, or a bug in an edit).
    NoFaces,               // the surface has no faces
    IdUsedTwice,           // element, id
    Missing,               // element, id: does not exist
    EdgeEndsInvalid,       // edge: does not join two distinct existing vertices
    DuplicateEdge,         // edge duplicates the edge between vertex and otherVertex
    FaceTooFewVertices,    // face
    FaceRepeatsVertex,     // face
    FaceMissingVertex,     // face refers to the missing vertex
    FaceOrientation,       // face runs along vertex → otherVertex as another face does
    FaceNonManifold,       // face
    NoEdgeBetween,         // vertex, otherVertex
    CurveCannotBeSmooth,   // edge: a curve; only rulings are smooth or sharp
    Unused,                // element, id: belongs to no face
    BeyondIdCounter,       // element, id
    RulingWithSplineData,  // edge
    SmoothNotShared,       // edge is marked smooth but not shared by two faces
    CurveMarkedSmooth,     // edge
    InvalidSplineSpace,    // edge, space
    ControlPointCount,     // edge has `count` control points, its space needs `expected`
    ControlPointNotFinite, // edge
    CurveNotAtVertex,      // edge does not start (count 0) or end (count 1) at vertex
    ConditionNotShared,    // edge carries a crease condition but is not shared by two faces
    InvalidFaceLabel,      // face with label `name`
    SplineSpacesDiffer,    // edge and otherEdge connected, spaces space and otherSpace
    DevelopmentSize,       // the kept development has `count` points, the sampled mesh `expected`
    DevelopmentNotFinite,  // a point of the kept development is not finite
    SheetDomainInvalid,    // the sheet's shape: count 1 a size not finite or not positive, 2 an
                           // annulus's inner radius not below its outer, 3 no outer loop
    // Degenerate geometry of a structurally sound design (also checked on every solver step).
    PositionNotFinite,  // vertex (faces around it)
    PositionTooFar,     // vertex (faces) lies `value` mm from the origin, beyond `limit`
    ControlPointTooFar, // edge (faces) has a control point beyond `limit` mm
    CurveZeroLength,    // edge (faces)
    CurvePinched,       // edge (faces): a stretch of the curve shrunk to a point, a cusp
    RulingZeroLength,   // edge (faces)
    CoincidentVertices, // face, vertex, otherVertex
    ZeroArea,           // face
    // Edits a designer asked for that the design cannot take.
    CreaseNeedsStrip,        // face of type faceType; only an SRSR strip can be cut
    CreaseBlocked,           // across ruling edge into otherFace of type faceType
    RowClosesSwapped,        // the row of strips through face closes with sides swapped
    CreasePositionOutside,   // value: the position t, not strictly between 0 and 1
    NothingToRelabel,        //
    NotACurve,               // edge is not a spline curve (S-edge)
    RulingNeedsStrip,        // face of type faceType
    SingleInterval,          // the curves of face have a single interval
    RulingPosition,          // breakpoint `count` of `expected` intervals of face's curves
    CurvesMeetReversed,      // the curves connected to face meet themselves reversed
    CurveSpaceDiffers,       // edge uses another spline space than face's curves
    RefineFactorTooSmall,    // count: the factor
    TooManyIntervals,        // the curves of edge already have `count` intervals
    NothingToMove,           //
    InvalidRotation,         // a rotation's axis point, direction or angle is not usable
    UnknownExample,          // name: the example asked for
    ExampleSize,             // name, count: the size asked for, between expected and limit
    SampleCount,             // count: samples per interval outside 1 … expected
    NotAStrip,               // face is not a strip or a cone
    DifferentFaces,          // two shapes compared do not have the same faces
    ConditionOnBoundary,     // edge has a crease condition but is a boundary curve
    ConditionBesideNonStrip, // edge has a crease condition beside a cone or planar patch
    ConditionNeedsDegree,    // edge has a crease condition but its curve's degree is `count`
    NotOneSheet, // not one sheet: count parts, or its unfolding (flat or around a cylinder)
                 // misses closing up by `value` mm
    WeldNeedsBoundaryEdges, // edge: a weld joins two boundary edges of one kind, of two faces
    EdgesTooFarApart, // edge and otherEdge lie `value` mm apart, more than `limit` to weld them
    MergeNeedsStrips, // edge: not a ruling between two SRSR strips with boundary curves alone
    Internal,         // a bug; detail says where
};

// What a problem's `element` and `id` name for the codes that concern any kind of entity.
enum class Element : std::uint8_t { Vertex, Edge, Face };

struct Problem {
    ProblemCode code = ProblemCode::Internal;
    Element element = Element::Vertex;
    std::uint32_t id = kInvalidId;
    VertexId vertex = kInvalidId;
    VertexId otherVertex = kInvalidId;
    EdgeId edge = kInvalidId;
    EdgeId otherEdge = kInvalidId;
    FaceId face = kInvalidId;
    FaceId otherFace = kInvalidId;
    std::vector<FaceId> faces; // the faces around the vertex or edge, to find it by
    FaceType faceType{};
    long long count = 0;
    long long expected = 0;
    double value = 0.0;
    double limit = 0.0;
    SplineSpace space{};
    SplineSpace otherSpace{};
    std::string name;   // data: an example's name, a face's label
    std::string detail; // Internal only: a technical note for a bug report, not for the user

    bool operator==(const Problem& o) const;
    bool operator!=(const Problem& o) const { return !(*this == o); }
};

// The code's name and the ids, as "CurveZeroLength edge=4": for logs, test messages and the
// text of ModelError::what(), never shown to a designer as a sentence.
std::string technicalKey(const Problem& problem);

} // namespace devsurf::model

namespace devsurf::model {

// Shorthands for the common shapes of a problem.
inline Problem problemOf(ProblemCode code) {
    Problem p;
    p.code = code;
    return p;
}
inline Problem elementProblem(ProblemCode code, Element element, std::uint32_t id) {
    Problem p = problemOf(code);
    p.element = element;
    p.id = id;
    return p;
}
inline Problem vertexProblem(ProblemCode code, VertexId vertex) {
    Problem p = problemOf(code);
    p.vertex = vertex;
    return p;
}
inline Problem edgeProblem(ProblemCode code, EdgeId edge) {
    Problem p = problemOf(code);
    p.edge = edge;
    return p;
}
inline Problem faceProblem(ProblemCode code, FaceId face) {
    Problem p = problemOf(code);
    p.face = face;
    return p;
}
inline Problem internalProblem(std::string detail) {
    Problem p = problemOf(ProblemCode::Internal);
    p.detail = std::move(detail);
    return p;
}

} // namespace devsurf::model
