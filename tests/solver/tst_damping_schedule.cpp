// The damping schedule of GuidedProjection: ε₁ and the adaptive ε₂, and the floor a failed
// factorisation leaves on ε₂.
#include "solver_test_problems.h"

#include "solver/core/guided_projection.h"
#include "solver/core/linear_term.h"
#include "solver/core/target_term.h"
#include "solver/formulation/perturbation.h"
#include "solver/formulation/surface_formulation.h"

#include "model/examples.h"

#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace devsurf::solver;
using namespace devsurf::solver::testing;

class TstDampingSchedule : public QObject {
    Q_OBJECT

private slots:
    // ExperimentalOptions::levenbergMarquardt: a rejected step raises ε₂ for the next one, also
    // across solve() calls, so that one iteration ten times equals ten iterations.
    void levenbergMarquardtKeepsItsBoostAcrossSolves() {
        devsurf::model::CompositeSurface start =
            devsurf::model::makeExample("annulus").surfaces.front();
        perturbSurface(start, 1e-3 * surfaceDiameter(start), 3, {});
        const SurfaceFormulation formulation(start, FormulationOptions{});
        ExperimentalOptions experimental;
        experimental.levenbergMarquardt = true;
        GuidedProjection one;
        GuidedProjection ten;
        one.setExperimentalOptions(experimental);
        ten.setExperimentalOptions(experimental);
        QVERIFY(ten.experimentalOptions().levenbergMarquardt);
        std::vector<double> a = formulation.initialState();
        std::vector<double> b = formulation.initialState();
        Options options;
        options.maxIterations = 1;
        for (int k = 0; k < 10; ++k) {
            options.scheduleOffset = k;
            QVERIFY(one.solve(formulation.problem(), a, options).succeeded());
        }
        options.maxIterations = 10;
        options.scheduleOffset = 0;
        const Summary summary = ten.solve(formulation.problem(), b, options);
        QVERIFY(summary.succeeded());
        QCOMPARE(summary.iterationsCompleted, 10);
        QVERIFY(std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0);
        QVERIFY(summary.finalMaxConstraintResidual < summary.initialMaxConstraintResidual);
        // A step was rejected before the last, so a later one depended on its boost.
        QVERIFY(std::any_of(summary.iterations.begin(), summary.iterations.end() - 1,
                            [](const IterationStats& it) { return it.rejected; }));
    }

    void epsilonSchedule() {
        Options options;
        QCOMPARE(epsilon1(options, 0), 0.1);
        QVERIFY(std::abs(epsilon1(options, 4) - 0.1 * std::pow(0.9, 4)) < 1e-16);
        QCOMPARE(epsilon1(options, 5), 0.0);
        QCOMPARE(options.eps2, 0.01);
        options.eps1Schedule = [](int i) { return i == 0 ? 1.0 : 0.5; };
        QCOMPARE(epsilon1(options, 3), 0.5);
    }

    void adaptiveEps2() {
        Options options;
        QVERIFY(options.adaptiveEps2);
        // During the ε₁ phase: the configured ε₂; afterwards the residual, clamped.
        QCOMPARE(epsilon2(options, 0, 1e-9), options.eps2);
        QCOMPARE(epsilon2(options, 5, 1.0), options.eps2);
        QCOMPARE(epsilon2(options, 5, 1e-4), 1e-4);
        QCOMPARE(epsilon2(options, 5, 1e-12), options.eps2Minimum);
        options.adaptiveEps2 = false;
        QCOMPARE(epsilon2(options, 5, 1e-4), options.eps2);
    }

    void singularAdaptiveStepIsRepeatedWithConfiguredEps2() {
        // A variable that no row touches: N is singular once the adaptive ε₂ reaches 0.
        Problem p;
        addTwoTargetsOfThree(p);
        std::vector<double> x{0.5, 0.5, 0.5};
        Options options;
        options.eps1Iterations = 0;
        options.eps2Minimum = 0.0;
        options.maxIterations = 6;
        GuidedProjection solver;
        const Summary s = solver.solve(p, x, options);
        QVERIFY2(s.succeeded(), s.briefReport().c_str());
        QCOMPARE(s.iterationsCompleted, 6);
        QCOMPARE(s.iterations.front().eps2, options.eps2);
        QVERIFY(s.iterations[1].eps2 < 1e-3);             // shrunk with the residual
        QCOMPARE(s.iterations.back().eps2, options.eps2); // 0 failed, repeated with ε₂
        QVERIFY(std::abs(x[0] - 1.0) < 1e-12 && std::abs(x[1] - 2.0) < 1e-12);
        QCOMPARE(x[2], 0.5);
        // Once failed, the adaptive ε₂ is not tried that small again: one repeated
        // factorisation, not one in every later iteration (nor in the next solve).
        const auto repeated = std::count_if(s.iterations.begin(), s.iterations.end(),
                                            [](const IterationStats& it) { return it.repeated; });
        QCOMPARE(repeated, 1);
        const Summary again = solver.solve(p, x, options);
        QVERIFY(std::none_of(again.iterations.begin(), again.iterations.end(),
                             [](const IterationStats& it) { return it.repeated; }));
    }

    void failedEps2FloorRisesGradually() {
        // One row w (x₀ − x₁) = w with w = 1e4: N = w² [1 −1; −1 1] + ε₂² I has the pivots
        // w² + ε₂² and 2ε₂² in exact arithmetic, but in double precision ε₂² vanishes beside
        // w² = 1e8 below half its ulp (ε₂ < 8.6e-5), and the second pivot is then zero.
        Problem p;
        p.addVariableBlock("x", 2);
        auto row = std::make_unique<LinearTerm>();
        row->addRow({{0, 1e4}, {1, -1e4}}, 1e4);
        p.add(p.addFamily("difference", TermRole::Constraint), std::move(row));
        std::vector<double> x{0.0, 0.0};
        Options options;
        options.eps1Iterations = 0;
        options.eps2Minimum = 8e-6;
        options.maxIterations = 12;
        GuidedProjection solver;
        const Summary s = solver.solve(p, x, options);
        QVERIFY2(s.succeeded(), s.briefReport().c_str());
        QVERIFY(std::abs(x[0] - x[1] - 1.0) < 1e-12);
        // Each failure is repeated with the configured ε₂ and raises the floor to twice the
        // failed value: 8e-6, 1.6e-5, 3.2e-5 and 6.4e-5 fail, 1.28e-4 factorises and is kept
        // (within twice the smallest value that factorises; a tenfold floor went from 8e-5
        // to 8e-4).
        const auto repeated = std::count_if(s.iterations.begin(), s.iterations.end(),
                                            [](const IterationStats& it) { return it.repeated; });
        QCOMPARE(repeated, 4);
        const IterationStats& last = s.iterations.back();
        QVERIFY(!last.repeated);
        QVERIFY2(std::abs(last.eps2 - 16 * 8e-6) < 1e-15, std::to_string(last.eps2).c_str());
    }

    void aTargetEnergyThatDrivesEpsilon1ActsWhereEveryConstraintHolds() {
        // x₀ = x₁ holds at the start; an energy pulls x₀ towards 1. ε₁ is capped by 1000 times
        // the residual, so an ordinary energy never acts on a design that satisfies its
        // constraints; one that drives ε₁ (a dragged crease's control points whose ends are
        // pinned) does, and lets go once its own weight is gone.
        auto run = [](bool drives, double weight) {
            Problem p;
            p.addVariableBlock("x", 2);
            auto equal = std::make_unique<LinearTerm>();
            equal->addRow({{0, 1.0}, {1, -1.0}});
            p.add(p.addFamily("equal", TermRole::Constraint), std::move(equal));
            auto target = std::make_unique<TargetTerm>();
            target->addTarget(0, 1.0);
            const FamilyId pull = p.addFamily("pull", TermRole::Energy, weight);
            p.add(pull, std::move(target));
            p.setFamilyDrivesEpsilon1(pull, drives);
            std::vector<double> x{0.0, 0.0};
            Options options;
            options.eps1Schedule = [](int) { return 0.1; };
            options.maxIterations = 20;
            GuidedProjection solver;
            const Summary s = solver.solve(p, x, options);
            return std::make_pair(x, s);
        };
        const auto [still, quiet] = run(false, 1.0);
        QCOMPARE(still[0], 0.0);
        QCOMPARE(quiet.iterations.front().eps1, 0.0);
        const auto [moved, driven] = run(true, 1.0);
        QCOMPARE(driven.iterations.front().eps1, 0.1); // 1000 × |1 − 0| caps nothing
        QVERIFY2(moved[0] > 0.5, std::to_string(moved[0]).c_str());
        QVERIFY(std::abs(moved[0] - moved[1]) < 1e-9);
        const auto [held, released] = run(true, 0.0);
        QCOMPARE(held[0], 0.0);
        QCOMPARE(released.iterations.front().eps1, 0.0);
    }
};

DEVSURF_REGISTER_TEST(TstDampingSchedule);

#include "tst_damping_schedule.moc"
