#include "model/bspline_curve.h"
#include "model/curve_fit.h"
#include "model/examples.h"
#include "model/math_constants.h"
#include "test_registry.h"

#include <QTest>

#include <cmath>

using namespace devsurf::model;

namespace {

using devsurf::model::kPi;

// An S-edge of fig8 that is a crease (not on the boundary) and its end vertices.
EdgeId someCrease(const CompositeSurface& surface) {
    for (const auto& [id, record] : surface.edges()) {
        if (record.isSpline() && record.from != 0 && record.to != 0 && record.from != 3 &&
            record.to != 3 && surface.position(record.from).y > 50 &&
            surface.position(record.from).y < 250 && surface.position(record.from).x < 1) {
            return id;
        }
    }
    return kInvalidId;
}

// The curve y ↦ (x, y0 + 10, 20 sin(π x / 300)) for x from −20 to 320: above and beside the
// crease, longer than it.
ReferenceCurve wave(double y0) {
    ReferenceCurve curve{"wave", "", {}};
    for (int i = 0; i <= 340; ++i) {
        const double x = -20.0 + i;
        curve.points.emplace_back(x, y0 + 10.0, 20.0 * std::sin(kPi * x / 300.0));
    }
    return curve;
}

double waveDistance(const Vec3& p, double y0) {
    // Nearest point of the wave: a coarse search, then a ternary search around the best.
    const auto gap = [&](double x) {
        return distance(p, Vec3(x, y0 + 10.0, 20.0 * std::sin(kPi * x / 300.0)));
    };
    double best = -20.0;
    for (double x = -20.0; x <= 320.0; x += 0.1) {
        best = gap(x) < gap(best) ? x : best;
    }
    double lo = best - 0.1, hi = best + 0.1;
    for (int i = 0; i < 100; ++i) {
        const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
        (gap(a) < gap(b) ? hi : lo) = gap(a) < gap(b) ? b : a;
    }
    return gap((lo + hi) / 2);
}

} // namespace

class TstCurveFit : public QObject {
    Q_OBJECT
private slots:
    void creaseLiesOnTheCurve() {
        CompositeSurface surface = makeExample("fig8").surfaces[0];
        const EdgeId crease = someCrease(surface);
        QVERIFY(crease != kInvalidId);
        const EdgeRecord before = surface.edge(crease);
        const double y0 = surface.position(before.from).y;
        const EdgeFit fit = fitEdgeToCurve(surface, crease, wave(y0));
        QVERIFY(!fit.refused);
        QVERIFY2(fit.largestDistance < 0.05, qPrintable(QString::number(fit.largestDistance)));
        QVERIFY(fit.moved > 9.0);
        // Measured independently: the spline sampled densely against the wave itself.
        const EdgeRecord& after = surface.edge(crease);
        const BSplineCurve spline = BSplineCurve::uniform(after.space, after.controlPoints);
        for (int i = 0; i <= 100; ++i) {
            const double u =
                spline.domainBegin() + (spline.domainEnd() - spline.domainBegin()) * i / 100.0;
            QVERIFY(waveDistance(spline.evaluate(u), y0) < 0.06);
        }
        // The ends moved onto the curve, and the vertices with them.
        QVERIFY(waveDistance(surface.position(after.from), y0) < 1e-3); // chords of 1 mm
        QVERIFY(waveDistance(surface.position(after.to), y0) < 1e-3);
        QCOMPARE(after.controlPoints.front(), surface.position(after.from));
    }

    void pinnedEndsStayAndRulingsAreRefused() {
        CompositeSurface surface = makeExample("fig8").surfaces[0];
        const EdgeId crease = someCrease(surface);
        const VertexId from = surface.edge(crease).from;
        const Vec3 pinned = surface.position(from);
        surface.setPinned(from, true);
        const double y0 = pinned.y;
        const EdgeFit fit = fitEdgeToCurve(surface, crease, wave(y0));
        QVERIFY(!fit.refused);
        QCOMPARE(surface.position(from), pinned);
        QVERIFY(waveDistance(surface.position(surface.edge(crease).to), y0) <
                1e-3); // chords of 1 mm
        // A ruling is not fitted; nothing changes.
        for (const auto& [id, record] : surface.edges()) {
            if (!record.isSpline()) {
                const std::map<VertexId, Vec3> vertices = surface.vertices();
                QCOMPARE(fitEdgeToCurve(surface, id, wave(y0)).refused,
                         std::optional(EdgeFit::Refusal::NotSpline));
                QVERIFY(surface.vertices() == vertices);
                break;
            }
        }
        // Both ends nearest the same point (the end of a curve far to the left): refused.
        const ReferenceCurve away{"away", "", {{-500, y0, 0}, {-400, y0, 0}}};
        QCOMPARE(fitEdgeToCurve(surface, crease, away).refused,
                 std::optional(EdgeFit::Refusal::EndsMeet));
        const ReferenceCurve dot{"dot", "", {{1, 2, 3}, {1, 2, 3}}};
        QCOMPARE(fitEdgeToCurve(surface, crease, dot).refused,
                 std::optional(EdgeFit::Refusal::TooFewPoints));
    }
};

DEVSURF_REGISTER_TEST(TstCurveFit);
#include "tst_curve_fit.moc"
