#include "solver_test_problems.h"

#include "solver/core/normal_equations.h"

#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <numeric>

using namespace devsurf::solver;
using namespace devsurf::solver::testing;

namespace {

// A problem with every term type, repeated columns, several families (one of weight 0) and
// fixed variables.
Problem makeMixedProblem(unsigned seed, int points) {
    std::mt19937 rng(seed);
    Problem p;
    const int pointBlock = p.addVariableBlock("points", 3 * points);
    const int normalBlock = p.addVariableBlock("normals", 3 * points);
    const int flatBlock = p.addVariableBlock("development", 2 * points);
    const FamilyId dev = p.addFamily("developability", TermRole::Constraint, 1.0);
    const FamilyId unit = p.addFamily("unit", TermRole::Constraint, 2.0);
    const FamilyId iso = p.addFamily("isometry", TermRole::Constraint, 0.5);
    const FamilyId off = p.addFamily("disabled", TermRole::Constraint, 0.0);
    const FamilyId fair = p.addFamily("fairness", TermRole::Energy, 0.3);
    const FamilyId target = p.addFamily("target", TermRole::Energy, 1.0);
    auto bilinear = std::make_unique<BilinearTerm>(3);
    auto norms = std::make_unique<UnitNormTerm>(3);
    auto isometry = std::make_unique<SquaredDistanceTerm>(2, 3);
    auto linear = std::make_unique<LinearTerm>();
    auto fairness = std::make_unique<FairnessTerm>(3);
    auto targets = std::make_unique<TargetTerm>();
    std::uniform_int_distribution<int> pick(0, points - 1);
    for (int i = 0; i < points; ++i) {
        PointCombination normal{{normalBlock + 3 * pick(rng), 1.0},
                                {normalBlock + 3 * pick(rng), 0.5}};
        PointCombination combination;
        for (const PointTerm& t : randomCombination(rng, points, 3, 3)) {
            combination.push_back({pointBlock + t.offset, t.coefficient});
        }
        combination.push_back(combination.front()); // repeated point
        bilinear->addRow(normal, combination);
        norms->addVector(normalBlock + 3 * i);
        const int a = pick(rng);
        const int b = pick(rng);
        isometry->addRow({{flatBlock + 2 * a, 1.0}, {flatBlock + 2 * b, -1.0}},
                         {{pointBlock + 3 * a, 1.0}, {pointBlock + 3 * b, -1.0}}, 0.0);
        targets->addTarget(pointBlock + 3 * i + 1, 0.1 * i);
    }
    linear->addRow({{pointBlock, 1.0}, {pointBlock + 3, -1.0}, {pointBlock, 1.0}}, 0.5);
    std::vector<int> sequence(static_cast<std::size_t>(points));
    for (int i = 0; i < points; ++i) {
        sequence[static_cast<std::size_t>(i)] = pointBlock + 3 * i;
    }
    fairness->addSequence(sequence);
    p.add(dev, std::move(bilinear));
    p.add(unit, std::move(norms));
    p.add(iso, std::move(isometry));
    p.add(off, std::move(linear));
    p.add(fair, std::move(fairness));
    p.add(target, std::move(targets));
    p.setFixed(pointBlock + 4);
    p.setFixed(normalBlock + 2);
    return p;
}

// Rows shaped like the developability conditions (4): at several values per interval of a
// cubic spline, ⟨n, b − a⟩, ⟨n, a′⟩ and ⟨n, b′⟩ with n, a, b combinations of the interval's
// four control normals and points (the first side names one point twice), so consecutive rows
// share their columns and are assembled in groups. Between the intervals, rows that share
// nothing (unit norms, fairness) and a disabled family of the same shape; two fixed variables
// inside the groups.
Problem makeCollocationProblem(unsigned seed, int intervals) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
    const int controls = intervals + 3;
    Problem p;
    const int aBlock = p.addVariableBlock("a", 3 * controls);
    const int bBlock = p.addVariableBlock("b", 3 * controls);
    const int normalBlock = p.addVariableBlock("normals", 3 * controls);
    const FamilyId dev = p.addFamily("developability", TermRole::Constraint, 1.5);
    const FamilyId off = p.addFamily("disabled", TermRole::Constraint, 0.0);
    const FamilyId unit = p.addFamily("unit", TermRole::Constraint, 1.0);
    const FamilyId fair = p.addFamily("fairness", TermRole::Energy, 0.3);
    auto combination = [&](int block, int first) {
        PointCombination c;
        for (int k = 0; k < 4; ++k) {
            c.push_back({block + 3 * (first + k), coefficient(rng)});
        }
        return c;
    };
    auto minus = [](PointCombination left, const PointCombination& right) {
        for (const PointTerm& t : right) {
            left.push_back({t.offset, -t.coefficient});
        }
        return left;
    };
    auto rows = std::make_unique<BilinearTerm>(3);
    auto disabled = std::make_unique<BilinearTerm>(3);
    for (int i = 0; i < intervals; ++i) {
        for (int value = 0; value < 4; ++value) {
            const PointCombination n = combination(normalBlock, i);
            PointCombination side = minus(combination(bBlock, i), combination(aBlock, i));
            side.push_back(side.front());
            rows->addRow(n, side);
            rows->addRow(n, combination(aBlock, i));
            rows->addRow(n, combination(bBlock, i));
            disabled->addRow(n, side);
            disabled->addRow(n, combination(bBlock, i));
        }
    }
    auto norms = std::make_unique<UnitNormTerm>(3);
    std::vector<int> sequence;
    for (int k = 0; k < controls; ++k) {
        norms->addVector(normalBlock + 3 * k);
        sequence.push_back(aBlock + 3 * k);
    }
    auto fairness = std::make_unique<FairnessTerm>(3);
    fairness->addSequence(sequence);
    p.add(dev, std::move(rows));
    p.add(unit, std::move(norms));
    p.add(off, std::move(disabled));
    p.add(fair, std::move(fairness));
    p.setFixed(aBlock + 4);
    p.setFixed(normalBlock + 7);
    return p;
}

double relativeDifference(const Eigen::SparseMatrix<double>& a,
                          const Eigen::SparseMatrix<double>& b) {
    return Eigen::SparseMatrix<double>(a - b).norm() / std::max(b.norm(), 1e-300);
}

// One row x_c − t whose evaluations are counted; its target changes through setTarget (tracked)
// or, untracked, through the pointer it reads.
class CountedTarget : public Term {
public:
    CountedTarget(int column, const double* target, bool tracks)
        : m_column(column), m_target(target), m_tracks(tracks) {}
    void setTarget(const double* target) {
        m_target = target;
        changed();
    }
    int evaluations() const { return m_evaluations; }
    const char* typeName() const override { return "CountedTarget"; }
    int rowCount() const override { return 1; }
    void buildPattern(PatternBuilder& builder) const override {
        builder.beginRow();
        builder.addColumn(m_column);
    }
    void evaluate(const double* x, double* residuals, double* jacobian) const override {
        ++m_evaluations;
        residuals[0] = x[m_column] - *m_target;
        jacobian[0] = 1.0;
    }
    bool tracksChanges() const override { return m_tracks; }

private:
    int m_column;
    const double* m_target;
    bool m_tracks;
    mutable int m_evaluations = 0;
};

} // namespace

class TstNormalEquations : public QObject {
    Q_OBJECT

private slots:
    void patternsAndCounts() {
        Problem p = makeMixedProblem(5, 12);
        NormalEquations equations;
        std::string error;
        QVERIFY(equations.build(p, &error));
        QCOMPARE(equations.variableCount(), 8 * 12);
        QCOMPARE(equations.rowCount(), p.rowCount());
        QVERIFY(equations.matches(p));
        // A new term changes the structure.
        auto extra = std::make_unique<TargetTerm>();
        extra->addTarget(0, 1.0);
        p.add(p.findFamily("target"), std::move(extra));
        QVERIFY(!equations.matches(p));
    }

    void onlyChangedTermsAreEvaluatedAgain() {
        // Evaluating only what changed gives, bit for bit, what evaluating all gives.
        Problem p = makeMixedProblem(3, 30);
        const double one = 1.0;
        const double two = 2.0;
        double external = 0.5;
        auto* tracked =
            p.add(p.findFamily("target"), std::make_unique<CountedTarget>(0, &one, true));
        auto* untracked =
            p.add(p.findFamily("target"), std::make_unique<CountedTarget>(1, &external, false));
        NormalEquations equations;
        QVERIFY(equations.build(p, nullptr));
        std::mt19937 rng(5);
        const std::vector<double> x = randomVector(rng, equations.variableCount(), 2.0);
        auto sameAsAll = [&] {
            NormalEquations all;
            return all.build(p, nullptr) && all.evaluate(p, x.data()) &&
                   all.residuals() == equations.residuals() &&
                   all.jacobianValues() == equations.jacobianValues() &&
                   all.constraintMerit() == equations.constraintMerit() &&
                   all.energy() == equations.energy();
        };
        QVERIFY(equations.evaluate(p, x.data(), true));
        QCOMPARE(tracked->evaluations(), 1);
        // Nothing changed: the tracked term is skipped, the untracked one evaluated again.
        QVERIFY(equations.evaluate(p, x.data(), true));
        QCOMPARE(tracked->evaluations(), 1);
        QCOMPARE(untracked->evaluations(), 2);
        // A tracked change and an untracked one: both are seen.
        tracked->setTarget(&two);
        external = -0.25;
        QVERIFY(equations.evaluate(p, x.data(), true));
        QCOMPARE(tracked->evaluations(), 2);
        QVERIFY(sameAsAll()); // evaluates it too
        // A new x: everything again.
        std::vector<double> moved = x;
        moved[7] += 1e-12;
        QVERIFY(equations.evaluate(p, moved.data(), true));
        QCOMPARE(tracked->evaluations(), 4);
        QVERIFY(equations.evaluate(p, x.data(), true));
        QVERIFY(sameAsAll());
        // Another fixed variable: everything again, its column zeroed in every term.
        p.setFixed(5);
        QVERIFY(equations.evaluate(p, x.data(), true));
        QCOMPARE(tracked->evaluations(), 7);
        QVERIFY(sameAsAll());
    }

    void invalidColumnIsReported() {
        Problem p;
        p.addVariableBlock("x", 3);
        auto term = std::make_unique<TargetTerm>();
        term->addTarget(3, 0.0);
        p.add(p.addFamily("t", TermRole::Constraint), std::move(term));
        NormalEquations equations;
        std::string error;
        QVERIFY(!equations.build(p, &error));
        QVERIFY(!error.empty());
    }

    void refillMatchesScratchAssembly_data() {
        QTest::addColumn<int>("layout");
        QTest::addColumn<bool>("collocation");
        QTest::newRow("identity upper") << 0 << false;
        QTest::newRow("permuted lower") << 1 << false;
        QTest::newRow("permuted upper") << 2 << false;
        QTest::newRow("row groups, identity upper") << 0 << true;
        QTest::newRow("row groups, permuted lower") << 1 << true;
        QTest::newRow("row groups, permuted upper") << 2 << true;
    }

    void refillMatchesScratchAssembly() {
        QFETCH(int, layout);
        QFETCH(bool, collocation);
        Problem p = collocation ? makeCollocationProblem(7, 9) : makeMixedProblem(7, 40);
        NormalEquations equations;
        QVERIFY(equations.build(p, nullptr));
        const int n = equations.variableCount();
        std::mt19937 rng(99);
        if (layout != 0) {
            std::vector<int> permutation(static_cast<std::size_t>(n));
            std::iota(permutation.begin(), permutation.end(), 0);
            std::shuffle(permutation.begin(), permutation.end(), rng);
            equations.setLayout(permutation, layout == 1 ? NormalEquations::Triangle::Lower
                                                         : NormalEquations::Triangle::Upper);
        }
        std::vector<double> values(static_cast<std::size_t>(equations.normalNonZeros()));
        std::vector<double> rhs(static_cast<std::size_t>(n));
        // Several evaluations and ε values: the refill must not accumulate old values.
        for (const double eps1 : {0.1, 0.0, 0.0729}) {
            const std::vector<double> x = randomVector(rng, n, 2.0);
            QVERIFY(equations.evaluate(p, x.data()));
            equations.fill(p, eps1, 0.01, values.data(), rhs.data());
            Eigen::SparseMatrix<double> scratch;
            Eigen::VectorXd scratchRhs;
            equations.assembleFromScratch(p, eps1, 0.01, scratch, scratchRhs);
            const Eigen::SparseMatrix<double> refilled = equations.toOriginalUpper(values.data());
            const double difference = relativeDifference(refilled, scratch);
            QVERIFY2(difference <= 1e-14, qPrintable(QString::number(difference)));
            const Eigen::Map<const Eigen::VectorXd> refilledRhs(rhs.data(), n);
            QVERIFY((refilledRhs - scratchRhs).norm() <= 1e-14 * scratchRhs.norm());
            QVERIFY(scratch.norm() > 1.0);
        }
    }

    void rowsSharingColumnsAreAssembledInGroups() {
        // The rows of the two bilinear families (12 and 8 per interval) are assembled in groups
        // of neighbouring intervals (up to a block's width); unit norms and fairness rows share
        // too little and stay alone. Each group adds its block once: far fewer additions than
        // every row adding its own products.
        const int intervals = 9;
        const Problem p = makeCollocationProblem(3, intervals);
        NormalEquations equations;
        QVERIFY(equations.build(p, nullptr));
        QCOMPARE(equations.groupedRowCount(), 20 * intervals);
        QVERIFY(equations.rowGroupCount() >= 4);
        QVERIFY(equations.rowGroupCount() <= 2 * intervals);
        const auto& start = equations.jacobianRowStart();
        long long products = 0;
        for (int r = 0; r < equations.rowCount(); ++r) {
            const long long m = start[r + 1] - start[r];
            products += m * (m + 1) / 2;
        }
        QVERIFY2(
            equations.pairCount() * 4 < products,
            qPrintable(
                QString("%1 additions for %2 products").arg(equations.pairCount()).arg(products)));
    }

    void scratchAssemblyAgreesWithDenseProduct() {
        // The reference itself against a dense HᵀW²H built entry by entry from the terms.
        Problem p = makeMixedProblem(3, 8);
        NormalEquations equations;
        QVERIFY(equations.build(p, nullptr));
        const int n = equations.variableCount();
        std::mt19937 rng(5);
        const std::vector<double> x = randomVector(rng, n);
        QVERIFY(equations.evaluate(p, x.data()));
        const double eps1 = 0.05;
        const double eps2 = 0.02;
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(equations.rowCount(), n);
        std::vector<double> weights;
        equations.rowWeights(p, eps1, weights);
        const auto& start = equations.jacobianRowStart();
        const auto& columns = equations.jacobianColumns();
        const auto& jac = equations.jacobianValues();
        for (int r = 0; r < equations.rowCount(); ++r) {
            for (int e = start[r]; e < start[r + 1]; ++e) {
                h(r, columns[e]) += weights[r] * jac[e];
            }
        }
        Eigen::MatrixXd dense = h.transpose() * h;
        dense.diagonal().array() += eps2 * eps2;
        for (int v : p.fixedVariables()) {
            dense(v, v) += 1.0;
        }
        Eigen::SparseMatrix<double> scratch;
        Eigen::VectorXd rhs;
        equations.assembleFromScratch(p, eps1, eps2, scratch, rhs);
        const Eigen::MatrixXd upper = Eigen::MatrixXd(scratch);
        const Eigen::MatrixXd expected = dense.triangularView<Eigen::Upper>();
        QVERIFY((upper - expected).norm() <= 1e-13 * expected.norm());
        // Fixed variables have no coupling.
        const int fixed = p.fixedVariables().front();
        QCOMPARE(upper(fixed, fixed), 1.0 + eps2 * eps2);
    }
};

DEVSURF_REGISTER_TEST(TstNormalEquations);
#include "tst_normal_equations.moc"
