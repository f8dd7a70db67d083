#include "solver_test_problems.h"

#include "solver/core/blas_info.h"
#include "solver/core/guided_projection.h"
#include "solver/core/linear_term.h"
#include "solver/core/minimum_length_term.h"
#include "solver/core/normal_equations.h"

#include "test_registry.h"

#include <QTest>

#include <suitesparse/SuiteSparse_config.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

using namespace devsurf::solver;
using namespace devsurf::solver::testing;

// Allocation counting for the no-allocation-in-the-loop test. Replacing the global operator
// new conflicts with AddressSanitizer's own, so it is compiled only without it.
#if defined(__SANITIZE_ADDRESS__)
#define DEVSURF_COUNT_ALLOCATIONS 0
#else
#define DEVSURF_COUNT_ALLOCATIONS 1
#endif

namespace {
std::atomic<long> g_newCount{0};
std::atomic<long> g_cholmodMallocCount{0};
void* (*g_originalMalloc)(size_t) = nullptr;
void* (*g_originalCalloc)(size_t, size_t) = nullptr;
void* (*g_originalRealloc)(void*, size_t) = nullptr;

void* countingMalloc(size_t size) {
    ++g_cholmodMallocCount;
    return g_originalMalloc(size);
}
void* countingCalloc(size_t count, size_t size) {
    ++g_cholmodMallocCount;
    return g_originalCalloc(count, size);
}
void* countingRealloc(void* p, size_t size) {
    ++g_cholmodMallocCount;
    return g_originalRealloc(p, size);
}
} // namespace

#if DEVSURF_COUNT_ALLOCATIONS
void* operator new(std::size_t size) {
    ++g_newCount;
    if (void* p = std::malloc(size == 0 ? 1 : size)) {
        return p;
    }
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
#endif

namespace {

double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        d = std::max(d, std::abs(a[i] - b[i]));
    }
    return d;
}

// p₀ = (x₀, x₁) pulled onto the origin by a hard target; its distance to the fixed
// p₁ = (x₂, x₃) guarded with the given minimum.
void pulledPastAGuard(Problem& p, double minimum) {
    const int points = p.addVariableBlock("points", 4);
    const FamilyId hard = p.addFamily("target", TermRole::Constraint, 1.0);
    const FamilyId guards = p.addFamily("guard", TermRole::Constraint, 1.0);
    auto target = std::make_unique<TargetTerm>();
    target->addTarget(points, 0.0);
    target->addTarget(points + 1, 0.0);
    p.add(hard, std::move(target));
    auto guard = std::make_unique<MinimumLengthTerm>(2);
    guard->addRow({{points, 1.0}, {points + 2, -1.0}}, minimum);
    p.add(guards, std::move(guard));
    p.setFixed(points + 2);
    p.setFixed(points + 3);
}

// Produces finite values for the first `goodEvaluations` evaluations, then NaN.
class PoisonTerm : public Term {
public:
    explicit PoisonTerm(int goodEvaluations) : m_remaining(goodEvaluations) {}
    const char* typeName() const override { return "PoisonTerm"; }
    int rowCount() const override { return 1; }
    void buildPattern(PatternBuilder& b) const override {
        b.beginRow();
        b.addColumn(0);
    }
    void evaluate(const double* x, double* r, double* j) const override {
        const bool poisoned = m_remaining-- <= 0;
        r[0] = poisoned ? std::nan("") : 0.0 * x[0];
        j[0] = 0.0;
    }

private:
    mutable int m_remaining;
};

// A large synthetic problem of strips of points with normals: ⟨n, pᵢ₊₁ − pᵢ⟩ = 0, unit
// normals, fairness; about 30k variables for strips = 500.
std::unique_ptr<Problem> makeStripProblem(int strips, int length, std::vector<double>& x) {
    auto p = std::make_unique<Problem>();
    const int pointsPerStrip = 2 * length;
    const int pointBlock = p->addVariableBlock("points", 3 * pointsPerStrip * strips);
    const int normalBlock = p->addVariableBlock("normals", 3 * length * strips);
    const FamilyId hard = p->addFamily("dev", TermRole::Constraint, 1.0);
    const FamilyId soft = p->addFamily("fair", TermRole::Energy, 0.1);
    auto dev = std::make_unique<BilinearTerm>(3);
    auto unit = std::make_unique<UnitNormTerm>(3);
    auto fair = std::make_unique<FairnessTerm>(3);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> noise(-0.02, 0.02);
    x.assign(static_cast<std::size_t>(p->variableCount()), 0.0);
    for (int s = 0; s < strips; ++s) {
        std::vector<int> a, b;
        for (int i = 0; i < length; ++i) {
            const int pa = pointBlock + 3 * (s * pointsPerStrip + 2 * i);
            const int pb = pa + 3;
            a.push_back(pa);
            b.push_back(pb);
            const double t = 0.1 * i;
            x[static_cast<std::size_t>(pa)] = t;
            x[static_cast<std::size_t>(pa + 1)] = s + noise(rng);
            x[static_cast<std::size_t>(pa + 2)] = noise(rng);
            x[static_cast<std::size_t>(pb)] = t + noise(rng);
            x[static_cast<std::size_t>(pb + 1)] = s + 0.5 + noise(rng);
            x[static_cast<std::size_t>(pb + 2)] = 0.1 * std::sin(t) + noise(rng);
            const int n = normalBlock + 3 * (s * length + i);
            x[static_cast<std::size_t>(n + 2)] = 1.0;
            unit->addVector(n);
            dev->addRow({{n, 1.0}}, {{pb, 1.0}, {pa, -1.0}});
            if (i + 1 < length) {
                dev->addRow({{n, 1.0}}, {{pa + 6, 1.0}, {pa, -1.0}});
                dev->addRow({{n, 1.0}}, {{pb + 6, 1.0}, {pb, -1.0}});
            }
        }
        fair->addSequence(a);
        fair->addSequence(b);
    }
    p->add(hard, std::move(dev));
    p->add(hard, std::move(unit));
    p->add(soft, std::move(fair));
    return p;
}

} // namespace

class TstGuidedProjection : public QObject {
    Q_OBJECT

private slots:
    void circleConverges_data() {
        QTest::addColumn<int>("method");
        QTest::newRow("supernodal") << static_cast<int>(FactorizationMethod::Supernodal);
        QTest::newRow("simplicial") << static_cast<int>(FactorizationMethod::Simplicial);
        QTest::newRow("automatic") << static_cast<int>(FactorizationMethod::Automatic);
        QTest::newRow("measured") << static_cast<int>(FactorizationMethod::Measured);
        QTest::newRow("calibrated") << static_cast<int>(FactorizationMethod::Calibrated);
    }

    void circleConverges() {
        QFETCH(int, method);
        auto circle = makeCircleProblem(24, 3);
        std::vector<double> x = circle->start;
        Options options;
        options.maxIterations = 60;
        options.residualTolerance = 1e-11;
        options.factorization = static_cast<FactorizationMethod>(method);
        GuidedProjection solver;
        const Summary summary = solver.solve(circle->problem, x, options);
        QVERIFY2(summary.status == Status::Converged, summary.briefReport().c_str());
        QVERIFY(summary.initialMaxConstraintResidual > 1e-2);
        QVERIFY(summary.factorizedInPlace);
        QVERIFY(summary.finalMaxConstraintResidual <= 1e-10);
        for (int i = 0; i < circle->points; ++i) {
            const double r = std::hypot(x[static_cast<std::size_t>(2 * i)],
                                        x[static_cast<std::size_t>(2 * i + 1)]);
            QVERIFY(std::abs(r - 1.0) < 1e-10);
        }
        QCOMPARE(static_cast<int>(summary.iterations.size()), summary.iterationsCompleted);
        const IterationStats& last = summary.iterations.back();
        QVERIFY(last.factorFlops > 0.0);
        QVERIFY(last.factorNonZeros >= circle->problem.variableCount());
        QVERIFY(last.assemblyMs >= 0.0 && last.factorizationMs >= 0.0 && last.solveMs >= 0.0);
        if (options.factorization == FactorizationMethod::Supernodal) {
            QVERIFY(summary.supernodal);
        } else if (options.factorization == FactorizationMethod::Simplicial) {
            QVERIFY(!summary.supernodal);
        }
    }

    void structureIsReusedAcrossSolves() {
        auto circle = makeCircleProblem(10, 4);
        std::vector<double> x = circle->start;
        Options options;
        options.maxIterations = 2;
        GuidedProjection solver;
        QVERIFY(!solver.solve(circle->problem, x, options).structureReused);
        QVERIFY(solver.solve(circle->problem, x, options).structureReused);
        circle->problem.setFamilyWeight(circle->soft, 0.5); // values only
        QVERIFY(solver.solve(circle->problem, x, options).structureReused);
        auto extra = std::make_unique<TargetTerm>();
        extra->addTarget(3, 0.0);
        circle->problem.add(circle->soft, std::move(extra));
        QVERIFY(!solver.solve(circle->problem, x, options).structureReused);
    }

    void softTargetPullsAndFixedStayFixed() {
        // Points on the unit circle (hard), p₀ pulled towards (1, 1)·2 by a soft target.
        Problem p;
        const int points = p.addVariableBlock("points", 6);
        const FamilyId hard = p.addFamily("circle", TermRole::Constraint, 1.0);
        const FamilyId soft = p.addFamily("target", TermRole::Energy, 1.0);
        auto norms = std::make_unique<UnitNormTerm>(2);
        for (int i = 0; i < 3; ++i) {
            norms->addVector(points + 2 * i);
        }
        p.add(hard, std::move(norms));
        auto target = std::make_unique<TargetTerm>();
        target->addTarget(points, 2.0);
        target->addTarget(points + 1, 2.0);
        TargetTerm* targetTerm = p.add(soft, std::move(target));
        auto coupling = std::make_unique<LinearTerm>(); // p₁ − p₂ tied to p₀: would move them
        coupling->addPointRelation(2, {{points, 1.0}, {points + 2, -1.0}, {points + 4, 1.0}});
        p.add(soft, std::move(coupling));
        p.setBlockFixed("points", false);
        p.setFixed(points + 2);
        p.setFixed(points + 3);

        const std::vector<double> start{1.0, 0.0, 0.0, 1.0, -1.0, 0.0};
        Options options;
        options.maxIterations = 10; // 5 with ε₁ (pull), 5 without (back onto the circle)
        // The start satisfies the constraints: by default (ε₁ capped by the constraint
        // residual) the energies do not act on it at all.
        {
            std::vector<double> y = start;
            QVERIFY(GuidedProjection().solve(p, y, options).succeeded());
            QVERIFY(maxAbsDifference(y, start) < 1e-14);
        }
        // The paper's schedule alone lets the soft target pull.
        options.eps1ResidualFactor = 0.0;
        GuidedProjection solver;

        std::vector<double> x = start;
        Summary s = solver.solve(p, x, options);
        QVERIFY2(s.succeeded(), s.briefReport().c_str());
        // p₀ moved along the circle towards the target direction (angle > 0) ...
        QVERIFY(x[1] > 0.05);
        QVERIFY(std::abs(std::hypot(x[0], x[1]) - 1.0) < 1e-6);
        QVERIFY(s.finalMaxConstraintResidual < 1e-6);
        // ... while the fixed point did not move at all.
        QCOMPARE(x[2], 0.0);
        QCOMPARE(x[3], 1.0);

        // Without ε₁ the energy has no influence: a feasible start stays put.
        x = start;
        options.eps1Initial = 0.0;
        s = solver.solve(p, x, options);
        QVERIFY(maxAbsDifference(x, start) < 1e-14);

        // A target family of weight 0 does not pull either.
        x = start;
        options.eps1Initial = 0.1;
        p.setFamilyWeight(soft, 0.0);
        solver.solve(p, x, options);
        QVERIFY(maxAbsDifference(x, start) < 1e-14);

        // Moving the target (a value change) pulls the other way.
        p.setFamilyWeight(soft, 1.0);
        targetTerm->setTarget(1, -2.0);
        x = start;
        s = solver.solve(p, x, options);
        QVERIFY(s.structureReused);
        QVERIFY(x[1] < -0.05);
    }

    void guardedLengthsShrinkAtMostByTheLimitPerStep() {
        // p₀ pulled onto the origin by a hard target, its distance to the fixed p₁ = (-1, 0)
        // guarded with minimum 0.5 (p₀ starts at (1, 0), 2 away): an undamped step lands on
        // the origin at once (distance 1, inactive guard); with the limit 0.75 the distance
        // shrinks by at most a quarter per step.
        Problem p;
        pulledPastAGuard(p, 0.5);
        const std::vector<double> start{1.0, 0.0, -1.0, 0.0};
        Options options;
        options.maxIterations = 1;
        options.eps1Initial = 0.0;
        options.eps2 = 1e-6;
        std::vector<double> x = start;
        GuidedProjection solver;
        QVERIFY(solver.solve(p, x, options).succeeded());
        QVERIFY(std::abs(x[0]) < 1e-6); // the full step
        options.guardShrinkLimit = 0.75;
        double distance = 2.0;
        x = start;
        for (int step = 0; step < 4; ++step) {
            const Summary s = solver.solve(p, x, options);
            QVERIFY(s.succeeded());
            const double now = std::hypot(x[0] + 1.0, x[1]);
            QVERIFY2(now >= 0.75 * distance - 1e-12, qPrintable(QString::number(now)));
            QVERIFY(s.iterations.front().stepFraction < 1.0 || now <= 1.0 + 1e-6);
            distance = now;
        }
        QVERIFY(std::abs(x[0]) < 0.1); // it gets there, in shorter steps
    }

    void aGuardTheStepWouldCrossIsHeldInThatStep() {
        // p₀ pulled from (1, 0) onto the origin, its distance to the fixed p₁ = (−1, 0) guarded
        // with minimum 1.5: the target and the guard meet at x₀ = 2/13 (the least squares of
        // x₀ and 1 − (x₀ + 1)/1.5). The first step lands on the origin, crossing the guard,
        // which only the next step sees; with Options::engageCrossedGuards the first step is
        // made again with the guard held and lands where they meet.
        Problem p;
        pulledPastAGuard(p, 1.5);
        Options options;
        options.maxIterations = 1;
        options.eps1Initial = 0.0;
        options.eps2 = 1e-9;
        options.adaptiveEps2 = false;
        const double meet = 2.0 / 13.0;
        for (bool engage : {false, true}) {
            options.engageCrossedGuards = engage;
            std::vector<double> x{1.0, 0.0, -1.0, 0.0};
            GuidedProjection solver;
            const Summary first = solver.solve(p, x, options);
            QVERIFY(first.succeeded());
            QCOMPARE(first.iterations.front().guardsEngaged, engage);
            const double afterOne = x[0];
            QVERIFY(solver.solve(p, x, options).succeeded());
            QVERIFY2(std::abs(x[0] - meet) < 1e-6, qPrintable(QString::number(x[0])));
            if (engage) {
                QVERIFY2(std::abs(afterOne - meet) < 1e-6, qPrintable(QString::number(afterOne)));
            } else {
                QVERIFY2(std::abs(afterOne) < 1e-6, qPrintable(QString::number(afterOne)));
            }
        }
    }

    void hardConstraintWeightZeroIsIgnored() {
        auto circle = makeCircleProblem(8, 5);
        circle->problem.setFamilyWeight(circle->hard, 0.0);
        std::vector<double> x = circle->start;
        Options options;
        options.maxIterations = 3;
        options.eps1Initial = 0.0;
        GuidedProjection solver;
        const Summary s = solver.solve(circle->problem, x, options);
        QVERIFY(maxAbsDifference(x, circle->start) < 1e-14);
        QCOMPARE(s.finalMaxConstraintResidual, 0.0); // weight-0 rows are not reported
    }

    void nanInInitialStateIsReported() {
        auto circle = makeCircleProblem(8, 6);
        std::vector<double> x = circle->start;
        x[3] = std::nan("");
        const std::vector<double> before = x;
        GuidedProjection solver;
        const Summary s = solver.solve(circle->problem, x, Options());
        QCOMPARE(s.status, Status::NonFiniteValue);
        QCOMPARE(s.iterationsCompleted, 0);
        QVERIFY(std::isnan(x[3]));
        x[3] = 0.0;
        QVERIFY(maxAbsDifference(x, [&] {
                    auto b = before;
                    b[3] = 0.0;
                    return b;
                }()) == 0.0);
    }

    void nanFromTermReturnsLastGoodState() {
        // Reference: three clean iterations.
        auto reference = makeCircleProblem(12, 7);
        std::vector<double> expected = reference->start;
        Options options;
        options.maxIterations = 3;
        GuidedProjection referenceSolver;
        QVERIFY(referenceSolver.solve(reference->problem, expected, options).succeeded());

        // Same problem with a term that turns NaN at its 5th evaluation (the initial state
        // and iterates 1..3 are fine, iterate 4 is poisoned).
        auto circle = makeCircleProblem(12, 7);
        circle->problem.add(circle->hard, std::make_unique<PoisonTerm>(4));
        std::vector<double> x = circle->start;
        options.maxIterations = 10;
        GuidedProjection solver;
        const Summary s = solver.solve(circle->problem, x, options);
        QCOMPARE(s.status, Status::NonFiniteValue);
        QCOMPARE(s.iterationsCompleted, 3);
        QVERIFY(!s.detail.empty());
        QVERIFY(maxAbsDifference(x, expected) < 1e-12);
        for (double v : x) {
            QVERIFY(std::isfinite(v));
        }
    }

    void failedFactorizationReturnsLastGoodState() {
        // ε₂ = 0 and a variable that no row touches: N is singular.
        Problem p;
        addTwoTargetsOfThree(p);
        std::vector<double> x{0.5, 0.5, 0.5};
        Options options;
        options.eps2 = 0.0;
        for (auto method : {FactorizationMethod::Supernodal, FactorizationMethod::Simplicial}) {
            options.factorization = method;
            GuidedProjection solver;
            const Summary s = solver.solve(p, x, options);
            QCOMPARE(s.status, Status::FactorizationFailed);
            QCOMPARE(s.iterationsCompleted, 0);
            QVERIFY(!s.detail.empty());
            QCOMPARE(x, (std::vector<double>{0.5, 0.5, 0.5}));
        }
        // Fixing the free variable makes it solvable (and it converges in one step).
        p.setFixed(2);
        GuidedProjection solver;
        const Summary s = solver.solve(p, x, options);
        QVERIFY2(s.succeeded(), s.briefReport().c_str());
        QVERIFY(std::abs(x[0] - 1.0) < 1e-12 && std::abs(x[1] - 2.0) < 1e-12);
        QCOMPARE(x[2], 0.5);
    }

    void invalidProblemIsReported() {
        Problem p;
        p.addVariableBlock("x", 2);
        auto linear = std::make_unique<LinearTerm>();
        linear->addRow({{5, 1.0}}, 0.0);
        p.add(p.addFamily("l", TermRole::Constraint), std::move(linear));
        std::vector<double> x{1.0, 2.0};
        GuidedProjection solver;
        QCOMPARE(solver.solve(p, x, Options()).status, Status::InvalidProblem);
        std::vector<double> wrongSize{1.0};
        QCOMPARE(solver.solve(p, wrongSize, Options()).status, Status::InvalidProblem);
        QCOMPARE(x, (std::vector<double>{1.0, 2.0}));
    }

    void cancellation() {
        auto circle = makeCircleProblem(16, 8);
        std::vector<double> x = circle->start;
        std::atomic<bool> cancel{true};
        Options options;
        options.cancel = &cancel;
        GuidedProjection solver;
        Summary s = solver.solve(circle->problem, x, options);
        QCOMPARE(s.status, Status::Cancelled);
        QCOMPARE(s.iterationsCompleted, 0);
        QCOMPARE(x, circle->start);

        // Raised from the progress callback after the second iteration.
        cancel = false;
        options.progress = [&cancel](const IterationStats& stats) {
            if (stats.iteration == 1) {
                cancel = true;
            }
        };
        std::vector<double> expected = circle->start;
        Options two;
        two.maxIterations = 2;
        QVERIFY(GuidedProjection().solve(circle->problem, expected, two).succeeded());
        s = solver.solve(circle->problem, x, options);
        QCOMPARE(s.status, Status::Cancelled);
        QCOMPARE(s.iterationsCompleted, 2);
        QVERIFY(maxAbsDifference(x, expected) < 1e-13);
    }

    void baselineMatchesCachedIterates_data() {
        QTest::addColumn<int>("method");
        QTest::newRow("supernodal") << static_cast<int>(FactorizationMethod::Supernodal);
        QTest::newRow("simplicial") << static_cast<int>(FactorizationMethod::Simplicial);
    }

    void baselineMatchesCachedIterates() {
        QFETCH(int, method);
        auto circle = makeCircleProblem(30, 9, 0.1);
        circle->problem.setFixed(7);
        Options options;
        options.factorization = static_cast<FactorizationMethod>(method);
        GuidedProjection cached;
        GuidedProjection baseline;
        ExperimentalOptions rebuildEverything;
        rebuildEverything.baseline = true;
        baseline.setExperimentalOptions(rebuildEverything);
        std::vector<double> a = circle->start;
        std::vector<double> b = circle->start;
        double largestStep = 0.0;
        // Iterate by iterate (continuing the ε₁ schedule), so every iterate is compared.
        for (int k = 0; k < 8; ++k) {
            options.maxIterations = 1;
            options.scheduleOffset = k;
            const Summary sa = cached.solve(circle->problem, a, options);
            const Summary sb = baseline.solve(circle->problem, b, options);
            QVERIFY(sa.succeeded() && sb.succeeded());
            largestStep = std::max(largestStep, sa.iterations.front().stepNorm);
            const double difference = maxAbsDifference(a, b);
            QVERIFY2(difference < 1e-12,
                     qPrintable(QString("iterate %1: %2").arg(k + 1).arg(difference)));
        }
        QVERIFY(largestStep > 1e-2); // the iterates really moved
    }

    void noAllocationInsideTheLoop() {
        // Our code must not call operator new between iterations; CHOLMOD's allocations per
        // iteration (counted through SuiteSparse_config) must not grow with the problem.
        g_originalMalloc = SuiteSparse_config.malloc_func;
        g_originalCalloc = SuiteSparse_config.calloc_func;
        g_originalRealloc = SuiteSparse_config.realloc_func;
        SuiteSparse_config.malloc_func = countingMalloc;
        SuiteSparse_config.calloc_func = countingCalloc;
        SuiteSparse_config.realloc_func = countingRealloc;
        std::vector<long> cholmodPerIteration;
        for (int strips : {4, 40}) {
            for (auto method : {FactorizationMethod::Supernodal, FactorizationMethod::Simplicial}) {
                std::vector<double> x;
                auto problem = makeStripProblem(strips, 30, x);
                std::vector<long> newCounts;
                std::vector<long> cholmodCounts;
                Options options;
                options.maxIterations = 6;
                options.factorization = method;
                options.recordIterations = false;
                options.progress = [&](const IterationStats&) {
                    newCounts.push_back(g_newCount.load());
                    cholmodCounts.push_back(g_cholmodMallocCount.load());
                };
                newCounts.reserve(16);
                cholmodCounts.reserve(16);
                GuidedProjection solver;
                const Summary s = solver.solve(*problem, x, options);
                QVERIFY2(s.succeeded(), s.briefReport().c_str());
                QCOMPARE(newCounts.size(), std::size_t{6});
                if (DEVSURF_COUNT_ALLOCATIONS) {
                    for (std::size_t i = 1; i < newCounts.size(); ++i) {
                        QCOMPARE(newCounts[i] - newCounts[i - 1], 0L);
                    }
                }
                cholmodPerIteration.push_back(cholmodCounts[5] - cholmodCounts[4]);
            }
        }
        SuiteSparse_config.malloc_func = g_originalMalloc;
        SuiteSparse_config.calloc_func = g_originalCalloc;
        SuiteSparse_config.realloc_func = g_originalRealloc;
        // Same count for the small and the 10× larger problem, per method.
        QCOMPARE(cholmodPerIteration[0], cholmodPerIteration[2]);
        QCOMPARE(cholmodPerIteration[1], cholmodPerIteration[3]);
        qInfo("CHOLMOD allocations per iteration: supernodal %ld, simplicial %ld",
              cholmodPerIteration[0], cholmodPerIteration[1]);
    }

    void blasIsReported() {
        const BlasInfo info = detectBlas();
        qInfo("BLAS: %s", info.describe().c_str());
        QVERIFY(!info.library.empty()); // CHOLMOD pulls in a BLAS providing dgemm_
        QVERIFY(!info.vendor.empty());
        if (info.library.find("openblas") != std::string::npos) {
            QCOMPARE(QString::fromStdString(info.vendor), QString("OpenBLAS"));
            QVERIFY(info.optimized);
        }
    }
};

DEVSURF_REGISTER_TEST(TstGuidedProjection);
#include "tst_guided_projection.moc"
