#include "model/composite_surface.h"
#include "model/examples.h"
#include "model/geometry_checks.h"
#include "straight_control_points.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <limits>

using namespace devsurf::model;

namespace {

// A planar face of rulings only through the given corners.
CompositeSurface polygon(const std::vector<Vec3>& corners) {
    CompositeSurface s;
    std::vector<VertexId> loop;
    for (const Vec3& p : corners) {
        loop.push_back(s.addVertex(p));
    }
    s.addFace(loop);
    return s;
}

// An SRSR strip: curve a from (0,0,0) to (100,0,0), curve b from (0,50,0) to (100,50,0).
CompositeSurface strip() {
    CompositeSurface s;
    const VertexId a0 = s.addVertex({0, 0, 0});
    const VertexId a1 = s.addVertex({100, 0, 0});
    const VertexId b1 = s.addVertex({100, 50, 0});
    const VertexId b0 = s.addVertex({0, 50, 0});
    s.addFace({a0, a1, b1, b0});
    const SplineSpace space{3, 2, 2};
    s.setSpline(a0, a1, space,
                devsurf::test::straightControlPoints(space, s.position(a0), s.position(a1)));
    s.setSpline(b1, b0, space,
                devsurf::test::straightControlPoints(space, s.position(b1), s.position(b0)));
    return s;
}

int count(const std::vector<std::string>& problems, const std::string& text) {
    return static_cast<int>(std::count_if(problems.begin(), problems.end(), [&](const auto& p) {
        return p.find(text) != std::string::npos;
    }));
}

QByteArray joined(const std::vector<std::string>& problems) {
    std::string all;
    for (const auto& p : problems) {
        all += p + "\n";
    }
    return QByteArray::fromStdString(all);
}

} // namespace

class TstGeometryChecks : public QObject {
    Q_OBJECT
private slots:
    void soundShapesHaveNoProblems() {
        QVERIFY(polygon({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}).validate().empty());
        QVERIFY(strip().validate().empty());
        for (const ExampleInfo& info : builtInExamples()) {
            for (int size : {info.minSize, info.defaultSize}) {
                for (const CompositeSurface& s : makeExample(info.name, size).surfaces) {
                    const auto problems = s.validate();
                    QVERIFY2(problems.empty(), joined(problems).constData());
                }
            }
        }
    }

    void coincidentVerticesOfAFace() {
        // Corners 0 and 2 coincide; no side is degenerate and the face encloses area.
        const auto problems = polygon({{0, 0, 0}, {100, 0, 0}, {0, 0, 0}, {0, 100, 0}}).validate();
        QCOMPARE(count(problems, "face 0 has coincident vertices 0 and 2."), 1);
        QCOMPARE(count(problems, "zero"), 0);
    }

    void zeroLengthRuling() {
        const auto problems =
            polygon({{0, 0, 0}, {100, 0, 0}, {100, 0, 0}, {0, 100, 0}}).validate();
        QCOMPARE(count(problems, "(a ruling of face 0) has zero length."), 1);
        // Reported once, as the side, not again as coincident corners.
        QCOMPARE(count(problems, "coincident"), 0);
        QCOMPARE(count(problems, "zero area"), 0);
    }

    void zeroLengthCurve() {
        CompositeSurface s = strip();
        // Collapse curve a to a point: its second vertex and every control point at the first.
        const EdgeId a = s.edgeBetween(0, 1);
        s.moveVertex(1, {0, 0, 0});
        s.setControlPoints(a, std::vector<Vec3>(s.edge(a).controlPoints.size(), Vec3{}));
        const auto problems = s.validate();
        QCOMPARE(count(problems, "edge " + std::to_string(a) +
                                     " (a spline curve of face 0) has zero length."),
                 1);
    }

    void zeroAreaFace() {
        // Four distinct corners on one line.
        const auto problems =
            polygon({{0, 0, 0}, {100, 0, 0}, {200, 0, 0}, {300, 0, 0}}).validate();
        QCOMPARE(count(problems, "face 0 has zero area."), 1);
        QCOMPARE(count(problems, "zero length"), 0);
    }

    void nonFiniteAndHugeCoordinates() {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        auto problems = polygon({{0, 0, 0}, {100, 0, 0}, {100, nan, 0}, {0, 100, 0}}).validate();
        QCOMPARE(count(problems, "vertex 2 (of face 0) has a position that is not a finite"), 1);
        problems = polygon({{0, 0, 0}, {100, 0, 0}, {100, 5e7, 0}, {0, 100, 0}}).validate();
        QCOMPARE(count(problems, "vertex 2 (of face 0) lies"), 1);
        QCOMPARE(count(problems, "not accepted"), 1);
        // Just inside the limit is accepted.
        QVERIFY(polygon({{0, 0, 0}, {9e5, 0, 0}, {9e5, 9e5, 0}, {0, 9e5, 0}}).validate().empty());
    }

    void allCoordinatesZeroNamesEveryFace() {
        Project project = makeExample("sheet", 2);
        CompositeSurface& s = project.surfaces[0];
        const CompositeSurface original = s;
        for (const auto& [id, p] : original.vertices()) {
            s.moveVertex(id, {0, 0, 0});
        }
        for (const auto& [id, record] : original.edges()) {
            if (record.isSpline()) {
                s.setControlPoints(id, std::vector<Vec3>(record.controlPoints.size(), Vec3{}));
            }
        }
        const auto problems = s.validate();
        for (const auto& [face, loop] : s.faces()) {
            QCOMPARE(count(problems, "face " + std::to_string(face) + " has zero area."), 1);
        }
        QVERIFY(count(problems, "has zero length.") >= static_cast<int>(s.edges().size()));
    }
};

DEVSURF_REGISTER_TEST(TstGeometryChecks);
#include "tst_geometry_checks.moc"
