#pragma once

#include "solver/core/squared_distance_term.h"

namespace devsurf::solver {

// Rows nᵀn − 1 = 0 for unit normals n (a point of `dimension` columns, or a linear
// combination such as a normal-spline evaluation n(0)).
class UnitNormTerm : public SquaredDistanceTerm {
public:
    explicit UnitNormTerm(int dimension = 3) : SquaredDistanceTerm(dimension, dimension) {}

    int addVector(int offset) { return addRow(PointCombination{{offset, 1.0}}, 1.0); }
    int addVector(const PointCombination& vector) { return addRow(vector, 1.0); }

    const char* typeName() const override { return "UnitNormTerm"; }
};

} // namespace devsurf::solver
