#pragma once

#include "solver/core/term.h"

#include <vector>

namespace devsurf::solver {

// One-sided rows max(0, 1 − ‖Σ cᵢ pᵢ‖ / L): zero while the length of a point combination (a
// ruling a(u) − b(u), a curve's first-derivative points a¹₁ − a¹₀) is at least L, and
// growing, dimensionless, as it falls below. In a constraint family they keep the iteration
// away from degenerate solutions of (4), a collapsed ruling or a cusp, which satisfy the
// developability rows without being a usable surface. A row of minimum 0 is never active.
class MinimumLengthTerm : public Term {
public:
    static constexpr int kMaxDimension = 4;

    explicit MinimumLengthTerm(int dimension = 3);

    // Returns the row index within this term.
    int addRow(const PointCombination& combination, double minimum);
    void setMinimum(int row, double minimum) {
        m_minimum[static_cast<std::size_t>(row)] = minimum;
        changed();
    }
    double minimum(int row) const { return m_minimum[static_cast<std::size_t>(row)]; }
    // ‖Σ cᵢ pᵢ‖ of row `row` at x.
    double length(int row, const double* x) const;

    const char* typeName() const override { return "MinimumLengthTerm"; }

    bool tracksChanges() const override { return true; }
    int rowCount() const override { return static_cast<int>(m_minimum.size()); }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;
    bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const override;
    // No guarded length (a row of positive minimum) shrinks below `keep` times its length at x.
    double admissibleStep(const double* x, const double* step, double keep) const override;
    int engageCrossedGuards(const double* x, const double* step) const override;
    void releaseGuards() const override;

private:
    int evaluateOne(std::size_t r, const double* x, double* residual, double* jacobian) const;
    // Row r's vector Σ cᵢ pᵢ at x (u) and along the step (w): u·u, u·w, w·w.
    struct Products {
        double uu = 0.0;
        double uw = 0.0;
        double ww = 0.0;
    };
    Products rowProducts(std::size_t r, const double* x, const double* step) const;
    int m_dimension;
    std::vector<int> m_start{0}; // row r uses m_points[m_start[r] .. m_start[r + 1])
    std::vector<PointTerm> m_points;
    std::vector<double> m_minimum;
    mutable std::vector<char> m_engaged; // per row, empty while none is
};

} // namespace devsurf::solver
