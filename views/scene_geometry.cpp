#include "scene_geometry.h"
#include "model/derived_geometry.h"

#include "model/pattern/cutting_pattern.h"
#include "model/pattern/pattern_layout.h"
#include "model/pattern/pattern_overlaps.h"
#include "model/pattern/pattern_sheet.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"
#include "solver/quality/quality_measures.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <set>

namespace devsurf::views {

using model::EdgeId;
using model::FaceId;
using model::Vec2;
using model::Vec3;
using model::VertexId;

namespace {

// Mesh index of every coarse vertex (the sampled mesh lists them first).
std::map<VertexId, int> coarseIndex(const model::SampledMesh& mesh) {
    std::map<VertexId, int> index;
    for (std::size_t i = 0; i < mesh.coarseVertexIds.size(); ++i) {
        index[mesh.coarseVertexIds[i]] = static_cast<int>(i);
    }
    return index;
}

// The coarse edges as index polylines into the sampled mesh, in their stored orientation.
std::vector<std::pair<EdgeId, std::vector<int>>>
edgePolylines(const model::CompositeSurface& surface, const model::SampledMesh& mesh) {
    const std::map<VertexId, int> index = coarseIndex(mesh);
    std::map<EdgeId, std::vector<int>> sampled;
    for (const auto& line : mesh.splineEdges) {
        sampled[line.edge] = line.vertices;
    }
    std::vector<std::pair<EdgeId, std::vector<int>>> result;
    for (const auto& [id, record] : surface.edges()) {
        auto it = sampled.find(id);
        if (it != sampled.end()) {
            result.emplace_back(id, it->second);
        } else {
            result.emplace_back(id, std::vector<int>{index.at(record.from), index.at(record.to)});
        }
    }
    return result;
}

EdgeCurve makeCurve(const model::CompositeSurface& surface, EdgeId id) {
    EdgeCurve curve;
    curve.id = id;
    curve.spline = surface.edge(id).isSpline();
    const std::size_t faces = surface.facesOfEdge(id).size();
    curve.crease = curve.spline && faces == 2;
    curve.boundary = faces == 1;
    if (curve.crease) {
        curve.condition = surface.edge(id).condition;
    }
    curve.smooth = !curve.spline && faces == 2 && surface.edge(id).smooth;
    return curve;
}

Vec3 toScene(const Vec2& p) {
    return {p.x, p.y, 0.0};
}

// The polygons of a strip patch are its sampled quads in the order of u (model::sampleSurface),
// so the k-th polygon of a patch is segment k of solver::developabilityOfPatches.
void addQualityMeasures(const model::CompositeSurface& surface, const model::SampledMesh& mesh,
                        SurfaceScene& scene) {
    std::map<FaceId, const solver::PatchDevelopability*> byFace;
    const std::vector<solver::PatchDevelopability> patches =
        solver::developabilityOfPatches(surface, kSamplesPerInterval);
    for (const solver::PatchDevelopability& patch : patches) {
        byFace[patch.face] = &patch;
    }
    std::map<FaceId, std::size_t> polygonsSoFar;
    scene.polygonDevelopability.reserve(scene.polygons.size());
    for (FaceId face : scene.polygonFace) {
        const std::size_t k = polygonsSoFar[face]++;
        const auto patch = byFace.find(face);
        if (patch == byFace.end()) {
            scene.polygonDevelopability.push_back(0.0); // cones and planar patches
        } else {
            const std::vector<double>& segments = patch->second->segments;
            scene.polygonDevelopability.push_back(k < segments.size() ? segments[k]
                                                                      : patch->second->worst);
        }
    }
    scene.polygonFlatness = solver::faceFlatness(mesh); // one polygon per sampled face
    const std::vector<double> defects = solver::vertexAngleDefects(mesh);
    scene.pointAngleDefect.reserve(scene.pointOrigin.size());
    for (int v : scene.pointOrigin) {
        scene.pointAngleDefect.push_back(defects[static_cast<std::size_t>(v)]);
    }
}

} // namespace

SurfaceScene buildSpatialScene(const model::CompositeSurface& surface, int surfaceIndex) {
    const auto derived = model::DerivedGeometry::of(surface, kSamplesPerInterval);
    const model::SampledMesh& mesh = derived->mesh();
    SurfaceScene scene;
    scene.surface = surfaceIndex;

    // One copy of a sampled vertex per coarse face: normals are smooth inside a patch and
    // break at creases, where the surface has a kink.
    std::map<std::pair<FaceId, int>, int> local;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const FaceId face = mesh.faceOrigin[f];
        std::vector<int> polygon;
        for (int v : mesh.faces[f]) {
            auto [it, inserted] = local.emplace(std::make_pair(face, v), 0);
            if (inserted) {
                it->second = static_cast<int>(scene.points.size());
                scene.points.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
                scene.normals.emplace_back();
                scene.pointOrigin.push_back(v);
            }
            polygon.push_back(it->second);
        }
        // Newell's normal: robust for quads that are not exactly planar and for triangles.
        Vec3 normal;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const Vec3& a = scene.points[static_cast<std::size_t>(polygon[i])];
            const Vec3& b =
                scene.points[static_cast<std::size_t>(polygon[(i + 1) % polygon.size()])];
            normal += cross(a, b);
        }
        for (int p : polygon) {
            scene.normals[static_cast<std::size_t>(p)] += normal;
        }
        scene.polygons.push_back(std::move(polygon));
        scene.polygonFace.push_back(face);
    }
    for (Vec3& n : scene.normals) {
        const double len = n.norm();
        n = len > 0.0 ? n / len : Vec3(0.0, 0.0, 1.0);
    }
    addQualityMeasures(surface, mesh, scene);

    std::map<EdgeId, model::FoldAssignment> folds;
    for (const model::Crease& crease : model::creasesOf(surface, model::stripsOf(surface), mesh)) {
        folds[crease.edge] = crease.assignment;
    }
    for (const auto& [id, indices] : edgePolylines(surface, mesh)) {
        EdgeCurve curve = makeCurve(surface, id);
        if (const auto fold = folds.find(id); fold != folds.end()) {
            curve.fold = fold->second;
        }
        for (int v : indices) {
            curve.points.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
        }
        if (curve.spline) {
            const auto& controls = surface.edge(id).controlPoints;
            scene.controlPolygons.push_back(controls);
            for (std::size_t i = 1; i + 1 < controls.size(); ++i) {
                scene.controlPoints.push_back(controls[i]);
            }
        }
        scene.edges.push_back(std::move(curve));
    }
    scene.vertices = surface.vertices();
    const auto pinned = surface.pinnedVertices();
    scene.pinned.insert(pinned.begin(), pinned.end());
    return scene;
}

namespace {

model::PatternOptions viewPatternOptions() {
    model::PatternOptions options;
    options.layout = false;                           // the pieces side by side, no sheets
    options.gap = 20.0;                               // mm between the pieces
    options.samplesPerInterval = kSamplesPerInterval; // as the 3D view samples the curves
    return options;
}

// The scenes of laid-out pieces; overlapping lists the pieces drawn outlined in red.
DevelopmentScenes scenesOfPieces(const model::Project& project,
                                 const std::vector<model::PatternPiece>& pieces,
                                 const std::set<std::size_t>& overlapping);

} // namespace

DevelopmentScenes buildDevelopmentScenes(const model::Project& project) {
    const model::CuttingPattern pattern = model::buildCuttingPattern(project, viewPatternOptions());
    std::set<std::size_t> overlapping;
    for (const model::PatternOverlap& overlap : pattern.overlaps) {
        overlapping.insert(static_cast<std::size_t>(overlap.first));
        overlapping.insert(static_cast<std::size_t>(overlap.second));
    }
    return scenesOfPieces(project, pattern.pieces, overlapping);
}

SurfaceDevelopment developSurfaceForView(const model::CompositeSurface& surface, int surfaceIndex) {
    SurfaceDevelopment result;
    if (!surface.validate().empty()) {
        result.invalid = true;
        return result;
    }
    int nameIndex = 0;
    try {
        result.pieces =
            model::developSurfacePieces(surface, surfaceIndex, viewPatternOptions(), nameIndex);
    } catch (const std::exception&) {
        result.pieces.clear(); // not developed: neither drawn nor reported as invalid
    }
    return result;
}

DevelopmentScenes layOutDevelopments(const model::Project& project,
                                     const std::vector<const SurfaceDevelopment*>& developments) {
    const model::PatternOptions options = viewPatternOptions();
    std::vector<model::PatternPiece> pieces;
    std::vector<std::string> surfaceNames;
    for (std::size_t s = 0; s < developments.size(); ++s) {
        surfaceNames.push_back(s < project.surfaces.size() ? project.surfaces[s].name()
                                                           : std::string());
        for (const model::PatternPiece& piece : developments[s]->pieces) {
            pieces.push_back(piece);
            pieces.back().surface = static_cast<int>(s);
        }
    }
    std::vector<model::PatternProblem> problems; // the development view marks, not words, them
    model::pattern::layoutPieces(pieces, options, surfaceNames, problems);
    std::set<std::size_t> overlapping;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        if (pieces[p].selfOverlapping) {
            overlapping.insert(p);
        }
    }
    for (const model::PatternOverlap& overlap : model::pattern::overlapsBetweenPieces(pieces)) {
        overlapping.insert(static_cast<std::size_t>(overlap.first));
        overlapping.insert(static_cast<std::size_t>(overlap.second));
    }
    return scenesOfPieces(project, pieces, overlapping);
}

namespace {

DevelopmentScenes scenesOfPieces(const model::Project& project,
                                 const std::vector<model::PatternPiece>& pieces,
                                 const std::set<std::size_t>& overlapping) {
    DevelopmentScenes result;
    std::map<int, std::size_t> sceneOf;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        const model::PatternPiece& piece = pieces[p];
        const model::CompositeSurface& surface =
            project.surfaces[static_cast<std::size_t>(piece.surface)];
        auto [it, inserted] = sceneOf.emplace(piece.surface, result.scenes.size());
        if (inserted) {
            result.scenes.emplace_back();
            result.scenes.back().surface = piece.surface;
        }
        SurfaceScene& scene = result.scenes[it->second];
        const int base = static_cast<int>(scene.points.size());
        for (const Vec2& v : piece.mesh.vertices) {
            scene.points.push_back(toScene(v));
        }
        for (std::size_t f = 0; f < piece.mesh.faces.size(); ++f) {
            std::vector<int> polygon;
            for (int v : piece.mesh.faces[f]) {
                polygon.push_back(base + v);
            }
            scene.polygons.push_back(std::move(polygon));
            scene.polygonFace.push_back(piece.mesh.faceOrigin[f]);
        }
        // The pattern's mountain and valley paths say how each crease is folded.
        std::map<EdgeId, model::FoldAssignment> folds;
        for (const model::PatternPath& path : piece.paths) {
            if (path.layer == model::PatternLayer::Mountain) {
                folds[path.edge] = model::FoldAssignment::Mountain;
            } else if (path.layer == model::PatternLayer::Valley) {
                folds[path.edge] = model::FoldAssignment::Valley;
            }
        }
        for (const model::PatternPath& path : piece.edgeCurves) {
            if (!surface.hasEdge(path.edge)) {
                continue;
            }
            EdgeCurve curve = makeCurve(surface, path.edge);
            if (const auto fold = folds.find(path.edge); fold != folds.end() && curve.crease) {
                curve.fold = fold->second;
            }
            for (const Vec2& p2 : path.points) {
                curve.points.push_back(toScene(p2));
            }
            scene.edges.push_back(std::move(curve));
        }
        for (const auto& segment : piece.rulingSegments) {
            scene.rulings.emplace_back(toScene(segment[0]), toScene(segment[1]));
        }
        // The outline is every closed cut loop, so a cut-open seam is drawn on both sides.
        for (const model::PatternPath& path : piece.paths) {
            if (path.layer != model::PatternLayer::Cut || !path.closed) {
                continue;
            }
            for (std::size_t i = 0; i < path.points.size(); ++i) {
                const auto segment = std::make_pair(
                    toScene(path.points[i]), toScene(path.points[(i + 1) % path.points.size()]));
                scene.outline.push_back(segment);
                if (overlapping.count(p) != 0) {
                    scene.overlapOutline.push_back(segment);
                }
            }
        }
        // A held sheet of a shape, drawn behind its development (chords within 0.05 mm).
        for (const std::vector<Vec2>& loop : model::pattern::sheetOnPiece(surface, piece, 0.05)) {
            std::vector<Vec3> closed;
            for (const Vec2& q : loop) {
                closed.push_back(toScene(q));
            }
            closed.push_back(closed.front());
            scene.sheet.push_back(std::move(closed));
        }
        // The curves drawn in it for the creases to follow, in the same line.
        for (const std::vector<Vec2>& curve : model::pattern::creaseCurvesOnPiece(surface, piece)) {
            std::vector<Vec3> line;
            for (const Vec2& q : curve) {
                line.push_back(toScene(q));
            }
            scene.sheet.push_back(std::move(line));
        }
        for (const auto& [id, position] : piece.vertices) {
            if (surface.isPinned(id)) {
                scene.pinned.insert(id);
            }
            if (!scene.vertices.emplace(id, toScene(position)).second) {
                scene.seamVertices.push_back(toScene(position));
            }
        }
    }
    for (std::size_t i = 0; i < project.surfaces.size(); ++i) {
        if (sceneOf.count(static_cast<int>(i)) == 0 && !project.surfaces[i].validate().empty()) {
            result.invalidSurfaces.push_back(static_cast<int>(i));
        }
    }
    return result;
}

} // namespace

std::pair<Vec3, Vec3> sceneBounds(const SurfaceScene& scene) {
    const double inf = std::numeric_limits<double>::infinity();
    Vec3 lo(inf, inf, inf);
    Vec3 hi(-inf, -inf, -inf);
    for (const Vec3& p : scene.points) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    return {lo, hi};
}

std::array<double, 3> patchRgb(FaceId face) {
    // Soft, distinguishable colours that keep black curves and the orange highlight readable.
    static const std::array<std::array<double, 3>, 10> palette = {{
        {0.55, 0.71, 0.89},
        {0.96, 0.73, 0.49},
        {0.60, 0.82, 0.58},
        {0.90, 0.58, 0.60},
        {0.74, 0.65, 0.86},
        {0.78, 0.66, 0.56},
        {0.94, 0.71, 0.84},
        {0.70, 0.80, 0.80},
        {0.88, 0.86, 0.55},
        {0.62, 0.84, 0.87},
    }};
    return palette[face % palette.size()];
}

} // namespace devsurf::views
