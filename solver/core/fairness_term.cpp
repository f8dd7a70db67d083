#include "solver/core/fairness_term.h"

namespace devsurf::solver {

void FairnessTerm::addSequence(const std::vector<int>& points, bool closed) {
    changed();
    const std::size_t n = points.size();
    if (n < 3) {
        return;
    }
    if (closed) {
        for (std::size_t i = 0; i < n; ++i) {
            m_triples.push_back({points[(i + n - 1) % n], points[i], points[(i + 1) % n]});
        }
    } else {
        for (std::size_t i = 1; i + 1 < n; ++i) {
            m_triples.push_back({points[i - 1], points[i], points[i + 1]});
        }
    }
}

void FairnessTerm::setReference(const double* reference) {
    changed();
    m_reference.clear();
    if (!reference) {
        return;
    }
    m_reference.reserve(m_triples.size() * static_cast<std::size_t>(m_dimension));
    for (const Triple& t : m_triples) {
        for (int k = 0; k < m_dimension; ++k) {
            m_reference.push_back(secondDifference(t, k, reference));
        }
    }
}

void FairnessTerm::buildPattern(PatternBuilder& builder) const {
    for (const Triple& t : m_triples) {
        for (int k = 0; k < m_dimension; ++k) {
            builder.beginRow();
            builder.addColumn(t.previous + k);
            builder.addColumn(t.current + k);
            builder.addColumn(t.next + k);
        }
    }
}

void FairnessTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    const double* reference = m_reference.empty() ? nullptr : m_reference.data();
    for (const Triple& t : m_triples) {
        for (int k = 0; k < m_dimension; ++k) {
            *residuals++ = secondDifference(t, k, x) - (reference ? *reference++ : 0.0);
            *jacobian++ = 1.0;
            *jacobian++ = -2.0;
            *jacobian++ = 1.0;
        }
    }
}

bool FairnessTerm::evaluateRow(int row, const double* x, double* residual, double* jacobian) const {
    const Triple& t = m_triples[static_cast<std::size_t>(row / m_dimension)];
    const int k = row % m_dimension;
    *residual = secondDifference(t, k, x) -
                (m_reference.empty() ? 0.0 : m_reference[static_cast<std::size_t>(row)]);
    jacobian[0] = 1.0;
    jacobian[1] = -2.0;
    jacobian[2] = 1.0;
    return true;
}

} // namespace devsurf::solver
