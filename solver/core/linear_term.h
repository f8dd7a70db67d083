#pragma once

#include "solver/core/term.h"

#include <utility>
#include <vector>

namespace devsurf::solver {

// Linear rows Σ a_j x_j − b = 0 (linear relations, fixed values, equal derivatives).
class LinearTerm : public Term {
public:
    struct Entry {
        int column = 0;
        double coefficient = 0.0;
    };

    // Adds the row Σ entries − rhs; returns its index within this term.
    int addRow(const std::vector<Entry>& entries, double rhs = 0.0);
    // Adds `dimension` rows Σ cᵢ pᵢ − rhs (one per coordinate); rhs may be null (zero).
    // Returns the index of the first row.
    int addPointRelation(int dimension, const PointCombination& points,
                         const double* rhs = nullptr);
    void setRhs(int row, double rhs) {
        m_rhs[static_cast<std::size_t>(row)] = rhs;
        changed();
    }
    double rhs(int row) const { return m_rhs[static_cast<std::size_t>(row)]; }

    const char* typeName() const override { return "LinearTerm"; }

    bool tracksChanges() const override { return true; }
    int rowCount() const override { return static_cast<int>(m_rhs.size()); }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;
    bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const override;

private:
    // Residual and Jacobian values of row r; returns the number of Jacobian values written.
    int evaluateOne(std::size_t r, const double* x, double* residual, double* jacobian) const;
    std::vector<int> m_rowStart{0};
    std::vector<Entry> m_entries;
    std::vector<double> m_rhs;
};

} // namespace devsurf::solver
