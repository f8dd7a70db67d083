#include "solver_test_problems.h"

#include "solver/core/guided_projection.h"

#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace devsurf::solver;
using namespace devsurf::solver::testing;

namespace {

// One row x³ − t on one variable: its slope changes fast, so a factorisation made at one x
// is far from right at another.
class CubeTerm : public Term {
public:
    explicit CubeTerm(double target) : m_target(target) {}
    const char* typeName() const override { return "CubeTerm"; }
    int rowCount() const override { return 1; }
    void buildPattern(PatternBuilder& builder) const override {
        builder.beginRow();
        builder.addColumn(0);
    }
    void evaluate(const double* x, double* residuals, double* jacobian) const override {
        residuals[0] = x[0] * x[0] * x[0] - m_target;
        jacobian[0] = 3.0 * x[0] * x[0];
    }

private:
    double m_target;
};

} // namespace

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

    void aReusedStepThatThrowsTheIterateOffIsUndone() {
        // x³ = 27 from x = 1: the first step (slope 3) lands at x = 9.67. A chord step there with
        // the factorisation made at x = 1 jumps to x = −282 (the merit from 7.7e5 to 5e14);
        // undone (Options::reusedStepMeritRise), Newton's step from 9.67 goes to 6.54.
        for (const double rise : {0.0, 100.0}) {
            Problem p;
            p.addVariableBlock("x", 1);
            p.add(p.addFamily("cube", TermRole::Constraint), std::make_unique<CubeTerm>(27.0));
            std::vector<double> x{1.0};
            Options options;
            options.maxIterations = 1;
            options.reuseFactorization = 1;
            options.reusedStepMeritRise = rise;
            GuidedProjection solver;
            QVERIFY(solver.solve(p, x, options).succeeded());
            QVERIFY2(std::abs(x[0] - 9.667) < 0.01, qPrintable(QString::number(x[0])));
            const Summary second = solver.solve(p, x, options);
            QVERIFY2(second.succeeded(), second.briefReport().c_str());
            const IterationStats& it = second.iterations.front();
            if (rise == 0.0) {
                QVERIFY(it.factorizationReused);
                QVERIFY(!it.reuseUndone);
                QVERIFY2(x[0] < -280.0, qPrintable(QString::number(x[0])));
            } else {
                QVERIFY(!it.factorizationReused);
                QVERIFY(it.reuseUndone);
                QVERIFY(it.factorizationMs > 0.0);
                QVERIFY2(std::abs(x[0] - 6.541) < 0.01, qPrintable(QString::number(x[0])));
            }
        }
    }

    void aReusedStepWithinTheRiseIsKept() {
        // The same chord step is kept when its merit stays within the rise: on the circle
        // problem every other step reuses, and with a rise of 100 none is undone.
        auto circle = makeCircleProblem(24, 3);
        std::vector<double> x = circle->start;
        Options options;
        options.maxIterations = 20;
        options.reuseFactorization = 1;
        options.reusedStepMeritRise = 100.0;
        GuidedProjection solver;
        const Summary summary = solver.solve(circle->problem, x, options);
        QVERIFY2(summary.succeeded(), summary.briefReport().c_str());
        for (std::size_t i = 0; i < summary.iterations.size(); ++i) {
            QCOMPARE(summary.iterations[i].factorizationReused, i % 2 == 1);
            QVERIFY(!summary.iterations[i].reuseUndone);
        }
    }

    void aFactorisationMadeAheadServesTheFirstStep() {
        // Options::factorizeAhead with no iteration (a drag prepared while the pointer rests):
        // x stays, and the next solve()'s first step is a chord step with that factorisation.
        // From a start whose residual is above ε₂'s top the weights are the step's own, so the
        // step is the one a fresh factorisation takes.
        auto circle = makeCircleProblem(24, 3, 0.2);
        Options options;
        options.maxIterations = 1;
        options.reuseFactorization = 2;
        std::vector<double> fresh = circle->start;
        GuidedProjection plain;
        const Summary first = plain.solve(circle->problem, fresh, options);
        QVERIFY2(first.succeeded(), first.briefReport().c_str());
        QVERIFY(!first.iterations.front().factorizationReused);
        QVERIFY(first.initialMaxConstraintResidual > options.eps2);

        for (const bool ahead : {false, true}) {
            std::vector<double> x = circle->start;
            GuidedProjection solver;
            Options prepare = options;
            prepare.maxIterations = 0;
            prepare.factorizeAhead = ahead;
            const Summary prepared = solver.solve(circle->problem, x, prepare);
            QVERIFY2(prepared.succeeded(), prepared.briefReport().c_str());
            QVERIFY(prepared.iterations.empty());
            QVERIFY(x == circle->start);
            const Summary step = solver.solve(circle->problem, x, options);
            QVERIFY2(step.succeeded(), step.briefReport().c_str());
            const IterationStats& it = step.iterations.front();
            QCOMPARE(it.factorizationReused, ahead);
            QCOMPARE(it.factorizationMs > 0.0, !ahead);
            double largest = 0.0;
            for (std::size_t i = 0; i < x.size(); ++i) {
                largest = std::max(largest, std::abs(x[i] - fresh[i]));
            }
            QVERIFY2(largest < 1e-12, qPrintable(QString::number(largest)));
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
        // Across solve() calls (one iteration each, as a drag runs them), at most twice in a row;
        // more only while a later factorisation is being made beside, and none is here.
        options.reuseWhileFactorizingBeside = 5;
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
