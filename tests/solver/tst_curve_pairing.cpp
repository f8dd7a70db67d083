// Joining strips fitted to a reference (§4.2, "Composite"): boundary curves paired by the
// linearised "samples of one lie on the tangent line of the other at their closest point",
// then welded into one shared S-edge of one composite surface, which a Solve keeps
// developable. Geometry is measured here independently of the solver.

#include "model/bspline_curve.h"
#include "model/math_constants.h"
#include "model/reference/distance_report.h"
#include "model/reference/initial_strip.h"
#include "model/strip.h"
#include "model/strip_joining.h"
#include "sampled_developability.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/session/approximation_setup.h"
#include "solver/session/join_job.h"
#include "solver/session/solve_job.h"
#include "solver_test_problems.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <atomic>
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

// A flat strip over a grid in the plane z = height, curves along x (x0 … x0 + 100), rulings
// along y (y0 … y0 + 40).
model::CompositeSurface flatStrip(double y0, double height, double x0 = 0.0) {
    std::vector<Vec3> points;
    for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 4; ++j) {
            points.emplace_back(x0 + 10.0 * i, y0 + 10.0 * j, height);
        }
    }
    return model::reference::initialStrip(points, {3, 2, 3}, 0.0);
}

// The formulation's one curve-pairing term; null unless there is exactly one.
const solver::Term* pairingTerm(const solver::SurfaceFormulation& f) {
    const solver::Term* found = nullptr;
    for (int t = 0; t < f.problem().termCount(); ++t) {
        const solver::Term& term = f.problem().term(t);
        if (std::string(term.typeName()) == "CurvePairingTerm") {
            if (found != nullptr) {
                return nullptr;
            }
            found = &term;
        }
    }
    return found;
}

// The largest difference between `term`'s analytic Jacobian and finite differences at a random
// state of `f`.
double jacobianErrorAtRandom(const solver::SurfaceFormulation& f, const solver::Term& term,
                             unsigned seed) {
    std::mt19937 rng(seed);
    const std::vector<double> x = solver::testing::randomVector(rng, f.problem().variableCount());
    return solver::testing::jacobianError(solver::testing::analyticJacobian(term, x),
                                          solver::testing::finiteDifferenceJacobian(term, x, 1e-6));
}

// The command line's approximate --strips K --join: K k-means strips fitted to `points`, then
// joined by the Join job with every thinned point as its target. Not ok (and no join report)
// when K strips were not laid or the fit failed.
solver::JobOutcome fitAndJoin(const std::vector<Vec3>& points, int count) {
    const solver::ThinnedTarget thinned = solver::thinTarget(points, 0.0);
    const std::vector<model::CompositeSurface> strips = solver::initialStrips(thinned, count, 4);
    solver::SolveJob job;
    const solver::JobOutcome fitted = job.run(solver::approximationRequest(
        strips, solver::assignToSurfaces(strips, thinned.thinned), thinned.rho, std::nullopt));
    if (strips.size() != static_cast<std::size_t>(count) || !fitted.ok) {
        return {};
    }
    solver::JobRequest request;
    request.kind = solver::JobKind::Join;
    request.surfaces = fitted.surfaces;
    request.joinTarget = std::make_shared<const model::reference::ThinningResult>(thinned.thinned);
    request.joinRho = thinned.rho;
    return job.run(request);
}

// Edges that two faces share: spline edges (curves), or rulings.
int sharedEdges(const model::CompositeSurface& surface, bool splines) {
    int count = 0;
    for (const auto& [id, record] : surface.edges()) {
        count += record.isSpline() == splines && surface.facesOfEdge(id).size() == 2 ? 1 : 0;
    }
    return count;
}
int sharedCurves(const model::CompositeSurface& surface) {
    return sharedEdges(surface, true);
}

// Two flat strips of the plane z = 0, 2 mm apart across y = 40 … 42.
std::vector<model::CompositeSurface> twoFlatStrips() {
    std::vector<model::CompositeSurface> strips = {flatStrip(0.0, 0.0), flatStrip(42.0, 0.0)};
    strips[0].setName("a");
    strips[1].setName("b");
    return strips;
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
        const solver::Term* term = pairingTerm(f);
        QVERIFY(term != nullptr);
        QCOMPARE(term->rowCount(), 3 * 2 * (3 * solver::kPairingSamplesPerInterval + 1));
        const double error = jacobianErrorAtRandom(f, *term, 3);
        QVERIFY2(error < 1e-6, qPrintable(QString::number(error)));
        // At the start state the rows of an interior sample are its offset across the other
        // curve (the tangent runs along x): (0, ∓3, ∓2) in state units.
        std::vector<double> residuals(static_cast<std::size_t>(term->rowCount()));
        std::vector<double> jacobian(1 << 16);
        term->evaluate(f.initialState().data(), residuals.data(), jacobian.data());
        const int middle = 3 * (3 * solver::kPairingSamplesPerInterval / 2);
        QVERIFY(std::abs(residuals[static_cast<std::size_t>(middle)]) < 1e-12);
        const double across = std::hypot(residuals[static_cast<std::size_t>(middle + 1)],
                                         residuals[static_cast<std::size_t>(middle + 2)]);
        QVERIFY(std::abs(across * f.scale() - std::sqrt(13.0)) < 1e-9);
    }

    void rulingPairJacobianMatchesFiniteDifferences() {
        // Strip 2 lies 3 mm beyond the end ruling of strip 1 and 2 mm above it: the rulings
        // face each other, nearer than any two curves.
        const model::SurfacesSideBySide both =
            model::placeSideBySide(flatStrip(0.0, 0.0), flatStrip(0.0, 2.0, 103.0));
        const auto parts = model::surfaceParts(both.surface);
        const auto nearest = model::nearestBoundaryCurves(both.surface, parts[0], parts[1]);
        QVERIFY(nearest.has_value());
        QVERIFY(!both.surface.edge(nearest->first).isSpline());
        QVERIFY(!both.surface.edge(nearest->second).isSpline());
        QVERIFY(std::abs(nearest->separation - std::sqrt(13.0)) < 1e-9);
        QVERIFY(std::abs(nearest->length - 40.0) < 1e-9);
        solver::FormulationOptions options;
        options.curvePairs = {{nearest->first, nearest->second}};
        const solver::SurfaceFormulation f(both.surface, options);
        QVERIFY(std::abs(f.curvePairing()->largestDistance() - std::sqrt(13.0)) < 1e-9);
        // A ruling paired with a curve is refused.
        model::EdgeId curve = model::kInvalidId;
        for (const auto& [id, record] : both.surface.edges()) {
            if (record.isSpline() && both.surface.facesOfEdge(id).size() == 1) {
                curve = id;
            }
        }
        solver::FormulationOptions mixed;
        mixed.curvePairs = {{nearest->first, curve}};
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 solver::SurfaceFormulation(both.surface, mixed));
        const solver::Term* term = pairingTerm(f);
        QVERIFY(term != nullptr);
        // One interval per ruling: kPairingSamplesPerInterval + 1 samples each way.
        QCOMPARE(term->rowCount(), 3 * 2 * (solver::kPairingSamplesPerInterval + 1));
        const double error = jacobianErrorAtRandom(f, *term, 5);
        QVERIFY2(error < 1e-6, qPrintable(QString::number(error)));
    }

    void theJoinJobWeldsStripsAlongARuling() {
        // Two strips end to end, 2 mm apart between their end rulings: joined along them.
        solver::JobRequest request;
        request.kind = solver::JobKind::Join;
        request.surfaces = {flatStrip(0.0, 0.0), flatStrip(0.0, 0.0, 102.0)};
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(request);
        QVERIFY(outcome.ok);
        QCOMPARE(outcome.join->welded, 1);
        QCOMPARE(outcome.join->parts, 1);
        const model::CompositeSurface& joined = outcome.surfaces.front();
        QVERIFY(joined.validate().empty());
        QCOMPARE(sharedEdges(joined, false), 1);
        QCOMPARE(sharedCurves(joined), 0);
        QVERIFY(test::sampledDevelopability(joined) <= 1e-8);
    }

    void fourStripsOnACylinderBecomeOneWatertightSurface() {
        // The automatic path's --join on a cylinder patch 209 mm around and 240 mm high: four
        // k-means strips, a 2 × 2 grid, welded along two curves and two rulings into one part,
        // then pulled onto the cylinder again as one surface.
        const std::vector<Vec3> points = cylinderPatch(0, 240, 60, 48);
        const solver::JobOutcome outcome = fitAndJoin(points, 4);
        QVERIFY(outcome.ok);
        QCOMPARE(outcome.join->welded, 4);
        QCOMPARE(outcome.join->parts, 1);
        const model::CompositeSurface& joined = outcome.surfaces.front();
        QVERIFY(joined.validate().empty());
        QCOMPARE(sharedEdges(joined, true), 2);
        QCOMPARE(sharedEdges(joined, false), 2);
        QVERIFY(test::sampledDevelopability(joined) <= 1e-8);
        // Every point of the patch near the joined surface (measured here by dense sampling).
        const auto report = model::reference::measureDistance(joined, points);
        qInfo("four strips joined: target to surface mean %.3g mm, max %.3g mm; %.0f ms",
              report.targetToSurface.mean, report.targetToSurface.max, outcome.elapsedMs);
        QVERIFY(report.targetToSurface.mean <= 0.1);
        QVERIFY(report.targetToSurface.max <= 2.0);
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

    void theJoinJobWeldsTwoStripsWithoutAReference() {
        // Tools ▸ Join Surfaces on a design without a reference shape: the facing curves are
        // paired by a Solve alone, welded, and the composite solved.
        solver::JobRequest request;
        request.kind = solver::JobKind::Join;
        request.surfaces = twoFlatStrips();
        solver::SolveJob job;
        int progressCalls = 0;
        const solver::JobOutcome outcome =
            job.run(request, nullptr, [&](const solver::JobProgress&) { ++progressCalls; });
        QVERIFY(outcome.ok);
        QCOMPARE(outcome.kind, solver::JobKind::Join);
        QVERIFY(outcome.join);
        const solver::JoinReport& join = *outcome.join;
        QCOMPARE(join.joined, (std::vector<int>{0, 1}));
        QCOMPARE(join.separations.size(), std::size_t(1));
        QVERIFY2(std::abs(join.separations.front() - 2.0) < 1e-6,
                 qPrintable(QString::number(join.separations.front())));
        QCOMPARE(join.welded, 1);
        QVERIFY(join.refused.empty());
        QCOMPARE(join.parts, 1);
        QVERIFY(!join.pulledToReference);
        QVERIFY(progressCalls > 0);

        QCOMPARE(outcome.surfaces.size(), std::size_t(1));
        QCOMPARE(outcome.assessments.size(), std::size_t(1));
        const model::CompositeSurface& joined = outcome.surfaces.front();
        QVERIFY(joined.validate().empty());
        QCOMPARE(joined.name(), std::string("a + b"));
        QCOMPARE(joined.faces().size(), std::size_t(2));
        QCOMPARE(sharedCurves(joined), 1);
        QCOMPARE(model::surfaceParts(joined).size(), std::size_t(1));
        QVERIFY(outcome.assessments.front().summary.toleranceReached);
        // Measured here: developable, still in the plane, and spanning both strips.
        QVERIFY(test::sampledDevelopability(joined) <= 1e-8);
        double yLow = 1e300, yHigh = -1e300, zMax = 0.0;
        for (const model::Strip& strip : model::stripsOf(joined)) {
            for (int i = 0; i <= 50; ++i) {
                for (int j = 0; j <= 10; ++j) {
                    const Vec3 p = strip.point(i / 50.0, j / 10.0);
                    yLow = std::min(yLow, p.y);
                    yHigh = std::max(yHigh, p.y);
                    zMax = std::max(zMax, std::abs(p.z));
                }
            }
        }
        qInfo("two flat strips joined without a reference in %.0f ms: z within %.2g mm, "
              "y %.3f … %.3f",
              outcome.elapsedMs, zMax, yLow, yHigh);
        QVERIFY2(zMax < 1e-6, qPrintable(QString::number(zMax)));
        QVERIFY2(yLow < 1.0 && yHigh > 81.0, qPrintable(QString("%1 … %2").arg(yLow).arg(yHigh)));
    }

    void theJoinJobLeavesSurfacesThatFaceNothing() {
        // Strips 60 mm apart (more than kJoinReach of their 100 mm): nothing is joined.
        solver::JobRequest request;
        request.kind = solver::JobKind::Join;
        request.surfaces = {flatStrip(0.0, 0.0), flatStrip(100.0, 0.0)};
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(request);
        QVERIFY(outcome.ok);
        QVERIFY(outcome.join);
        QVERIFY(outcome.join->separations.empty());
        QCOMPARE(outcome.join->welded, 0);
        QCOMPARE(outcome.surfaces.size(), std::size_t(2));
        QVERIFY(outcome.surfaces[0] == request.surfaces[0]);
        QVERIFY(outcome.surfaces[1] == request.surfaces[1]);
        // One surface: nothing to join either.
        request.surfaces.mutableSurfaces().resize(1);
        const solver::JobOutcome single = job.run(request);
        QVERIFY(single.ok && single.join && single.join->separations.empty());
        QCOMPARE(single.surfaces.size(), std::size_t(1));
    }

    void aSurfaceFacingNoOtherIsLeftOut() {
        // a and b 2 mm apart, c 200 mm beyond: only a and b become the joined surface.
        solver::JobRequest request;
        request.kind = solver::JobKind::Join;
        request.surfaces = twoFlatStrips();
        request.surfaces.push_back(flatStrip(0.0, 0.0, 300.0));
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(request);
        QVERIFY(outcome.ok);
        QCOMPARE(outcome.join->joined, (std::vector<int>{0, 1}));
        QCOMPARE(outcome.join->welded, 1);
        QCOMPARE(outcome.join->parts, 1);
        QCOMPARE(outcome.surfaces.size(), std::size_t(1));
        QCOMPARE(outcome.surfaces.front().faces().size(), std::size_t(2));
        QCOMPARE(outcome.surfaces.front().name(), std::string("a + b"));
    }

    void aCancelledJoinChangesNothing() {
        solver::JobRequest request;
        request.kind = solver::JobKind::Join;
        request.surfaces = twoFlatStrips();
        std::atomic<bool> cancel{true};
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(request, &cancel);
        QVERIFY(!outcome.ok);
        QVERIFY(outcome.cancelled());
        QVERIFY(outcome.surfaces.empty());
    }

    void theJoinJobPullsTowardsTheReference() {
        // The command line's --join: two strips fitted to a cylinder patch 209 mm around and
        // 160 mm high, so split around it, joined by the Join job (along their facing rulings)
        // with every point as its target.
        const std::vector<Vec3> points = cylinderPatch(0, 160, 60, 48);
        const solver::JobOutcome outcome = fitAndJoin(points, 2);
        QVERIFY(outcome.ok);
        QVERIFY(outcome.join->pulledToReference);
        QCOMPARE(outcome.join->welded, 1);
        QCOMPARE(outcome.surfaces.size(), std::size_t(1));
        const model::CompositeSurface& joined = outcome.surfaces.front();
        QVERIFY(joined.validate().empty());
        QCOMPARE(sharedEdges(joined, false), 1);
        QCOMPARE(sharedCurves(joined), 0);
        QVERIFY(test::sampledDevelopability(joined) <= 1e-8);
        const CylinderFit fit = cylinderFit(joined);
        qInfo("join job on the cylinder: %.3g mm apart before, weld gap %.3g mm, distance to the "
              "cylinder %.3g mm, z %.1f … %.1f, %.0f ms",
              outcome.join->separations.front(), outcome.join->largestGap, fit.distance, fit.zLow,
              fit.zHigh, outcome.elapsedMs);
        QVERIFY(fit.distance <= 0.5);
        QVERIFY(fit.zLow <= 5.0 && fit.zHigh >= 155.0);
    }
};

DEVSURF_REGISTER_TEST(TstCurvePairing);
#include "tst_curve_pairing.moc"
