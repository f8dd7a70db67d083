#pragma once

#include "model/problem.h"

// The cutting pattern of a project: every surface developed into flat pieces, with cut lines,
// folds, scoring lines, seam allowances and labels on named layers, laid out on sheets. This is
// the one place that computes it; the development view draws it and every writer in io/ (DXF,
// SVG, PDF and printing, FOLD) writes it out unchanged.

#include "model/ids.h"
#include "model/vec3.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::model {

class CompositeSurface;
struct Project;

// The layers of a pattern. Names (patternLayerName) are the same in every file format.
enum class PatternLayer : std::uint8_t {
    Cut = 0,      // "CUT": outlines to cut
    Mountain = 1, // "MOUNTAIN": creases folded as mountains
    Valley = 2,   // "VALLEY": creases folded as valleys
    Crease = 3,   // "CREASE": creases without a mountain/valley assignment (or flat)
    Score = 4,    // "SCORE": rulings, as optional scoring lines
    Seam = 5,     // "SEAM": the original outline where a seam allowance or glue tab was added
    Labels = 6    // "LABELS": text
};
inline constexpr int kPatternLayerCount = 7;

// "CUT", "MOUNTAIN", "VALLEY", "CREASE", "SCORE", "SEAM", "LABELS".
const char* patternLayerName(PatternLayer layer);

// A polyline on one layer, in sheet coordinates (mm, y up). Curves are already sampled so that
// the chord error against the model's curve is at most PatternOptions::tolerance.
struct PatternPath {
    PatternLayer layer = PatternLayer::Cut;
    std::vector<Vec2> points;
    bool closed = false;
    FaceId face = kInvalidId; // the patch it belongs to, if any
    EdgeId edge = kInvalidId; // the coarse edge it draws, if any
    // Mountain/valley fold angle in degrees (signed: > 0 mountain), when known.
    std::optional<double> foldAngleDegrees;
};

// A text on the LABELS layer: its anchor is the centre of the text's baseline.
struct PatternLabel {
    Vec2 position;
    double height = 5.0;       // mm
    double angleDegrees = 0.0; // counter-clockwise from +x
    std::string text;
};

// One flat piece: a connected part of one surface's development, cut open where needed.
struct PatternPiece {
    int surface = 0;           // index in Project::surfaces
    std::string name;          // e.g. "A", "B", … (also written as a label on the piece)
    std::vector<FaceId> faces; // the patches it is made of
    // The closed outline that is cut (counter-clockwise, without the closing point repeated);
    // includes the seam allowance and tabs when they were asked for.
    std::vector<Vec2> outline;
    std::vector<PatternPath> paths; // everything drawn for this piece, outline included
    std::vector<PatternLabel> labels;
    // Further closed cut loops inside the outline (clockwise), e.g. the hole of an annulus.
    // They are also in paths (CUT, closed).
    std::vector<std::vector<Vec2>> holes;

    // What the development view draws (placed like everything above): the sampled mesh of the
    // piece, every coarse edge as a polyline (an edge on a cut-open seam appears twice, once per
    // side), every coarse vertex (twice on a seam) and every sampled ruling.
    struct Mesh {
        std::vector<Vec2> vertices;
        std::vector<std::vector<int>> faces;
        std::vector<FaceId> faceOrigin; // the patch of each face
    } mesh;
    std::vector<PatternPath> edgeCurves; // layer: CUT on the boundary, CREASE inside
    std::vector<std::pair<VertexId, Vec2>> vertices;
    std::vector<std::array<Vec2, 2>> rulingSegments;

    // Placement: the piece's coordinates above are already placed on its sheet.
    int sheet = -1;             // -1: not placed (larger than the sheet)
    double rotationDegrees = 0; // rotation applied by the layout

    // Fabrication figures.
    double area = 0.0;             // mm², of the developed patches (without seam allowance)
    Vec2 size;                     // bounding box width/height as placed, mm
    double maxIsometryError = 0.0; // mm: largest |3D edge length − pattern edge length|
    bool selfOverlapping = false;  // the development overlaps itself
};

// Two pieces whose outlines overlap (only possible when the layout could not place them apart,
// e.g. no layout was asked for), or a piece that overlaps itself (first == second).
struct PatternOverlap {
    int first = 0;
    int second = 0;
    std::vector<FaceId> faces; // patches involved
};

// What a designer must know before cutting, as a code with data; app/ words it.
enum class PatternProblemCode {
    SheetSizeInvalid,    // the sheet size is not positive: pieces are laid out side by side
    SurfaceInvalid,      // surface has no pattern: cause says why
    NotDeveloped,        // surface could not be developed: cause (or detail) says why
    PieceOverlapsItself, // piece (of surface) overlaps itself at the patches `faces`
    PiecesOverlap,       // piece and otherPiece overlap on sheet (patches of each: the pieces')
    PieceTooLarge,       // piece of `size` does not fit on the sheet of sheetSize with gap
};

struct PatternProblem {
    PatternProblemCode code = PatternProblemCode::SheetSizeInvalid;
    int surface = -1; // index in Project::surfaces
    std::string surfaceName;
    int piece = -1; // indices in CuttingPattern::pieces
    int otherPiece = -1;
    int sheet = -1;
    std::vector<FaceId> faces;
    Vec2 size;
    Vec2 sheetSize;
    double gap = 0.0;
    std::optional<Problem> cause;
    std::string detail; // NotDeveloped without a model problem: technical, for a bug report
};

struct PatternOptions {
    double tolerance = 0.01;      // mm: chord error of sampled curves
    bool rulings = false;         // write rulings on the SCORE layer
    double seamAllowance = 0.0;   // mm: offset of the outline along glued edges (0: none)
    bool glueTabs = false;        // trapezoidal tabs instead of a parallel offset
    Vec2 sheetSize{600.0, 400.0}; // mm
    double gap = 5.0;             // mm: kerf + margin between pieces and to the sheet edge
    bool allowRotation = true;    // rotate pieces where that saves material
    bool layout = true;           // arrange pieces on sheets (otherwise side by side)
    // Samples per spline interval; 0: as many as the tolerance needs (the views use a fixed
    // resolution to match the 3D view).
    int samplesPerInterval = 0;
    // Boundary edges (surface index, edge id) that get a seam allowance or tab as well, e.g.
    // where the piece is glued to another part. The cut-open seams always get them.
    std::vector<std::pair<int, EdgeId>> gluedEdges;
};

struct CuttingPattern {
    std::string units = "mm";
    std::vector<PatternPiece> pieces;
    Vec2 sheetSize;     // as in the options
    int sheetCount = 0; // sheets used by the layout
    std::vector<PatternOverlap> overlaps;
    // What a designer must know before cutting (a piece larger than the sheet, an overlap, a
    // surface that could not be developed).
    std::vector<PatternProblem> problems;

    // Bounding box of everything on one sheet (sheet < 0: of all pieces): {min, max}.
    std::pair<Vec2, Vec2> bounds(int sheet = -1) const;
};

// One valid surface developed into pieces not yet laid out (what buildCuttingPattern does per
// surface): each piece checked for overlapping itself (PatternPiece::selfOverlapping, with the
// patches involved in selfOverlapFaces, one entry per piece) and given its seam allowance. Pieces
// are named from nameIndex on (A, B, …), which advances. Throws std::exception where the surface
// cannot be developed.
std::vector<PatternPiece>
developSurfacePieces(const CompositeSurface& surface, int surfaceIndex,
                     const PatternOptions& options, int& nameIndex,
                     std::vector<std::vector<FaceId>>* selfOverlapFaces = nullptr);

// The patches at which the development of one surface overlaps itself, so that it cannot be
// cut from one sheet (developSurfacePieces at samplesPerInterval samples per spline interval,
// no layout), sorted and without repeats; empty where it does not overlap itself, and for an
// invalid surface or one that cannot be developed. A result can satisfy every condition of the
// solver and still overlap itself where it is unfolded, e.g. a patch turned over in the plane.
std::vector<FaceId> selfOverlappingPatches(const CompositeSurface& surface,
                                           int samplesPerInterval = 8);

// Builds the pattern of every surface of the project. Invalid surfaces are skipped with a
// problem sentence naming them; it never throws for bad geometry.
CuttingPattern buildCuttingPattern(const Project& project, const PatternOptions& options = {});

} // namespace devsurf::model
