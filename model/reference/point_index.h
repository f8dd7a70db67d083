#pragma once

#include "model/vec3.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace devsurf::model::reference {

// A KD-tree (nanoflann) over a fixed set of points: nearest, k nearest and radius queries.
// Queries are const and may run from several threads at once.
class PointIndex {
public:
    struct Neighbour {
        std::size_t index = 0;
        double squaredDistance = 0.0;
    };

    explicit PointIndex(std::vector<Vec3> points);
    ~PointIndex();
    PointIndex(const PointIndex&) = delete;
    PointIndex& operator=(const PointIndex&) = delete;

    const std::vector<Vec3>& points() const { return m_points; }
    std::size_t size() const { return m_points.size(); }
    bool empty() const { return m_points.empty(); }

    // The nearest point; the index must not be empty (throws std::logic_error).
    Neighbour nearest(const Vec3& query) const;
    // The min(k, size()) nearest points, nearest first.
    std::vector<Neighbour> nearest(const Vec3& query, std::size_t k) const;
    // Every point at a distance strictly below radius, nearest first, into `found` (cleared
    // first; passing the same vector again saves the allocations in a loop).
    void withinRadius(const Vec3& query, double radius, std::vector<Neighbour>& found) const;

private:
    struct Tree;
    std::vector<Vec3> m_points;
    std::unique_ptr<Tree> m_tree;
};

} // namespace devsurf::model::reference
