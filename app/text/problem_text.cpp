#include "problem_text.h"

#include "face_type_text.h"
#include "model/examples.h"

#include <QStringList>

namespace devsurf::app {

namespace {

using model::Element;
using model::ProblemCode;

QString id(std::uint32_t value) {
    return QString::number(value);
}

// "1, 2, 5" with at most eight ids shown.
QString idList(const std::vector<model::FaceId>& faces) {
    QStringList ids;
    for (std::size_t i = 0; i < faces.size() && i < 8; ++i) {
        ids << id(faces[i]);
    }
    if (faces.size() > 8) {
        ids << QStringLiteral("…");
    }
    return ids.join(QStringLiteral(", "));
}

QString millimetres(double value) {
    return QString::number(value, 'g', 3);
}

} // namespace

QString ProblemText::patches(const std::vector<model::FaceId>& faces) {
    if (faces.empty()) {
        return tr("no patch");
    }
    if (faces.size() == 1) {
        return tr("patch %1").arg(faces.front());
    }
    return tr("patches %1").arg(idList(faces));
}

QString ProblemText::splineSpace(const model::SplineSpace& space) {
    if (space.intervals == 1) {
        return tr("degree %1, C%2, 1 interval").arg(space.degree).arg(space.smoothness);
    }
    return tr("degree %1, C%2, %3 intervals")
        .arg(space.degree)
        .arg(space.smoothness)
        .arg(space.intervals);
}

QString ProblemText::surface(int index, const std::string& name) {
    if (name.empty()) {
        return tr("Surface %1").arg(index + 1);
    }
    return tr("Surface %1 “%2”").arg(index + 1).arg(QString::fromStdString(name));
}

QString ProblemText::of(const model::Problem& p) {
    const Element element = p.element;
    switch (p.code) {
    case ProblemCode::NoFaces:
        return tr("The surface has no patches.");
    case ProblemCode::IdUsedTwice:
        return element == Element::Vertex ? tr("Vertex id %1 is used twice.").arg(p.id)
               : element == Element::Edge ? tr("Edge id %1 is used twice.").arg(p.id)
                                          : tr("Patch id %1 is used twice.").arg(p.id);
    case ProblemCode::Missing:
        return element == Element::Vertex ? tr("Vertex %1 does not exist.").arg(p.id)
               : element == Element::Edge ? tr("Edge %1 does not exist.").arg(p.id)
                                          : tr("Patch %1 does not exist.").arg(p.id);
    case ProblemCode::EdgeEndsInvalid:
        return tr("Edge %1 does not join two distinct existing vertices.").arg(p.edge);
    case ProblemCode::DuplicateEdge:
        return tr("Edge %1 duplicates the edge between vertices %2 and %3.")
            .arg(p.edge)
            .arg(p.vertex)
            .arg(p.otherVertex);
    case ProblemCode::FaceTooFewVertices:
        return tr("Patch %1 has fewer than three corners.").arg(p.face);
    case ProblemCode::FaceRepeatsVertex:
        return tr("Patch %1 visits a vertex twice.").arg(p.face);
    case ProblemCode::FaceMissingVertex:
        return tr("Patch %1 refers to vertex %2, which does not exist.").arg(p.face).arg(p.vertex);
    case ProblemCode::FaceOrientation:
        return tr("Patch %1 runs along the edge from vertex %2 to vertex %3 in the same direction "
                  "as another patch: patches must be oriented consistently and an edge can "
                  "border at most two patches.")
            .arg(p.face)
            .arg(p.vertex)
            .arg(p.otherVertex);
    case ProblemCode::FaceNonManifold:
        return tr("Patch %1 cannot be attached without making the surface non-manifold.")
            .arg(p.face);
    case ProblemCode::NoEdgeBetween:
        return tr("There is no edge between vertices %1 and %2.").arg(p.vertex).arg(p.otherVertex);
    case ProblemCode::CurveCannotBeSmooth:
        return tr("Edge %1 is a curve; only rulings are smooth or sharp.").arg(p.edge);
    case ProblemCode::Unused:
        return element == Element::Vertex ? tr("Vertex %1 belongs to no patch.").arg(p.id)
                                          : tr("Edge %1 belongs to no patch.").arg(p.id);
    case ProblemCode::BeyondIdCounter:
        return element == Element::Vertex ? tr("Vertex %1 lies beyond the id counter.").arg(p.id)
               : element == Element::Edge ? tr("Edge %1 lies beyond the id counter.").arg(p.id)
                                          : tr("Patch %1 lies beyond the id counter.").arg(p.id);
    case ProblemCode::RulingWithSplineData:
        return tr("Edge %1 is a ruling but carries spline data.").arg(p.edge);
    case ProblemCode::SmoothNotShared:
        return tr("Edge %1 is marked smooth but is not shared by two patches.").arg(p.edge);
    case ProblemCode::CurveMarkedSmooth:
        return tr("Edge %1 is a curve but is marked smooth (only rulings are).").arg(p.edge);
    case ProblemCode::InvalidSplineSpace:
        return tr("Edge %1 has an invalid spline space (%2).")
            .arg(p.edge)
            .arg(splineSpace(p.space));
    case ProblemCode::ControlPointCount:
        return tr("Edge %1 has %2 control points; its spline space (%3) needs %4.")
            .arg(p.edge)
            .arg(p.count)
            .arg(splineSpace(p.space))
            .arg(p.expected);
    case ProblemCode::ControlPointNotFinite:
        return tr("Edge %1 has a control point that is not a finite number.").arg(p.edge);
    case ProblemCode::CurveNotAtVertex:
        return p.count == 0
                   ? tr("Edge %1 does not start at its vertex %2.").arg(p.edge).arg(p.vertex)
                   : tr("Edge %1 does not end at its vertex %2.").arg(p.edge).arg(p.vertex);
    case ProblemCode::ConditionNotShared:
        return tr("Edge %1 carries a crease condition but is not shared by two patches.")
            .arg(p.edge);
    case ProblemCode::InvalidFaceLabel:
        return tr("Patch %1 is labelled %2; a patch must be an SRSR strip, an SRS strip, an SRR "
                  "cone or a polygon of rulings only (R…R).")
            .arg(p.face)
            .arg(QString::fromStdString(p.name));
    case ProblemCode::SplineSpacesDiffer:
        return tr("Curves %1 and %2 are connected through patches but use different spline "
                  "spaces (%3 and %4).")
            .arg(p.edge)
            .arg(p.otherEdge)
            .arg(splineSpace(p.space), splineSpace(p.otherSpace));
    case ProblemCode::DevelopmentSize:
        return tr("The kept development has %1 points, but the surface's sampled mesh has %2.")
            .arg(p.count)
            .arg(p.expected);
    case ProblemCode::DevelopmentNotFinite:
        return tr("A point of the kept development is not a finite number.");
    case ProblemCode::SheetDomainInvalid:
        if (p.count == 2) {
            return tr("The sheet's inner radius must be smaller than its outer radius.");
        }
        if (p.count == 3) {
            return tr("The sheet's outline has no closed loop enclosing an area.");
        }
        if (p.count == 4) {
            return tr("A crease curve of the sheet has too few points, a point that is not a "
                      "finite number, or is not there.");
        }
        return tr("The sheet's sizes must be finite and greater than zero.");
    case ProblemCode::PositionNotFinite:
        return tr("Vertex %1 (of %2) has a position that is not a finite number.")
            .arg(p.vertex)
            .arg(patches(p.faces));
    case ProblemCode::PositionTooFar:
        return tr("Vertex %1 (of %2) lies %3 mm from the origin; coordinates beyond %4 mm (1 km) "
                  "are not accepted.")
            .arg(p.vertex)
            .arg(patches(p.faces), millimetres(p.value), millimetres(p.limit));
    case ProblemCode::ControlPointTooFar:
        return tr("Edge %1 (a curve of %2) has a control point beyond %3 mm from the origin.")
            .arg(p.edge)
            .arg(patches(p.faces), millimetres(p.limit));
    case ProblemCode::CurveZeroLength:
        return tr("Edge %1 (a curve of %2) has zero length.").arg(p.edge).arg(patches(p.faces));
    case ProblemCode::CurvePinched:
        return tr("Edge %1 (a curve of %2) is pinched: a stretch of it has shrunk to a point.")
            .arg(p.edge)
            .arg(patches(p.faces));
    case ProblemCode::RulingZeroLength:
        return tr("Edge %1 (a ruling of %2) has zero length.").arg(p.edge).arg(patches(p.faces));
    case ProblemCode::CoincidentVertices:
        return tr("Patch %1 has coincident vertices %2 and %3.")
            .arg(p.face)
            .arg(p.vertex)
            .arg(p.otherVertex);
    case ProblemCode::ZeroArea:
        return tr("Patch %1 has zero area.").arg(p.face);
    case ProblemCode::CreaseNeedsStrip:
        return tr("Patch %1 is a %2; only an SRSR strip can be cut by a new crease.")
            .arg(p.face)
            .arg(faceTypeText(p.faceType));
    case ProblemCode::CreaseBlocked:
        return tr("The new crease cannot continue across ruling edge %1 into patch %2, a %3; a "
                  "row of strips can only be cut where its rulings border SRSR strips, planar "
                  "patches or the boundary.")
            .arg(p.edge)
            .arg(p.otherFace)
            .arg(faceTypeText(p.faceType));
    case ProblemCode::RowClosesSwapped:
        return tr("The row of strips through patch %1 closes on itself with its sides swapped, so "
                  "it cannot be cut at one distance between its curves.")
            .arg(p.face);
    case ProblemCode::CreasePositionOutside:
        return tr("The new crease must lie strictly between the strip's two curves (0 < t < 1, "
                  "not %1).")
            .arg(p.value);
    case ProblemCode::NothingToRelabel:
        return tr("No edge was given to relabel.");
    case ProblemCode::NotACurve:
        return tr("Edge %1 is not a spline curve.").arg(p.edge);
    case ProblemCode::RulingNeedsStrip:
        return tr("Patch %1 is a %2; a ruling can only be added to a strip or a cone.")
            .arg(p.face)
            .arg(faceTypeText(p.faceType));
    case ProblemCode::SingleInterval:
        return tr("The curves of patch %1 have a single interval; refine them before adding a "
                  "ruling.")
            .arg(p.face);
    case ProblemCode::RulingPosition:
        return tr("A ruling can only be added at an interior breakpoint i/%1 of the curves of "
                  "patch %2 (1 ≤ i ≤ %3, not %4); refine the curves for finer positions.")
            .arg(p.expected)
            .arg(p.face)
            .arg(p.expected - 1)
            .arg(p.count);
    case ProblemCode::CurvesMeetReversed:
        return tr("The curves connected to patch %1 meet themselves reversed, so no ruling "
                  "position is consistent across them.")
            .arg(p.face);
    case ProblemCode::CurveSpaceDiffers:
        return tr("Curve %1 uses a different spline space from the curves of patch %2.")
            .arg(p.edge)
            .arg(p.face);
    case ProblemCode::RefineFactorTooSmall:
        return tr("Refining needs a factor of at least 2, not %1.").arg(p.count);
    case ProblemCode::TooManyIntervals:
        return tr("The curves of edge %1 already have %2 intervals; refining them beyond %3 is "
                  "not supported.")
            .arg(p.edge)
            .arg(p.count)
            .arg(p.expected);
    case ProblemCode::NothingToMove:
        return tr("No vertex was given to move.");
    case ProblemCode::InvalidRotation:
        return tr("A rotation needs a finite axis point, a non-zero axis direction and a finite "
                  "angle.");
    case ProblemCode::UnknownExample: {
        QStringList names;
        for (const model::ExampleInfo& info : model::builtInExamples()) {
            names << QString::fromStdString(info.name);
        }
        return tr("There is no example called “%1”; the examples are %2.")
            .arg(QString::fromStdString(p.name), names.join(QStringLiteral(", ")));
    }
    case ProblemCode::ExampleSize:
        return tr("The size of the example “%1” must be between %2 and %3, not %4.")
            .arg(QString::fromStdString(p.name))
            .arg(p.expected)
            .arg(p.limit)
            .arg(p.count);
    case ProblemCode::SampleCount:
        return tr("The number of samples per spline interval must be between 1 and %1, not %2.")
            .arg(p.expected)
            .arg(p.count);
    case ProblemCode::NotAStrip:
        return tr("Patch %1 is not a strip or a cone.").arg(p.face);
    case ProblemCode::DifferentFaces:
        return tr("The two shapes do not have the same patches.");
    case ProblemCode::ConditionOnBoundary:
        return tr("Edge %1 has a crease condition but is a boundary curve, not a crease.")
            .arg(p.edge);
    case ProblemCode::ConditionBesideNonStrip:
        return tr("Edge %1 has a crease condition but a cone or planar patch lies beside it; "
                  "crease "
                  "conditions need a strip on either side.")
            .arg(p.edge);
    case ProblemCode::ConditionNeedsDegree:
        return tr("Edge %1 has a crease condition but its curve is of degree %2; a crease "
                  "condition needs degree 2 or more.")
            .arg(p.edge)
            .arg(p.count);
    case ProblemCode::NotOneSheet:
        if (p.count != 1) {
            return tr("The surface is not one sheet: it has %n separate part(s).", nullptr,
                      static_cast<int>(p.count));
        }
        return tr("The surface is not one flat sheet: its unfolding misses closing up by %1 mm.")
            .arg(QString::number(p.value, 'g', 3));
    case ProblemCode::WeldNeedsBoundaryEdges:
        return tr("Edge %1 cannot be welded: a weld joins two boundary edges of the same kind "
                  "(two curves or two rulings) of two different patches.")
            .arg(p.edge);
    case ProblemCode::EdgesTooFarApart:
        return tr("Edges %1 and %2 lie up to %3 mm apart, more than the %4 mm within which they "
                  "can be welded.")
            .arg(p.edge)
            .arg(p.otherEdge)
            .arg(millimetres(p.value), millimetres(p.limit));
    case ProblemCode::MergeNeedsStrips:
        return tr("The strips beside edge %1 cannot be merged: it must be a ruling between two "
                  "strips whose curves are boundary curves of the same degree and smoothness, "
                  "and its ends may belong to no other patch.")
            .arg(p.edge);
    case ProblemCode::Internal:
        break;
    }
    return tr("DevSurf met an internal error (%1). Please report it.")
        .arg(QString::fromStdString(model::technicalKey(p)));
}

QString ProblemText::of(const model::PatternProblem& p, const model::CuttingPattern& pattern) {
    auto pieceName = [&pattern](int index) {
        return index >= 0 && index < static_cast<int>(pattern.pieces.size())
                   ? QString::fromStdString(pattern.pieces[static_cast<std::size_t>(index)].name)
                   : QString::number(index);
    };
    auto pieceFaces = [&pattern](int index) {
        return index >= 0 && index < static_cast<int>(pattern.pieces.size())
                   ? idList(pattern.pieces[static_cast<std::size_t>(index)].faces)
                   : QString();
    };
    const QString where = surface(p.surface, p.surfaceName);
    switch (p.code) {
    case model::PatternProblemCode::SheetSizeInvalid:
        return tr("The sheet size must be positive; the pieces are laid out side by side.");
    case model::PatternProblemCode::SurfaceInvalid:
        return tr("%1 is not valid and has no pattern: %2")
            .arg(where, p.cause ? of(*p.cause) : QString());
    case model::PatternProblemCode::NotDeveloped:
        return tr("%1 could not be developed: %2")
            .arg(where, p.cause ? of(*p.cause) : of(model::internalProblem(p.detail)));
    case model::PatternProblemCode::PieceOverlapsItself:
        return tr("Piece %1 (%2) overlaps itself at patches %3 and cannot be cut from one sheet.")
            .arg(pieceName(p.piece), where, idList(p.faces));
    case model::PatternProblemCode::PiecesOverlap:
        return tr("Pieces %1 (patches %2) and %3 (patches %4) overlap on sheet %5.")
            .arg(pieceName(p.piece), pieceFaces(p.piece), pieceName(p.otherPiece),
                 pieceFaces(p.otherPiece))
            .arg(p.sheet + 1);
    case model::PatternProblemCode::PieceTooLarge:
        return tr("Piece %1 (%2) measures %3 × %4 mm and does not fit on the %5 × %6 mm sheet "
                  "with a %7 mm gap.")
            .arg(pieceName(p.piece), where)
            .arg(p.size.x, 0, 'f', 1)
            .arg(p.size.y, 0, 'f', 1)
            .arg(p.sheetSize.x, 0, 'f', 1)
            .arg(p.sheetSize.y, 0, 'f', 1)
            .arg(p.gap, 0, 'f', 1);
    }
    return QString();
}

std::string withoutFinalPeriod(std::string text) {
    while (!text.empty() && (text.back() == '.' || text.back() == ' ')) {
        text.pop_back();
    }
    return text;
}

std::vector<std::string> patternProblemTexts(const model::CuttingPattern& pattern) {
    std::vector<std::string> texts;
    for (const model::PatternProblem& problem : pattern.problems) {
        texts.push_back(ProblemText::of(problem, pattern).toStdString());
    }
    return texts;
}

} // namespace devsurf::app
