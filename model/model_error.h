#pragma once

#include "problem.h"

#include <stdexcept>

namespace devsurf::model {

// Thrown when an edit or a construction step would break the model. It carries the problem as
// a code with data for the front ends to word; what() is only its technical key.
class ModelError : public std::runtime_error {
public:
    explicit ModelError(Problem problem)
        : std::runtime_error(technicalKey(problem)), m_problem(std::move(problem)) {}
    const Problem& problem() const { return m_problem; }

private:
    Problem m_problem;
};

} // namespace devsurf::model
