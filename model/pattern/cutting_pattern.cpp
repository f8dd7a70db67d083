#include "cutting_pattern.h"

#include "model/model_error.h"
#include "model/project.h"
#include "pattern_geometry.h"
#include "pattern_layout.h"
#include "pattern_overlaps.h"
#include "pattern_pieces.h"
#include "pattern_seams.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

namespace devsurf::model {

const char* patternLayerName(PatternLayer layer) {
    switch (layer) {
    case PatternLayer::Cut:
        return "CUT";
    case PatternLayer::Mountain:
        return "MOUNTAIN";
    case PatternLayer::Valley:
        return "VALLEY";
    case PatternLayer::Crease:
        return "CREASE";
    case PatternLayer::Score:
        return "SCORE";
    case PatternLayer::Seam:
        return "SEAM";
    case PatternLayer::Labels:
        return "LABELS";
    }
    return "CUT";
}

std::pair<Vec2, Vec2> CuttingPattern::bounds(int sheet) const {
    const double inf = std::numeric_limits<double>::infinity();
    Vec2 lo(inf, inf);
    Vec2 hi(-inf, -inf);
    for (const PatternPiece& piece : pieces) {
        if (sheet >= 0 && piece.sheet != sheet) {
            continue;
        }
        const auto [a, b] = pattern::pieceBounds(piece);
        lo = Vec2(std::min(lo.x, a.x), std::min(lo.y, a.y));
        hi = Vec2(std::max(hi.x, b.x), std::max(hi.y, b.y));
    }
    if (!std::isfinite(lo.x)) {
        return {Vec2(), Vec2()};
    }
    return {lo, hi};
}

std::vector<PatternPiece> developSurfacePieces(const CompositeSurface& surface, int surfaceIndex,
                                               const PatternOptions& options, int& nameIndex,
                                               std::vector<std::vector<FaceId>>* selfOverlapFaces) {
    std::vector<PatternPiece> pieces;
    for (pattern::PieceBuild& build :
         pattern::developSurface(surface, surfaceIndex, options, nameIndex)) {
        std::vector<FaceId> faces;
        build.piece.selfOverlapping = pattern::selfOverlaps(build.piece, faces);
        if (selfOverlapFaces) {
            selfOverlapFaces->push_back(std::move(faces));
        }
        pattern::addSeamAllowances(build, options);
        pieces.push_back(std::move(build.piece));
    }
    return pieces;
}

std::vector<FaceId> selfOverlappingPatches(const CompositeSurface& surface,
                                           int samplesPerInterval) {
    std::vector<FaceId> patches;
    if (!surface.validate().empty()) {
        return patches;
    }
    PatternOptions options;
    options.layout = false;
    options.samplesPerInterval = std::max(1, samplesPerInterval);
    int nameIndex = 0;
    std::vector<std::vector<FaceId>> faces;
    try {
        developSurfacePieces(surface, 0, options, nameIndex, &faces);
    } catch (const std::exception&) {
        return patches;
    }
    for (const std::vector<FaceId>& pieceFaces : faces) {
        patches.insert(patches.end(), pieceFaces.begin(), pieceFaces.end());
    }
    std::sort(patches.begin(), patches.end());
    patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
    return patches;
}

CuttingPattern buildCuttingPattern(const Project& project, const PatternOptions& requested) {
    PatternOptions options = requested;
    if (!std::isfinite(options.tolerance) || options.tolerance <= 0.0) {
        options.tolerance = PatternOptions{}.tolerance;
    }
    options.tolerance = std::clamp(options.tolerance, 1e-6, 10.0);
    if (!std::isfinite(options.seamAllowance) || options.seamAllowance < 0.0) {
        options.seamAllowance = 0.0;
    }
    if (!std::isfinite(options.gap) || options.gap < 0.0) {
        options.gap = 0.0;
    }

    CuttingPattern pattern;
    pattern.units = project.units;
    pattern.sheetSize = options.sheetSize;
    if (options.layout &&
        !(options.sheetSize.x > 0.0 && options.sheetSize.y > 0.0 &&
          std::isfinite(options.sheetSize.x) && std::isfinite(options.sheetSize.y))) {
        PatternProblem problem;
        problem.code = PatternProblemCode::SheetSizeInvalid;
        pattern.problems.push_back(std::move(problem));
        options.layout = false;
    }

    std::vector<std::string> surfaceNames;
    int nameIndex = 0;
    for (std::size_t s = 0; s < project.surfaces.size(); ++s) {
        const CompositeSurface& surface = project.surfaces[s];
        surfaceNames.push_back(surface.name());
        PatternProblem about;
        about.surface = static_cast<int>(s);
        about.surfaceName = surface.name();
        const std::vector<Problem> invalid = surface.validate();
        if (!invalid.empty()) {
            PatternProblem problem = about;
            problem.code = PatternProblemCode::SurfaceInvalid;
            problem.cause = invalid.front();
            pattern.problems.push_back(std::move(problem));
            continue;
        }
        std::vector<PatternPiece> pieces;
        std::vector<std::vector<FaceId>> selfOverlapFaces;
        try {
            pieces = developSurfacePieces(surface, static_cast<int>(s), options, nameIndex,
                                          &selfOverlapFaces);
        } catch (const ModelError& error) {
            PatternProblem problem = about;
            problem.code = PatternProblemCode::NotDeveloped;
            problem.cause = error.problem();
            pattern.problems.push_back(std::move(problem));
        } catch (const std::exception& error) {
            PatternProblem problem = about;
            problem.code = PatternProblemCode::NotDeveloped;
            problem.detail = error.what();
            pattern.problems.push_back(std::move(problem));
        }
        for (std::size_t p = 0; p < pieces.size(); ++p) {
            const int index = static_cast<int>(pattern.pieces.size());
            if (pieces[p].selfOverlapping) {
                pattern.overlaps.push_back({index, index, selfOverlapFaces[p]});
                PatternProblem problem = about;
                problem.code = PatternProblemCode::PieceOverlapsItself;
                problem.piece = index;
                problem.faces = selfOverlapFaces[p];
                pattern.problems.push_back(std::move(problem));
            }
            pattern.pieces.push_back(std::move(pieces[p]));
        }
    }

    pattern.sheetCount =
        pattern::layoutPieces(pattern.pieces, options, surfaceNames, pattern.problems);

    for (PatternOverlap& overlap : pattern::overlapsBetweenPieces(pattern.pieces)) {
        const PatternPiece& a = pattern.pieces[static_cast<std::size_t>(overlap.first)];
        PatternProblem problem;
        problem.code = PatternProblemCode::PiecesOverlap;
        problem.surface = a.surface;
        problem.piece = overlap.first;
        problem.otherPiece = overlap.second;
        problem.sheet = a.sheet;
        problem.faces = overlap.faces;
        pattern.problems.push_back(std::move(problem));
        pattern.overlaps.push_back(std::move(overlap));
    }
    return pattern;
}

} // namespace devsurf::model
