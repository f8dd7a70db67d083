#pragma once

#include "model/composite_surface.h"

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace devsurf::solver {

// The surfaces a job starts from (JobRequest::surfaces), held read-only and shared: copying a
// request copies a pointer. A drag sends the same press with every move, and a deep copy of a
// large design took about 1 ms of the GUI thread per move (docs/tuning.md). Changing it
// (mutableSurfaces(), push_back) copies the surfaces first if another holder shares them.
class SharedSurfaces {
public:
    using const_iterator = std::vector<model::CompositeSurface>::const_iterator;

    SharedSurfaces() = default;
    SharedSurfaces(std::vector<model::CompositeSurface> surfaces) // NOLINT: converts implicitly
        : m_surfaces(std::make_shared<std::vector<model::CompositeSurface>>(std::move(surfaces))) {}
    SharedSurfaces(std::initializer_list<model::CompositeSurface> surfaces)
        : SharedSurfaces(std::vector<model::CompositeSurface>(surfaces)) {}

    std::size_t size() const { return m_surfaces ? m_surfaces->size() : 0; }
    bool empty() const { return size() == 0; }
    const model::CompositeSurface& operator[](std::size_t i) const { return (*m_surfaces)[i]; }
    const model::CompositeSurface& at(std::size_t i) const { return all().at(i); }
    const model::CompositeSurface& front() const { return m_surfaces->front(); }
    const_iterator begin() const { return all().begin(); }
    const_iterator end() const { return all().end(); }
    const std::vector<model::CompositeSurface>& all() const {
        static const std::vector<model::CompositeSurface> none;
        return m_surfaces ? *m_surfaces : none;
    }

    // The surfaces to change, unshared first.
    std::vector<model::CompositeSurface>& mutableSurfaces() {
        if (!m_surfaces) {
            m_surfaces = std::make_shared<std::vector<model::CompositeSurface>>();
        } else if (m_surfaces.use_count() > 1) {
            m_surfaces = std::make_shared<std::vector<model::CompositeSurface>>(*m_surfaces);
        }
        return *m_surfaces;
    }
    void push_back(model::CompositeSurface surface) {
        mutableSurfaces().push_back(std::move(surface));
    }

private:
    // Not const inside: mutableSurfaces() changes it in place when no one else holds it.
    std::shared_ptr<std::vector<model::CompositeSurface>> m_surfaces;
};

} // namespace devsurf::solver
