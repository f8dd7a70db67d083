#include "model/composite_surface.h"
#include "model/model_error.h"
#include "model/strip.h"
#include "straight_control_points.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>

using namespace devsurf::model;

namespace {

// One polygon with the given labels along its loop ('S' or 'R'); S-edges share one space.
CompositeSurface polygonWithLabels(const std::string& labels, FaceId* faceOut = nullptr) {
    CompositeSurface s;
    const int n = static_cast<int>(labels.size());
    std::vector<VertexId> loop;
    for (int i = 0; i < n; ++i) {
        const double angle = 2.0 * 3.14159265358979 * i / n;
        loop.push_back(s.addVertex({100 * std::cos(angle), 100 * std::sin(angle), 0}));
    }
    const FaceId face = s.addFace(loop);
    const SplineSpace space{3, 2, 2};
    for (int i = 0; i < n; ++i) {
        if (labels[static_cast<std::size_t>(i)] == 'S') {
            const VertexId a = loop[static_cast<std::size_t>(i)];
            const VertexId b = loop[static_cast<std::size_t>((i + 1) % n)];
            s.setSpline(a, b, space,
                        devsurf::test::straightControlPoints(space, s.position(a), s.position(b)));
        }
    }
    if (faceOut != nullptr) {
        *faceOut = face;
    }
    return s;
}

// Whether a problem's technical key ("CurveZeroLength edge=4") contains `text`.
bool mentions(const std::vector<Problem>& problems, const std::string& text) {
    return std::any_of(problems.begin(), problems.end(), [&](const Problem& p) {
        return technicalKey(p).find(text) != std::string::npos;
    });
}

} // namespace

class TstCompositeSurface : public QObject {
    Q_OBJECT
private slots:
    void everyLabellingIsClassified() {
        // All labellings of triangles, quads and pentagons: exactly the four face types of
        // §3.1 are accepted, every other one is rejected with a message naming the face.
        for (int sides = 3; sides <= 5; ++sides) {
            for (int mask = 0; mask < (1 << sides); ++mask) {
                std::string labels;
                int splines = 0;
                for (int i = 0; i < sides; ++i) {
                    const bool s = (mask >> i) & 1;
                    labels += s ? 'S' : 'R';
                    splines += s ? 1 : 0;
                }
                FaceId face = kInvalidId;
                const CompositeSurface surface = polygonWithLabels(labels, &face);
                FaceType expected = FaceType::Invalid;
                if (splines == 0) {
                    expected = FaceType::Planar;
                } else if (sides == 3 && splines == 1) {
                    expected = FaceType::ConeSRR;
                } else if (sides == 3 && splines == 2) {
                    expected = FaceType::StripSRS;
                } else if (sides == 4 && (labels == "SRSR" || labels == "RSRS")) {
                    expected = FaceType::StripSRSR;
                }
                QCOMPARE(int(surface.faceType(face)), int(expected));
                QCOMPARE(surface.labelString(face), labels);
                const auto problems = surface.validate();
                if (expected == FaceType::Invalid) {
                    QVERIFY2(mentions(problems, "InvalidFaceLabel face=" + std::to_string(face) +
                                                    " name=" + labels),
                             labels.c_str());
                } else {
                    QVERIFY2(problems.empty(),
                             (labels + ": " +
                              (problems.empty() ? std::string() : technicalKey(problems.front())))
                                 .c_str());
                }
            }
        }
    }

    void stripSidesShareParameter() {
        FaceId face = kInvalidId;
        const CompositeSurface quad = polygonWithLabels("RSRS", &face);
        const Strip strip = stripOfFace(quad, face);
        // Rulings at u = 0 and u = 1 are the R-edges: a(0)b(0) and a(1)b(1) are edges.
        const auto& v = quad.vertices();
        auto isVertex = [&](const Vec3& p) {
            return std::any_of(v.begin(), v.end(), [&](const auto& e) { return e.second == p; });
        };
        QVERIFY(isVertex(strip.a.evaluate(0)) && isVertex(strip.b.evaluate(1)));
        QVERIFY(quad.edgeBetween(0, 0) == kInvalidId);
        const Vec3 a0 = strip.a.evaluate(0);
        const Vec3 b0 = strip.b.evaluate(0);
        const Vec3 a1 = strip.a.evaluate(1);
        const Vec3 b1 = strip.b.evaluate(1);
        auto idOf = [&](const Vec3& p) {
            for (const auto& [id, q] : v) {
                if (q == p) {
                    return id;
                }
            }
            return kInvalidId;
        };
        QCOMPARE(quad.edge(quad.edgeBetween(idOf(a0), idOf(b0))).label, EdgeLabel::Ruling);
        QCOMPARE(quad.edge(quad.edgeBetween(idOf(a1), idOf(b1))).label, EdgeLabel::Ruling);

        FaceId pointed = kInvalidId;
        const CompositeSurface srs = polygonWithLabels("RSS", &pointed);
        const Strip s2 = stripOfFace(srs, pointed);
        QCOMPARE(s2.a.evaluate(1), s2.b.evaluate(1)); // the collapsed ruling
        QVERIFY(s2.a.evaluate(0) != s2.b.evaluate(0));

        FaceId cone = kInvalidId;
        const CompositeSurface srr = polygonWithLabels("RSR", &cone);
        const Strip s3 = stripOfFace(srr, cone);
        QVERIFY(s3.isCone());
        QCOMPARE(s3.apex, srr.position(srr.faceLoop(cone)[0]));
        QCOMPARE(s3.point(0.3, 1.0), s3.apex);
    }

    void reversingAnEdgeReversesItsSequence() {
        FaceId face = kInvalidId;
        CompositeSurface s = polygonWithLabels("SRSR", &face);
        const EdgeId e = s.faceEdges(face)[0];
        const EdgeRecord before = s.edge(e);
        const Strip stripBefore = stripOfFace(s, face);
        s.reverseEdge(e);
        const EdgeRecord& after = s.edge(e);
        QCOMPARE(after.from, before.to);
        QCOMPARE(after.to, before.from);
        std::vector<Vec3> reversed = before.controlPoints;
        std::reverse(reversed.begin(), reversed.end());
        QVERIFY(after.controlPoints == reversed);
        QVERIFY(s.controlPointsFrom(before.from, before.to) == before.controlPoints);
        QVERIFY(s.validate().empty());
        const Strip stripAfter = stripOfFace(s, face);
        for (double u = 0; u <= 1.0; u += 0.125) {
            QCOMPARE(stripAfter.point(u, 0.25), stripBefore.point(u, 0.25));
        }
        QCOMPARE(stripAfter.aSide.reversed, !stripBefore.aSide.reversed);
    }

    void splineSpacesAreConstantOnClasses() {
        FaceId face = kInvalidId;
        CompositeSurface s = polygonWithLabels("SRSR", &face);
        QVERIFY(s.validate().empty());
        QCOMPARE(s.splineClasses().size(), std::size_t(1));
        const auto loop = s.faceLoop(face);
        const SplineSpace other{2, 1, 2};
        s.setSpline(
            loop[2], loop[3], other,
            devsurf::test::straightControlPoints(other, s.position(loop[2]), s.position(loop[3])));
        QVERIFY(mentions(s.validate(), "SplineSpacesDiffer"));
    }

    void sequencesStartAndEndAtTheirVertices() {
        FaceId face = kInvalidId;
        CompositeSurface s = polygonWithLabels("SRSR", &face);
        const EdgeId e = s.faceEdges(face)[0];
        auto points = s.edge(e).controlPoints;
        points.front().x += 1e-9;
        s.setControlPoints(e, points);
        QVERIFY(mentions(s.validate(), "CurveNotAtVertex"));
        // Moving a vertex carries the curve ends along.
        CompositeSurface t = polygonWithLabels("SRSR", &face);
        t.moveVertex(t.faceLoop(face)[0], {1, 2, 3});
        QVERIFY(t.validate().empty());
        points = t.edge(e).controlPoints;
        points.pop_back();
        t.setControlPoints(e, points);
        QVERIFY(mentions(t.validate(), "ControlPointCount"));
    }

    void nonManifoldFacesAreRefused() {
        CompositeSurface s;
        const VertexId a = s.addVertex({0, 0, 0});
        const VertexId b = s.addVertex({1, 0, 0});
        const VertexId c = s.addVertex({0, 1, 0});
        const VertexId d = s.addVertex({0, 0, 1});
        const VertexId e = s.addVertex({1, 1, 1});
        s.addFace({a, b, c});
        // Same direction along a→b: inconsistent orientation.
        QVERIFY_THROWS_EXCEPTION(ModelError, s.addFace({a, b, d}));
        s.addFace({b, a, d});
        // A third face at edge a–b.
        QVERIFY_THROWS_EXCEPTION(ModelError, s.addFace({b, a, e}));
        QVERIFY_THROWS_EXCEPTION(ModelError, s.addFace({a, a, e}));
        QVERIFY_THROWS_EXCEPTION(ModelError, s.addFace({a, 99, e}));
        try {
            s.addFace({a, b, e});
            QFAIL("expected a refusal");
        } catch (const ModelError& error) {
            QVERIFY(std::string(error.what()).find("face=2") != std::string::npos);
        }
        QVERIFY(mentions(s.validate(), "Unused vertex=4"));
        QCOMPARE(s.facesOfEdge(s.edgeBetween(a, b)).size(), std::size_t(2));
    }

    void copiesAreIndependent() {
        FaceId face = kInvalidId;
        CompositeSurface s = polygonWithLabels("SRSR", &face);
        CompositeSurface copy = s;
        QVERIFY(copy == s);
        copy.moveVertex(0, {5, 5, 5});
        QVERIFY(copy != s);
        QCOMPARE(copy.facesOfEdge(copy.faceEdges(face)[0]), s.facesOfEdge(s.faceEdges(face)[0]));
        CompositeSurface assigned;
        assigned = copy;
        QVERIFY(assigned == copy);
        QVERIFY(assigned.validate().empty());
    }

    void moveVerticesMovesAsMoveVertexDoesEach() {
        // Every vertex of an S/R polygon moved at once: the same surface as one moveVertex after
        // the other (S-edge ends follow; a vertex given twice takes its last position); an
        // unknown vertex is refused and nothing moves.
        CompositeSurface one = polygonWithLabels("SRSRS");
        CompositeSurface many = one;
        const CompositeSurface start = one;
        std::vector<std::pair<VertexId, Vec3>> moves;
        for (const auto& [id, position] : start.vertices()) {
            moves.emplace_back(id, position + Vec3(1.0 * id, 2.0, -3.0));
        }
        moves.emplace_back(moves.front().first, Vec3(7, 8, 9));
        for (const auto& [id, position] : moves) {
            one.moveVertex(id, position);
        }
        many.moveVertices(moves);
        QVERIFY(many == one);
        QVERIFY(!(many == start));
        QCOMPARE(many.position(moves.front().first), Vec3(7, 8, 9));
        CompositeSurface refused = start;
        QVERIFY_THROWS_EXCEPTION(ModelError, refused.moveVertices({{moves[1].first, Vec3(1, 1, 1)},
                                                                   {9999, Vec3(0, 0, 0)}}));
        QVERIFY(refused == start);
    }

    void onlyRulingsAreSmooth() {
        FaceId face = kInvalidId;
        CompositeSurface s = polygonWithLabels("SRSR", &face);
        const std::vector<EdgeId> edges = s.faceEdges(face);
        // A curve cannot be smooth; a ruling on the boundary can be flagged but is reported.
        QVERIFY_THROWS_EXCEPTION(ModelError, s.setSmooth(edges[0], true));
        QVERIFY_THROWS_EXCEPTION(ModelError, s.setSmooth(9999, true));
        s.setSmooth(edges[1], true);
        QVERIFY(s.edge(edges[1]).smooth);
        QVERIFY(mentions(s.validate(), "SmoothNotShared edge=" + std::to_string(edges[1])));
        CompositeSurface sharp = s;
        sharp.setSmooth(edges[1], false);
        QVERIFY(sharp != s);
        QVERIFY(sharp.validate().empty());
        // Relabelling a smooth ruling as a curve drops the flag.
        const EdgeRecord& ruling = s.edge(edges[1]);
        const SplineSpace space{3, 2, 2};
        s.setSpline(ruling.from, ruling.to, space,
                    devsurf::test::straightControlPoints(space, s.position(ruling.from),
                                                         s.position(ruling.to)));
        QVERIFY(!s.edge(edges[1]).smooth);
    }
};

DEVSURF_REGISTER_TEST(TstCompositeSurface);
#include "tst_composite_surface.moc"
