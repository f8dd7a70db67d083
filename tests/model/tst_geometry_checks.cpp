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

// Problems whose technical key ("ZeroArea face=0") contains `text`.
int count(const std::vector<Problem>& problems, const std::string& text) {
    return static_cast<int>(std::count_if(problems.begin(), problems.end(), [&](const auto& p) {
        return technicalKey(p).find(text) != std::string::npos;
    }));
}

QByteArray joined(const std::vector<Problem>& problems) {
    std::string all;
    for (const auto& p : problems) {
        all += technicalKey(p) + "\n";
    }
    return QByteArray::fromStdString(all);
}

// The first problem with `code`; fails the test if there is none.
const Problem* find(const std::vector<Problem>& problems, ProblemCode code) {
    for (const Problem& p : problems) {
        if (p.code == code) {
            return &p;
        }
    }
    return nullptr;
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
        QCOMPARE(count(problems, "CoincidentVertices vertex=0 other-vertex=2 face=0"), 1);
        QCOMPARE(count(problems, "Zero"), 0);
    }

    void zeroLengthRuling() {
        const auto problems =
            polygon({{0, 0, 0}, {100, 0, 0}, {100, 0, 0}, {0, 100, 0}}).validate();
        QCOMPARE(count(problems, "RulingZeroLength"), 1);
        QCOMPARE(find(problems, ProblemCode::RulingZeroLength)->faces, std::vector<FaceId>{0});
        // Reported once, as the side, not again as coincident corners.
        QCOMPARE(count(problems, "Coincident"), 0);
        QCOMPARE(count(problems, "ZeroArea"), 0);
    }

    void zeroLengthCurve() {
        CompositeSurface s = strip();
        // Collapse curve a to a point: its second vertex and every control point at the first.
        const EdgeId a = s.edgeBetween(0, 1);
        s.moveVertex(1, {0, 0, 0});
        s.setControlPoints(a, std::vector<Vec3>(s.edge(a).controlPoints.size(), Vec3{}));
        const auto problems = s.validate();
        QCOMPARE(count(problems, "CurveZeroLength edge=" + std::to_string(a)), 1);
        QCOMPARE(find(problems, ProblemCode::CurveZeroLength)->faces, std::vector<FaceId>{0});
    }

    void pinchedCurve() {
        // Curve a stays at its first vertex over its first knot interval (its first four control
        // points there) and then runs to the second: its length is not zero, but a stretch of
        // it has shrunk to a point, as a held sheet's boundary pressed into a corner does.
        CompositeSurface s = strip();
        const EdgeId a = s.edgeBetween(0, 1);
        std::vector<Vec3> points = s.edge(a).controlPoints;
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            points[i] = points.front();
        }
        s.setControlPoints(a, points);
        const auto problems = s.validate();
        QCOMPARE(count(problems, "CurvePinched edge=" + std::to_string(a)), 1);
        QCOMPARE(find(problems, ProblemCode::CurvePinched)->faces, std::vector<FaceId>{0});
        QCOMPARE(count(problems, "ZeroLength"), 0);
        // A straight curve and one whose control points merely crowd are not pinched.
        QCOMPARE(count(strip().validate(), "CurvePinched"), 0);
        points = strip().edge(a).controlPoints;
        points[1] = points.front() + Vec3(1e-3, 0, 0);
        s.setControlPoints(a, points);
        QCOMPARE(count(s.validate(), "CurvePinched"), 0);
    }

    void zeroAreaFace() {
        // Four distinct corners on one line.
        const auto problems =
            polygon({{0, 0, 0}, {100, 0, 0}, {200, 0, 0}, {300, 0, 0}}).validate();
        QCOMPARE(count(problems, "ZeroArea face=0"), 1);
        QCOMPARE(count(problems, "ZeroLength"), 0);
    }

    void nonFiniteAndHugeCoordinates() {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        auto problems = polygon({{0, 0, 0}, {100, 0, 0}, {100, nan, 0}, {0, 100, 0}}).validate();
        QCOMPARE(count(problems, "PositionNotFinite vertex=2"), 1);
        QCOMPARE(find(problems, ProblemCode::PositionNotFinite)->faces, std::vector<FaceId>{0});
        problems = polygon({{0, 0, 0}, {100, 0, 0}, {100, 5e7, 0}, {0, 100, 0}}).validate();
        QCOMPARE(count(problems, "PositionTooFar vertex=2"), 1);
        const Problem* far = find(problems, ProblemCode::PositionTooFar);
        QVERIFY(far->value > far->limit && far->limit == kMaxCoordinate);
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
            QCOMPARE(count(problems, "ZeroArea face=" + std::to_string(face)), 1);
        }
        QVERIFY(count(problems, "ZeroLength") >= static_cast<int>(s.edges().size()));
    }
};

DEVSURF_REGISTER_TEST(TstGeometryChecks);
#include "tst_geometry_checks.moc"
