#include "cutting_pattern.h"

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

namespace {

std::string facesText(const std::vector<FaceId>& faces) {
    std::string text;
    const std::size_t shown = std::min<std::size_t>(faces.size(), 8);
    for (std::size_t i = 0; i < shown; ++i) {
        text += (i == 0 ? "" : ", ") + std::to_string(faces[i]);
    }
    if (shown < faces.size()) {
        text += ", …";
    }
    return text;
}

} // namespace

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
        pattern.problems.push_back(
            "The sheet size must be positive; the pieces are laid out side by side.");
        options.layout = false;
    }

    std::vector<std::string> surfaceNames;
    int nameIndex = 0;
    for (std::size_t s = 0; s < project.surfaces.size(); ++s) {
        const CompositeSurface& surface = project.surfaces[s];
        const std::string name = "surface " + std::to_string(s + 1) +
                                 (surface.name().empty() ? "" : " \"" + surface.name() + "\"");
        surfaceNames.push_back(name);
        const std::vector<std::string> invalid = surface.validate();
        if (!invalid.empty()) {
            pattern.problems.push_back("The " + name +
                                       " is not valid and has no pattern: " + invalid.front());
            continue;
        }
        std::vector<PatternPiece> pieces;
        std::vector<std::vector<FaceId>> selfOverlapFaces;
        try {
            pieces = developSurfacePieces(surface, static_cast<int>(s), options, nameIndex,
                                          &selfOverlapFaces);
        } catch (const std::exception& error) {
            pattern.problems.push_back("The " + name + " could not be developed: " + error.what());
        }
        for (std::size_t p = 0; p < pieces.size(); ++p) {
            const int index = static_cast<int>(pattern.pieces.size());
            if (pieces[p].selfOverlapping) {
                pattern.overlaps.push_back({index, index, selfOverlapFaces[p]});
                pattern.problems.push_back(
                    "Piece " + pieces[p].name + " (" + name + ") overlaps itself at patches " +
                    facesText(selfOverlapFaces[p]) + " and cannot be cut from one sheet.");
            }
            pattern.pieces.push_back(std::move(pieces[p]));
        }
    }

    pattern.sheetCount =
        pattern::layoutPieces(pattern.pieces, options, surfaceNames, pattern.problems);

    for (PatternOverlap& overlap : pattern::overlapsBetweenPieces(pattern.pieces)) {
        const PatternPiece& a = pattern.pieces[static_cast<std::size_t>(overlap.first)];
        const PatternPiece& b = pattern.pieces[static_cast<std::size_t>(overlap.second)];
        pattern.problems.push_back("Pieces " + a.name + " (patches " + facesText(a.faces) +
                                   ") and " + b.name + " (patches " + facesText(b.faces) +
                                   ") overlap on sheet " + std::to_string(a.sheet + 1) + ".");
        pattern.overlaps.push_back(std::move(overlap));
    }
    return pattern;
}

} // namespace devsurf::model
