#include "domain_terms.h"

#include "model/sheet_creases.h"
#include "solver/core/linear_term.h"

#include <memory>
#include <set>

namespace devsurf::solver {

DomainBoundaryTerm::DomainBoundaryTerm(std::vector<model::DomainLoop> loops, model::Vec2 origin,
                                       double scale)
    : m_loops(std::move(loops)), m_origin(origin), m_scale(scale) {}

void DomainBoundaryTerm::addVertex(int column, int loop) {
    m_rows.push_back({column, loop});
}

void DomainBoundaryTerm::buildPattern(PatternBuilder& builder) const {
    for (const Row& row : m_rows) {
        builder.beginRow();
        builder.addColumns(row.column, 2);
    }
}

bool DomainBoundaryTerm::evaluateRow(int r, const double* x, double* residual,
                                     double* jacobian) const {
    const Row& row = m_rows[static_cast<std::size_t>(r)];
    const model::Vec2 p = m_origin + model::Vec2(x[row.column], x[row.column + 1]) * m_scale;
    const model::DomainFoot foot = model::footPoint(m_loops[static_cast<std::size_t>(row.loop)], p);
    const model::Vec2 away = p - foot.point;
    *residual = (foot.normal.x * away.x + foot.normal.y * away.y) / m_scale;
    jacobian[0] = foot.normal.x;
    jacobian[1] = foot.normal.y;
    return true;
}

void DomainBoundaryTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (int r = 0; r < rowCount(); ++r) {
        evaluateRow(r, x, residuals + r, jacobian + 2 * r);
    }
}

void addDomain(const model::SheetDomain& domain, const DevelopmentVariables& variables,
               Problem& problem, const std::vector<double>& state) {
    if (domain.isFree() || variables.offset < 0) {
        return;
    }
    const model::Development start = variables.read(state);
    const model::DomainAssignment held =
        model::assignToDomain(domain, variables.mesh, start.vertices);
    // The crease curves follow the boundary loops, each crease sample on the tangent line of
    // its curve like a boundary vertex on its loop; a vertex fixed at a corner stays fixed.
    std::vector<model::DomainLoop> loops = model::domainLoops(domain);
    const int firstCurve = static_cast<int>(loops.size());
    for (model::DomainLoop& curve : model::creaseCurveLoops(domain)) {
        loops.push_back(std::move(curve));
    }
    auto boundary =
        std::make_unique<DomainBoundaryTerm>(std::move(loops), variables.origin, variables.scale);
    for (const model::DomainAssignment::OnLoop& on : held.onLoops) {
        boundary->addVertex(variables.offset + 2 * on.vertex, on.loop);
    }
    std::set<int> atCorner;
    for (const model::DomainAssignment::AtCorner& at : held.atCorners) {
        atCorner.insert(at.vertex);
    }
    for (const model::OnCreaseCurve& on : model::creaseSamplesOnCurves(domain, variables.mesh)) {
        if (atCorner.count(on.vertex) == 0) {
            boundary->addVertex(variables.offset + 2 * on.vertex, firstCurve + on.curve);
        }
    }
    auto corners = std::make_unique<LinearTerm>();
    for (const model::DomainAssignment::AtCorner& at : held.atCorners) {
        const model::Vec2 c = (at.corner - variables.origin) * (1.0 / variables.scale);
        const double rhs[2] = {c.x, c.y};
        corners->addPointRelation(2, {{variables.offset + 2 * at.vertex, 1.0}}, rhs);
    }
    const FamilyId family = problem.addFamily("developmentDomain", TermRole::Constraint);
    if (boundary->rowCount() > 0) {
        problem.add(family, std::move(boundary));
    }
    if (corners->rowCount() > 0) {
        problem.add(family, std::move(corners));
    }
}

} // namespace devsurf::solver
