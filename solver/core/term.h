#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

namespace devsurf::solver {

// One summand of a linear combination Σ cᵢ pᵢ of points: `offset` is the column of the
// point's first coordinate (the point occupies `dimension` consecutive columns, where the
// dimension is a property of the term using the combination).
struct PointTerm {
    int offset = 0;
    double coefficient = 1.0;
};

using PointCombination = std::vector<PointTerm>;

// Collects the sparsity pattern of a term: for each of its rows, the variable columns its
// Jacobian row may be non-zero in. The order of the columns defines the order in which
// Term::evaluate writes the Jacobian values. A column may repeat within a row (the
// derivative is then the sum of the repeated entries).
class PatternBuilder {
public:
    PatternBuilder(std::vector<int>& rowStart, std::vector<int>& columns)
        : m_rowStart(rowStart), m_columns(columns) {}

    void beginRow() { m_rowStart.push_back(static_cast<int>(m_columns.size())); }
    void addColumn(int column) { m_columns.push_back(column); }
    // Adds `count` consecutive columns starting at `first` (the coordinates of a point).
    void addColumns(int first, int count) {
        for (int k = 0; k < count; ++k) {
            m_columns.push_back(first + k);
        }
    }

private:
    std::vector<int>& m_rowStart;
    std::vector<int>& m_columns;
};

// A term appends rows φ_r(x) to the problem. Its sparsity pattern is fixed once it has been
// added to a Problem: later changes may only alter values (targets, right-hand sides),
// never the number of rows or their columns. Whether the rows are hard constraints or soft
// energies, and their weight, is decided by the term's family in the Problem.
class Term {
public:
    Term() : m_revision(nextRevision()) {}
    Term(const Term&) = delete;
    Term& operator=(const Term&) = delete;
    virtual ~Term() = default;

    virtual const char* typeName() const = 0;
    virtual int rowCount() const = 0;
    // Must emit exactly rowCount() rows (beginRow() once per row).
    virtual void buildPattern(PatternBuilder& builder) const = 0;
    // Writes rowCount() residuals and, in pattern order, the Jacobian values of all rows.
    // Must not allocate: it runs inside the iteration loop.
    virtual void evaluate(const double* x, double* residuals, double* jacobian) const = 0;
    // Evaluates row `row` alone: its residual and its Jacobian values in pattern order. Used by
    // solvers that evaluate residuals one by one (the Ceres peer of the benchmark); returns
    // false if the term does not support it.
    virtual bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const {
        (void)row;
        (void)x;
        (void)residual;
        (void)jacobian;
        return false;
    }
    // The largest fraction α ∈ (0, 1] of the step δ from x that the term admits, given that no
    // guarded quantity may fall below `keep` times its value at x in one step (1: no limit).
    virtual double admissibleStep(const double* x, const double* step, double keep) const {
        (void)x;
        (void)step;
        (void)keep;
        return 1.0;
    }
    // Guards (one-sided rows) that the step δ from x would cross are engaged: evaluated as
    // equalities at their bound until releaseGuards(). Returns how many were engaged.
    virtual int engageCrossedGuards(const double* x, const double* step) const {
        (void)x;
        (void)step;
        return 0;
    }
    virtual void releaseGuards() const {}

    // True if the term's values at a given x change only through its own setters, each of
    // which calls changed(): NormalEquations::evaluate(…, onlyChanged) then skips it while
    // x and revision() stay. False (the default): evaluated every time.
    virtual bool tracksChanges() const { return false; }
    // Unique across all terms of the process: a new term never shows an old term's revision.
    // Not thread-safe (read where the term is evaluated).
    std::uint64_t revision() const {
        if (m_changed) {
            m_revision = nextRevision();
            m_changed = false;
        }
        return m_revision;
    }

protected:
    void changed() const { m_changed = true; }

private:
    static std::uint64_t nextRevision() {
        static std::atomic<std::uint64_t> counter{0};
        return ++counter;
    }
    mutable std::uint64_t m_revision;
    mutable bool m_changed = false;
};

} // namespace devsurf::solver
