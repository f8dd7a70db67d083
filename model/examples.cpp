#include "examples.h"

#include "bspline_curve.h"
#include "development.h"
#include "held_by_pins.h"
#include "model/math_constants.h"
#include "model_error.h"
#include "sampled_mesh.h"
#include "sheet_creases.h"
#include "sheet_domain.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace devsurf::model {

namespace {

// Control points of a curve in the given space whose Greville abscissae lie on f; this
// reproduces lines exactly and approximates other curves closely. The end points are the
// given vertex positions bit for bit, so the curve starts and ends at its vertices.
std::vector<Vec3> controlPointsAlong(const SplineSpace& space, const Vec3& start, const Vec3& end,
                                     const std::function<Vec3(double)>& f) {
    const std::vector<double> knots = space.knots(false);
    const int count = space.controlPointCount(false);
    const int m = space.degree;
    std::vector<Vec3> points(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        double greville = 0.0;
        for (int j = 1; j <= m; ++j) {
            greville += knots[static_cast<std::size_t>(i + j)];
        }
        points[static_cast<std::size_t>(i)] = f(greville / m);
    }
    points.front() = start;
    points.back() = end;
    return points;
}

// As controlPointsAlong, then corrected a few times by what the curve misses at the Greville
// abscissae, so that a curve such as a circular arc lies on f to a fraction of a micrometre
// rather than inside it by the control polygon's sag.
std::vector<Vec3> controlPointsThrough(const SplineSpace& space, const Vec3& start, const Vec3& end,
                                       const std::function<Vec3(double)>& f) {
    std::vector<Vec3> points = controlPointsAlong(space, start, end, f);
    const std::vector<double> knots = space.knots(false);
    const int m = space.degree;
    for (int round = 0; round < 20; ++round) {
        const BSplineCurve curve = BSplineCurve::uniform(space, points);
        std::vector<Vec3> corrected = points;
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            double greville = 0.0;
            for (int j = 1; j <= m; ++j) {
                greville += knots[i + static_cast<std::size_t>(j)];
            }
            greville /= m;
            corrected[i] = points[i] + (f(greville) - curve.evaluate(greville));
        }
        points = std::move(corrected);
    }
    return points;
}

Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
    return a * (1.0 - t) + b * t;
}

// A flat rectangle cut into size × size strips: rows bounded by straight S-edges (creases),
// split by rulings into size faces each (Fig. 8).
CompositeSurface makeSheet(int size) {
    const double width = 300.0;
    const double height = 300.0;
    const SplineSpace space{3, 2, 3};
    CompositeSurface s;
    s.setName("sheet");
    std::vector<std::vector<VertexId>> grid(size + 1, std::vector<VertexId>(size + 1));
    for (int j = 0; j <= size; ++j) {
        for (int i = 0; i <= size; ++i) {
            grid[j][i] = s.addVertex({width * i / size, height * j / size, 0.0});
        }
    }
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            s.addFace({grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]});
        }
    }
    for (int j = 0; j <= size; ++j) {
        for (int i = 0; i < size; ++i) {
            const Vec3 p = s.position(grid[j][i]);
            const Vec3 q = s.position(grid[j][i + 1]);
            s.setSpline(grid[j][i], grid[j][i + 1], space,
                        controlPointsAlong(space, p, q, [&](double t) { return lerp(p, q, t); }));
        }
    }
    return s;
}

// A flat annulus cut into rings by concentric circular creases and into sectors by radial
// rulings (Fig. 12). Its arcs have their control points' Greville abscissae on the circles,
// or, `throughCircles`, lie on them (controlPointsThrough), so that a held annulus's rims lie
// on its annulus sheet rather than sag 1 mm inside it.
CompositeSurface makeAnnulus(int rings, bool throughCircles) {
    const int sectors = std::max(3, static_cast<int>(std::lround(4.0 * rings / 3.0)));
    const double innerRadius = 100.0;
    const double ringWidth = 150.0 / rings;
    const SplineSpace space{3, 2, 3};
    CompositeSurface s;
    s.setName("annulus");
    auto angle = [sectors](int i) { return 2.0 * kPi * i / sectors; };
    auto onCircle = [](double r, double phi) {
        return Vec3(r * std::cos(phi), r * std::sin(phi), 0);
    };
    std::vector<std::vector<VertexId>> grid(rings + 1, std::vector<VertexId>(sectors));
    for (int j = 0; j <= rings; ++j) {
        for (int i = 0; i < sectors; ++i) {
            grid[j][i] = s.addVertex(onCircle(innerRadius + ringWidth * j, angle(i)));
        }
    }
    for (int j = 0; j < rings; ++j) {
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            // Counter-clockwise seen from +z, so the normal points up as in the other examples.
            s.addFace({grid[j][i], grid[j + 1][i], grid[j + 1][next], grid[j][next]});
        }
    }
    for (int j = 0; j <= rings; ++j) {
        const double r = innerRadius + ringWidth * j;
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            const double phi0 = angle(i);
            const double phi1 = angle(i + 1);
            const auto arc = [&](double t) { return onCircle(r, phi0 + t * (phi1 - phi0)); };
            const Vec3 from = s.position(grid[j][i]);
            const Vec3 to = s.position(grid[j][next]);
            s.setSpline(grid[j][i], grid[j][next], space,
                        throughCircles ? controlPointsThrough(space, from, to, arc)
                                       : controlPointsAlong(space, from, to, arc));
        }
    }
    return s;
}

// A closed cylinder of strips around the z-axis (Fig. 14): sectors around, rows stacked. Every
// strip is a general cylinder (its top curve is its bottom curve translated), so exactly
// developable.
CompositeSurface makeCylinder(int sectors) {
    const int rows = std::max(1, sectors / 2);
    const double radius = 100.0;
    const double rowHeight = 60.0;
    const SplineSpace space{3, 2, 2};
    CompositeSurface s;
    s.setName("cylinder");
    auto angle = [sectors](int i) { return 2.0 * kPi * i / sectors; };
    auto xy = [radius](double phi) {
        return Vec3(radius * std::cos(phi), radius * std::sin(phi), 0);
    };
    std::vector<std::vector<VertexId>> grid(rows + 1, std::vector<VertexId>(sectors));
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i < sectors; ++i) {
            grid[j][i] = s.addVertex(xy(angle(i)) + Vec3(0, 0, rowHeight * j));
        }
    }
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            s.addFace({grid[j][i], grid[j][next], grid[j + 1][next], grid[j + 1][i]});
        }
    }
    for (int j = 0; j <= rows; ++j) {
        const Vec3 lift(0, 0, rowHeight * j);
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            const double phi0 = angle(i);
            const double phi1 = angle(i + 1);
            // Same x, y at every height: the rows are translates of each other.
            s.setSpline(
                grid[j][i], grid[j][next], space,
                controlPointsAlong(space, s.position(grid[j][i]), s.position(grid[j][next]),
                                   [&](double t) { return xy(phi0 + t * (phi1 - phi0)) + lift; }));
        }
    }
    return s;
}

// One flat surface with all four face types: a planar square, an SRSR strip with wavy
// creases, an SRS strip ending in a point and an SRR cone (a sector of a disk), each family
// of S-edges in its own spline space.
CompositeSurface makeMixed(int intervals) {
    CompositeSurface s;
    s.setName("mixed");
    const VertexId a = s.addVertex({0, 0, 0});
    const VertexId b = s.addVertex({100, 0, 0});
    const VertexId c = s.addVertex({100, 100, 0});
    const VertexId d = s.addVertex({0, 100, 0});
    const VertexId e = s.addVertex({200, 0, 0});
    const VertexId f = s.addVertex({200, 100, 0});
    const VertexId g = s.addVertex({50, 180, 0});
    const VertexId h = s.addVertex({100, -100, 0});
    s.addFace({a, b, c, d}); // R R R R
    s.addFace({b, e, f, c}); // S R S R
    s.addFace({d, c, g});    // R S S
    s.addFace({b, a, h});    // R S R: cone with apex b

    const SplineSpace stripSpace{3, 2, intervals};
    const Vec3 pb = s.position(b);
    const Vec3 pe = s.position(e);
    const Vec3 pf = s.position(f);
    const Vec3 pc = s.position(c);
    s.setSpline(b, e, stripSpace, controlPointsAlong(stripSpace, pb, pe, [&](double t) {
                    return lerp(pb, pe, t) + Vec3(0, -15.0 * std::sin(kPi * t), 0);
                }));
    s.setSpline(f, c, stripSpace, controlPointsAlong(stripSpace, pf, pc, [&](double t) {
                    return lerp(pf, pc, t) + Vec3(0, 15.0 * std::sin(kPi * t), 0);
                }));

    const SplineSpace pointedSpace{2, 1, intervals};
    const Vec3 pg = s.position(g);
    const Vec3 pd = s.position(d);
    auto bulge = [](const Vec3& p, const Vec3& q, double t, double amount) {
        const Vec3 along = q - p;
        const Vec3 outward = Vec3(along.y, -along.x, 0) * (amount / along.norm());
        return lerp(p, q, t) + outward * std::sin(kPi * t);
    };
    s.setSpline(c, g, pointedSpace, controlPointsAlong(pointedSpace, pc, pg, [&](double t) {
                    return bulge(pc, pg, t, 12.0);
                }));
    s.setSpline(g, d, pointedSpace, controlPointsAlong(pointedSpace, pg, pd, [&](double t) {
                    return bulge(pg, pd, t, 12.0);
                }));

    const SplineSpace coneSpace{3, 1, intervals};
    const Vec3 pa = s.position(a);
    const Vec3 ph = s.position(h);
    s.setSpline(a, h, coneSpace, controlPointsAlong(coneSpace, pa, ph, [&](double t) {
                    const double phi = kPi + t * kPi / 2.0;
                    return pb + Vec3(100.0 * std::cos(phi), 100.0 * std::sin(phi), 0);
                }));
    return s;
}

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
            const std::size_t last = points.size() - 1;
            points[1] = points[0] + creaseTangent(j, x0) * (points[1] - points[0]).norm();
            points[last - 1] =
                points[last] - creaseTangent(j, x1) * (points[last] - points[last - 1]).norm();
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

// A torus (major radius 150 mm, minor 60 mm) of size bands around the tube, each a cone
// between two parallel circles cut by rulings in the meridian planes into 2 × size sectors (the
// paper's Fig. 15b). Every band's top curve is its bottom curve scaled about the axis and
// lifted, so a′ ∥ b′ and the band is exactly developable; the circles are tangent-continuous
// through the vertices, where the rulings in the meridian planes meet them at right angles, so
// every vertex is developable too. The surface as a whole unfolds into no flat sheet: it has
// local conditions only.
CompositeSurface makeTorus(int size) {
    const int bands = size;
    const int sectors = 2 * size;
    const double majorRadius = 150.0;
    const double minorRadius = 60.0;
    const SplineSpace space{3, 2, 2};
    CompositeSurface s;
    s.setName("torus");
    auto around = [sectors](int i) { return 2.0 * kPi * i / sectors; };
    // The circle of band boundary j: its radius about the z-axis and its height.
    auto radiusOf = [&](int j) {
        return majorRadius + minorRadius * std::cos(2.0 * kPi * j / bands);
    };
    auto heightOf = [&](int j) { return minorRadius * std::sin(2.0 * kPi * j / bands); };
    auto onCircle = [&](int j, double phi) {
        return Vec3(radiusOf(j) * std::cos(phi), radiusOf(j) * std::sin(phi), heightOf(j));
    };
    std::vector<std::vector<VertexId>> grid(bands, std::vector<VertexId>(sectors));
    for (int j = 0; j < bands; ++j) {
        for (int i = 0; i < sectors; ++i) {
            grid[j][i] = s.addVertex(onCircle(j, around(i)));
        }
    }
    for (int j = 0; j < bands; ++j) {
        const int up = (j + 1) % bands;
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            // Counter-clockwise seen from outside the tube: the normals point out of it.
            s.addFace({grid[j][i], grid[j][next], grid[up][next], grid[up][i]});
        }
    }
    for (int j = 0; j < bands; ++j) {
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            const double phi0 = around(i);
            const double phi1 = around(i + 1);
            std::vector<Vec3> points =
                controlPointsAlong(space, s.position(grid[j][i]), s.position(grid[j][next]),
                                   [&](double t) { return onCircle(j, phi0 + t * (phi1 - phi0)); });
            // The curve's ends along the circle's tangent, so that the circles pass smoothly
            // through the vertices and the four right angles there sum to 2π.
            const std::size_t last = points.size() - 1;
            const Vec3 t0(-std::sin(phi0), std::cos(phi0), 0.0);
            const Vec3 t1(-std::sin(phi1), std::cos(phi1), 0.0);
            points[1] = points[0] + t0 * (points[1] - points[0]).norm();
            points[last - 1] = points[last] - t1 * (points[last] - points[last - 1]).norm();
            s.setSpline(grid[j][i], grid[j][next], space, points);
        }
    }
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
        const std::size_t last = points.size() - 1;
        if (k > 0) {
            points[1] = points[0] + creaseTangent(k) * (points[1] - points[0]).norm();
        }
        if (k + 1 < size) {
            points[last - 1] =
                points[last] - creaseTangent(k + 1) * (points[last] - points[last - 1]).norm();
        }
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

// `s`, holding no sheet, holding the sheet it starts as (ExampleSheet::Held).
void holdStartingSheet(CompositeSurface& s, SheetShape shape) {
    for (auto taut = findTautPinLines(s); !taut.empty(); taut = findTautPinLines(s)) {
        s.setPinned(taut.front().second, false);
    }
    if (const auto problem = keepDevelopment(s)) {
        throw ModelError(*problem);
    }
    if (s.sheetDomain().shape == SheetShape::Cylinder) {
        return; // it closes around: held on the cylinder keepDevelopment found
    }
    const SampledMesh mesh = sampleSurface(s, kDevelopmentSamplesPerInterval);
    SheetDomain domain = fittingDomain(shape, mesh, s.development());
    const bool curvedFolds = std::any_of(s.edges().begin(), s.edges().end(), [](const auto& e) {
        return e.second.condition == CreaseCondition::CurvedFold;
    });
    if (!domain.isFree() && curvedFolds) {
        // The crease pattern is scored where it is drawn: its creases stay on their curves in
        // the sheet while the rulings move.
        domain.creaseCurves = sheetFrameCurves(domain, creaseCurvesAsTheyLie(s, s.development()));
        domain.creaseCurveOf = assignCreasesToCurves(domain, s, mesh, s.development());
    }
    s.setSheetDomain(domain);
}

} // namespace

const std::vector<ExampleInfo>& builtInExamples() {
    static const std::vector<ExampleInfo> examples{
        {"sheet", 3, 1, 60, true, false},     {"annulus", 6, 1, 60, true, false},
        {"cylinder", 6, 3, 120, true, false}, {"mixed", 2, 1, 50, true, false},
        {"fig8", 3, 2, 30, true, false},      {"fig6", 4, 1, 40, true, false},
        {"fig13", 6, 3, 40, false, true},     {"torus", 6, 3, 40, false, false},
        {"column", 12, 6, 48, false, true},
    };
    return examples;
}

Project makeExample(const std::string& name, int size, ExampleSheet sheet) {
    for (const ExampleInfo& info : builtInExamples()) {
        if (info.name != name) {
            continue;
        }
        if (size == 0) {
            size = info.defaultSize;
        }
        if (size < info.minSize || size > info.maxSize) {
            Problem problem = problemOf(ProblemCode::ExampleSize);
            problem.name = name;
            problem.count = size;
            problem.expected = info.minSize;
            problem.limit = info.maxSize;
            throw ModelError(problem);
        }
        Project project;
        if (name == "sheet") {
            project.addSurface(makeSheet(size));
        } else if (name == "annulus") {
            project.addSurface(makeAnnulus(size, sheet == ExampleSheet::Held));
        } else if (name == "cylinder") {
            project.addSurface(makeCylinder(size));
        } else if (name == "mixed") {
            project.addSurface(makeMixed(size));
        } else if (name == "fig8") {
            project.addSurface(makeFig8(size));
        } else if (name == "fig13") {
            project.addSurface(makeFig13(size));
        } else if (name == "torus") {
            project.addSurface(makeTorus(size));
        } else if (name == "column") {
            project.addSurface(makeColumn(size));
        } else {
            project.addSurface(makeFig6(size));
        }
        if (sheet == ExampleSheet::Held && info.canHoldItsSheet) {
            // (The cylinder holds the cylinder its unfolding rolls onto.)
            const SheetShape shape = name == "annulus" ? SheetShape::Annulus
                                     : name == "mixed" || name == "cylinder"
                                         ? SheetShape::Free
                                         : SheetShape::Rectangle;
            holdStartingSheet(project.surfaces.front(), shape);
        }
        return project;
    }
    Problem problem = problemOf(ProblemCode::UnknownExample);
    problem.name = name;
    throw ModelError(problem);
}

} // namespace devsurf::model
