#include "derived_geometry.h"

#include <algorithm>
#include <cstring>
#include <list>

namespace devsurf::model {

namespace {

void mix(std::size_t& seed, std::size_t value) {
    seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
}

void mix(std::size_t& seed, double value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    mix(seed, static_cast<std::size_t>(bits));
}

void mix(std::size_t& seed, const Vec3& p) {
    mix(seed, p.x);
    mix(seed, p.y);
    mix(seed, p.z);
}

// A hash of everything the derived geometry depends on (not the name, id or pins).
std::size_t geometryKey(const CompositeSurface& surface, int samples) {
    std::size_t seed = static_cast<std::size_t>(samples);
    for (const auto& [id, position] : surface.vertices()) {
        mix(seed, static_cast<std::size_t>(id));
        mix(seed, position);
    }
    for (const auto& [id, edge] : surface.edges()) {
        mix(seed, static_cast<std::size_t>(id));
        mix(seed, static_cast<std::size_t>(edge.from) << 32 | edge.to);
        mix(seed, static_cast<std::size_t>(edge.label) << 8 |
                      static_cast<std::size_t>(edge.condition) << 1 |
                      static_cast<std::size_t>(edge.smooth));
        for (const Vec3& point : edge.controlPoints) {
            mix(seed, point);
        }
    }
    mix(seed, surface.faces().size());
    return seed;
}

bool sameGeometry(const CompositeSurface& a, const CompositeSurface& b) {
    if (!(a.vertices() == b.vertices()) || a.faces() != b.faces() ||
        a.edges().size() != b.edges().size()) {
        return false;
    }
    return std::equal(
        a.edges().begin(), a.edges().end(), b.edges().begin(), [](const auto& x, const auto& y) {
            const EdgeRecord& e = x.second;
            const EdgeRecord& f = y.second;
            return x.first == y.first && e.from == f.from && e.to == f.to && e.label == f.label &&
                   e.space == f.space && e.controlPoints == f.controlPoints &&
                   e.condition == f.condition && e.smooth == f.smooth;
        });
}

} // namespace

// Most recently used first.
class DerivedGeometryCache {
public:
    static DerivedGeometryCache& instance() {
        static DerivedGeometryCache cache;
        return cache;
    }

    std::shared_ptr<const DerivedGeometry> find(const CompositeSurface& surface, int samples,
                                                std::size_t key) {
        std::lock_guard lock(m_mutex);
        for (auto it = m_entries.begin(); it != m_entries.end(); ++it) {
            const DerivedGeometry& entry = **it;
            if (entry.m_key == key && entry.m_samples == samples &&
                sameGeometry(entry.m_surface, surface)) {
                m_entries.splice(m_entries.begin(), m_entries, it);
                return m_entries.front();
            }
        }
        return nullptr;
    }

    void insert(std::shared_ptr<const DerivedGeometry> entry) {
        std::lock_guard lock(m_mutex);
        m_entries.push_front(std::move(entry));
        while (m_entries.size() > DerivedGeometry::kCacheCapacity) {
            m_entries.pop_back();
        }
    }

    std::size_t size() {
        std::lock_guard lock(m_mutex);
        return m_entries.size();
    }

    void clear() {
        std::lock_guard lock(m_mutex);
        m_entries.clear();
    }

private:
    std::mutex m_mutex;
    std::list<std::shared_ptr<const DerivedGeometry>> m_entries;
};

DerivedGeometry::DerivedGeometry(CompositeSurface surface, int samplesPerInterval, std::size_t key)
    : m_surface(std::move(surface)), m_samples(samplesPerInterval), m_key(key),
      m_mesh(sampleSurface(m_surface, samplesPerInterval)) {}

std::shared_ptr<const DerivedGeometry> DerivedGeometry::of(const CompositeSurface& surface,
                                                           int samplesPerInterval) {
    const std::size_t key = geometryKey(surface, samplesPerInterval);
    DerivedGeometryCache& cache = DerivedGeometryCache::instance();
    if (auto found = cache.find(surface, samplesPerInterval, key)) {
        return found;
    }
    // Sampled outside the lock: two threads asking for the same new state both sample it.
    auto entry = std::make_shared<const DerivedGeometry>(surface, samplesPerInterval, key);
    cache.insert(entry);
    return entry;
}

const Development& DerivedGeometry::development() const {
    std::call_once(m_developed, [this] { m_development = unfoldSampledMesh(m_mesh); });
    return m_development;
}

const std::vector<Strip>& DerivedGeometry::strips() const {
    std::call_once(m_creased, [this] {
        m_strips = stripsOf(m_surface);
        m_creases = creasesOf(m_surface, m_strips, m_mesh);
    });
    return m_strips;
}

const std::vector<Crease>& DerivedGeometry::creases() const {
    strips();
    return m_creases;
}

std::size_t DerivedGeometry::cachedCount() {
    return DerivedGeometryCache::instance().size();
}

void DerivedGeometry::clearCache() {
    DerivedGeometryCache::instance().clear();
}

} // namespace devsurf::model
