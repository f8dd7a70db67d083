// Approximation of a reference shape (§4.2, eqs. 9–11): strips pulled towards points sampled
// from known developables recover them, and stay exactly developable, measured here
// independently of the solver.

#include "model/reference/distance_report.h"
#include "model/reference/initial_strip.h"
#include "model/reference/strip_rings.h"
#include "model/reference/thinning.h"
#include "model/strip_joining.h"
#include "sampled_developability.h"
#include "solver/session/approximation_setup.h"
#include "solver/session/solve_job.h"
#include "test_registry.h"

#include <QTest>

#include <cmath>
#include <functional>
#include <memory>

using namespace devsurf;
using model::Vec3;
using test::sampledDevelopability;

namespace {

// Points on a grid of the surface f over [0, 1]².
std::vector<Vec3> sampleGrid(const std::function<Vec3(double, double)>& f, int nu, int nv) {
    std::vector<Vec3> points;
    for (int i = 0; i <= nu; ++i) {
        for (int j = 0; j <= nv; ++j) {
            points.push_back(f(static_cast<double>(i) / nu, static_cast<double>(j) / nv));
        }
    }
    return points;
}

struct Recovery {
    model::CompositeSurface surface;
    solver::JobOutcome outcome;
    model::reference::DistanceReport distance;
    double developability = 0.0;
};

// Thins `points` (ρ: 2 % of their diagonal), fits a flat strip with `intervals` intervals and
// runs the approximation job.
// 80° × 50° of a sphere of radius 100 mm, which no developable strip fits closely.
std::vector<Vec3> sphereCap() {
    const double radius = 100.0;
    return sampleGrid(
        [radius](double s, double t) {
            const double theta = (-40.0 + 80.0 * s) * 3.141592653589793 / 180.0;
            const double phi = (-25.0 + 50.0 * t) * 3.141592653589793 / 180.0;
            return Vec3(radius * std::cos(phi) * std::sin(theta),
                        radius * std::cos(phi) * std::cos(theta), radius * std::sin(phi));
        },
        80, 48);
}

// `cylinderStart`: the damped pull, if needed, starts from the cylinder over the thinned points
// (as for the automatic path's strips: ApproximationTarget::dampedStart).
Recovery approximate(const std::vector<Vec3>& points, int intervals, int iterations,
                     bool cylinderStart = false) {
    const model::reference::ThinningResult thinned = model::reference::thinReference(points, 0.0);
    auto target = std::make_shared<solver::ApproximationTarget>();
    for (const model::reference::ThinnedPoint& p : thinned.points) {
        target->points.push_back(p.position);
        target->normals.push_back(p.normal);
    }
    target->borderReach = thinned.radius;
    target->falloff = 3.0 * thinned.radius; // as devsurf-cli approximate
    solver::JobRequest request;
    request.kind = solver::JobKind::Approximate;
    request.iterations = iterations;
    request.surfaces = {model::reference::initialStrip(target->points, {3, 2, intervals})};
    if (cylinderStart) {
        target->dampedStart = model::reference::initialCylinderStrip(
            target->points, target->normals, {3, 2, intervals}, 0.0);
    }
    request.targets[0] = target;
    solver::SolveJob job;
    Recovery r;
    r.outcome = job.run(request);
    if (r.outcome.ok) {
        r.surface = r.outcome.surfaces.front();
        r.distance = model::reference::measureDistance(r.surface, points);
        r.developability = sampledDevelopability(r.surface);
    }
    return r;
}

} // namespace

class TstApproximation : public QObject {
    Q_OBJECT

private slots:
    void recoversAParabolicCylinder_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }

    void recoversAParabolicCylinder() {
        // A cylinder over the parabola y = x² / 100: cubic splines hold it exactly.
        QFETCH(double, scale);
        const std::vector<Vec3> points = sampleGrid(
            [scale](double s, double t) {
                const double x = -50 + 100 * s;
                return Vec3(x, 0.01 * x * x, 60 * t) * scale;
            },
            80, 48);
        const Recovery r = approximate(points, 4, 30);
        QVERIFY(r.outcome.ok);
        const double diameter = r.distance.diagonal;
        qInfo("cylinder x %g: target to surface max %.3g of the diameter (mean %.3g); "
              "developability %.3g; residual %.3g; %d iterations, %.0f ms",
              scale, r.distance.targetToSurface.max / diameter,
              r.distance.targetToSurface.mean / diameter, r.developability,
              r.outcome.largestResidual(), r.outcome.largestIterationCount(), r.outcome.elapsedMs);
        QVERIFY(r.distance.targetToSurface.max <= 1e-6 * diameter);
        QCOMPARE(r.distance.coverage, 1.0);
        QVERIFY(r.developability <= 1e-8);
        QVERIFY(r.outcome.assessments.front().summary.toleranceReached);
        QVERIFY(!r.outcome.assessments.front().dampedApproximation); // it fits exactly
    }

    void recoversAConePatch() {
        // The cone from the apex (0, −20, −60) over the parabola above: exact in cubic splines.
        // The flat start is a trapezoid whose curves each span their half of the points
        // (model::reference::initialStrip), so it follows without damping. The unit length of
        // the control normals fades with the pull: a cone's normal spline cannot keep unit
        // control normals, and held at full weight while the pull faded they bent the strip
        // 1.3e-4 of the diameter away. Now 4.3e-6 (2.7e-6 after 100 iterations), still short
        // of the 1e-6 for a reason not established (the parabolic cylinder: 5.5e-7).
        const Vec3 apex(0, -20, -60);
        const std::vector<Vec3> points = sampleGrid(
            [&apex](double s, double t) {
                const double x = -50 + 100 * s;
                const Vec3 directrix(x, 0.01 * x * x, 60);
                return apex + (directrix - apex) * (0.5 + 0.5 * t);
            },
            80, 40);
        const Recovery r = approximate(points, 4, 30);
        QVERIFY(r.outcome.ok);
        const double diameter = r.distance.diagonal;
        qInfo("cone: target to surface max %.3g of the diameter (mean %.3g); developability "
              "%.3g; residual %.3g",
              r.distance.targetToSurface.max / diameter, r.distance.targetToSurface.mean / diameter,
              r.developability, r.outcome.largestResidual());
        QVERIFY(r.developability <= 1e-8);
        QVERIFY(!r.outcome.assessments.front().dampedApproximation);
        QVERIFY(r.distance.targetToSurface.max <= 1e-5 * diameter);
        QEXPECT_FAIL("", "the strip stays 4.3e-6 of the diameter away (see above)", Continue);
        QVERIFY(r.distance.targetToSurface.max <= 1e-6 * diameter);
    }

    void approachesACircularCylinder() {
        // A quarter of a circular cylinder, which cubic splines hold only approximately: the
        // faded pull leaves the strip near the spline's approximation error (2.2e-6 of the
        // diameter; 4.2e-5 while the unit control normals did not fade with the pull),
        // developable (sampled det 8e-12; docs/tuning.md).
        const double radius = 50.0;
        const std::vector<Vec3> points = sampleGrid(
            [radius](double s, double t) {
                const double phi = 1.5707963267948966 * (s - 0.5);
                return Vec3(radius * std::sin(phi), radius * (1.0 - std::cos(phi)), 60 * t);
            },
            80, 48);
        const Recovery r = approximate(points, 4, 30);
        QVERIFY(r.outcome.ok);
        const double diameter = r.distance.diagonal;
        qInfo("circular cylinder: target to surface max %.3g of the diameter (mean %.3g); "
              "developability %.3g; %d iterations",
              r.distance.targetToSurface.max / diameter, r.distance.targetToSurface.mean / diameter,
              r.developability, r.outcome.largestIterationCount());
        QVERIFY(r.distance.targetToSurface.max <= 1e-5 * diameter);
        QVERIFY(r.developability <= 1e-8);
        QVERIFY(r.outcome.assessments.front().summary.toleranceReached);
    }

    void twoStripsFollowTheirHalvesOfACylinder() {
        // The parabolic cylinder split in two by the setup's K-means: each half is narrower
        // around (57 mm of arc) than along the rulings (60 mm), so a strip laid along its
        // longest axis ran across the rulings, could not bend onto it and was pulled again
        // damped, 1.3 % of the diagonal away on average. The thinned normals turn the strips
        // (model::reference::initialStrip): both follow closely, neither damped.
        const std::vector<Vec3> points = sampleGrid(
            [](double s, double t) {
                const double x = -50 + 100 * s;
                return Vec3(x, 0.01 * x * x, 60 * t);
            },
            40, 24);
        solver::ApproximationOptions options;
        options.strips = 2;
        options.intervals = 2;
        options.oneSurface = false; // separate strips, as over a closed shape
        const solver::ApproximationSetup setup = solver::prepareApproximation(points, {}, options);
        QCOMPARE(setup.surfaces.size(), std::size_t(2));
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(setup.request);
        QVERIFY(outcome.ok);
        for (const solver::SurfaceAssessment& a : outcome.assessments) {
            QVERIFY(!a.dampedApproximation);
            QVERIFY(a.summary.toleranceReached);
        }
        const model::reference::DistanceReport distance =
            model::reference::measureDistance(outcome.surfaces, points);
        qInfo("two strips: target to surface mean %.3g, max %.3g of the diagonal",
              distance.targetToSurface.mean / distance.diagonal,
              distance.targetToSurface.max / distance.diagonal);
        QVERIFY(distance.targetToSurface.mean <= 1e-3 * distance.diagonal);
        for (const model::CompositeSurface& strip : outcome.surfaces) {
            QVERIFY(sampledDevelopability(strip) <= 1e-8);
        }
    }

    void stripsOverAPatchAreLaidAsOneSurface() {
        // The same parabolic cylinder, 100 × 120 mm: one patch, so three new strips are laid
        // side by side as one surface and pulled as one: watertight, exactly developable and as
        // close as separate strips.
        const std::vector<Vec3> points = sampleGrid(
            [](double s, double t) {
                const double x = -50 + 100 * s;
                return Vec3(x, 0.01 * x * x, 120 * t);
            },
            40, 48);
        solver::ApproximationOptions options;
        options.strips = 3;
        options.intervals = 2;
        const solver::ApproximationSetup setup = solver::prepareApproximation(points, {}, options);
        QCOMPARE(setup.error, solver::ApproximationSetup::Error::None);
        QCOMPARE(setup.surfaces.size(), std::size_t(1));
        QCOMPARE(setup.stripsInOneSurface, 3);
        QVERIFY(setup.newStrips);
        QVERIFY(!setup.request.targets.at(0)->overhang); // no trim: it is not one strip
        QCOMPARE(setup.surfaces.front().faces().size(), std::size_t(3));
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(setup.request);
        QVERIFY(outcome.ok);
        const model::CompositeSurface& result = outcome.surfaces.front();
        QVERIFY(outcome.assessments.front().summary.toleranceReached);
        QVERIFY(!outcome.assessments.front().approximationKeptStart);
        QCOMPARE(model::surfaceParts(result).size(), std::size_t(1));
        QVERIFY(sampledDevelopability(result) <= 1e-8);
        const model::reference::DistanceReport distance =
            model::reference::measureDistance(outcome.surfaces, points);
        qInfo("one surface of three strips: target to surface mean %.3g, max %.3g of the "
              "diagonal, coverage %.3g",
              distance.targetToSurface.mean / distance.diagonal,
              distance.targetToSurface.max / distance.diagonal, distance.coverage);
        QVERIFY(distance.targetToSurface.mean <= 1e-3 * distance.diagonal);
        QCOMPARE(distance.coverage, 1.0);
        // A torus is neither one patch nor closed around an axis: separate strips.
        const std::vector<Vec3> torus = sampleGrid(
            [](double s, double t) {
                const double phi = 6.2 * s;
                const double psi = 6.2 * t;
                return Vec3((100 + 30 * std::cos(psi)) * std::cos(phi),
                            (100 + 30 * std::cos(psi)) * std::sin(phi), 30 * std::sin(psi));
            },
            120, 40);
        const solver::ApproximationSetup apart = solver::prepareApproximation(torus, {}, options);
        QCOMPARE(apart.stripsInOneSurface, 0);
        QCOMPARE(apart.surfaces.size(), std::size_t(3));
    }

    void ringsAroundAClosedShapeAreOneSurface() {
        // A sphere of radius 100 (all but 3° at its poles) closes around an axis: four new
        // strips are laid as rings one after another around it, one surface open only at the
        // poles, and pulled as one: watertight, exactly developable and close.
        const std::vector<Vec3> sphere = sampleGrid(
            [](double s, double t) {
                const double theta = 0.05 + 3.04 * s;
                const double phi = 6.2 * t;
                return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                            std::cos(theta)) *
                       100.0;
            },
            40, 60);
        solver::ApproximationOptions options;
        options.strips = 4;
        options.intervals = 2;
        const solver::ApproximationSetup setup = solver::prepareApproximation(sphere, {}, options);
        QCOMPARE(setup.error, solver::ApproximationSetup::Error::None);
        QCOMPARE(setup.surfaces.size(), std::size_t(1));
        QCOMPARE(setup.stripsInOneSurface, 4);
        QVERIFY(setup.stripsAsRings);
        QCOMPARE(setup.surfaces.front().faces().size(),
                 std::size_t(4 * model::reference::kRingSectors));
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(setup.request);
        QVERIFY(outcome.ok);
        const model::CompositeSurface& result = outcome.surfaces.front();
        QVERIFY(outcome.assessments.front().summary.toleranceReached);
        QCOMPARE(model::surfaceParts(result).size(), std::size_t(1));
        QVERIFY(sampledDevelopability(result) <= 1e-8);
        const model::reference::DistanceReport distance =
            model::reference::measureDistance(outcome.surfaces, sphere);
        qInfo("four rings around a sphere: target to surface mean %.3g, max %.3g of the "
              "diagonal, coverage %.3g",
              distance.targetToSurface.mean / distance.diagonal,
              distance.targetToSurface.max / distance.diagonal, distance.coverage);
        QVERIFY(distance.targetToSurface.mean <= 5e-3 * distance.diagonal);
        QVERIFY(distance.coverage >= 0.9);
        // Without one surface, separate strips over its patches.
        options.oneSurface = false;
        const solver::ApproximationSetup apart = solver::prepareApproximation(sphere, {}, options);
        QCOMPARE(apart.stripsInOneSurface, 0);
        QVERIFY(!apart.stripsAsRings);
        QCOMPARE(apart.surfaces.size(), std::size_t(4));
    }

    void aNewStripIsTrimmedWhereItOverhangsTheShape() {
        // A cylinder z = x² / 400 over 160 × 40 mm but for the triangle beyond the line from
        // (100, 40) to (160, 0): one new strip laid over it covers its rectangle, so it stands
        // off the shape over the triangle. Once pulled it is trimmed back there, and ends
        // developable.
        std::vector<Vec3> points;
        for (const Vec3& p :
             sampleGrid([](double s, double t) { return Vec3(160 * s, 40 * t, 0); }, 64, 16)) {
            if (p.x <= 100.0 + 1e-9 || p.y <= 40.0 * (160.0 - p.x) / 60.0 + 1e-9) {
                points.emplace_back(p.x, p.y, p.x * p.x / 400.0);
            }
        }
        solver::ApproximationOptions options;
        options.strips = 1;
        options.intervals = 2;
        const solver::ApproximationSetup setup = solver::prepareApproximation(points, {}, options);
        QCOMPARE(setup.surfaces.size(), std::size_t(1));
        solver::SolveJob job;
        const solver::JobOutcome trimmed = job.run(setup.request);
        // The same job without the trim.
        solver::JobRequest whole = setup.request;
        auto target = std::make_shared<solver::ApproximationTarget>(*whole.targets.at(0));
        target->overhang.reset();
        whole.targets[0] = target;
        const solver::JobOutcome untrimmed = job.run(whole);
        QVERIFY(trimmed.ok && untrimmed.ok);
        const solver::SurfaceAssessment& a = trimmed.assessments.front();
        QVERIFY(a.approximationTrim && a.approximationTrim->trims());
        QVERIFY(!untrimmed.assessments.front().approximationTrim);
        QVERIFY(a.summary.toleranceReached);
        QVERIFY(sampledDevelopability(trimmed.surfaces.front()) <= 1e-8);
        const model::reference::DistanceReport cut =
            model::reference::measureDistance(trimmed.surfaces, points);
        const model::reference::DistanceReport full =
            model::reference::measureDistance(untrimmed.surfaces, points);
        qInfo("trimmed: surface to target max %.3g mm (untrimmed %.3g), coverage %.3g (%.3g), "
              "%.2f of the parameters kept",
              cut.surfaceToTarget.max, full.surfaceToTarget.max, cut.coverage, full.coverage,
              a.approximationTrim->kept());
        QVERIFY(cut.surfaceToTarget.max <
                0.7 * full.surfaceToTarget.max); // measured 16.1 and 26.1 mm
        QVERIFY(cut.coverage > 0.8);
    }

    void aDoublyCurvedPatchIsFollowedDampedAndStaysDevelopable() {
        // 80° × 50° of a sphere of radius 100 mm, which no developable strip fits closely. At
        // full weight the pull left the strip far from developable and it ran away in the fade
        // (parts of it 3.7 m from the target, sampled det 3e-4); the job falls back to the
        // damped recipe, which ends developable and near (measured: 24 mm of the 157 mm
        // diagonal at most, det 4e-10).
        const std::vector<Vec3> points = sphereCap();
        const Recovery r = approximate(points, 4, 30);
        QVERIFY(r.outcome.ok);
        const solver::SurfaceAssessment& a = r.outcome.assessments.front();
        const double diameter = r.distance.diagonal;
        qInfo("sphere cap: target to surface mean %.3g, max %.3g; surface to target max %.3g "
              "of the diameter; developability %.3g; residual %.3g",
              r.distance.targetToSurface.mean / diameter, r.distance.targetToSurface.max / diameter,
              r.distance.surfaceToTarget.max / diameter, r.developability,
              a.summary.finalMaxConstraintResidual);
        QVERIFY(a.dampedApproximation);
        QVERIFY(a.summary.toleranceReached);
        QVERIFY(r.developability <= 1e-8);
        QVERIFY(r.distance.surfaceToTarget.max <= 0.25 * diameter);
        QVERIFY(r.distance.targetToSurface.mean <= 0.06 * diameter);
    }

    void aDoublyCurvedPatchIsPulledDampedFromItsCylinder() {
        // The sphere cap above with the damped pull starting from the cylinder that fits the
        // points best instead of the flat strip: it ends developable and nearer (measured:
        // target to surface mean 0.016 of the diameter against 0.039, the largest 0.047
        // against 0.135).
        const std::vector<Vec3> points = sphereCap();
        const Recovery flat = approximate(points, 4, 30);
        const Recovery cylinder = approximate(points, 4, 30, true);
        QVERIFY(flat.outcome.ok && cylinder.outcome.ok);
        const double diameter = cylinder.distance.diagonal;
        qInfo("sphere cap from the cylinder: target to surface mean %.3g, max %.3g of the "
              "diameter (from the flat strip %.3g, %.3g); developability %.3g",
              cylinder.distance.targetToSurface.mean / diameter,
              cylinder.distance.targetToSurface.max / diameter,
              flat.distance.targetToSurface.mean / diameter,
              flat.distance.targetToSurface.max / diameter, cylinder.developability);
        const solver::SurfaceAssessment& a = cylinder.outcome.assessments.front();
        QVERIFY(a.dampedApproximation);
        QVERIFY(a.summary.toleranceReached);
        QVERIFY(cylinder.developability <= 1e-8);
        QVERIFY(cylinder.distance.targetToSurface.mean < 0.7 * flat.distance.targetToSurface.mean);
    }

    void pointsBeyondTheBorderDoNotDragTheStrip() {
        // Half the target is a far-away blob beside the strip's points, and the border reach
        // keeps the strip on its own points.
        std::vector<Vec3> points =
            sampleGrid([](double s, double t) { return Vec3(100 * s, 60 * t, 0.0); }, 40, 24);
        auto target = std::make_shared<solver::ApproximationTarget>();
        const model::CompositeSurface start = model::reference::initialStrip(points, {3, 2, 2});
        for (const Vec3& p : points) {
            target->points.push_back(p + Vec3(0, 0, 1.0)); // the strip is pulled up by 1
            target->normals.push_back(Vec3(0, 0, 1));
        }
        for (int i = 0; i < 200; ++i) {
            target->points.push_back(Vec3(400 + i, 30, 200));
            target->normals.push_back(Vec3(0, 0, 1));
        }
        target->borderReach = 5.0;
        solver::JobRequest request;
        request.kind = solver::JobKind::Approximate;
        request.surfaces = {start};
        request.targets[0] = target;
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(request);
        QVERIFY(outcome.ok);
        points.resize(41 * 25);
        for (Vec3& p : points) {
            p.z += 1.0;
        }
        const auto report = model::reference::measureDistance(outcome.surfaces.front(), points);
        QVERIFY2(report.targetToSurface.max < 1e-3,
                 qPrintable(QString::number(report.targetToSurface.max)));
    }
};

DEVSURF_REGISTER_TEST(TstApproximation);
#include "tst_approximation.moc"
