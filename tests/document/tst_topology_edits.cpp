#include "document_test_support.h"
#include "model/examples.h"
#include "model/model_error.h"
#include "model/topology_edits.h"
#include "straight_control_points.h"
#include "test_registry.h"

#include <QTest>

using namespace devsurf::model;
using devsurf::test::firstProblem;
using devsurf::test::maxDeviation;
using devsurf::test::sizeOf;

namespace {

using devsurf::test::kExamples;

CompositeSurface example(const char* name, int size = 0) {
    return makeExample(name, size).surfaces.front();
}

using devsurf::test::firstFaceOfType;

std::size_t countType(const CompositeSurface& s, FaceType type) {
    std::size_t n = 0;
    for (const auto& [id, loop] : s.faces()) {
        n += s.faceType(id) == type ? 1 : 0;
    }
    return n;
}

// Both surfaces cover the same point set (every sample of one lies on the other).
void verifySameGeometry(const CompositeSurface& before, const CompositeSurface& after) {
    const double tolerance = 1e-9 * sizeOf(before);
    const double there = maxDeviation(before, after, tolerance);
    const double back = maxDeviation(after, before, tolerance);
    QVERIFY2(there <= tolerance,
             qPrintable(QString("old samples off the new surface by %1").arg(there)));
    QVERIFY2(back <= tolerance,
             qPrintable(QString("new samples off the old surface by %1").arg(back)));
}

} // namespace

class TstTopologyEdits : public QObject {
    Q_OBJECT
private slots:
    void rigidMotions() {
        const RigidMotion quarter = RigidMotion::rotationAbout({1, 1, 0}, {0, 0, 2}, M_PI / 2);
        const Vec3 p = quarter.apply({2, 1, 5}); // (1,0,5) from the axis turns to (0,1,5)
        QVERIFY(distance(p, Vec3(1, 2, 5)) < 1e-14);
        QVERIFY(distance(quarter.apply({1, 1, -3}), Vec3(1, 1, -3)) < 1e-14);
        QCOMPARE(RigidMotion::translationBy({1, 2, 3}).apply({1, 1, 1}), Vec3(2, 3, 4));
        QVERIFY_THROWS_EXCEPTION(ModelError, RigidMotion::rotationAbout({0, 0, 0}, {0, 0, 0}, 1));
    }

    void geometryCheckDetectsChanges() {
        // The comparison used below must notice a real change of shape.
        const CompositeSurface s = example("mixed");
        const CompositeSurface moved =
            moveVertices(s, {1}, RigidMotion::translationBy({0, 0, 1e-3}));
        const double tolerance = 1e-9 * sizeOf(s);
        QVERIFY(maxDeviation(s, moved, tolerance) > 1e-5);
        QVERIFY(maxDeviation(s, s, tolerance) <= tolerance);
    }

    void subdivideKeepsGeometryOnEveryExample() {
        for (const char* name : kExamples) {
            const CompositeSurface s = example(name);
            const FaceId face = firstFaceOfType(s, FaceType::StripSRSR);
            const std::size_t rowLength = stripRow(s, face).size();
            const CompositeSurface t = subdivideStrip(s, face, 0.3);
            QVERIFY2(firstProblem(t).empty(), firstProblem(t).c_str());
            QCOMPARE(t.faces().size(), s.faces().size() + rowLength);
            QCOMPARE(countType(t, FaceType::StripSRSR),
                     countType(s, FaceType::StripSRSR) + rowLength);
            QVERIFY(t.hasFace(face));
            verifySameGeometry(s, t);
        }
    }

    void subdivideCutsTheWholeRowAtT() {
        // 3 × 3 sheet: the row of face 0 is faces 0, 1, 2; the new crease runs at y = 0.3·100.
        const CompositeSurface s = example("sheet", 3);
        QCOMPARE(stripRow(s, 1).size(), std::size_t(3));
        const CompositeSurface t = subdivideStrip(s, 1, 0.3);
        std::size_t onCrease = 0;
        for (const auto& [id, p] : t.vertices()) {
            onCrease += std::abs(p.y - 30.0) < 1e-12 ? 1 : 0;
        }
        QCOMPARE(onCrease, std::size_t(4));
        QCOMPARE(t.vertices().size(), s.vertices().size() + 4);
        // Closed rows (cylinder) cut every strip around once.
        const CompositeSurface c = example("cylinder", 5);
        const CompositeSurface cut = subdivideStrip(c, 0, 0.5);
        QCOMPARE(cut.vertices().size(), c.vertices().size() + 5);
    }

    void subdivideInsertsTheVertexIntoPlanarNeighbours() {
        const CompositeSurface s = example("mixed");
        const FaceId planar = firstFaceOfType(s, FaceType::Planar);
        const CompositeSurface t = subdivideStrip(s, firstFaceOfType(s, FaceType::StripSRSR), 0.5);
        QCOMPARE(t.faceLoop(planar).size(), s.faceLoop(planar).size() + 1);
        QCOMPARE(t.faceType(planar), FaceType::Planar);
    }

    void subdivideRefusals() {
        const CompositeSurface mixed = example("mixed");
        QVERIFY_THROWS_EXCEPTION(
            ModelError, subdivideStrip(mixed, firstFaceOfType(mixed, FaceType::ConeSRR), 0.5));
        QVERIFY_THROWS_EXCEPTION(
            ModelError, subdivideStrip(mixed, firstFaceOfType(mixed, FaceType::StripSRSR), 1.0));
        QVERIFY_THROWS_EXCEPTION(ModelError, subdivideStrip(mixed, 999, 0.5));
        // An SRSR strip whose ruling borders an SRS strip: the cut cannot continue.
        CompositeSurface s;
        const VertexId a = s.addVertex({0, 0, 0});
        const VertexId b = s.addVertex({100, 0, 0});
        const VertexId c = s.addVertex({100, 100, 0});
        const VertexId d = s.addVertex({0, 100, 0});
        const VertexId e = s.addVertex({200, 50, 0});
        s.addFace({a, b, c, d});
        s.addFace({b, e, c});
        const SplineSpace space{3, 2, 2};
        s.setSpline(a, b, space,
                    devsurf::test::straightControlPoints(space, s.position(a), s.position(b)));
        s.setSpline(c, d, space,
                    devsurf::test::straightControlPoints(space, s.position(c), s.position(d)));
        s.setSpline(b, e, space,
                    devsurf::test::straightControlPoints(space, s.position(b), s.position(e)));
        s.setSpline(e, c, space,
                    devsurf::test::straightControlPoints(space, s.position(e), s.position(c)));
        QVERIFY2(firstProblem(s).empty(), firstProblem(s).c_str());
        try {
            subdivideStrip(s, 0, 0.5);
            QFAIL("the cut into an SRS strip was not refused");
        } catch (const ModelError& error) {
            QCOMPARE(error.problem().code, ProblemCode::CreaseBlocked);
            QCOMPARE(error.problem().otherFace, FaceId(1));
        }
    }

    void splitKeepsGeometryOnEveryExample() {
        for (const char* name : kExamples) {
            const CompositeSurface s = example(name);
            for (FaceType type : {FaceType::StripSRSR, FaceType::StripSRS, FaceType::ConeSRR}) {
                const FaceId face = firstFaceOfType(s, type);
                if (face == kInvalidId) {
                    continue;
                }
                const Strip strip = stripOfFace(s, face);
                const int n = s.edge(strip.aSide.edge).space.intervals;
                for (int i = 1; i < n; ++i) {
                    const CompositeSurface t = splitAtRuling(s, face, i);
                    QVERIFY2(firstProblem(t).empty(), firstProblem(t).c_str());
                    QVERIFY(t.faces().size() > s.faces().size());
                    verifySameGeometry(s, t);
                    // The start face's curve a now ends at the ruling: its piece has i intervals
                    // (or n − i, if the face kept the other part).
                    const int piece = t.edge(strip.aSide.edge).space.intervals;
                    QVERIFY(piece == i || piece == n - i);
                }
            }
        }
    }

    void splitPropagatesAcrossTheClassAndFollowsOrientation() {
        // Annulus: a class is one sector column; every strip of the column gets the ruling.
        const CompositeSurface s = example("annulus", 3);
        const FaceId face = 0;
        const auto cls = splineClassOf(s, stripOfFace(s, face).aSide.edge);
        const CompositeSurface t = splitAtRuling(s, face, 1);
        QCOMPARE(t.vertices().size(), s.vertices().size() + cls.size());
        QCOMPARE(t.faces().size(), s.faces().size() + cls.size() - 1);
        // Reverse one curve of the column: the split point must stay the same point.
        CompositeSurface r = s;
        r.reverseEdge(cls.back());
        const CompositeSurface tr = splitAtRuling(r, face, 1);
        QCOMPARE(tr.vertices().size(), t.vertices().size());
        for (const auto& [id, p] : t.vertices()) {
            QVERIFY(distance(p, tr.position(id)) < 1e-9);
        }
        verifySameGeometry(r, tr);
    }

    void splitRefusals() {
        const CompositeSurface mixed = example("mixed", 1);
        QVERIFY_THROWS_EXCEPTION(ModelError, splitAtRuling(mixed, 1, 1)); // one interval
        QVERIFY_THROWS_EXCEPTION(ModelError,
                                 splitAtRuling(mixed, firstFaceOfType(mixed, FaceType::Planar), 1));
        const CompositeSurface sheet = example("sheet", 2);
        QVERIFY_THROWS_EXCEPTION(ModelError, splitAtRuling(sheet, 0, 0));
        QVERIFY_THROWS_EXCEPTION(ModelError, splitAtRuling(sheet, 0, 3));
    }

    void refineKeepsGeometry() {
        for (const char* name : kExamples) {
            const CompositeSurface s = example(name);
            const auto classes = s.splineClasses();
            for (const auto& cls : classes) {
                const int n = s.edge(cls.front()).space.intervals;
                const CompositeSurface t = refineSplineClass(s, cls.front(), 2);
                QVERIFY2(firstProblem(t).empty(), firstProblem(t).c_str());
                for (EdgeId e : cls) {
                    QCOMPARE(t.edge(e).space.intervals, 2 * n);
                }
                // Independent check per curve: the refined curve evaluates to the old one.
                for (EdgeId e : cls) {
                    const BSplineCurve oldCurve =
                        BSplineCurve::uniform(s.edge(e).space, s.edge(e).controlPoints);
                    const BSplineCurve newCurve =
                        BSplineCurve::uniform(t.edge(e).space, t.edge(e).controlPoints);
                    for (int k = 0; k <= 97; ++k) {
                        const double u = k / 97.0;
                        QVERIFY(distance(oldCurve.evaluate(u), newCurve.evaluate(u)) <
                                1e-9 * sizeOf(s));
                    }
                }
                if (&cls == &classes.front()) {
                    verifySameGeometry(s, t); // the curve checks above cover the other classes
                }
            }
        }
        QVERIFY_THROWS_EXCEPTION(ModelError, refineSplineClass(example("sheet"), 0, 1));
    }

    void relabel() {
        const CompositeSurface mixed = example("mixed");
        // The cone's boundary ruling opposite its curve's start becomes S: an SRS strip.
        const FaceId cone = firstFaceOfType(mixed, FaceType::ConeSRR);
        EdgeId boundaryRuling = kInvalidId;
        for (EdgeId e : mixed.faceEdges(cone)) {
            if (!mixed.edge(e).isSpline() && mixed.facesOfEdge(e).size() == 1) {
                boundaryRuling = e;
            }
        }
        QVERIFY(boundaryRuling != kInvalidId);
        const CompositeSurface t = relabelEdges(mixed, {{boundaryRuling, EdgeLabel::Spline}});
        QCOMPARE(t.faceType(cone), FaceType::StripSRS);
        const EdgeRecord& made = t.edge(boundaryRuling);
        QCOMPARE(made.space, spaceForNewSplineEdge(mixed, boundaryRuling));
        // Straight: every control point on the segment between the vertices.
        const Vec3 p = t.position(made.from);
        const Vec3 q = t.position(made.to);
        for (const Vec3& c : made.controlPoints) {
            QVERIFY(devsurf::test::pointSegmentDistance(c, p, q) < 1e-12);
        }
        // Back to R gives the original surface.
        QVERIFY(relabelEdges(t, {{boundaryRuling, EdgeLabel::Ruling}}) == mixed);
        // A lone sheet strip cannot lose one S-edge, but can lose both (planar face).
        const CompositeSurface sheet = example("sheet", 1);
        try {
            relabelEdges(sheet, {{0, EdgeLabel::Ruling}});
            QFAIL("an invalid labelling was accepted");
        } catch (const ModelError& error) {
            QCOMPARE(error.problem().code, ProblemCode::InvalidFaceLabel);
            QCOMPARE(error.problem().face, FaceId(0));
        }
        std::vector<std::pair<EdgeId, EdgeLabel>> both;
        for (EdgeId e : sheet.faceEdges(0)) {
            if (sheet.edge(e).isSpline()) {
                both.emplace_back(e, EdgeLabel::Ruling);
            }
        }
        QCOMPARE(relabelEdges(sheet, both).faceType(0), FaceType::Planar);
    }

    void moveCarriesNeighbouringControlPoints() {
        const CompositeSurface s = example("sheet", 2);
        const VertexId v = 4; // the middle vertex of the 3 × 3 grid
        const RigidMotion motion = RigidMotion::rotationAbout({0, 0, 0}, {1, 1, 0}, 0.3);
        const CompositeSurface t = moveVertices(s, {v}, motion);
        QVERIFY(distance(t.position(v), motion.apply(s.position(v))) < 1e-12);
        int neighbours = 0;
        for (const auto& [id, record] : s.edges()) {
            if (!record.isSpline()) {
                continue;
            }
            const auto& before = record.controlPoints;
            const auto& after = t.edge(id).controlPoints;
            const std::size_t last = before.size() - 1;
            for (std::size_t i = 0; i <= last; ++i) {
                const bool moves =
                    (record.from == v && i <= 1) || (record.to == v && i + 1 >= last);
                if (moves) {
                    QVERIFY(distance(after[i], motion.apply(before[i])) < 1e-12);
                    neighbours += (i == 1 || i + 1 == last) ? 1 : 0;
                } else {
                    QCOMPARE(after[i], before[i]);
                }
            }
        }
        QCOMPARE(neighbours, 2);
        QVERIFY_THROWS_EXCEPTION(ModelError, moveVertices(s, {}, motion));
        QVERIFY_THROWS_EXCEPTION(ModelError, moveVertices(s, {999}, motion));
    }
};

DEVSURF_REGISTER_TEST(TstTopologyEdits);
#include "tst_topology_edits.moc"
