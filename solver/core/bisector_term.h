#pragma once

#include "solver/core/term.h"

#include <vector>

namespace devsurf::solver {

// Rows ⟨d, w_n n + w_m m⟩ = 0 with n, m and d linear combinations of 3D points and constant side
// weights (w_n, w_m) = 2 (|m|, |n|) / (|n| + |m|) taken at a chosen state (weighSidesAt): at that
// state a row says that d is normal to the bisector n/|n| + m/|m| of the two directions n and
// m, whatever their lengths; with weights 1 (the default) it is the bilinear ⟨d, n + m⟩. The
// form of the curved-fold condition (7) with the normal splines of the two strips beside a
// crease (and of the geodesic condition (8) with m negated): those splines have unit length at
// u = 0 only, and on a curved strip their length varies along it, so ⟨d, n + m⟩ = 0 does not
// say what (7) says. The weights are constants between two calls of weighSidesAt, so the rows
// stay bilinear in the iteration; the exact form with its full Jacobian diverged
// (docs/tuning.md). See FormulationOptions::weighCreaseNormals for when they are taken.
//
// Rows may carry constant scales s = 1/(|w_n n + w_m m| |d|) taken at a reference state
// (scaleRowsAt), kept within a factor 100 of the median, as BilinearTerm does.
class BisectorTerm : public Term {
public:
    // Returns the row index within this term.
    int addRow(const PointCombination& n, const PointCombination& m, const PointCombination& d);
    // Takes every row's side weights from the lengths of n and m at x (weights 1 where one of
    // them vanishes). Values only: the pattern is unchanged.
    void weighSidesAt(const double* x);
    void scaleRowsAt(const double* reference);
    double rowScale(int row) const {
        return m_scale.empty() ? 1.0 : m_scale[static_cast<std::size_t>(row)];
    }
    // The residual of one row at x (outside the iteration loop: it allocates).
    double rowResidual(int row, const double* x) const;

    const char* typeName() const override { return "BisectorTerm"; }

    bool tracksChanges() const override { return true; }
    int rowCount() const override { return static_cast<int>(m_rowStart.size()) - 1; }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;
    bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const override;

private:
    struct Sides {
        double n[3];
        double m[3];
        double d[3];
    };
    Sides sides(std::size_t r, const double* x) const;
    // w_n n + w_m m of row r.
    void bisector(std::size_t r, const Sides& s, double* out) const;
    int evaluateOne(std::size_t r, const double* x, double* residual, double* jacobian) const;
    // Row r uses m_points[m_rowStart[r] .. m_mStart[r]) for n, [m_mStart[r] .. m_dStart[r])
    // for m and [m_dStart[r] .. m_rowStart[r + 1]) for d.
    std::vector<int> m_rowStart{0};
    std::vector<int> m_mStart;
    std::vector<int> m_dStart;
    std::vector<PointTerm> m_points;
    std::vector<double> m_nWeight; // per row
    std::vector<double> m_mWeight;
    std::vector<double> m_scale; // per row; empty: all 1
};

} // namespace devsurf::solver
