#pragma once

#include "solver/core/term.h"

#include <vector>

namespace devsurf::solver {

// Second differences p_{i−1} − 2pᵢ + p_{i+1} (one row per interior point and coordinate) of
// point sequences, e.g. the control points of a spline: the fairness energy
// Σ ‖a_{i+1} − 2aᵢ + a_{i−1}‖². Usually in an energy family.
//
// With a reference state r (setReference) the rows are the second differences of the change,
// Δ²(x − r): the energy then regularises how a design moves away from r instead of pulling
// every curve towards a straight line, so a design that already satisfies the constraints
// stays where it is.
class FairnessTerm : public Term {
public:
    explicit FairnessTerm(int dimension = 3) : m_dimension(dimension) {}

    // `points` are the column offsets of the points in sequence order. A closed sequence
    // also gets the second differences across its start.
    void addSequence(const std::vector<int>& points, bool closed = false);
    // Measures the second differences relative to those of the state `reference` (all
    // variables); null restores absolute fairness.
    void setReference(const double* reference);

    const char* typeName() const override { return "FairnessTerm"; }

    bool tracksChanges() const override { return true; }
    int rowCount() const override { return static_cast<int>(m_triples.size()) * m_dimension; }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;
    bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const override;

private:
    struct Triple {
        int previous;
        int current;
        int next;
    };
    double secondDifference(const Triple& t, int k, const double* x) const {
        return x[t.previous + k] - 2.0 * x[t.current + k] + x[t.next + k];
    }
    int m_dimension;
    std::vector<Triple> m_triples;
    std::vector<double> m_reference; // per row: Δ² of the reference (empty: zero)
};

} // namespace devsurf::solver
