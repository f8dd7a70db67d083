#pragma once

#include "solver/core/term.h"

#include <vector>

namespace devsurf::solver {

// Rows x_j − t_j: pulls single variables (or points) towards targets that may change between
// iterations (dragged handles, closest points). In an energy family it is a soft target; in
// a constraint family it is a hard "x_j = t_j".
class TargetTerm : public Term {
public:
    // Returns the row index of the new target.
    int addTarget(int column, double target);
    // Adds `dimension` rows for the point at `offset`; returns the first row index.
    int addPointTarget(int offset, int dimension, const double* target);
    void setTarget(int row, double target) {
        m_target[static_cast<std::size_t>(row)] = target;
        changed();
    }
    double target(int row) const { return m_target[static_cast<std::size_t>(row)]; }

    const char* typeName() const override { return "TargetTerm"; }

    bool tracksChanges() const override { return true; }
    int rowCount() const override { return static_cast<int>(m_target.size()); }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;
    bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const override;

private:
    std::vector<int> m_column;
    std::vector<double> m_target;
};

} // namespace devsurf::solver
