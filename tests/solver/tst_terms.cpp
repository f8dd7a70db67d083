#include "solver_test_problems.h"

#include "solver/core/bisector_term.h"
#include "solver/core/minimum_length_term.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <cstdint>

using namespace devsurf::solver;
using namespace devsurf::solver::testing;

namespace {

constexpr int kPoints = 6;
constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-7;

// Checks the analytic Jacobian against central differences at several random points.
void checkAgainstFiniteDifferences(const Term& term, int variables, unsigned seed) {
    std::mt19937 rng(seed);
    QVERIFY(term.rowCount() > 0);
    for (int trial = 0; trial < 5; ++trial) {
        const std::vector<double> x = randomVector(rng, variables, 1.5);
        const SparseRows analytic = analyticJacobian(term, x);
        const SparseRows numeric = finiteDifferenceJacobian(term, x, kStep);
        QVERIFY(!numeric.empty());
        const double error = jacobianError(analytic, numeric);
        QVERIFY2(error < kTolerance,
                 qPrintable(QString("%1: |J - J_fd| = %2").arg(term.typeName()).arg(error)));
    }
}

} // namespace

class TstTerms : public QObject {
    Q_OBJECT

private slots:
    void linearTerm() {
        std::mt19937 rng(1);
        LinearTerm term;
        term.addRow({{0, 2.0}, {5, -1.0}, {0, 0.5}}, 0.25); // repeated column
        term.addPointRelation(3, randomCombination(rng, kPoints, 3, 3), nullptr);
        const double rhs[3] = {1.0, 2.0, 3.0};
        term.addPointRelation(3, {{3, 1.0}, {6, -1.0}}, rhs);
        QCOMPARE(term.rowCount(), 7);
        checkAgainstFiniteDifferences(term, 3 * kPoints, 11);
        // Residual value: 2.5 x0 − x5 − 0.25.
        std::vector<double> x(3 * kPoints, 0.0);
        x[0] = 1.0;
        x[5] = 0.5;
        std::vector<double> r(7), j(20);
        term.evaluate(x.data(), r.data(), j.data());
        QCOMPARE(r[0], 2.5 - 0.5 - 0.25);
    }

    void bilinearTerm() {
        std::mt19937 rng(2);
        for (int dimension : {2, 3}) {
            BilinearTerm term(dimension);
            for (int row = 0; row < 5; ++row) {
                term.addRow(randomCombination(rng, kPoints, dimension, 2),
                            randomCombination(rng, kPoints, dimension, 4), 0.3 * row);
            }
            // The same point on both sides and twice on one side.
            term.addRow({{0, 1.0}, {dimension, 0.5}}, {{0, 1.0}, {0, -0.25}});
            checkAgainstFiniteDifferences(term, dimension * kPoints, 12u + dimension);
        }
        // Value: ⟨(1,2,3), 2·(1,0,1) − (0,1,0)⟩ − 1 = 2 − 2 + 6 − 1 = 5.
        BilinearTerm term(3);
        term.addRow({{0, 1.0}}, {{3, 2.0}, {6, -1.0}}, 1.0);
        const std::vector<double> x{1, 2, 3, 1, 0, 1, 0, 1, 0};
        double r = 0.0;
        std::vector<double> j(9);
        term.evaluate(x.data(), &r, j.data());
        QCOMPARE(r, 5.0);
    }

    void bisectorTerm() {
        std::mt19937 rng(3);
        BisectorTerm term;
        for (int row = 0; row < 5; ++row) {
            term.addRow(randomCombination(rng, kPoints, 3, 2),
                        randomCombination(rng, kPoints, 3, 3),
                        randomCombination(rng, kPoints, 3, 4));
        }
        // One point in all three combinations, and twice in one.
        term.addRow({{0, 1.0}, {3, 0.5}}, {{0, -0.5}, {6, 1.0}}, {{0, 1.0}, {0, -0.25}});
        checkAgainstFiniteDifferences(term, 3 * kPoints, 31);
        const std::vector<double> reference = randomVector(rng, 3 * kPoints, 1.5);
        term.weighSidesAt(reference.data());
        term.scaleRowsAt(reference.data());
        checkAgainstFiniteDifferences(term, 3 * kPoints, 32);
        // Values at n = (2,0,0), m = (0,0,3): with weights 1 the bilinear ⟨d, n + m⟩, which is
        // not zero for d = (1,5,−1) normal to the bisector (1,0,1) of n and m (2 − 3 = −1).
        BisectorTerm value;
        value.addRow({{0, 1.0}}, {{3, 1.0}}, {{6, 1.0}});
        value.addRow({{0, 1.0}}, {{3, 1.0}}, {{9, 1.0}});
        const std::vector<double> x{2, 0, 0, 0, 0, 3, 1, 0, 1, 1, 5, -1};
        QCOMPARE(value.rowResidual(0, x.data()), 5.0);
        QCOMPARE(value.rowResidual(1, x.data()), -1.0);
        // Weighed at x, (w_n, w_m) = 2 (3, 2) / 5: w_n n + w_m m = (2.4, 0, 2.4) lies on the
        // bisector, and that d gives zero whatever the lengths of n and m.
        value.weighSidesAt(x.data());
        QVERIFY(std::abs(value.rowResidual(0, x.data()) - 4.8) < 1e-14);
        QVERIFY(std::abs(value.rowResidual(1, x.data())) < 1e-15);
        // Scaled at x: the first row is the cosine of d and the bisector, 1.
        value.scaleRowsAt(x.data());
        QVERIFY(std::abs(value.rowResidual(0, x.data()) - 1.0) < 1e-14);
    }

    void unitNormTerm() {
        std::mt19937 rng(3);
        UnitNormTerm term(3);
        term.addVector(0);
        term.addVector(9);
        term.addVector(randomCombination(rng, kPoints, 3, 3));
        checkAgainstFiniteDifferences(term, 3 * kPoints, 13);
        const std::vector<double> x{0.6, 0.8, 0.0};
        UnitNormTerm unit(3);
        unit.addVector(0);
        double r = 1.0;
        double j[3];
        unit.evaluate(x.data(), &r, j);
        QVERIFY(std::abs(r) < 1e-15);
        QCOMPARE(j[0], 1.2);
    }

    void squaredDistanceTerm() {
        std::mt19937 rng(4);
        // (12): a 2D development against 3D points, in one variable vector.
        const int offset2d = 3 * kPoints;
        SquaredDistanceTerm isometry(2, 3);
        for (int row = 0; row < 4; ++row) {
            PointCombination flat;
            for (const PointTerm& p : randomCombination(rng, kPoints, 2, 2)) {
                flat.push_back({offset2d + p.offset, p.coefficient});
            }
            isometry.addRow(flat, randomCombination(rng, kPoints, 3, 2), 0.0);
        }
        checkAgainstFiniteDifferences(isometry, 3 * kPoints + 2 * kPoints, 14);

        SquaredDistanceTerm distance(3, 3);
        distance.addRow({{0, 1.0}, {3, -1.0}}, 4.0);
        distance.addRow(randomCombination(rng, kPoints, 3, 3), 0.5);
        checkAgainstFiniteDifferences(distance, 3 * kPoints, 15);
        const std::vector<double> x{0, 0, 0, 1, 2, 2};
        double r[2];
        std::vector<double> j(64);
        SquaredDistanceTerm simple(3, 3);
        simple.addRow({{0, 1.0}, {3, -1.0}}, 4.0);
        simple.evaluate(x.data(), r, j.data());
        QCOMPARE(r[0], 9.0 - 4.0);
        // A row scaled by 1 / (2 d) measures the change of the length d to first order: the
        // residual and every Jacobian value are scaled, and the Jacobian still matches.
        simple.setRowScale(0, 0.25);
        double scaled = 0.0;
        std::vector<double> jScaled(64);
        simple.evaluate(x.data(), &scaled, jScaled.data());
        QCOMPARE(scaled, 0.25 * (9.0 - 4.0));
        for (int k = 0; k < 6; ++k) {
            QCOMPARE(jScaled[static_cast<std::size_t>(k)], 0.25 * j[static_cast<std::size_t>(k)]);
        }
        distance.setRowScale(1, 3.0);
        checkAgainstFiniteDifferences(distance, 3 * kPoints, 16);
    }

    void fairnessTerm() {
        FairnessTerm term(3);
        term.addSequence({0, 3, 6, 9});
        term.addSequence({0, 6, 12, 15}, true);
        QCOMPARE(term.rowCount(), (2 + 4) * 3);
        checkAgainstFiniteDifferences(term, 3 * kPoints, 16);
        // Collinear, equally spaced points have zero second differences.
        std::vector<double> x(3 * kPoints);
        for (int i = 0; i < kPoints; ++i) {
            for (int k = 0; k < 3; ++k) {
                x[static_cast<std::size_t>(3 * i + k)] = i * (k + 1.0);
            }
        }
        FairnessTerm open(3);
        open.addSequence({0, 3, 6, 9, 12});
        std::vector<double> r(9), j(27);
        open.evaluate(x.data(), r.data(), j.data());
        for (double v : r) {
            QCOMPARE(v, 0.0);
        }
    }

    void scaledBilinearRows() {
        // Row scales 1/(|u||v|) taken at a reference state: the Jacobian is that of the scaled
        // rows, and near the reference the residual is the cosine of the sides' angle.
        std::mt19937 rng(21);
        BilinearTerm term(3);
        for (int row = 0; row < 5; ++row) {
            term.addRow(randomCombination(rng, kPoints, 3, 2),
                        randomCombination(rng, kPoints, 3, 3), 0.1 * row);
        }
        const std::vector<double> reference = randomVector(rng, 3 * kPoints, 1.5);
        term.scaleRowsAt(reference.data());
        checkAgainstFiniteDifferences(term, 3 * kPoints, 22);
        // At the reference: ⟨u, v⟩/(|u||v|) for the row ⟨x₀, x₁ − x₂⟩, computed by hand.
        BilinearTerm angle(3);
        angle.addRow({{0, 1.0}}, {{3, 1.0}, {6, -1.0}});
        const std::vector<double> x{1, 2, 2, 4, 0, 3, 1, 0, 3}; // u = (1,2,2), v = (3,0,0)
        angle.scaleRowsAt(x.data());
        QCOMPARE(angle.rowScale(0), 1.0 / 9.0);
        QVERIFY(std::abs(angle.rowResidual(0, x.data()) - 3.0 / 9.0) < 1e-15);
        // Scaling every point by λ (state and reference alike) leaves the residual unchanged.
        std::vector<double> y = x;
        for (double& v : y) {
            v *= 1e-3;
        }
        angle.scaleRowsAt(y.data());
        QVERIFY(std::abs(angle.rowResidual(0, y.data()) - 3.0 / 9.0) < 1e-12);
        angle.scaleRowsAt(nullptr);
        QCOMPARE(angle.rowScale(0), 1.0);
    }

    void minimumLengthTerm() {
        // Rows max(0, 1 − |Σ cᵢ pᵢ|/L): active rows have minima above their lengths, inactive
        // ones below (away from the kink at |·| = L, where the derivative jumps).
        std::mt19937 rng(23);
        for (int trial = 0; trial < 5; ++trial) {
            const std::vector<double> x = randomVector(rng, 3 * kPoints, 1.5);
            MinimumLengthTerm term(3);
            for (int row = 0; row < 6; ++row) {
                const PointCombination c = randomCombination(rng, kPoints, 3, 3);
                const int r = term.addRow(c, 0.0);
                term.setMinimum(r, (row % 2 == 0 ? 2.0 : 0.5) * term.length(r, x.data()));
            }
            const double error =
                jacobianError(analyticJacobian(term, x), finiteDifferenceJacobian(term, x, kStep));
            QVERIFY2(error < kTolerance, qPrintable(QString("|J - J_fd| = %1").arg(error)));
        }
        // Values: |(3,4,0)| = 5 against minima 10 (active, 0.5), 4 (inactive) and 0 (never).
        MinimumLengthTerm term(3);
        term.addRow({{0, 1.0}, {3, -1.0}}, 10.0);
        term.addRow({{0, 1.0}, {3, -1.0}}, 4.0);
        term.addRow({{0, 1.0}, {3, -1.0}}, 0.0);
        const std::vector<double> x{3, 4, 0, 0, 0, 0};
        double r[3];
        std::vector<double> j(18);
        term.evaluate(x.data(), r, j.data());
        QCOMPARE(r[0], 0.5);
        QCOMPARE(r[1], 0.0);
        QCOMPARE(r[2], 0.0);
        QCOMPARE(j[0], -3.0 / 50.0); // −c v/(|v| L) = −3/(5·10)
        QCOMPARE(j[6], 0.0);
    }

    void minimumLengthTermLimitsTheStep() {
        // u = p₀ − p₁ = (4, 0, 0), |u| = 4; each step is checked against |u + αw| on the line.
        MinimumLengthTerm term(3);
        term.addRow({{0, 1.0}, {3, -1.0}}, 2.0);
        const std::vector<double> x{4, 0, 0, 0, 0, 0};
        auto lengthAfter = [&x](const std::vector<double>& step, double alpha) {
            return std::hypot(x[0] + alpha * step[0] - x[3] - alpha * step[3],
                              x[1] + alpha * step[1] - x[4] - alpha * step[4]);
        };
        // Shrinking to 1: at most to half (2) of the length, reached at α = 2/3.
        const std::vector<double> shrink{-3, 0, 0, 0, 0, 0};
        double alpha = term.admissibleStep(x.data(), shrink.data(), 0.5);
        QVERIFY(std::abs(alpha - 2.0 / 3.0) < 1e-14);
        QVERIFY(std::abs(lengthAfter(shrink, alpha) - 2.0) < 1e-14);
        // Through zero to the other side (−4): the first crossing, α = 1/4.
        const std::vector<double> through{-8, 0, 0, 0, 0, 0};
        alpha = term.admissibleStep(x.data(), through.data(), 0.5);
        QVERIFY(std::abs(alpha - 0.25) < 1e-14);
        QVERIFY(std::abs(lengthAfter(through, alpha) - 2.0) < 1e-14);
        // Sideways, ending at 5 (the length never falls below 4): admitted.
        const std::vector<double> sideways{-1, 3, 0, -1, 0, 0};
        QCOMPARE(term.admissibleStep(x.data(), sideways.data(), 0.5), 1.0);
        // Shrinking to 3, above half: admitted; the same step with keep 0.9 stops at 3.6.
        const std::vector<double> small{-1, 0, 0, 0, 0, 0};
        QCOMPARE(term.admissibleStep(x.data(), small.data(), 0.5), 1.0);
        alpha = term.admissibleStep(x.data(), small.data(), 0.9);
        QVERIFY(std::abs(lengthAfter(small, alpha) - 3.6) < 1e-14);
        // A row of minimum 0 guards nothing.
        term.setMinimum(0, 0.0);
        QCOMPARE(term.admissibleStep(x.data(), through.data(), 0.5), 1.0);
    }

    void minimumLengthTermEngagesTheGuardsAStepCrosses() {
        // u = p₀ − p₁ = (4, 0, 0) against minimum 2: a step to length 1 crosses the guard, one
        // to 3 does not. An engaged row is evaluated as 1 − |u|/L on either side of its bound
        // (−1 here, at length 4), with its Jacobian, until the guards are released.
        MinimumLengthTerm term(3);
        term.addRow({{0, 1.0}, {3, -1.0}}, 2.0);
        term.addRow({{0, 1.0}, {3, -1.0}}, 0.0); // guards nothing, never engaged
        const std::vector<double> x{4, 0, 0, 0, 0, 0};
        const std::vector<double> small{-1, 0, 0, 0, 0, 0};
        const std::vector<double> through{-3, 0, 0, 0, 0, 0};
        double r[2];
        std::vector<double> j(12);
        QCOMPARE(term.engageCrossedGuards(x.data(), small.data()), 0);
        term.evaluate(x.data(), r, j.data());
        QCOMPARE(r[0], 0.0);
        QCOMPARE(j[0], 0.0);
        const std::uint64_t before = term.revision();
        QCOMPARE(term.engageCrossedGuards(x.data(), through.data()), 1);
        QVERIFY(term.revision() != before); // evaluated again, not taken from a cache
        QCOMPARE(term.engageCrossedGuards(x.data(), through.data()), 0); // engaged already
        term.evaluate(x.data(), r, j.data());
        QCOMPARE(r[0], -1.0);
        QCOMPARE(j[0], -0.5); // −c v/(|v| L) = −4/(4·2)
        QCOMPARE(r[1], 0.0);
        term.releaseGuards();
        term.evaluate(x.data(), r, j.data());
        QCOMPARE(r[0], 0.0);
        QCOMPARE(j[0], 0.0);
    }

    void fairnessOfTheChange() {
        // With a reference r the rows are Δ²(x − r): zero at the reference, whatever its shape.
        std::mt19937 rng(24);
        FairnessTerm term(3);
        term.addSequence({0, 3, 6, 9});
        term.addSequence({0, 6, 12, 15}, true);
        const std::vector<double> reference = randomVector(rng, 3 * kPoints, 1.5);
        term.setReference(reference.data());
        checkAgainstFiniteDifferences(term, 3 * kPoints, 25);
        std::vector<double> r(static_cast<std::size_t>(term.rowCount())), j(3 * r.size());
        term.evaluate(reference.data(), r.data(), j.data());
        for (double v : r) {
            QVERIFY(std::abs(v) < 1e-15);
        }
        // A translated reference has the same second differences.
        std::vector<double> moved = reference;
        for (double& v : moved) {
            v += 0.25;
        }
        term.evaluate(moved.data(), r.data(), j.data());
        for (double v : r) {
            QVERIFY(std::abs(v) < 1e-14);
        }
        term.setReference(nullptr);
        term.evaluate(reference.data(), r.data(), j.data());
        QVERIFY(std::any_of(r.begin(), r.end(), [](double v) { return std::abs(v) > 1e-3; }));
    }

    void targetTerm() {
        TargetTerm term;
        term.addTarget(4, 1.5);
        const double target[3] = {1.0, 2.0, 3.0};
        const int first = term.addPointTarget(9, 3, target);
        QCOMPARE(first, 1);
        checkAgainstFiniteDifferences(term, 3 * kPoints, 17);
        term.setTarget(0, -1.0);
        std::vector<double> x(3 * kPoints, 0.0);
        std::vector<double> r(4), j(4);
        term.evaluate(x.data(), r.data(), j.data());
        QCOMPARE(r[0], 1.0);
        QCOMPARE(r[3], -3.0);
    }

    void finiteDifferenceCheckDetectsWrongJacobian() {
        // The checker itself must be able to fail: a term with a deliberately wrong derivative.
        struct WrongTerm : Term {
            const char* typeName() const override { return "WrongTerm"; }
            int rowCount() const override { return 1; }
            void buildPattern(PatternBuilder& b) const override {
                b.beginRow();
                b.addColumn(0);
            }
            void evaluate(const double* x, double* r, double* j) const override {
                r[0] = x[0] * x[0];
                j[0] = x[0]; // should be 2 x0
            }
        } wrong;
        const std::vector<double> x{0.7};
        QVERIFY(jacobianError(analyticJacobian(wrong, x),
                              finiteDifferenceJacobian(wrong, x, kStep)) > 0.5);
    }
};

DEVSURF_REGISTER_TEST(TstTerms);
#include "tst_terms.moc"
