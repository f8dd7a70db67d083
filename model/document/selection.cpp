#include "selection.h"

namespace devsurf::document {

void Selection::set(std::set<Pick> picks) {
    if (picks == m_picks) {
        return;
    }
    m_picks = std::move(picks);
    emit selectionChanged();
}

void Selection::add(const Pick& pick) {
    if (m_picks.insert(pick).second) {
        emit selectionChanged();
    }
}

void Selection::toggle(const Pick& pick) {
    if (m_picks.erase(pick) == 0) {
        m_picks.insert(pick);
    }
    emit selectionChanged();
}

void Selection::clear() {
    set({});
}

} // namespace devsurf::document
