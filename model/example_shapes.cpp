#include "example_shapes.h"

#include "bspline_curve.h"
#include "model/math_constants.h"

#include <algorithm>
#include <cmath>

namespace devsurf::model::example_shapes {

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

std::vector<Vec3> alongEndTangents(std::vector<Vec3> points, const std::optional<Vec3>& start,
                                   const std::optional<Vec3>& end) {
    const std::size_t last = points.size() - 1;
    if (start) {
        points[1] = points[0] + *start * (points[1] - points[0]).norm();
    }
    if (end) {
        points[last - 1] = points[last] - *end * (points[last] - points[last - 1]).norm();
    }
    return points;
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
            points = alongEndTangents(points, Vec3(-std::sin(phi0), std::cos(phi0), 0.0),
                                      Vec3(-std::sin(phi1), std::cos(phi1), 0.0));
            s.setSpline(grid[j][i], grid[j][next], space, points);
        }
    }
    return s;
}

} // namespace devsurf::model::example_shapes
