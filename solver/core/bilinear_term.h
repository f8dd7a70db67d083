#pragma once

#include "solver/core/term.h"

#include <vector>

namespace devsurf::solver {

// Bilinear rows ⟨Σ dₖ nₖ, Σ cᵢ pᵢ⟩ − t = 0: the form of the developability conditions (4),
// the crease conditions (7), (8) and the reference-shape condition (11). Both sides are
// linear combinations of points of the same dimension (e.g. a normal-spline evaluation and
// a difference of de Boor points).
//
// Rows may carry constant scales sᵣ (scaleRowsAt): sᵣ(⟨u, v⟩ − t) with sᵣ = 1/(|u| |v|) taken
// at a reference state, so that near it a row measures the cosine of the angle between its two
// sides: dimensionless, and comparable between thin and wide strips, fine and coarse control
// spacings and models of any size. The scales are constants, not the exact cosine rescaled at
// every x: that is invariant to the scale of the points and normals, and the iteration drifted
// along those directions (docs/tuning.md).
class BilinearTerm : public Term {
public:
    static constexpr int kMaxDimension = 4;

    explicit BilinearTerm(int dimension = 3);

    int dimension() const { return m_dimension; }
    // Returns the row index within this term.
    int addRow(const PointCombination& left, const PointCombination& right, double target = 0.0);
    void setTarget(int row, double target) {
        m_target[static_cast<std::size_t>(row)] = target;
        changed();
    }
    // Sets every row's scale to 1/(|u| |v|) at `reference`, kept within a factor 100 of the
    // median scale (the median where a side vanishes there);
    // null resets the scales to 1. Values only: the pattern is unchanged.
    void scaleRowsAt(const double* reference);
    double rowScale(int row) const {
        return m_scale.empty() ? 1.0 : m_scale[static_cast<std::size_t>(row)];
    }
    // The residual of one row at x (outside the iteration loop: it allocates).
    double rowResidual(int row, const double* x) const;

    const char* typeName() const override { return "BilinearTerm"; }

    bool tracksChanges() const override { return true; }
    int rowCount() const override { return static_cast<int>(m_target.size()); }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;
    bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const override;

private:
    // Residual and Jacobian values of row r; returns the number of Jacobian values written.
    int evaluateOne(std::size_t r, const double* x, double* residual, double* jacobian) const;
    // The same for a dimension D known at compile time (0: m_dimension), so that the loops over
    // the coordinates of points of space (D = 3) are unrolled (docs/tuning.md).
    template <int D>
    int evaluateOneOf(std::size_t r, const double* x, double* residual, double* jacobian) const;
    // The two sides of row r at x.
    void sides(std::size_t r, const double* x, double* u, double* v) const;
    int m_dimension;
    std::vector<double> m_scale; // per row; empty: all 1
    // Row r uses m_points[m_leftStart[r] .. m_rightStart[r]) on the left and
    // m_points[m_rightStart[r] .. m_leftStart[r + 1]) on the right.
    std::vector<int> m_leftStart{0};
    std::vector<int> m_rightStart;
    std::vector<PointTerm> m_points;
    std::vector<double> m_target;
};

} // namespace devsurf::solver
