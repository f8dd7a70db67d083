#pragma once

#include <Eigen/SparseCore>

#include <cstdint>
#include <string>
#include <vector>

namespace devsurf::solver {

class Problem;

// The linearised system of one guided-projection step, with a sparsity structure that is
// built once per problem structure:
//
//   N = HᵀW²H + ε₁²KᵀK + ε₂²I,   g = −(HᵀW²φ_H + ε₁²Kᵀ φ_K),   N δ = g,   x_{k+1} = x_k + δ
//
// (the step form of (6); identical to solving for x with right-hand side HᵀW²r + ε₁²Kᵀs +
// ε₂²x_k). H and K are the Jacobians of the constraint and energy rows. The index of the
// normal-matrix nonzero every product of two Jacobian entries contributes to is precomputed,
// so fill() only runs multiply-adds into the stored triangle. Consecutive rows of one term
// whose columns largely coincide (the three rows of (4) at the collocation values of one
// interval share one set of control points) form a group: their products are summed in a
// small dense block over the union of their columns (RᵀR by BLAS dgemm, R the group's rows,
// dense), which is added to the stored triangle once, instead of every row adding its own products
// (ten times fewer scattered additions, docs/tuning.md).
// The pattern is built from the groups too (every pair of a group's columns is stored, a few
// explicit zeros where no row has both), so build() costs one pass per group rather than per row.
// The stored triangle can be laid out in a permuted order (setLayout) so that CHOLMOD factorises it
// in place without permuting or transposing a copy.
class NormalEquations {
public:
    enum class Triangle { Upper, Lower };
    // Working memory of a fill (a group's dense rows and block).
    struct FillScratch {
        std::vector<double> rows;
        std::vector<double> block;
    };

    // Builds the Jacobian (CSR) and normal-matrix patterns. Returns false and sets `error` for
    // an inconsistent problem (column out of range, wrong number of rows from a term).
    bool build(const Problem& problem, std::string* error);
    // True if build() ran for this problem structure (same structureId and row counts).
    bool matches(const Problem& problem) const;
    bool isBuilt() const { return m_built; }

    // Evaluates all terms at x, zeroes the Jacobian columns of fixed variables and computes
    // the residual statistics. Returns false if a residual or Jacobian entry is not finite.
    // onlyChanged: if the last evaluation was of this x (bit for bit) with the same fixed
    // variables, terms that track their changes (Term::tracksChanges) and have not changed
    // since keep their values; the result is the same as evaluating all.
    bool evaluate(const Problem& problem, const double* x, bool onlyChanged = false);
    double maxConstraintResidual() const { return m_maxConstraintResidual; }
    // The residual that caps ε₁: the larger of maxConstraintResidual() and the weighted
    // residuals of the energy families that drive it (TermFamily::drivesEpsilon1).
    double maxDrivingResidual() const { return m_maxDrivingResidual; }
    double energy() const { return m_energy; }
    // Σ w² φ² over the constraint rows: the merit a step is judged by.
    double constraintMerit() const { return m_constraintMerit; }

    // Lays the stored triangle out in the order perm (position k holds original variable
    // perm[k]; empty = identity).
    void setLayout(const std::vector<int>& permutation, Triangle triangle);
    Triangle triangle() const { return m_triangle; }
    const std::vector<int>& columnStart() const { return m_colStart; }
    const std::vector<int>& rowIndex() const { return m_rowIndex; }

    // Refills the stored triangle of N (current layout) and g (original order) in place from
    // the last evaluate(). Allocation-free.
    // `proximity` is μ, the multiplier of the proximity families' weights; `eps2` multiplies
    // the damping families' weights too.
    void fill(const Problem& problem, double eps1, double eps2, double* values, double* rhs,
              double proximity = 0.0);

    // w² per term of `problem` for fill (the family's weight times ε₁, μ or ε₂ by its role).
    void termWeights2(const Problem& problem, double eps1, double eps2, double proximity,
                      std::vector<double>& weights) const;
    // N alone (current layout), from Jacobian values in jacobianValues()' order, w² per term
    // (termWeights2) and the fixed variables. It reads the structure only: another thread may
    // run it, with its own values and scratch, while this object evaluates (not while it is
    // built or laid out).
    void fillMatrix(const double* jacobian, const std::vector<double>& termWeight2,
                    const std::vector<int>& fixed, double eps2, double* values,
                    FillScratch& scratch) const;

    // g alone (original order) from the residuals of the last evaluate() and the Jacobian
    // values `jacobian` (in jacobianValues()' order: those of an earlier evaluate(), such as
    // the one last factorised), for a step with an earlier factorisation.
    void fillRightHandSide(const Problem& problem, double eps1, double proximity, double eps2,
                           const std::vector<double>& jacobian, double* rhs) const;

    int variableCount() const { return m_variables; }
    int rowCount() const { return m_rows; }
    long long jacobianNonZeros() const { return static_cast<long long>(m_jacColumn.size()); }
    long long normalNonZeros() const { return static_cast<long long>(m_rowIndex.size()); }
    // Additions into the stored triangle per fill (products of single rows, and entries of
    // the dense blocks of row groups).
    long long pairCount() const {
        return static_cast<long long>(m_pairTarget.size() + m_groupPairTarget.size());
    }
    // Groups of rows assembled through a dense block, and the rows in them.
    int rowGroupCount() const { return static_cast<int>(m_groups.size()); }
    int groupedRowCount() const;

    const std::vector<double>& residuals() const { return m_residual; }
    const std::vector<double>& jacobianValues() const { return m_jacValue; }
    const std::vector<int>& jacobianRowStart() const { return m_jacRowStart; }
    const std::vector<int>& jacobianColumns() const { return m_jacColumn; }
    // Per-row weight w (family weight, times ε₁ for energy rows, times μ for proximity rows,
    // times ε₂ for damping rows).
    void rowWeights(const Problem& problem, double eps1, std::vector<double>& weights,
                    double proximity = 0.0, double eps2 = 0.0) const;

    // Reference assembly from scratch (used by the baseline mode and the tests): the weighted
    // Jacobian W̃ J (fixed columns zero) built from triplets.
    Eigen::SparseMatrix<double> weightedJacobian(const Problem& problem, double eps1,
                                                 double proximity = 0.0, double eps2 = 0.0) const;
    // N (upper triangle, original order) and g from scratch via Eigen sparse products.
    void assembleFromScratch(const Problem& problem, double eps1, double eps2,
                             Eigen::SparseMatrix<double>& upper, Eigen::VectorXd& rhs,
                             double proximity = 0.0) const;
    // Converts stored values in the current layout to an upper-triangular matrix in the
    // original order.
    Eigen::SparseMatrix<double> toOriginalUpper(const double* values) const;

private:
    struct DuplicatePair {
        int first;  // Jacobian entry index
        int second; // Jacobian entry index
        int term;   // of the row (its weight)
        int target; // normal-matrix nonzero in the original layout
    };
    // Rows [firstRow, rowEnd) of one term, assembled through a dense block over the union of
    // their columns (m_groupColumns [columnStart, columnStart + width)); the targets of the
    // block's upper triangle, column by column, are m_groupPairTarget [pairStart, pairEnd).
    struct RowGroup {
        int firstRow;
        int rowEnd;
        int width;
        int columnStart;
        int pairStart;
        int pairEnd;
    };
    // Splits every term's rows into groups (from the Jacobian's pattern alone).
    void formGroups(const Problem& problem);
    // fill() and fillMatrix(): N, and g unless `rhs` is null (then `residual` is not read).
    void fillFrom(const double* jac, const double* residual, const std::vector<double>& termWeight2,
                  const std::vector<int>& fixed, double eps2, double* values, double* rhs,
                  FillScratch& scratch) const;
    // Adds group's rows (weight² w2) to the stored triangle and, unless null, the right-hand
    // side.
    void fillGroup(const RowGroup& group, double w2, const double* jac, const double* residual,
                   double* values, double* rhs, FillScratch& scratch) const;

    bool m_built = false;
    std::uint64_t m_structureId = 0;
    int m_variables = 0;
    int m_rows = 0;
    std::vector<int> m_termRowStart; // per term, first row (size terms + 1)
    std::vector<int> m_termJacStart; // per term, first Jacobian entry (size terms + 1)
    std::vector<int> m_jacRowStart;  // CSR row starts (size rows + 1)
    std::vector<int> m_jacColumn;
    std::vector<double> m_jacValue;
    std::vector<double> m_residual;
    std::vector<double> m_termWeight2; // fill()'s, per term

    // Normal matrix in the original order, upper triangle, CSC.
    std::vector<int> m_originalColStart;
    std::vector<int> m_originalRowIndex;
    std::vector<int> m_originalPairTarget;
    std::vector<int> m_originalDiagonal;
    // Current layout.
    Triangle m_triangle = Triangle::Upper;
    std::vector<int> m_colStart;
    std::vector<int> m_rowIndex;
    std::vector<int> m_position;   // original nonzero -> current nonzero
    std::vector<int> m_pairTarget; // rows outside groups, in row order
    std::vector<int> m_diagonal;   // per original variable
    std::vector<DuplicatePair> m_duplicates;
    // Row groups: per Jacobian entry of a grouped row, its column's index in the group's
    // union (-1 outside groups); per entry of a block's upper triangle, its target.
    std::vector<RowGroup> m_groups;
    std::vector<int> m_groupColumns;
    std::vector<int> m_entryLocal;
    std::vector<int> m_originalGroupPairTarget;
    std::vector<int> m_groupPairTarget;
    std::size_t m_groupRowSize = 0;   // a group's rows, dense over its union, at most
    std::size_t m_groupBlockSize = 0; // a block (its upper triangle is used)
    FillScratch m_scratch;            // fill()'s

    // The last evaluation: its x and each term's revision (evaluate's onlyChanged).
    std::vector<double> m_evaluatedAt;
    std::vector<std::uint64_t> m_evaluatedRevision;
    bool m_evaluated = false;

    // Fixed variables.
    std::uint64_t m_fixedRevision = ~std::uint64_t{0};
    std::vector<int> m_fixedJacobianEntries;

    double m_maxConstraintResidual = 0.0;
    double m_maxDrivingResidual = 0.0;
    double m_energy = 0.0;
    double m_constraintMerit = 0.0;
};

} // namespace devsurf::solver
