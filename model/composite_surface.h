#pragma once

#include "ids.h"
#include "problem.h"
#include "sheet_domain.h"
#include "spline_space.h"
#include "vec3.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::model {

// The sampling of the sampled mesh (sampleSurface) whose flat copy a surface keeps.
inline constexpr int kDevelopmentSamplesPerInterval = 2;

// R: a ruling (straight segment), S: a spline curve (boundary or crease) (§3.1).
enum class EdgeLabel : std::uint8_t { Ruling = 0, Spline = 1 };

// Condition imposed on an S-edge shared by two strips (§3.3, eqs. 7, 8).
enum class CreaseCondition : std::uint8_t { None = 0, CurvedFold = 1, Geodesic = 2, Straight = 3 };

// Face classes by the labels of their boundary edges (§3.1, Fig. 5).
enum class FaceType : std::uint8_t {
    Invalid = 0,
    StripSRSR = 1, // spline strip between two S-edges
    StripSRS = 2,  // spline strip whose second ruling collapsed to a point
    ConeSRR = 3,   // cone over one S-edge, apex at the opposite vertex
    Planar = 4     // planar polygon bounded by rulings only
};

const char* faceTypeName(FaceType type);
const char* creaseConditionName(CreaseCondition condition);

struct EdgeRecord {
    // The orientation in which the control points run. Reversing it reverses the sequence.
    VertexId from = kInvalidId;
    VertexId to = kInvalidId;
    EdgeLabel label = EdgeLabel::Ruling;
    // Only meaningful for S-edges:
    SplineSpace space;
    std::vector<Vec3> controlPoints; // clamped open curve; front() == from, back() == to
    CreaseCondition condition = CreaseCondition::None;
    // Only meaningful for R-edges shared by two faces: the surface is smooth across the ruling
    // (both faces have the same unit normal along it). Otherwise it may form a straight fold.
    bool smooth = false;

    bool isSpline() const { return label == EdgeLabel::Spline; }
};

// A composite developable (§3.1): a coarse polygon mesh whose edges are labelled R or S, every
// vertex with a position and every S-edge with a control-point sequence. The canonical data are
// the maps below (what is saved and what undo restores); the OpenMesh connectivity is derived
// from them and kept up to date by every mutation.
class CompositeSurface {
public:
    CompositeSurface();
    ~CompositeSurface();
    CompositeSurface(const CompositeSurface& other);
    CompositeSurface& operator=(const CompositeSurface& other);
    CompositeSurface(CompositeSurface&& other) noexcept;
    CompositeSurface& operator=(CompositeSurface&& other) noexcept;

    const std::string& name() const { return m_name; }
    // The surface's id in its project (see SurfaceId); part of the design.
    SurfaceId id() const { return m_id; }
    void setId(SurfaceId id) { m_id = id; }
    void setName(std::string name) { m_name = std::move(name); }

    // --- construction ---------------------------------------------------------------------
    VertexId addVertex(const Vec3& position);
    // Adds a face given as a loop of vertex ids (its orientation). Edges that do not exist yet
    // are created as R-edges oriented along the loop. Throws ModelError (naming the face) when
    // the face would make the mesh non-manifold or refers to unknown vertices.
    FaceId addFace(const std::vector<VertexId>& loop);
    // Labels the edge between a and b as S with the given space and control points running
    // from a to b. Throws ModelError if there is no such edge.
    EdgeId setSpline(VertexId a, VertexId b, const SplineSpace& space,
                     std::vector<Vec3> controlPoints);
    // Labels an edge R and drops its control points.
    void setRuling(EdgeId edge);
    void setCreaseCondition(EdgeId edge, CreaseCondition condition);
    // Marks an R-edge smooth (see EdgeRecord::smooth) or sharp. Throws ModelError for an
    // unknown edge or an S-edge.
    void setSmooth(EdgeId edge, bool smooth);
    // Reverses the stored orientation of an edge (and so its control sequence); the geometry
    // is unchanged.
    void reverseEdge(EdgeId edge);
    // Moves a vertex; the end control points of its S-edges follow, so that the curves keep
    // starting and ending at their vertices.
    void moveVertex(VertexId vertex, const Vec3& position);
    // Moves many vertices as moveVertex does each, in one pass over the edges (moveVertex scans
    // every edge: a solver's write-back of all vertices was quadratic in the design's size). A
    // vertex given twice takes its last position. Throws ModelError, changing nothing, if a
    // vertex does not exist.
    void moveVertices(const std::vector<std::pair<VertexId, Vec3>>& moves);
    void setControlPoints(EdgeId edge, std::vector<Vec3> controlPoints);
    // Pins a vertex (the solver never moves it) or releases it. Throws ModelError for an
    // unknown vertex.
    void setPinned(VertexId vertex, bool pinned);

    // --- the sheet (§5) --------------------------------------------------------------------
    // With keepsDevelopment(), every solve and drag keeps the surface isometric to its
    // development(): a flat position per vertex of sampleSurface(*this,
    // kDevelopmentSamplesPerInterval), the sheet it is folded from. Empty until a solve derives
    // it by unfolding; a change of the combinatorics, of an S-edge's space or of an edge's
    // orientation empties it (the indexing of the samples changes), the setting stays.
    bool keepsDevelopment() const { return m_keepsDevelopment; }
    void setKeepsDevelopment(bool keep);
    const std::vector<Vec2>& development() const { return m_development; }
    void setDevelopment(std::vector<Vec2> development) { m_development = std::move(development); }
    // The sheet the kept development is confined to (free: the development is held as it is;
    // otherwise it may change inside the sheet, its boundary on the sheet's). A setting like
    // keepsDevelopment(): edits keep it; setKeepsDevelopment(false) clears it.
    const SheetDomain& sheetDomain() const { return m_sheetDomain; }
    void setSheetDomain(SheetDomain domain) { m_sheetDomain = std::move(domain); }

    // Construction with explicit ids (file loading). Ids must be new; next ids advance past them.
    void addVertexWithId(VertexId id, const Vec3& position);
    void addEdgeWithId(EdgeId id, const EdgeRecord& record);
    void addFaceWithId(FaceId id, const std::vector<VertexId>& loop);
    void setNextIds(VertexId vertex, EdgeId edge, FaceId face);

    // --- canonical data --------------------------------------------------------------------
    const std::map<VertexId, Vec3>& vertices() const { return m_vertices; }
    const std::map<EdgeId, EdgeRecord>& edges() const { return m_edges; }
    const std::map<FaceId, std::vector<VertexId>>& faces() const { return m_faces; }
    const std::set<VertexId>& pinnedVertices() const { return m_pinned; }
    bool isPinned(VertexId id) const { return m_pinned.count(id) != 0; }
    VertexId nextVertexId() const { return m_nextVertexId; }
    EdgeId nextEdgeId() const { return m_nextEdgeId; }
    FaceId nextFaceId() const { return m_nextFaceId; }

    bool hasVertex(VertexId id) const { return m_vertices.count(id) != 0; }
    bool hasEdge(EdgeId id) const { return m_edges.count(id) != 0; }
    bool hasFace(FaceId id) const { return m_faces.count(id) != 0; }
    const Vec3& position(VertexId id) const;
    const EdgeRecord& edge(EdgeId id) const;
    const std::vector<VertexId>& faceLoop(FaceId id) const;

    // --- connectivity ----------------------------------------------------------------------
    EdgeId edgeBetween(VertexId a, VertexId b) const;   // kInvalidId if none
    std::vector<FaceId> facesOfEdge(EdgeId edge) const; // one or two faces
    std::vector<EdgeId> faceEdges(FaceId face) const; // along the loop, side i = loop[i]→loop[i+1]
    // The control points of the edge between a and b as they run from a to b.
    std::vector<Vec3> controlPointsFrom(VertexId a, VertexId b) const;

    // --- classification and invariants -----------------------------------------------------
    FaceType faceType(FaceId face) const;
    std::string labelString(FaceId face) const; // e.g. "SRSR", in loop order
    // Classes of S-edges connected through faces; every class must have one spline space.
    std::vector<std::vector<EdgeId>> splineClasses() const;
    // Every problem found, as codes naming the entity; empty when the surface is valid.
    std::vector<Problem> validate() const;

    // Distinct control points: vertices plus interior control points of S-edges.
    std::size_t controlPointCount() const;

    // Structural equality of the canonical data (bitwise for coordinates).
    bool operator==(const CompositeSurface& other) const;
    bool operator!=(const CompositeSurface& other) const { return !(*this == other); }

private:
    void insertFace(FaceId id, const std::vector<VertexId>& loop);
    EdgeRecord& mutableEdge(EdgeId id);

    struct Connectivity;

    std::string m_name;
    SurfaceId m_id = 0;
    std::map<VertexId, Vec3> m_vertices;
    std::map<EdgeId, EdgeRecord> m_edges;
    std::map<FaceId, std::vector<VertexId>> m_faces;
    std::set<VertexId> m_pinned;
    bool m_keepsDevelopment = false;
    std::vector<Vec2> m_development;
    SheetDomain m_sheetDomain;
    std::map<std::pair<VertexId, VertexId>, EdgeId> m_edgeByVertices; // key: (min, max)
    VertexId m_nextVertexId = 0;
    EdgeId m_nextEdgeId = 0;
    FaceId m_nextFaceId = 0;
    std::unique_ptr<Connectivity> m_connectivity;
};

} // namespace devsurf::model
