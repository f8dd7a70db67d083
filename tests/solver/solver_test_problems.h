#pragma once

// Shared helpers of the solver tests: random points, finite differences, test problems.

#include "solver/core/bilinear_term.h"
#include "solver/core/fairness_term.h"
#include "solver/core/linear_term.h"
#include "solver/core/problem.h"
#include "solver/core/squared_distance_term.h"
#include "solver/core/target_term.h"
#include "solver/core/unit_norm_term.h"
#include "solver/quality/shape_change.h"

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::solver::testing {

inline std::vector<double> randomVector(std::mt19937& rng, int n, double scale = 1.0) {
    std::uniform_real_distribution<double> u(-scale, scale);
    std::vector<double> x(static_cast<std::size_t>(n));
    for (double& v : x) {
        v = u(rng);
    }
    return x;
}

inline PointCombination randomCombination(std::mt19937& rng, int points, int dimension, int count) {
    std::uniform_int_distribution<int> pick(0, points - 1);
    std::uniform_real_distribution<double> coefficient(-2.0, 2.0);
    PointCombination c;
    for (int k = 0; k < count; ++k) {
        c.push_back({pick(rng) * dimension, coefficient(rng)});
    }
    return c;
}

// Analytic Jacobian of a term as (row, column) -> value, repeated columns summed.
using SparseRows = std::map<std::pair<int, int>, double>;

inline SparseRows analyticJacobian(const Term& term, const std::vector<double>& x) {
    std::vector<int> rowStart;
    std::vector<int> columns;
    PatternBuilder builder(rowStart, columns);
    term.buildPattern(builder);
    rowStart.push_back(static_cast<int>(columns.size()));
    std::vector<double> residual(static_cast<std::size_t>(term.rowCount()));
    std::vector<double> jacobian(columns.size());
    term.evaluate(x.data(), residual.data(), jacobian.data());
    SparseRows rows;
    for (int r = 0; r + 1 < static_cast<int>(rowStart.size()); ++r) {
        for (int e = rowStart[r]; e < rowStart[r + 1]; ++e) {
            rows[{r, columns[e]}] += jacobian[e];
        }
    }
    return rows;
}

// Central differences for every column (zero entries must come out as zero).
inline SparseRows finiteDifferenceJacobian(const Term& term, std::vector<double> x, double h) {
    const auto rows = static_cast<std::size_t>(term.rowCount());
    std::vector<int> rowStart;
    std::vector<int> columns;
    PatternBuilder builder(rowStart, columns);
    term.buildPattern(builder);
    std::vector<double> plus(rows), minus(rows), jacobian(columns.size());
    SparseRows result;
    for (std::size_t c = 0; c < x.size(); ++c) {
        const double saved = x[c];
        x[c] = saved + h;
        term.evaluate(x.data(), plus.data(), jacobian.data());
        x[c] = saved - h;
        term.evaluate(x.data(), minus.data(), jacobian.data());
        x[c] = saved;
        for (std::size_t r = 0; r < rows; ++r) {
            const double d = (plus[r] - minus[r]) / (2.0 * h);
            if (d != 0.0) {
                result[{static_cast<int>(r), static_cast<int>(c)}] = d;
            }
        }
    }
    return result;
}

// Largest |analytic − finite difference| over the union of both supports.
inline double jacobianError(const SparseRows& analytic, const SparseRows& numeric);

// The type of the first term of `problem` whose Jacobian at x differs from central differences
// (step 1e-6) by more than `tolerance`; empty when none does.
inline std::string termWithWrongJacobian(const Problem& problem, const std::vector<double>& x,
                                         double tolerance = 1e-6);

inline double jacobianError(const SparseRows& analytic, const SparseRows& numeric) {
    double error = 0.0;
    for (const auto& [key, value] : analytic) {
        const auto it = numeric.find(key);
        error = std::max(error, std::abs(value - (it == numeric.end() ? 0.0 : it->second)));
    }
    for (const auto& [key, value] : numeric) {
        const auto it = analytic.find(key);
        error = std::max(error, std::abs(value - (it == analytic.end() ? 0.0 : it->second)));
    }
    return error;
}

inline std::string termWithWrongJacobian(const Problem& problem, const std::vector<double>& x,
                                         double tolerance) {
    for (int t = 0; t < problem.termCount(); ++t) {
        const Term& term = problem.term(t);
        if (jacobianError(analyticJacobian(term, x), finiteDifferenceJacobian(term, x, 1e-6)) >
            tolerance) {
            return term.typeName();
        }
    }
    return {};
}

// Points on the unit circle: ‖pᵢ‖² = 1 (hard), ⟨pᵢ, pᵢ₊₁⟩ = cos(2π/n) (hard, closed chain),
// p₀ = (1, 0) (hard, linear), fairness (soft). Its solutions are regular n-gons; with p₀ fixed
// and orientation kept by continuity the solution is unique near the start.
struct CircleProblem {
    Problem problem;
    int points = 0;
    FamilyId hard = -1;
    FamilyId soft = -1;
    std::vector<double> start;
};

inline std::unique_ptr<CircleProblem> makeCircleProblem(int points, unsigned seed,
                                                        double noise = 0.05) {
    auto c = std::make_unique<CircleProblem>();
    c->points = points;
    Problem& p = c->problem;
    const int offset = p.addVariableBlock("points", 2 * points);
    c->hard = p.addFamily("hard", TermRole::Constraint, 1.0);
    c->soft = p.addFamily("fairness", TermRole::Energy, 0.1);
    auto norm = std::make_unique<UnitNormTerm>(2);
    auto dots = std::make_unique<BilinearTerm>(2);
    auto linear = std::make_unique<LinearTerm>();
    auto fairness = std::make_unique<FairnessTerm>(2);
    const double pi = std::acos(-1.0);
    const double cosine = std::cos(2.0 * pi / points);
    std::vector<int> sequence;
    for (int i = 0; i < points; ++i) {
        const int pi0 = offset + 2 * i;
        const int pi1 = offset + 2 * ((i + 1) % points);
        norm->addVector(pi0);
        dots->addRow({{pi0, 1.0}}, {{pi1, 1.0}}, cosine);
        sequence.push_back(pi0);
    }
    linear->addRow({{offset, 1.0}}, 1.0);
    linear->addRow({{offset + 1, 1.0}}, 0.0);
    fairness->addSequence(sequence, true);
    p.add(c->hard, std::move(norm));
    p.add(c->hard, std::move(dots));
    p.add(c->hard, std::move(linear));
    p.add(c->soft, std::move(fairness));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-noise, noise);
    c->start.resize(static_cast<std::size_t>(2 * points));
    for (int i = 0; i < points; ++i) {
        const double angle = 2.0 * pi * i / points + u(rng);
        const double radius = 1.0 + u(rng);
        c->start[static_cast<std::size_t>(2 * i)] = radius * std::cos(angle);
        c->start[static_cast<std::size_t>(2 * i + 1)] = radius * std::sin(angle);
    }
    return c;
}

// The largest distance of a vertex or control point between two states of one surface.
inline double largestMove(const model::CompositeSurface& a, const model::CompositeSurface& b) {
    return measureShapeChange(a, b).largestMove;
}

// The rows of every term of the named family (0 if there is no such family).
inline int familyRows(const Problem& problem, const char* name) {
    const int family = problem.findFamily(name);
    int rows = 0;
    for (int t = 0; t < problem.termCount(); ++t) {
        if (family >= 0 && problem.termFamily(t) == family) {
            rows += problem.term(t).rowCount();
        }
    }
    return rows;
}

// Three variables; hard targets x₀ = 1 and x₁ = 2; no row touches x₂, so N is singular
// without damping.
inline void addTwoTargetsOfThree(Problem& p) {
    p.addVariableBlock("x", 3);
    auto target = std::make_unique<TargetTerm>();
    target->addTarget(0, 1.0);
    target->addTarget(1, 2.0);
    p.add(p.addFamily("t", TermRole::Constraint), std::move(target));
}

} // namespace devsurf::solver::testing
