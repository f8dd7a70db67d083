#include "point_index.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace devsurf::model::reference {

namespace {

// nanoflann's view of the points (it reads coordinates through these three calls).
struct Cloud {
    const std::vector<Vec3>* points = nullptr;
    std::size_t kdtree_get_point_count() const { return points->size(); }
    double kdtree_get_pt(std::size_t index, std::size_t dim) const {
        return (*points)[index][static_cast<int>(dim)];
    }
    template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud,
                                                 3, std::size_t>;

// Leaves of about this many points: nanoflann's recommended range for 3D queries is 10 to 50.
constexpr std::size_t kLeafSize = 16;

} // namespace

struct PointIndex::Tree {
    Cloud cloud;
    reference::Tree tree;
    explicit Tree(const std::vector<Vec3>& points)
        : cloud{&points}, tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize)) {}
};

PointIndex::PointIndex(std::vector<Vec3> points)
    : m_points(std::move(points)), m_tree(std::make_unique<Tree>(m_points)) {}

PointIndex::~PointIndex() = default;

PointIndex::Neighbour PointIndex::nearest(const Vec3& query) const {
    if (m_points.empty()) {
        throw std::logic_error("PointIndex::nearest on an empty index");
    }
    const double q[3] = {query.x, query.y, query.z};
    Neighbour best;
    nanoflann::KNNResultSet<double, std::size_t> result(1);
    result.init(&best.index, &best.squaredDistance);
    m_tree->tree.findNeighbors(result, q, nanoflann::SearchParams());
    return best;
}

std::vector<PointIndex::Neighbour> PointIndex::nearest(const Vec3& query, std::size_t k) const {
    k = std::min(k, m_points.size());
    std::vector<std::size_t> indices(k);
    std::vector<double> distances(k);
    std::vector<Neighbour> found;
    if (k == 0) {
        return found;
    }
    const double q[3] = {query.x, query.y, query.z};
    nanoflann::KNNResultSet<double, std::size_t> result(k);
    result.init(indices.data(), distances.data());
    m_tree->tree.findNeighbors(result, q, nanoflann::SearchParams());
    found.reserve(result.size());
    for (std::size_t i = 0; i < result.size(); ++i) {
        found.push_back({indices[i], distances[i]});
    }
    return found;
}

namespace {

// Collects into PointIndex::Neighbour directly, without nanoflann's pair vector.
struct RadiusCollector {
    double squaredRadius;
    std::vector<PointIndex::Neighbour>& found;
    std::size_t size() const { return found.size(); }
    bool full() const { return true; }
    double worstDist() const { return squaredRadius; }
    bool addPoint(double squaredDistance, std::size_t index) {
        if (squaredDistance < squaredRadius) {
            found.push_back({index, squaredDistance});
        }
        return true;
    }
};

} // namespace

void PointIndex::withinRadius(const Vec3& query, double radius,
                              std::vector<Neighbour>& found) const {
    found.clear();
    if (m_points.empty() || !(radius > 0.0)) {
        return;
    }
    const double q[3] = {query.x, query.y, query.z};
    RadiusCollector collector{radius * radius, found};
    m_tree->tree.findNeighbors(collector, q, nanoflann::SearchParams());
    std::sort(found.begin(), found.end(), [](const Neighbour& x, const Neighbour& y) {
        return x.squaredDistance < y.squaredDistance ||
               (x.squaredDistance == y.squaredDistance && x.index < y.index);
    });
}

} // namespace devsurf::model::reference
