#pragma once

// The development confined to a sheet (§5, "isometric mapping to a domain", Fig. 12, 13;
// docs/math.md §7): development vertices on the boundary of the sheet lie on the tangent line
// of its boundary at their foot point, refreshed every iteration; those nearest the sheet's
// corners are fixed there.

#include "model/sheet_domain.h"
#include "solver/core/problem.h"
#include "solver/core/term.h"
#include "solver/formulation/development_terms.h"

#include <vector>

namespace devsurf::solver {

// One row per held vertex: the signed distance of v̄ (in state units) from its loop of the
// domain, ⟨n, v̄ − f⟩ with f the foot point of v̄ on the loop and n the loop's normal at f. Its
// Jacobian is nᵀ, so each Gauss–Newton step asks for v̄ on the tangent line at the foot point of
// the current iterate.
class DomainBoundaryTerm : public Term {
public:
    // `origin` and `scale` map state values to millimetres: p = origin + scale · x.
    DomainBoundaryTerm(std::vector<model::DomainLoop> loops, model::Vec2 origin, double scale);
    // Holds the 2D point at columns `column`, `column + 1` on loop `loop`.
    void addVertex(int column, int loop);

    const char* typeName() const override { return "DomainBoundaryTerm"; }
    int rowCount() const override { return static_cast<int>(m_rows.size()); }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;
    bool evaluateRow(int row, const double* x, double* residual, double* jacobian) const override;

private:
    struct Row {
        int column = 0;
        int loop = 0;
    };
    std::vector<model::DomainLoop> m_loops;
    model::Vec2 m_origin;
    double m_scale = 1.0;
    std::vector<Row> m_rows;
};

// Appends a family "developmentDomain" (constraints) holding the development of `variables`
// in `domain` (model::assignToDomain at the development in `state`) and the samples of its
// creases on their curves (model::creaseSamplesOnCurves). No-op for a free sheet.
void addDomain(const model::SheetDomain& domain, const DevelopmentVariables& variables,
               Problem& problem, const std::vector<double>& state);

} // namespace devsurf::solver
