// Joining strips fitted to a reference (§4.2, "Composite"): boundary curves paired by the
// linearised "samples of one lie on the tangent line of the other at their closest point",
// then welded into one shared S-edge of one composite surface, which a Solve keeps
// developable. Geometry is measured here independently of the solver.

#include "model/bspline_curve.h"
#include "model/math_constants.h"
#include "model/reference/initial_strip.h"
#include "model/strip.h"
#include "model/strip_joining.h"
#include "sampled_developability.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/session/approximation_setup.h"
#include "solver/session/solve_job.h"
#include "solver_test_problems.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace devsurf;
using model::Vec3;

namespace {

constexpr double kRadius = 100.0;
using devsurf::model::kPi;

// Points on the cylinder x² + y² = r² around the z-axis, the angle within ±60°, z0 ≤ z ≤ z1.
std::vector<Vec3> cylinderPatch(double z0, double z1, int around, int up) {
    std::vector<Vec3> points;
    for (int i = 0; i <= around; ++i) {
        const double phi = kPi / 3.0 * (2.0 * i / around - 1.0);
        for (int j = 0; j <= up; ++j) {
            const double z = z0 + (z1 - z0) * j / up;
            points.emplace_back(kRadius * std::cos(phi), kRadius * std::sin(phi), z);
        }
    }
    return points;
}

model::BSplineCurve curveOf(const model::CompositeSurface& surface, model::EdgeId edge) {
    const model::EdgeRecord& record = surface.edge(edge);
    return model::BSplineCurve::uniform(record.space, record.controlPoints);
}

// The largest distance of a point of curve a from curve b, both densely sampled.
double curveDistance(const model::BSplineCurve& a, const model::BSplineCurve& b) {
    std::vector<Vec3> onB;
    for (int i = 0; i <= 4000; ++i) {
        onB.push_back(b.evaluate(i / 4000.0));
    }
    double worst = 0.0;
    for (int i = 0; i <= 200; ++i) {
        const Vec3 p = a.evaluate(i / 200.0);
        double nearest = 1e300;
        for (const Vec3& q : onB) {
            nearest = std::min(nearest, (p - q).norm());
        }
        worst = std::max(worst, nearest);
    }
    return worst;
}

// Over a dense grid of every strip: the largest | ‖(x, y)‖ − r | and the z-range.
struct CylinderFit {
    double distance = 0.0;
    double zLow = 1e300;
    double zHigh = -1e300;
};
CylinderFit cylinderFit(const model::CompositeSurface& surface) {
    CylinderFit fit;
    for (const model::Strip& strip : model::stripsOf(surface)) {
        for (int i = 0; i <= 200; ++i) {
            for (int j = 0; j <= 20; ++j) {
                const Vec3 p = strip.point(i / 200.0, j / 20.0);
                fit.distance = std::max(fit.distance, std::abs(std::hypot(p.x, p.y) - kRadius));
                fit.zLow = std::min(fit.zLow, p.z);
                fit.zHigh = std::max(fit.zHigh, p.z);
            }
        }
    }
    return fit;
}

// A flat strip over a grid in the plane z = height, curves along x.
model::CompositeSurface flatStrip(double y0, double height) {
    std::vector<Vec3> points;
    for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 4; ++j) {
            points.emplace_back(10.0 * i, y0 + 10.0 * j, height);
        }
    }
    return model::reference::initialStrip(points, {3, 2, 3}, 0.0);
}

} // namespace

class TstCurvePairing : public QObject {
    Q_OBJECT

private slots:
    void pairingJacobianMatchesFiniteDifferences() {
        // Strip 2 lies 3 mm beside and 2 mm above strip 1; the samples at the curves' ends
        // project onto the other curve's ends (P = I there).
        const model::SurfacesSideBySide both =
            model::placeSideBySide(flatStrip(0.0, 0.0), flatStrip(43.0, 2.0));
        const auto parts = model::surfaceParts(both.surface);
        QCOMPARE(parts.size(), std::size_t(2));
        const auto nearest = model::nearestBoundaryCurves(both.surface, parts[0], parts[1]);
        QVERIFY(nearest.has_value());
        solver::FormulationOptions options;
        options.curvePairs = {{nearest->first, nearest->second}};
        const solver::SurfaceFormulation f(both.surface, options);
        QVERIFY(f.curvePairing() != nullptr);
        // Strip 1's upper curve at y = 40 and strip 2's lower at y = 43, z = 2: every sample
        // lies √13 mm from the other curve's line.
        QVERIFY(std::abs(f.curvePairing()->largestDistance() - std::sqrt(13.0)) < 1e-9);
        int checked = 0;
        std::mt19937 rng(3);
        const std::vector<double> x =
            solver::testing::randomVector(rng, f.problem().variableCount());
        for (int t = 0; t < f.problem().termCount(); ++t) {
            const solver::Term& term = f.problem().term(t);
            if (std::string(term.typeName()) != "CurvePairingTerm") {
                continue;
            }
            QCOMPARE(term.rowCount(), 3 * 2 * (3 * solver::kPairingSamplesPerInterval + 1));
            const double error = solver::testing::jacobianError(
                solver::testing::analyticJacobian(term, x),
                solver::testing::finiteDifferenceJacobian(term, x, 1e-6));
            QVERIFY2(error < 1e-6, qPrintable(QString::number(error)));
            // At the start state the rows of an interior sample are its offset across the other
            // curve (the tangent runs along x): (0, ∓3, ∓2) in state units.
            std::vector<double> residuals(static_cast<std::size_t>(term.rowCount()));
            std::vector<double> jacobian(1 << 16);
            term.evaluate(f.initialState().data(), residuals.data(), jacobian.data());
            const int middle = 3 * (3 * solver::kPairingSamplesPerInterval / 2);
            QVERIFY(std::abs(residuals[static_cast<std::size_t>(middle)]) < 1e-12);
            const double across = std::hypot(residuals[static_cast<std::size_t>(middle + 1)],
                                             residuals[static_cast<std::size_t>(middle + 2)]);
            QVERIFY(std::abs(across * f.scale() - std::sqrt(13.0)) < 1e-9);
            ++checked;
        }
        QCOMPARE(checked, 1);
    }

    void twoHalvesOfACylinderBecomeOneComposite() {
        // The test: strips fitted to the lower and the upper half of a cylinder patch,
        // their facing curves paired, welded and the composite solved.
        const std::vector<std::vector<Vec3>> halves = {cylinderPatch(0, 80, 60, 24),
                                                       cylinderPatch(80, 160, 60, 24)};
        std::vector<model::CompositeSurface> strips;
        solver::SurfaceTargets targets;
        double rho = 0.0;
        for (const std::vector<Vec3>& half : halves) {
            const solver::ThinnedTarget thinned = solver::thinTarget(half, 0.0);
            const auto initial = solver::initialStrips(thinned, 1, 4);
            QCOMPARE(initial.size(), std::size_t(1));
            strips.push_back(initial.front());
            targets.points.emplace_back();
            targets.normals.emplace_back();
            for (const auto& p : thinned.thinned.points) {
                targets.points.back().push_back(p.position);
                targets.normals.back().push_back(p.normal);
            }
            rho = std::max(rho, thinned.rho);
        }
        solver::SolveJob job;
        const solver::JobOutcome fitted =
            job.run(solver::approximationRequest(strips, targets, rho, std::nullopt));
        QVERIFY(fitted.ok);

        // One surface of two parts; the curves that face each other near z = 80.
        const model::SurfacesSideBySide both =
            model::placeSideBySide(fitted.surfaces[0], fitted.surfaces[1]);
        const auto parts = model::surfaceParts(both.surface);
        QCOMPARE(parts.size(), std::size_t(2));
        const auto nearest = model::nearestBoundaryCurves(both.surface, parts[0], parts[1]);
        QVERIFY(nearest.has_value());
        const double gapBefore = curveDistance(curveOf(both.surface, nearest->first),
                                               curveOf(both.surface, nearest->second));
        for (model::EdgeId e : {nearest->first, nearest->second}) {
            QVERIFY(std::abs(curveOf(both.surface, e).evaluate(0.5).z - 80.0) < 20.0);
        }

        // Paired: both strips pulled towards all points and their curves onto each other.
        solver::SurfaceTargets all;
        all.points.resize(1);
        all.normals.resize(1);
        for (std::size_t s = 0; s < 2; ++s) {
            all.points[0].insert(all.points[0].end(), targets.points[s].begin(),
                                 targets.points[s].end());
            all.normals[0].insert(all.normals[0].end(), targets.normals[s].begin(),
                                  targets.normals[s].end());
        }
        solver::JobRequest pairing =
            solver::approximationRequest({both.surface}, all, rho, std::nullopt);
        pairing.curvePairs[0] = {{nearest->first, nearest->second}};
        const solver::JobOutcome paired = job.run(pairing);
        QVERIFY(paired.ok);
        const model::CompositeSurface& pairedSurface = paired.surfaces.front();
        const double gapAfter = std::max(curveDistance(curveOf(pairedSurface, nearest->first),
                                                       curveOf(pairedSurface, nearest->second)),
                                         curveDistance(curveOf(pairedSurface, nearest->second),
                                                       curveOf(pairedSurface, nearest->first)));
        QVERIFY(gapBefore > 1.0); // the separate fits left the curves apart
        QVERIFY2(gapAfter < 1e-6, qPrintable(QString::number(gapAfter)));

        // Welded: one shared S-edge that both faces use.
        const model::Weld weld = model::weldEdges(pairedSurface, nearest->first, nearest->second);
        QVERIFY(weld.surface.validate().empty());
        QVERIFY(weld.gap < 1e-6);
        QCOMPARE(weld.surface.faces().size(), std::size_t(2));
        QVERIFY(weld.surface.edge(weld.shared).isSpline());
        for (const auto& [face, loop] : weld.surface.faces()) {
            const auto edges = weld.surface.faceEdges(face);
            QVERIFY(std::count(edges.begin(), edges.end(), weld.shared) == 1);
        }
        QCOMPARE(model::surfaceParts(weld.surface).size(), std::size_t(1));

        // Solved as one composite.
        solver::JobRequest solve;
        solve.kind = solver::JobKind::Solve;
        solve.surfaces = {weld.surface};
        const solver::JobOutcome solved = job.run(solve);
        QVERIFY(solved.ok);
        const model::CompositeSurface& composite = solved.surfaces.front();
        QVERIFY(composite.validate().empty());
        QCOMPARE(composite.facesOfEdge(weld.shared).size(), std::size_t(2));
        const double developability = test::sampledDevelopability(composite);
        const CylinderFit fit = cylinderFit(composite);
        qInfo("cylinder halves: facing curves %.3g mm apart after the fit, %.3g after pairing "
              "(%d iterations, %.0f ms), weld gap %.3g mm; composite after Solve (%d iterations, "
              "%.0f ms): developability %.3g, distance to the cylinder %.3g mm, z %.1f … %.1f",
              gapBefore, gapAfter, paired.largestIterationCount(), paired.elapsedMs, weld.gap,
              solved.largestIterationCount(), solved.elapsedMs, developability, fit.distance,
              fit.zLow, fit.zHigh);
        QVERIFY(developability <= 1e-8);
        QVERIFY(fit.distance <= 0.01);
        // It still spans both halves.
        QVERIFY(fit.zLow <= 5.0 && fit.zHigh >= 155.0);
    }
};

DEVSURF_REGISTER_TEST(TstCurvePairing);
#include "tst_curve_pairing.moc"
