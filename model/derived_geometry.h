#pragma once

#include "composite_surface.h"
#include "creases.h"
#include "development.h"
#include "sampled_mesh.h"
#include "strip.h"

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace devsurf::model {

// What the views, the solver's measures, the writers and the command line derive from one state
// of a surface, computed once per state and sample density and shared between them: the sampled
// mesh, its development and the crease table. Entries are immutable; the cache behind of() keeps
// the most recently used ones and is safe to use from any thread (the solver worker's and the
// GUI's).
class DerivedGeometry {
public:
    // The derived geometry of `surface` at samplesPerInterval samples per spline interval.
    // Throws ModelError for an invalid surface, as sampleSurface() does.
    static std::shared_ptr<const DerivedGeometry> of(const CompositeSurface& surface,
                                                     int samplesPerInterval);

    int samplesPerInterval() const { return m_samples; }
    const SampledMesh& mesh() const { return m_mesh; }
    // Unfolded at the first call (unfoldSampledMesh).
    const Development& development() const;
    // stripsOf() and creasesOf() with this mesh, at the first call.
    const std::vector<Strip>& strips() const;
    const std::vector<Crease>& creases() const;

    // The cache: how many states it holds at most, and how many it holds now.
    static constexpr std::size_t kCacheCapacity = 24;
    static std::size_t cachedCount();
    static void clearCache();

    DerivedGeometry(CompositeSurface surface, int samplesPerInterval, std::size_t key);

private:
    friend class DerivedGeometryCache;
    CompositeSurface m_surface; // the state this was derived from (the cache's key)
    int m_samples;
    std::size_t m_key;
    SampledMesh m_mesh;
    mutable std::once_flag m_developed;
    mutable Development m_development;
    mutable std::once_flag m_creased;
    mutable std::vector<Strip> m_strips;
    mutable std::vector<Crease> m_creases;
};

} // namespace devsurf::model
