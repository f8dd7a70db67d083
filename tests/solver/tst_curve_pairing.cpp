// Pairing boundary curves (§4.2, "Composite"): the linearised "samples of one lie on the
// tangent line of the other at their closest point".

#include "model/reference/initial_strip.h"
#include "model/strip_joining.h"
#include "solver/formulation/surface_formulation.h"
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
};

DEVSURF_REGISTER_TEST(TstCurvePairing);
#include "tst_curve_pairing.moc"
