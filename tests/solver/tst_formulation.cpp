#include "solver_test_problems.h"

#include "model/bspline_curve.h"
#include "model/examples.h"
#include "solver/core/guided_projection.h"
#include "solver/formulation/perturbation.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/quality_measures.h"
#include "solver_test_models.h"

#include "test_registry.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace devsurf;
using namespace devsurf::solver;
using namespace devsurf::solver::testing;
using model::Vec3;

namespace {

Options testOptions(int iterations) {
    Options o;
    o.maxIterations = iterations;
    o.eps2 = 1e-3;
    return o;
}

// Largest distance between the curves of two surfaces with the same combinatorics, sampled.
double curveDeviation(const model::CompositeSurface& a, const model::CompositeSurface& b) {
    double deviation = 0.0;
    for (const auto& [id, record] : a.edges()) {
        if (!record.isSpline()) {
            continue;
        }
        const auto ca = model::BSplineCurve::uniform(record.space, record.controlPoints);
        const auto cb = model::BSplineCurve::uniform(b.edge(id).space, b.edge(id).controlPoints);
        for (int i = 0; i <= 100; ++i) {
            deviation = std::max(deviation,
                                 model::distance(ca.evaluate(i / 100.0), cb.evaluate(i / 100.0)));
        }
    }
    return deviation;
}

} // namespace

class TstFormulation : public QObject {
    Q_OBJECT

private slots:
    void countsOfTheSheet() {
        const model::CompositeSurface sheet = model::makeExample("sheet", 3).surfaces.front();
        const SurfaceFormulation f(sheet, FormulationOptions{});
        QCOMPARE(f.stripCount(), 9);
        QCOMPARE(f.pointCount(), static_cast<int>(sheet.controlPointCount()));
        // 9 strips × 3 intervals × 7 values × 3 rows of (4) + 9 rows n(0)ᵀn(0) = 1.
        QCOMPARE(f.problem().rowCount() - (9 * 6 * 3) - /*fairness*/ 0 >= 9 * 3 * 7 * 3 + 9, true);
        // The sheet is developable: its normal splines are quintic C¹ (3 intervals: 14 control
        // normals), which hold the normal of every developable strip; the paper's cubic C²
        // space has 6.
        QCOMPARE(f.problem().block("normalControls").size, 9 * 14 * 3);
        FormulationOptions cubic;
        cubic.exactNormalSpace = false;
        QCOMPARE(SurfaceFormulation(sheet, cubic).problem().block("normalControls").size,
                 9 * 6 * 3);
        FormulationOptions aux;
        aux.auxiliaryDerivativePoints = true;
        const SurfaceFormulation g(sheet, aux);
        QCOMPARE(g.problem().block("derivativePoints").size, 9 * 3 * 7 * 4 * 3);
    }

    void termJacobiansMatchFiniteDifferences_data() {
        QTest::addColumn<bool>("auxiliary");
        QTest::newRow("substituted") << false;
        QTest::newRow("auxiliary") << true;
    }
    void termJacobiansMatchFiniteDifferences() {
        QFETCH(bool, auxiliary);
        FormulationOptions options;
        options.auxiliaryDerivativePoints = auxiliary;
        const model::CompositeSurface mixed = model::makeExample("mixed", 1).surfaces.front();
        const SurfaceFormulation f(mixed, options);
        std::mt19937 rng(7);
        const std::vector<double> x = randomVector(rng, f.problem().variableCount());
        for (int t = 0; t < f.problem().termCount(); ++t) {
            const Term& term = f.problem().term(t);
            const double error =
                jacobianError(analyticJacobian(term, x), finiteDifferenceJacobian(term, x, 1e-6));
            QVERIFY2(error < 1e-6, term.typeName());
        }
    }

    void generalizedCylinderStaysPut() {
        // a(t) is a cubic polynomial (exactly a cubic C² spline on any knots) and b = a + d, so
        // the normal a′ × d is quadratic and the strip is exactly developable.
        const model::CompositeSurface cylinder = makeGeneralizedCylinder(1.0);
        FormulationOptions options;
        // Fairness slides control points along flat curves and bends curved ones.
        options.fairnessWeight = 0.0;
        options.normalFairnessWeight = 0.0;
        options.unitControlNormalWeight = 0.0;
        SurfaceFormulation f(cylinder, options);
        std::vector<double> x = f.initialState();
        GuidedProjection projection;
        const Summary summary = projection.solve(f.problem(), x, testOptions(10));
        QVERIFY(summary.succeeded());
        model::CompositeSurface out = cylinder;
        QVERIFY(f.writeBack(x, out));
        QVERIFY2(curveDeviation(cylinder, out) < 1e-6 * surfaceDiameter(cylinder),
                 std::to_string(curveDeviation(cylinder, out)).c_str());
    }

    void coneStaysPut() {
        const model::CompositeSurface cone = makeCone();
        FormulationOptions options;
        options.fairnessWeight = 0.0;
        SurfaceFormulation f(cone, options);
        QCOMPARE(f.coneCount(), 1);
        std::vector<double> x = f.initialState();
        GuidedProjection projection;
        const Summary summary = projection.solve(f.problem(), x, testOptions(10));
        QVERIFY(summary.succeeded());
        QVERIFY(summary.finalMaxConstraintResidual < 1e-12);
        model::CompositeSurface out = cone;
        QVERIFY(f.writeBack(x, out));
        QVERIFY(curveDeviation(cone, out) < 1e-9 * surfaceDiameter(cone));
    }

    void randomStripConverges_data() {
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<double>("scale");
        QTest::newRow("seed 1, 1e-3") << 1u << 1e-3;
        QTest::newRow("seed 2, 1") << 2u << 1.0;
        QTest::newRow("seed 3, 1e3") << 3u << 1e3;
    }
    void randomStripConverges() {
        QFETCH(unsigned, seed);
        QFETCH(double, scale);
        model::CompositeSurface strip = makeRandomStrip(seed, scale);
        const SurfaceFormulation f(strip, FormulationOptions{});
        std::vector<double> x = f.initialState();
        Options options = testOptions(30);
        options.residualTolerance = 1e-10;
        // ε₂ shrinking with the residual: fast local convergence on a far-off random start.
        options.eps2Schedule = residualEps2Schedule(1e-2, 1e-6, 1.0);
        GuidedProjection projection;
        const Summary summary = projection.solve(f.problem(), x, options);
        QVERIFY2(summary.status == Status::Converged, summary.briefReport().c_str());
        QVERIFY(summary.finalMaxConstraintResidual <= 1e-10);
        model::CompositeSurface out = strip;
        QVERIFY(f.writeBack(x, out));
        // Independent check: the strip is developable where the solver never looked.
        QVERIFY(measureQuality(out).developabilityMax < 1e-6);
    }

    void perturbedExamplesReachQuality_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<double>("paperFlatnessMean");
        // Fig. 17's rows; the cylinder and the mixed example have none, so they get the
        // smallest mean of the table (Fig. 15b).
        const struct {
            const char* name;
            double flatness;
        } examples[] = {{"sheet", 4.7e-5},
                        {"two-strips", 1.4e-4},
                        {"annulus", 1.8e-3},
                        {"cylinder", 1.5e-5},
                        {"mixed", 1.5e-5}};
        for (const auto& example : examples) {
            for (unsigned seed : {20150801u, 7u}) {
                QTest::addRow("%s, seed %u", example.name, seed)
                    << QString(example.name) << seed << example.flatness;
            }
        }
    }
    void perturbedExamplesReachQuality() {
        // Gaussian noise of σ = 0.1 % of the diameter on every vertex and control point (except
        // three fixed boundary vertices), then 10 iterations with the default options. From the
        // benchmark's 1 % start the annulus does not get there (its noise is 30 % of the ring
        // width; see the benchmark's figures).
        QFETCH(QString, name);
        QFETCH(unsigned, seed);
        QFETCH(double, paperFlatnessMean);
        model::CompositeSurface surface =
            name == "two-strips" ? makeTwoStrips(9)
                                 : model::makeExample(name.toStdString(), 0).surfaces.front();
        const auto anchors = spreadBoundaryVertices(surface, 3);
        QCOMPARE(static_cast<int>(anchors.size()), 3);
        perturbSurface(surface, 0.001 * surfaceDiameter(surface), seed, anchors);
        QVERIFY(measureQuality(surface).developabilityMax > 1e-4); // really perturbed
        FormulationOptions options;
        for (auto v : anchors) {
            options.handles.push_back({v, true, {}});
        }
        const SurfaceFormulation f(surface, options);
        std::vector<double> x = f.initialState();
        GuidedProjection projection;
        QVERIFY(projection.solve(f.problem(), x, testOptions(10)).succeeded());
        model::CompositeSurface out = surface;
        QVERIFY(f.writeBack(x, out));
        const QualityMeasures q = measureQuality(out);
        QVERIFY2(q.developabilityMax <= 1e-8, qPrintable(QString::number(q.developabilityMax)));
        QVERIFY2(q.flatnessMean <= paperFlatnessMean, qPrintable(QString::number(q.flatnessMean)));
        for (auto v : anchors) {
            QVERIFY(out.position(v) == surface.position(v)); // fixed: bit for bit
        }
    }

    void pulledHandleMovesTowardsTarget() {
        const model::CompositeSurface sheet = model::makeExample("sheet", 2).surfaces.front();
        const auto anchors = spreadBoundaryVertices(sheet, 3);
        FormulationOptions options;
        for (auto v : anchors) {
            options.handles.push_back({v, true, {}});
        }
        const model::VertexId pulled = 4; // the middle vertex of the 3 × 3 grid
        const Vec3 target = sheet.position(pulled) + Vec3(0, 0, 30.0);
        options.handles.push_back({pulled, false, target});
        SurfaceFormulation f(sheet, options);
        std::vector<double> x = f.initialState();
        GuidedProjection projection;
        QVERIFY(projection.solve(f.problem(), x, testOptions(20)).succeeded());
        QVERIFY(distance(f.vertexPosition(x, pulled), target) < 1.0);
        QVERIFY(f.setHandleTarget(pulled, target));
        QVERIFY(!f.setHandleTarget(anchors.front(), target));
    }

    void nanIsReportedAndNotWrittenBack() {
        const model::CompositeSurface sheet = model::makeExample("sheet", 2).surfaces.front();
        const SurfaceFormulation f(sheet, FormulationOptions{});
        std::vector<double> x = f.initialState();
        x[5] = std::numeric_limits<double>::quiet_NaN();
        GuidedProjection projection;
        std::vector<double> y = x;
        const Summary summary = projection.solve(f.problem(), y, testOptions(3));
        QCOMPARE(summary.status, Status::NonFiniteValue);
        model::CompositeSurface out = sheet;
        std::string error;
        QVERIFY(!f.writeBack(y, out, &error));
        QVERIFY(!error.empty());
        QVERIFY(out == sheet);
        std::vector<double> wrongSize(3, 0.0);
        QVERIFY(!f.writeBack(wrongSize, out, &error));
        QVERIFY(out == sheet);
    }

    void invalidOptionsAreRefused() {
        const model::CompositeSurface sheet = model::makeExample("sheet", 2).surfaces.front();
        FormulationOptions options;
        options.handles.push_back({9999, true, {}});
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SurfaceFormulation(sheet, options));
        FormulationOptions smooth;
        for (const auto& [id, record] : sheet.edges()) {
            if (record.isSpline()) {
                smooth.smoothRulings.push_back(id);
                break;
            }
        }
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SurfaceFormulation(sheet, smooth));
    }

    void smoothRulingKeepsNormalsEqual() {
        const model::CompositeSurface sheet = model::makeExample("sheet", 2).surfaces.front();
        FormulationOptions options;
        for (const auto& [id, record] : sheet.edges()) {
            if (!record.isSpline() && sheet.facesOfEdge(id).size() == 2) {
                options.smoothRulings.push_back(id);
            }
        }
        QVERIFY(!options.smoothRulings.empty());
        model::CompositeSurface surface = sheet;
        perturbSurface(surface, 1e-3 * surfaceDiameter(surface), 3u);
        SurfaceFormulation f(surface, options);
        std::vector<double> x = f.initialState();
        GuidedProjection projection;
        const Summary summary = projection.solve(f.problem(), x, testOptions(20));
        QVERIFY2(summary.finalMaxConstraintResidual < 1e-6, summary.briefReport().c_str());
        model::CompositeSurface out = surface;
        QVERIFY(f.writeBack(x, out));
        // Independent check: across each smooth ruling the sampled quads on either side are
        // coplanar (the strips' tangent planes agree along the shared ruling).
        QVERIFY(measureQuality(out).curvatureMax < 1e-3);
    }
};

DEVSURF_REGISTER_TEST(TstFormulation);
#include "tst_formulation.moc"
