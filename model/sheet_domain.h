#pragma once

// The sheet a kept development is confined to (§5, "isometric mapping to a domain", Fig. 12,
// 13): a rectangle, a disk, an annulus or an imported outline, placed in the development's
// plane. Its boundary curves confine the development's boundary loops; its corners fix the
// development vertices nearest to them. Or a cylinder (Fig. 14): the development of a surface
// that closes around is periodic, its coordinates read modulo (2πr, 0), and otherwise free.

#include "problem.h"
#include "reference_curve.h"
#include "vec3.h"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace devsurf::model {

struct SampledMesh;

enum class SheetShape : std::uint8_t {
    Free = 0,
    Rectangle = 1,
    Disk = 2,
    Annulus = 3,
    Outline = 4,
    Cylinder = 5
};

struct SheetDomain {
    SheetShape shape = SheetShape::Free;
    double width = 0.0;       // Rectangle
    double height = 0.0;      // Rectangle
    double radius = 0.0;      // Disk; the outer circle of an Annulus; Cylinder
    double innerRadius = 0.0; // Annulus
    // Outline: closed loops in mm in their own frame, the largest the outer boundary, the
    // others holes; a loop does not repeat its first point.
    std::vector<std::vector<Vec2>> outline;
    // Where the shape lies in the development's plane: its frame turned by `angle` (radians,
    // counter-clockwise) and moved to `centre` (the rectangle's and circles' centre, the
    // outline frame's origin).
    Vec2 centre;
    double angle = 0.0;
    // Curves drawn in the sheet, in its own frame (the outline's frame; the rectangle's and
    // circles' centre at the origin), that creases are confined to (§5, "crease vertices on a
    // curve in the sheet"): a crease S-edge listed in creaseCurveOf has the development of
    // every sample on its curve (model/sheet_creases.h). A closed curve's last point is not
    // repeated; an open one goes on along its end segments.
    struct Curve {
        std::vector<Vec2> points;
        bool closed = false;
        bool operator==(const Curve& other) const {
            return points == other.points && closed == other.closed;
        }
    };
    std::vector<Curve> creaseCurves;
    std::map<EdgeId, int> creaseCurveOf; // crease S-edge -> index into creaseCurves

    bool isFree() const { return shape == SheetShape::Free; }
    bool operator==(const SheetDomain& other) const;
    bool operator!=(const SheetDomain& other) const { return !(*this == other); }
};

// The period of a cylinder's development, (2πr, 0) turned by its angle; none for the others.
std::optional<Vec2> domainPeriod(const SheetDomain& domain);

// The whole number k for which `p` + k · period lies nearest to `near` (0 without a period):
// where a face or curve of a periodic development crosses the cut, its vertices are read
// shifted so that they lie together.
int periodShift(const Vec2& near, const Vec2& p, const std::optional<Vec2>& period);

// One boundary curve of a placed domain: a circle, or a closed polygon.
struct DomainLoop {
    bool circle = false;
    bool open = false; // a polygon whose last point does not join its first (a crease curve)
    // A polygon standing for a smooth curve (a drawn crease curve): the normal blends along
    // each side from the mean normals at its ends, so that the tangent-line condition does
    // not jump where a point crosses a polygon vertex.
    bool smooth = false;
    Vec2 centre;               // circle
    double radius = 0.0;       // circle
    std::vector<Vec2> polygon; // counter-clockwise for the outer loop, clockwise for holes
    bool outer = true;         // the domain's outer boundary (false: a hole)
};

// The nearest point of a loop to p and the loop's unit normal there (pointing out of the
// sheet), so that dot(normal, p − point) is the signed distance of p outside the sheet.
struct DomainFoot {
    Vec2 point;
    Vec2 normal;
};

// The boundary loops of the placed domain (empty for a free sheet and a cylinder).
std::vector<DomainLoop> domainLoops(const SheetDomain& domain);
DomainFoot footPoint(const DomainLoop& loop, const Vec2& p);
// The placed domain's corners: a rectangle's four, an outline's vertices turning by 30° or more.
std::vector<Vec2> domainCorners(const SheetDomain& domain);
// The sheet's area (mm²), holes taken off.
double domainArea(const SheetDomain& domain);

// The problem with a domain's sizes (not finite, not positive, an inner radius not below the
// outer, an outline without an outer loop of three points), if any.
std::optional<Problem> domainProblem(const SheetDomain& domain);

// Which development vertices the domain holds, for a mesh and a development of it: every
// vertex of the development's outer boundary loop on the domain's outer loop, every vertex of
// another boundary loop on the domain's hole nearest to it (free if the domain has no holes),
// and for each corner the boundary vertex nearest to it fixed there.
struct DomainAssignment {
    struct OnLoop {
        int vertex = 0; // mesh vertex
        int loop = 0;   // index into domainLoops()
    };
    struct AtCorner {
        int vertex = 0;
        Vec2 corner;
    };
    std::vector<OnLoop> onLoops; // corner vertices excluded
    std::vector<AtCorner> atCorners;
};
DomainAssignment assignToDomain(const SheetDomain& domain, const SampledMesh& mesh,
                                const std::vector<Vec2>& development);

// The domain moved and turned so that its boundary lies closest (least squares) to the
// development's boundary: circles centred on the outer loop's area centroid; a rectangle or
// an outline centred there too and turned to the best of a search over the angle. A cylinder
// stays as it is.
SheetDomain placeDomain(SheetDomain domain, const SampledMesh& mesh,
                        const std::vector<Vec2>& development);

// A sheet of `shape` that just holds the development, placed on it: the smallest-area
// rectangle around it, the disk around its outer loop's centroid through its farthest vertex,
// the annulus from that to the nearest vertex of its holes (half the outer radius without
// holes); for the circles the vertices are the design's own (the mesh's coarse vertices) where
// a loop has any. Free for Free, Outline and Cylinder (whose radius is the unfolding's period).
SheetDomain fittingDomain(SheetShape shape, const SampledMesh& mesh,
                          const std::vector<Vec2>& development);

// The area of a development of a mesh: the sum of its faces' areas (mm²).
double developedArea(const SampledMesh& mesh, const std::vector<Vec2>& development);

// The closed curves among `curves` seen from above (z dropped) as an outline's loops: a curve
// is closed when it ends where it starts (within 1e-6 of its length) and has three points
// or more; the repeated last point is dropped.
std::vector<std::vector<Vec2>> closedLoopsFromAbove(const std::vector<ReferenceCurve>& curves);

// The largest distance of a vertex the domain holds from its loop or corner (mm).
double largestDomainGap(const SheetDomain& domain, const SampledMesh& mesh,
                        const std::vector<Vec2>& development);

} // namespace devsurf::model
