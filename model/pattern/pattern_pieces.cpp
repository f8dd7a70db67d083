#include "pattern_pieces.h"
#include "model/derived_geometry.h"

#include "model/bspline_curve.h"
#include "model/creases.h"
#include "model/development.h"
#include "model/plane_motion.h"
#include "model/sampled_mesh.h"
#include "pattern_cut.h"
#include "pattern_geometry.h"
#include "pattern_kept_sheet.h"
#include "pattern_labels.h"
#include "pattern_overlaps.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace devsurf::model::pattern {

namespace {

double pointSegmentDistance3(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 d = b - a;
    const double length2 = d.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp(dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
    return distance(p, a + d * t);
}

// The rotation that shows a piece as the surface is seen in the 3D view: a mostly horizontal
// piece as from above (x right, y up), a mostly vertical one from the front (x right, z up) or
// the side (y right, z up), whichever it faces more. It is the least-squares rotation of the
// developed edge vectors onto the projected 3D edge vectors (mirrored parts, such as the back
// of a cylinder, cancel out and leave "up" as up).
double viewAngle(const SampledMesh& mesh, const std::vector<Vec2>& flat,
                 const std::vector<int>& faces) {
    Vec3 facing;
    for (int f : faces) {
        const auto& face = mesh.faces[static_cast<std::size_t>(f)];
        Vec3 normal;
        for (std::size_t i = 0; i < face.size(); ++i) {
            normal += cross(mesh.vertices[static_cast<std::size_t>(face[i])],
                            mesh.vertices[static_cast<std::size_t>(face[(i + 1) % face.size()])]);
        }
        facing += Vec3(std::abs(normal.x), std::abs(normal.y), std::abs(normal.z));
    }
    int view = 2; // from above
    if (facing.z < std::max(facing.x, facing.y)) {
        view = facing.y >= facing.x ? 1 : 0; // from the front : from the side
    }
    auto project = [view](const Vec3& e) {
        return view == 2 ? Vec2(e.x, e.y) : (view == 1 ? Vec2(e.x, e.z) : Vec2(e.y, e.z));
    };
    double sumCross = 0.0;
    double sumDot = 0.0;
    for (int f : faces) {
        const auto& face = mesh.faces[static_cast<std::size_t>(f)];
        for (std::size_t i = 0; i < face.size(); ++i) {
            const auto a = static_cast<std::size_t>(face[i]);
            const auto b = static_cast<std::size_t>(face[(i + 1) % face.size()]);
            const Vec2 d = flat[b] - flat[a];
            const Vec2 target = project(mesh.vertices[b] - mesh.vertices[a]);
            sumCross += cross2(d, target);
            sumDot += dot2(d, target);
        }
    }
    return std::atan2(sumCross, sumDot);
}

} // namespace

std::string pieceName(int index) {
    std::string name;
    for (int i = index; i >= 0; i = i / 26 - 1) {
        name.insert(name.begin(), static_cast<char>('A' + i % 26));
    }
    return name;
}

int samplesForTolerance(const CompositeSurface& surface, double tolerance) {
    const double bound = std::max(tolerance, 1e-9);
    int samples = 1;
    for (const auto& [id, record] : surface.edges()) {
        if (!record.isSpline()) {
            continue;
        }
        const BSplineCurve curve = BSplineCurve::uniform(record.space, record.controlPoints);
        while (samples < 1000) {
            const int count = record.space.intervals * samples;
            double worst = 0.0;
            Vec3 previous = curve.evaluate(0.0);
            for (int i = 1; i <= count; ++i) {
                const Vec3 next = curve.evaluate(static_cast<double>(i) / count);
                for (double q : {0.25, 0.5, 0.75}) {
                    const Vec3 p = curve.evaluate((i - 1 + q) / count);
                    worst = std::max(worst, pointSegmentDistance3(p, previous, next));
                }
                previous = next;
            }
            if (worst <= bound) {
                break;
            }
            samples = std::min(1000, samples * 2);
        }
    }
    return samples;
}

namespace {

// The pieces of the surface cut open along cutEdges (fewer where the cut is not needed).
std::vector<PieceBuild> developAlong(const CompositeSurface& surface, int surfaceIndex,
                                     const PatternOptions& options, int& nameIndex,
                                     std::set<EdgeId> cutEdges) {
    const int samples = options.samplesPerInterval > 0
                            ? std::min(options.samplesPerInterval, 1000)
                            : samplesForTolerance(surface, options.tolerance);
    const auto derived = DerivedGeometry::of(surface, samples);
    const SampledMesh& mesh = derived->mesh();
    CutMesh cut = splitAlong(mesh, cutSegments(surface, mesh, cutEdges));
    Development development = unfoldSampledMesh(cut.mesh);
    bool laid = false;
    if (!cutEdges.empty() && copiesCoincide(cut, development, options.tolerance)) {
        cutEdges.clear();
        cut = splitAlong(mesh, {});
        development = unfoldSampledMesh(cut.mesh);
    } else if (!cutEdges.empty()) {
        // A kept sheet that closes around a hole closes at its own sampling; the finer
        // unfolding here of the curves between its samples need not (a folded annulus: by
        // 0.9 mm). Laid onto the kept sheet, the copies of the cut meet, and it is not cut.
        Development onSheet = development;
        if (layOntoKeptSheet(surface, mesh, cut, onSheet) &&
            copiesCoincide(cut, onSheet, options.tolerance)) {
            CutMesh whole = splitAlong(mesh, {});
            std::vector<int> anyCopy(mesh.vertices.size(), 0);
            for (std::size_t v = 0; v < cut.original.size(); ++v) {
                anyCopy[static_cast<std::size_t>(cut.original[v])] = static_cast<int>(v);
            }
            development.vertices.assign(whole.mesh.vertices.size(), Vec2());
            for (std::size_t v = 0; v < whole.original.size(); ++v) {
                development.vertices[v] = onSheet.vertices[static_cast<std::size_t>(
                    anyCopy[static_cast<std::size_t>(whole.original[v])])];
            }
            cut = std::move(whole);
            cutEdges.clear();
            laid = true;
        }
    }
    if (cutEdges.empty() && !laid) {
        layOntoKeptSheet(surface, mesh, cut, development);
    }

    // Pieces: the connected parts of the cut mesh.
    const std::size_t vertexCount = cut.mesh.vertices.size();
    std::vector<int> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&parent](int v) {
        while (parent[static_cast<std::size_t>(v)] != v) {
            v = parent[static_cast<std::size_t>(v)] =
                parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
        }
        return v;
    };
    for (const auto& face : cut.mesh.faces) {
        for (int v : face) {
            const int a = find(face[0]);
            const int b = find(v);
            parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
        }
    }
    std::map<int, std::size_t> pieceOfRoot;
    std::vector<std::vector<int>> pieceFaces;
    for (std::size_t f = 0; f < cut.mesh.faces.size(); ++f) {
        const auto [it, inserted] = pieceOfRoot.emplace(find(cut.mesh.faces[f][0]), 0);
        if (inserted) {
            it->second = pieceFaces.size();
            pieceFaces.emplace_back();
        }
        pieceFaces[it->second].push_back(static_cast<int>(f));
    }
    auto pieceOf = [&](int v) { return pieceOfRoot.at(find(v)); };

    std::vector<PieceBuild> builds(pieceFaces.size());
    std::vector<Vec2> flat(vertexCount);
    std::vector<int> local(vertexCount, -1);
    std::map<EdgeKey, int> uses; // faces per edge of the cut mesh
    for (const auto& face : cut.mesh.faces) {
        for (std::size_t k = 0; k < face.size(); ++k) {
            const int a = face[k];
            const int b = face[(k + 1) % face.size()];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::vector<std::map<int, int>> outlineIndex(pieceFaces.size());
    for (std::size_t p = 0; p < pieceFaces.size(); ++p) {
        PatternPiece& piece = builds[p].piece;
        piece.surface = surfaceIndex;
        piece.name = pieceName(nameIndex++);
        const Placement turn{viewAngle(cut.mesh, development.vertices, pieceFaces[p]), Vec2()};
        for (int f : pieceFaces[p]) {
            const auto& face = cut.mesh.faces[static_cast<std::size_t>(f)];
            std::vector<int> localFace;
            for (int v : face) {
                auto& index = local[static_cast<std::size_t>(v)];
                if (index < 0) {
                    index = static_cast<int>(piece.mesh.vertices.size());
                    flat[static_cast<std::size_t>(v)] =
                        turn.apply(development.vertices[static_cast<std::size_t>(v)]);
                    piece.mesh.vertices.push_back(flat[static_cast<std::size_t>(v)]);
                }
                localFace.push_back(index);
            }
            // Fabrication figures over the sampled mesh, in mm.
            std::vector<Vec2> polygon;
            for (std::size_t k = 0; k < face.size(); ++k) {
                const auto a = static_cast<std::size_t>(face[k]);
                const auto b = static_cast<std::size_t>(face[(k + 1) % face.size()]);
                polygon.push_back(flat[a]);
                piece.maxIsometryError =
                    std::max(piece.maxIsometryError,
                             std::abs(distance(cut.mesh.vertices[a], cut.mesh.vertices[b]) -
                                      (flat[a] - flat[b]).norm()));
            }
            piece.area += std::abs(signedArea(polygon));
            piece.mesh.faces.push_back(std::move(localFace));
            piece.mesh.faceOrigin.push_back(cut.mesh.faceOrigin[static_cast<std::size_t>(f)]);
        }
        piece.faces = piece.mesh.faceOrigin;
        std::sort(piece.faces.begin(), piece.faces.end());
        piece.faces.erase(std::unique(piece.faces.begin(), piece.faces.end()), piece.faces.end());

        // Outline: the boundary loop enclosing the largest area; the others are holes.
        std::vector<std::vector<int>> loops = boundaryLoops(piece.mesh.faces);
        std::vector<double> areas;
        for (const auto& loop : loops) {
            std::vector<Vec2> points;
            for (int v : loop) {
                points.push_back(piece.mesh.vertices[static_cast<std::size_t>(v)]);
            }
            areas.push_back(signedArea(points));
        }
        if (loops.empty()) {
            continue;
        }
        const std::size_t outer = static_cast<std::size_t>(
            std::max_element(areas.begin(), areas.end(),
                             [](double a, double b) { return std::abs(a) < std::abs(b); }) -
            areas.begin());
        const bool mirrored = areas[outer] < 0.0;
        for (std::size_t l = 0; l < loops.size(); ++l) {
            if (mirrored) {
                std::reverse(loops[l].begin(), loops[l].end());
            }
            std::vector<Vec2> points;
            for (int v : loops[l]) {
                points.push_back(piece.mesh.vertices[static_cast<std::size_t>(v)]);
            }
            PatternPath path;
            path.layer = PatternLayer::Cut;
            path.points = points;
            path.closed = true;
            piece.paths.push_back(std::move(path));
            if (l == outer) {
                piece.outline = std::move(points);
                for (std::size_t i = 0; i < loops[l].size(); ++i) {
                    outlineIndex[p][loops[l][i]] = static_cast<int>(i);
                }
            } else {
                piece.holes.push_back(std::move(points));
            }
        }
    }
    auto point = [&flat](int v) { return flat[static_cast<std::size_t>(v)]; };
    auto points = [&point](const std::vector<int>& line) {
        std::vector<Vec2> result;
        for (int v : line) {
            result.push_back(point(v));
        }
        return result;
    };
    auto onBoundary = [&uses](int a, int b) {
        const auto it = uses.find({std::min(a, b), std::max(a, b)});
        return it != uses.end() && it->second == 1;
    };

    // Coarse vertices (twice along a seam) and edges, creases and rulings, on their pieces.
    const auto copies = edgeCopies(mesh, cut);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const auto original = static_cast<std::size_t>(cut.original[v]);
        if (original < mesh.coarseVertexIds.size()) {
            builds[pieceOf(static_cast<int>(v))].piece.vertices.emplace_back(
                mesh.coarseVertexIds[original], flat[v]);
        }
    }
    std::map<EdgeId, Crease> folds;
    for (const Crease& crease : creasesOf(surface, stripsOf(surface), mesh)) {
        folds.emplace(crease.edge, crease);
    }
    std::map<EdgeId, std::vector<int>> sampled;
    for (const auto& line : mesh.splineEdges) {
        sampled.emplace(line.edge, line.vertices);
    }
    std::map<VertexId, int> coarse;
    for (std::size_t i = 0; i < mesh.coarseVertexIds.size(); ++i) {
        coarse[mesh.coarseVertexIds[i]] = static_cast<int>(i);
    }
    std::vector<int> seamCount(builds.size(), 0);
    for (const auto& [id, record] : surface.edges()) {
        const auto it = sampled.find(id);
        const std::vector<int> line =
            it != sampled.end() ? it->second
                                : std::vector<int>{coarse.at(record.from), coarse.at(record.to)};
        const bool isCut = cutEdges.count(id) != 0;
        const bool glued = std::find(options.gluedEdges.begin(), options.gluedEdges.end(),
                                     std::make_pair(surfaceIndex, id)) != options.gluedEdges.end();
        std::vector<std::vector<int>> sides = polylineCopies(line, copies);
        std::map<std::size_t, int> seamNumber; // per piece
        for (const auto& side : sides) {
            const std::size_t p = pieceOf(side.front());
            PatternPiece& piece = builds[p].piece;
            const bool boundary = onBoundary(side[0], side[1]);
            PatternPath curve;
            curve.layer = boundary
                              ? PatternLayer::Cut
                              : (record.isSpline() ? PatternLayer::Crease : PatternLayer::Score);
            curve.points = points(side);
            curve.edge = id;
            const auto fold = folds.find(id);
            if (fold != folds.end() && !boundary) {
                PatternPath crease = curve;
                crease.face = fold->second.left.face;
                crease.foldAngleDegrees = fold->second.foldAngleDegrees;
                if (fold->second.assignment != FoldAssignment::Flat) {
                    crease.layer = fold->second.assignment == FoldAssignment::Mountain
                                       ? PatternLayer::Mountain
                                       : PatternLayer::Valley;
                }
                piece.paths.push_back(std::move(crease));
            }
            piece.edgeCurves.push_back(std::move(curve));

            // Where a side of a cut-open seam, or a chosen glued edge, lies on the outline.
            const auto& index = outlineIndex[p];
            const auto first = index.find(side.front());
            const auto last = index.find(side.back());
            if (!(isCut || glued) || side.size() < 2 || first == index.end() ||
                last == index.end()) {
                continue;
            }
            const int n = static_cast<int>(piece.outline.size());
            const auto& local2 = piece.outline;
            SeamRun run;
            run.edge = id;
            if (local2[static_cast<std::size_t>((first->second + 1) % n)] == point(side[1])) {
                run.first = first->second;
                run.last = last->second;
            } else {
                run.first = last->second;
                run.last = first->second;
            }
            const auto [numberIt, fresh] = seamNumber.emplace(p, 0);
            if (fresh) {
                numberIt->second = ++seamCount[p];
            }
            run.seam = numberIt->second;
            builds[p].seams.push_back(run);
        }
    }
    for (const auto& [a, b] : mesh.rulings) {
        for (const auto& side : polylineCopies({a, b}, copies)) {
            PatternPiece& piece = builds[pieceOf(side.front())].piece;
            piece.rulingSegments.push_back({point(side[0]), point(side[1])});
            if (options.rulings && !onBoundary(side[0], side[1])) {
                PatternPath ruling;
                ruling.layer = PatternLayer::Score;
                ruling.points = {point(side[0]), point(side[1])};
                piece.paths.push_back(std::move(ruling));
            }
        }
    }
    for (PieceBuild& build : builds) {
        choosePrimarySides(build);
        addPieceLabel(build.piece);
        addSeamLabels(build);
    }
    return builds;
}

bool isClosed(const CompositeSurface& surface) {
    for (const auto& [id, record] : surface.edges()) {
        (void)record;
        if (surface.facesOfEdge(id).size() != 2) {
            return false;
        }
    }
    return !surface.edges().empty();
}

bool anyOverlapsItself(const std::vector<PieceBuild>& builds) {
    std::vector<FaceId> faces;
    return std::any_of(builds.begin(), builds.end(), [&faces](const PieceBuild& build) {
        return selfOverlaps(build.piece, faces);
    });
}

double worstIsometryError(const std::vector<PieceBuild>& builds) {
    double worst = 0.0;
    for (const PieceBuild& build : builds) {
        worst = std::max(worst, build.piece.maxIsometryError);
    }
    return worst;
}

// mm: a piece whose edges are off by more does not close up where it was cut open.
constexpr double kRowsIsometryError = 1.0;

} // namespace

std::vector<PieceBuild> developSurface(const CompositeSurface& surface, int surfaceIndex,
                                       const PatternOptions& options, int& nameIndex) {
    const int first = nameIndex;
    const std::set<EdgeId> cutOpen = chooseCutEdges(surface);
    std::vector<PieceBuild> builds =
        developAlong(surface, surfaceIndex, options, nameIndex, cutOpen);
    // A surface that closes around (closed, or cut open to develop at all) may have no one
    // sheet to keep: where its pieces overlap themselves or do not close up (an edge off its
    // length by more than kRowsIsometryError), it is cut along its creases too (a torus of
    // cones, or rings of cones laid around a closed shape: one annular sector per row of
    // strips), if that is better.
    if ((isClosed(surface) || !cutOpen.empty()) &&
        (anyOverlapsItself(builds) || worstIsometryError(builds) > kRowsIsometryError)) {
        int next = first;
        std::vector<PieceBuild> rows =
            developAlong(surface, surfaceIndex, options, next, chooseCutEdges(surface, true));
        if (!anyOverlapsItself(rows) &&
            (anyOverlapsItself(builds) || worstIsometryError(rows) < worstIsometryError(builds))) {
            nameIndex = next;
            return rows;
        }
    }
    return builds;
}

} // namespace devsurf::model::pattern
