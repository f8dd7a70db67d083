#include "example_shapes.h"

#include "development.h"
#include "model/math_constants.h"
#include "model_error.h"
#include "sampled_mesh.h"
#include "sheet_domain.h"

#include <algorithm>
#include <cmath>

namespace devsurf::model::example_shapes {

// The flat composite developable of the paper's Fig. 8: a 300 mm square of size rows of size
// strips each. The rows are bounded by creases that bow 25 mm towards +y (the top and bottom
// boundaries are straight) and split by straight rulings. Every interior crease carries the
// curved-fold condition, and the two corners of the bottom edge are pinned, so that dragging
// interior vertices up folds the sheet along curved creases. (Pinning all four corners would
// make the sheet rigid: the distance between two pinned corners equals the length of the
// straight line joining them in the flat sheet, so an isometric fold must keep that line
// straight and in place, and the lines between four corners hold the whole square.)
CompositeSurface makeFig8(int size) {
    const double width = 300.0;
    const double height = 300.0;
    const double bow = 25.0;
    const SplineSpace space{3, 2, 3};
    CompositeSurface s;
    s.setName("fig8");
    auto crease = [&](int j, double x) {
        const double amount = (j == 0 || j == size) ? 0.0 : bow;
        return Vec3(x, height * j / size + amount * std::sin(kPi * x / width), 0.0);
    };
    auto creaseTangent = [&](int j, double x) {
        const double amount = (j == 0 || j == size) ? 0.0 : bow;
        const Vec3 t(1.0, amount * kPi / width * std::cos(kPi * x / width), 0.0);
        return t / t.norm();
    };
    std::vector<std::vector<VertexId>> grid(size + 1, std::vector<VertexId>(size + 1));
    for (int j = 0; j <= size; ++j) {
        for (int i = 0; i <= size; ++i) {
            grid[j][i] = s.addVertex(crease(j, width * i / size));
        }
    }
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            s.addFace({grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]});
        }
    }
    for (int j = 0; j <= size; ++j) {
        for (int i = 0; i < size; ++i) {
            const double x0 = width * i / size;
            const double x1 = width * (i + 1) / size;
            std::vector<Vec3> points =
                controlPointsAlong(space, s.position(grid[j][i]), s.position(grid[j][i + 1]),
                                   [&](double t) { return crease(j, x0 + t * (x1 - x0)); });
            // The second and the last-but-one control point on the crease's tangent at the
            // ends (at their sampled distances), so that consecutive segments meet
            // tangent-continuously: the crease is one smooth curve through each vertex, as the
            // solver keeps it, and Solve leaves the sheet where it is.
            points = alongEndTangents(points, creaseTangent(j, x0), creaseTangent(j, x1));
            const EdgeId edge = s.setSpline(grid[j][i], grid[j][i + 1], space, points);
            if (j > 0 && j < size) {
                s.setCreaseCondition(edge, CreaseCondition::CurvedFold);
            }
        }
    }
    s.setPinned(grid[0][0], true);
    s.setPinned(grid[0][size], true);
    return s;
}

// A single curved crease in the spirit of the paper's Fig. 6: a 300 × 200 mm rectangle cut by
// a crease that bows 30 mm towards +y into two strips, with the curved-fold condition on the
// crease and the two bottom corners pinned. Lifting the top corners folds it. size is the
// number of spline intervals per curve.
CompositeSurface makeFig6(int intervals) {
    const double width = 300.0;
    const double bow = 30.0;
    const SplineSpace space{3, 2, intervals};
    CompositeSurface s;
    s.setName("fig6");
    auto curve = [&](int row, double x) {
        const double y = 100.0 * row + (row == 1 ? bow * std::sin(kPi * x / width) : 0.0);
        return Vec3(x, y, 0.0);
    };
    VertexId v[3][2];
    for (int row = 0; row < 3; ++row) {
        v[row][0] = s.addVertex(curve(row, 0.0));
        v[row][1] = s.addVertex(curve(row, width));
    }
    s.addFace({v[0][0], v[0][1], v[1][1], v[1][0]});
    s.addFace({v[1][0], v[1][1], v[2][1], v[2][0]});
    for (int row = 0; row < 3; ++row) {
        const EdgeId edge =
            s.setSpline(v[row][0], v[row][1], space,
                        controlPointsAlong(space, s.position(v[row][0]), s.position(v[row][1]),
                                           [&](double t) { return curve(row, t * width); }));
        if (row == 1) {
            s.setCreaseCondition(edge, CreaseCondition::CurvedFold);
        }
    }
    s.setPinned(v[0][0], true);
    s.setPinned(v[0][1], true);
    return s;
}

// A flat disk of radius 150 mm with one curved crease (the paper's Fig. 13): the crease runs
// from the leftmost to the rightmost point of the circle, bowing 40 mm up, with the curved-fold
// condition, and divides the disk into two strips, each ruled straight across from the crease
// to its half of the circle and cut by those rulings into size faces (the outer two ending in
// the crease's end points). The disk keeps its development on a disk-shaped sheet, so that its
// rulings can move in the sheet as it folds (with the development fixed, a flat sheet whose
// rulings are not those of a curved fold cannot start folding).
CompositeSurface makeFig13(int size) {
    const double radius = 150.0;
    const double bow = 40.0;
    const SplineSpace space{3, 2, 2};
    CompositeSurface s;
    s.setName("fig13");
    // Point k of size + 1 along the crease and both arcs shares its x: the rulings are vertical
    // in the sheet and meet the crease from both sides at its interior vertices.
    // (Sines of the smaller angle, so that the middle and the ends come out exact.)
    auto xAt = [&](double k) { return radius * std::sin(kPi * (k / size - 0.5)); };
    auto crease = [&](double k) {
        const double x = xAt(k);
        return Vec3(x, bow * (1.0 - (x / radius) * (x / radius)), 0.0);
    };
    auto creaseTangent = [&](double k) {
        const Vec3 t(1.0, -2.0 * bow * xAt(k) / (radius * radius), 0.0);
        return t / t.norm();
    };
    auto arc = [&](double k, double side) { // side +1: the upper half, −1: the lower
        return Vec3(xAt(k), side * radius * std::sin(kPi * std::min(k, size - k) / size), 0.0);
    };
    std::vector<VertexId> onCrease(size + 1);
    std::vector<VertexId> upper(size + 1);
    std::vector<VertexId> lower(size + 1);
    for (int k = 0; k <= size; ++k) {
        onCrease[k] = s.addVertex(crease(k));
        upper[k] = (k == 0 || k == size) ? onCrease[k] : s.addVertex(arc(k, 1.0));
        lower[k] = (k == 0 || k == size) ? onCrease[k] : s.addVertex(arc(k, -1.0));
    }
    // Both halves counter-clockwise seen from +z; the outer faces end in the crease's ends.
    auto addLoop = [&s](std::vector<VertexId> loop) {
        loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
        if (loop.front() == loop.back()) {
            loop.pop_back();
        }
        s.addFace(loop);
    };
    for (int k = 0; k < size; ++k) {
        addLoop({onCrease[k], onCrease[k + 1], upper[k + 1], upper[k]});
        addLoop({lower[k], lower[k + 1], onCrease[k + 1], onCrease[k]});
    }
    for (int k = 0; k < size; ++k) {
        const double k0 = k;
        auto along = [&](VertexId from, VertexId to, const std::function<Vec3(double)>& f) {
            return controlPointsAlong(space, s.position(from), s.position(to), f);
        };
        std::vector<Vec3> points =
            along(onCrease[k], onCrease[k + 1], [&](double t) { return crease(k0 + t); });
        // Tangent-continuous through the interior crease vertices, as fig8's creases.
        points = alongEndTangents(
            points, k > 0 ? std::optional<Vec3>(creaseTangent(k)) : std::nullopt,
            k + 1 < size ? std::optional<Vec3>(creaseTangent(k + 1)) : std::nullopt);
        const EdgeId fold = s.setSpline(onCrease[k], onCrease[k + 1], space, points);
        s.setCreaseCondition(fold, CreaseCondition::CurvedFold);
        // The rim on the circle, so that the development starts on its sheet.
        s.setSpline(upper[k], upper[k + 1], space,
                    controlPointsThrough(space, s.position(upper[k]), s.position(upper[k + 1]),
                                         [&](double t) { return arc(k0 + t, 1.0); }));
        s.setSpline(lower[k], lower[k + 1], space,
                    controlPointsThrough(space, s.position(lower[k]), s.position(lower[k + 1]),
                                         [&](double t) { return arc(k0 + t, -1.0); }));
    }
    // The crease's middle vertex and the rim point below it pinned: lifting the rim point
    // above them folds the disk. (Two pins with the straight line between them across rulings
    // would keep the strips around that line planar, and a curved crease with a planar side
    // cannot fold.)
    s.setPinned(onCrease[size / 2], true);
    s.setPinned(lower[size / 2], true);
    if (const auto problem = keepDevelopment(s)) {
        throw ModelError(*problem);
    }
    SheetDomain disk;
    disk.shape = SheetShape::Disk;
    disk.radius = radius;
    s.setSheetDomain(
        placeDomain(disk, sampleSurface(s, kDevelopmentSamplesPerInterval), s.development()));
    return s;
}

// A pleated column after Huffman's hexagonal column (the paper's Fig. 14): a tube folded along
// `sectors` upright creases (sectors / 2 ridges, sectors / 2 valleys, their cross-section a
// star), each crease split into four S-edges with the curved-fold condition, the strips
// between them ruled across. As built every strip is planar and every crease straight; drags
// curve them. It closes around, so its development is periodic: it holds that sheet, a
// cylinder whose circumference is the star's perimeter (SheetShape::Cylinder), and three
// vertices of its bottom rim are pinned.
CompositeSurface makeColumn(int sectors) {
    const double ridgeRadius = 100.0;
    const double valleyRadius = 70.0;
    const double height = 240.0;
    const int rows = 4;
    const SplineSpace space{3, 2, 2};
    CompositeSurface s;
    s.setName("column");
    auto at = [&](int i, int j) {
        const double phi = 2.0 * kPi * i / sectors;
        const double r = i % 2 == 0 ? ridgeRadius : valleyRadius;
        return Vec3(r * std::cos(phi), r * std::sin(phi), height * j / rows);
    };
    std::vector<std::vector<VertexId>> grid(rows + 1, std::vector<VertexId>(sectors));
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i < sectors; ++i) {
            grid[j][i] = s.addVertex(at(i, j));
        }
    }
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            // Counter-clockwise around the axis, then up: the normals point out of the tube.
            s.addFace({grid[j][i], grid[j][next], grid[j + 1][next], grid[j + 1][i]});
        }
    }
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < sectors; ++i) {
            const Vec3 from = s.position(grid[j][i]);
            const Vec3 to = s.position(grid[j + 1][i]);
            const EdgeId edge = s.setSpline(
                grid[j][i], grid[j + 1][i], space,
                controlPointsAlong(space, from, to, [&](double t) { return lerp(from, to, t); }));
            s.setCreaseCondition(edge, CreaseCondition::CurvedFold);
        }
    }
    // Three rim vertices a third of the way around from each other. (With the whole rim
    // pinned the held sheet allows no motion near this state: a drag is held back in full.)
    for (int k = 0; k < 3; ++k) {
        s.setPinned(grid[0][k * sectors / 3], true);
    }
    if (const auto problem = keepDevelopment(s)) {
        throw ModelError(*problem);
    }
    return s;
}

} // namespace devsurf::model::example_shapes
