#include "ceres_peer.h"

#include "solver/core/normal_equations.h"
#include "solver/core/problem.h"

#ifdef DEVSURF_HAVE_CERES
#include <ceres/ceres.h>
#endif

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>

namespace devsurf::bench {

#ifdef DEVSURF_HAVE_CERES

namespace {

// One constraint row of a Term as a Ceres residual block. Its parameter blocks are the points
// (3 consecutive variables) its Jacobian row touches; Term::evaluateRow reads the full state,
// so the block values are copied into a shared scratch state first.
class RowCost : public ceres::CostFunction {
public:
    RowCost(const solver::Term& term, int row, std::vector<int> columns, std::vector<int> points,
            double weight, std::vector<double>& scratch)
        : m_term(term), m_row(row), m_columns(std::move(columns)), m_points(std::move(points)),
          m_weight(weight), m_scratch(scratch), m_jacobian(m_columns.size()) {
        set_num_residuals(1);
        for (std::size_t i = 0; i < m_points.size(); ++i) {
            mutable_parameter_block_sizes()->push_back(3);
        }
        for (int column : m_columns) {
            const int point = column / 3;
            m_slot.push_back(static_cast<int>(std::find(m_points.begin(), m_points.end(), point) -
                                              m_points.begin()));
        }
    }

    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        for (std::size_t b = 0; b < m_points.size(); ++b) {
            std::copy(parameters[b], parameters[b] + 3,
                      m_scratch.begin() + 3 * static_cast<std::ptrdiff_t>(m_points[b]));
        }
        double value = 0.0;
        if (!m_term.evaluateRow(m_row, m_scratch.data(), &value, m_jacobian.data())) {
            return false;
        }
        residuals[0] = m_weight * value;
        if (jacobians) {
            for (std::size_t b = 0; b < m_points.size(); ++b) {
                if (jacobians[b]) {
                    std::fill(jacobians[b], jacobians[b] + 3, 0.0);
                }
            }
            for (std::size_t e = 0; e < m_columns.size(); ++e) {
                double* block = jacobians[m_slot[e]];
                if (block) {
                    block[m_columns[e] % 3] += m_weight * m_jacobian[e];
                }
            }
        }
        return true;
    }

private:
    const solver::Term& m_term;
    int m_row;
    std::vector<int> m_columns;
    std::vector<int> m_points;
    std::vector<int> m_slot;
    double m_weight;
    std::vector<double>& m_scratch;
    mutable std::vector<double> m_jacobian;
};

// Stops Ceres once our residual measure reaches the target; its own cost is timed so that it
// can be taken out of Ceres' time.
class ResidualCheck : public ceres::IterationCallback {
public:
    ResidualCheck(const solver::Problem& problem, const std::vector<double>& x, double target)
        : m_problem(problem), m_x(x), m_target(target) {
        std::string error;
        m_equations.build(problem, &error);
    }

    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
        const auto start = std::chrono::steady_clock::now();
        m_equations.evaluate(m_problem, m_x.data());
        residual = m_equations.maxConstraintResidual();
        iterations = summary.iteration;
        checkMs +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        if (residual <= m_target) {
            reached = true;
            return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
        }
        return ceres::SOLVER_CONTINUE;
    }

    double residual = 0.0;
    double checkMs = 0.0;
    int iterations = 0;
    bool reached = false;

private:
    const solver::Problem& m_problem;
    const std::vector<double>& m_x;
    double m_target;
    solver::NormalEquations m_equations;
};

} // namespace

CeresResult runCeres(const solver::Problem& problem, std::vector<double> x, double targetResidual,
                     double capSeconds) {
    CeresResult result;
    result.available = true;
    std::vector<double> scratch = x;
    ceres::Problem::Options problemOptions;
    ceres::Problem ceresProblem(problemOptions);
    const int points = problem.variableCount() / 3;
    std::vector<char> used(static_cast<std::size_t>(points), 0);
    for (int t = 0; t < problem.termCount(); ++t) {
        const solver::TermFamily& family = problem.family(problem.termFamily(t));
        if (family.role != solver::TermRole::Constraint || family.weight == 0.0) {
            continue; // Ceres gets the constraints; energies only regularise our first steps
        }
        const solver::Term& term = problem.term(t);
        std::vector<int> rowStart;
        std::vector<int> columns;
        solver::PatternBuilder builder(rowStart, columns);
        term.buildPattern(builder);
        rowStart.push_back(static_cast<int>(columns.size()));
        for (int r = 0; r < term.rowCount(); ++r) {
            std::vector<int> rowColumns(columns.begin() + rowStart[static_cast<std::size_t>(r)],
                                        columns.begin() +
                                            rowStart[static_cast<std::size_t>(r) + 1]);
            std::vector<int> rowPoints;
            for (int c : rowColumns) {
                if (std::find(rowPoints.begin(), rowPoints.end(), c / 3) == rowPoints.end()) {
                    rowPoints.push_back(c / 3);
                }
            }
            std::vector<double*> blocks;
            for (int p : rowPoints) {
                blocks.push_back(x.data() + 3 * p);
                used[static_cast<std::size_t>(p)] = 1;
            }
            ceresProblem.AddResidualBlock(
                new RowCost(term, r, rowColumns, rowPoints, family.weight, scratch), nullptr,
                blocks);
        }
    }
    for (int p = 0; p < points; ++p) {
        if (used[static_cast<std::size_t>(p)] && problem.isFixed(3 * p)) {
            ceresProblem.SetParameterBlockConstant(x.data() + 3 * p);
        }
    }
    ResidualCheck check(problem, x, targetResidual);
    ceres::Solver::Options options;
    options.minimizer_type = ceres::TRUST_REGION;
    options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
    options.num_threads = 1;
    options.max_num_iterations = 1000;
    options.max_solver_time_in_seconds = capSeconds;
    options.function_tolerance = 1e-30;
    options.gradient_tolerance = 1e-30;
    options.parameter_tolerance = 1e-30;
    options.logging_type = ceres::SILENT;
    options.update_state_every_iteration = true;
    options.callbacks.push_back(&check);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &ceresProblem, &summary);
    result.reached = check.reached;
    result.iterations = check.iterations;
    result.finalResidual = check.residual;
    result.milliseconds = 1000.0 * summary.total_time_in_seconds - check.checkMs;
    result.hitTimeCap = !check.reached && summary.total_time_in_seconds >= 0.99 * capSeconds;
    result.message = summary.message;
    return result;
}

#else

CeresResult runCeres(const solver::Problem&, std::vector<double>, double, double) {
    CeresResult result;
    result.message = "Ceres Solver was not found when DevSurf was built (install libceres-dev "
                     "and reconfigure); the Ceres peer is unavailable.";
    return result;
}

#endif

} // namespace devsurf::bench
