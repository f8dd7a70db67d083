#pragma once

#include "solver/core/term.h"

#include <vector>

namespace devsurf::solver {

// Rows ‖Σ cᵢ pᵢ‖² − ‖Σ c′ⱼ qⱼ‖² − d² = 0. The left side lives in `leftDimension`, the
// optional right side in `rightDimension`. With an empty right side this is the
// squared-distance equality ‖Σ cᵢ pᵢ‖² = d²; with d = 0 and both sides it is the isometry
// condition (12) between a development (2D) and the surface (3D).
class SquaredDistanceTerm : public Term {
public:
    static constexpr int kMaxDimension = 4;

    explicit SquaredDistanceTerm(int leftDimension = 3, int rightDimension = 3);

    int addRow(const PointCombination& left, const PointCombination& right, double squaredDistance);
    int addRow(const PointCombination& left, double squaredDistance) {
        return addRow(left, {}, squaredDistance);
    }
    void setSquaredDistance(int row, double value) {
        m_squaredDistance[static_cast<std::size_t>(row)] = value;
        changed();
    }
    // Multiplies row `row` (its residual and Jacobian) by `scale` (1 when added). With
    // 1 / (2 d) a row measures, to first order, the change of the length d.
    void setRowScale(int row, double scale) {
        m_rowScale[static_cast<std::size_t>(row)] = scale;
        changed();
    }

    // ‖Σ cᵢ pᵢ‖ of the left side of row `row` at x.
    double leftLength(int row, const double* x) const;

    const char* typeName() const override { return "SquaredDistanceTerm"; }

    bool tracksChanges() const override { return true; }
    int rowCount() const override { return static_cast<int>(m_squaredDistance.size()); }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;
    bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const override;

private:
    // Residual and Jacobian values of row r; returns the number of Jacobian values written.
    int evaluateOne(std::size_t r, const double* x, double* residual, double* jacobian) const;
    int m_leftDimension;
    int m_rightDimension;
    std::vector<int> m_leftStart{0};
    std::vector<int> m_rightStart;
    std::vector<PointTerm> m_points;
    std::vector<double> m_squaredDistance;
    std::vector<double> m_rowScale;
};

} // namespace devsurf::solver
