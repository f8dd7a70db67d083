#pragma once

#include "model/ids.h"

#include <QObject>

#include <set>
#include <tuple>

namespace devsurf::document {

// One selected entity of the coarse mesh: a vertex, an edge or a face (patch) of a surface.
struct Pick {
    enum class Kind { Vertex, Edge, Face };
    Kind kind = Kind::Vertex;
    int surface = 0;
    std::uint32_t id = model::kInvalidId;

    bool operator<(const Pick& o) const {
        return std::tie(surface, kind, id) < std::tie(o.surface, o.kind, o.id);
    }
    bool operator==(const Pick& o) const {
        return kind == o.kind && surface == o.surface && id == o.id;
    }
};

// The current selection, shared by the 3D view, the development view and the panels. It is
// interface state, not part of the design: it is not undone and not saved.
class Selection : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    const std::set<Pick>& picks() const { return m_picks; }
    bool contains(const Pick& pick) const { return m_picks.count(pick) != 0; }
    bool isEmpty() const { return m_picks.empty(); }

    void set(std::set<Pick> picks);
    void add(const Pick& pick);
    void toggle(const Pick& pick);
    void clear();
    // Drops picks whose entity no longer exists (after undo, a topological edit, a new file).
    template <class Exists> void prune(Exists&& exists) {
        std::set<Pick> kept;
        for (const Pick& p : m_picks) {
            if (exists(p)) {
                kept.insert(p);
            }
        }
        set(std::move(kept));
    }

signals:
    void selectionChanged();

private:
    std::set<Pick> m_picks;
};

} // namespace devsurf::document
