#include "solver_test_problems.h"

#include "solver/core/guided_projection.h"

#include "test_registry.h"

#include <QTest>

#include <cmath>

using namespace devsurf::solver;
using namespace devsurf::solver::testing;

// Options::reuseFactorization: steps that solve with an earlier iteration's factorisation.
class TstFactorReuse : public QObject {
    Q_OBJECT

private slots:
    void reusedFactorizationAlternatesAndConverges() {
        // Options::reuseFactorization = 1: every other iteration solves with the factorisation
        // of the iteration before (a chord step), and the iteration still converges.
        auto circle = makeCircleProblem(24, 3);
        std::vector<double> x = circle->start;
        Options options;
        options.maxIterations = 60;
        options.reuseFactorization = 1;
        GuidedProjection solver;
        const Summary summary = solver.solve(circle->problem, x, options);
        QVERIFY2(summary.succeeded(), summary.briefReport().c_str());
        QCOMPARE(static_cast<int>(summary.iterations.size()), 60);
        for (std::size_t i = 0; i < summary.iterations.size(); ++i) {
            const IterationStats& it = summary.iterations[i];
            QCOMPARE(it.factorizationReused, i % 2 == 1);
            if (it.factorizationReused) {
                QCOMPARE(it.factorizationMs, 0.0);
            }
        }
        QVERIFY2(summary.finalMaxConstraintResidual <= 1e-10,
                 qPrintable(QString::number(summary.finalMaxConstraintResidual)));
        for (int i = 0; i < circle->points; ++i) {
            const double r = std::hypot(x[static_cast<std::size_t>(2 * i)],
                                        x[static_cast<std::size_t>(2 * i + 1)]);
            QVERIFY(std::abs(r - 1.0) < 1e-10);
        }
    }

    void factorizationIsReusedOnlyWhileItHolds() {
        auto circle = makeCircleProblem(12, 5);
        std::vector<double> x = circle->start;
        Options options;
        options.maxIterations = 1;
        options.reuseFactorization = 2;
        GuidedProjection solver;
        auto reused = [&] {
            const Summary s = solver.solve(circle->problem, x, options);
            return s.succeeded() && s.iterations.front().factorizationReused;
        };
        // Across solve() calls (one iteration each, as a drag runs them), at most twice in a row.
        QVERIFY(!reused());
        QVERIFY(reused());
        QVERIFY(reused());
        QVERIFY(!reused());
        QVERIFY(reused());
        // Not once the fixed variables changed, nor below the flops asked for.
        circle->problem.setFixed(5);
        QVERIFY(!reused());
        options.reuseFactorizationMinimumFlops = 1e12;
        QVERIFY(!reused());
        options.reuseFactorizationMinimumFlops = 0.0;
        QVERIFY(reused());
        options.reuseFactorization = 0;
        QVERIFY(!reused());

        // Never a factorisation that failed: ε₂ = 0 and a variable that no row touches.
        Problem p;
        addTwoTargetsOfThree(p);
        std::vector<double> y{0.5, 0.5, 0.5};
        Options two;
        two.reuseFactorization = 1;
        two.maxIterations = 1;
        GuidedProjection other;
        QVERIFY(other.solve(p, y, two).succeeded()); // factorised with ε₂ = 0.01
        two.eps2 = 0.0;
        two.reuseFactorization = 0;
        QCOMPARE(other.solve(p, y, two).status, Status::FactorizationFailed);
        two.reuseFactorization = 1;
        const Summary again = other.solve(p, y, two);
        QCOMPARE(again.status, Status::FactorizationFailed);
        QCOMPARE(again.iterationsCompleted, 0);
    }
};

DEVSURF_REGISTER_TEST(TstFactorReuse);
#include "tst_factor_reuse.moc"
