#include "scene_cache.h"

#include "model/document/document.h"

#include <algorithm>
#include <exception>

namespace devsurf::views {

SceneCache* SceneCache::of(document::Document* document) {
    if (document == nullptr) {
        return nullptr;
    }
    if (auto* cache = document->findChild<SceneCache*>(QString(), Qt::FindDirectChildrenOnly)) {
        return cache;
    }
    return new SceneCache(document);
}

SceneCache::SceneCache(document::Document* document) : QObject(document), m_document(document) {
    m_pool.setMaxThreadCount(1);
    connect(document, &document::Document::projectReset, this, [this] {
        ++m_generation;
        m_wanted.clear();
    });
}

SceneCache::~SceneCache() {
    // A running job posts its result to this object: let it finish first (the posted event is
    // dropped with the object).
    m_pool.waitForDone();
}

SceneCache::Key SceneCache::keyOf(int surfaceIndex) const {
    return {m_document->surface(surfaceIndex).id(), m_document->surfaceRevision(surfaceIndex)};
}

std::shared_ptr<const SceneSet> SceneCache::spatialScenes() {
    if (m_document == nullptr) {
        return std::make_shared<const SceneSet>();
    }
    if (m_spatial != nullptr && m_spatialRevision == m_document->revision()) {
        return m_spatial;
    }
    auto result = std::make_shared<SceneSet>();
    std::vector<SpatialEntry> entries;
    for (int i = 0; i < m_document->surfaceCount(); ++i) {
        SpatialEntry entry{keyOf(i), -1};
        const auto old = std::find_if(m_spatialEntries.begin(), m_spatialEntries.end(),
                                      [&](const SpatialEntry& e) { return e.key == entry.key; });
        if (old != m_spatialEntries.end() && m_spatial != nullptr) {
            if (old->scene >= 0) {
                // Unchanged since the last build: copied, not resampled.
                entry.scene = static_cast<int>(result->scenes.size());
                result->scenes.push_back(m_spatial->scenes[static_cast<std::size_t>(old->scene)]);
                result->scenes.back().surface = i;
            }
        } else {
            ++m_spatialBuilds;
            try {
                result->scenes.push_back(buildSpatialScene(m_document->surface(i), i));
                entry.scene = static_cast<int>(result->scenes.size()) - 1;
            } catch (const std::exception&) {
                // An invalid surface (e.g. mid-way through an edit) is skipped, not fatal.
            }
        }
        if (entry.scene < 0) {
            result->invalidSurfaces.push_back(i);
        }
        entries.push_back(entry);
    }
    m_spatialEntries = std::move(entries);
    m_spatial = std::move(result);
    m_spatialRevision = m_document->revision();
    return m_spatial;
}

std::shared_ptr<const SceneSet> SceneCache::developmentScenes() {
    return development(false);
}

std::shared_ptr<const SceneSet> SceneCache::latestDevelopmentScenes() {
    return development(true);
}

std::shared_ptr<const SceneSet> SceneCache::development(bool latest) {
    if (m_document == nullptr) {
        return std::make_shared<const SceneSet>();
    }
    std::vector<Key> keys;
    std::vector<const SurfaceDevelopment*> developments;
    std::set<quint32> present;
    for (int i = 0; i < m_document->surfaceCount(); ++i) {
        const Key key = keyOf(i);
        present.insert(key.surface);
        DevelopmentEntry& entry = m_developments[key.surface];
        const bool stale = !(entry.key == key);
        const bool waitForJob = latest && m_wanted.count(key.surface) != 0 && entry.development;
        if (stale && !waitForJob) {
            ++m_developmentBuilds;
            entry.key = key;
            entry.development = std::make_shared<const SurfaceDevelopment>(
                developSurfaceForView(m_document->surface(i), i));
            m_wanted.erase(key.surface); // developed at its current revision
        }
        keys.push_back(entry.key);
        developments.push_back(entry.development.get());
    }
    for (auto it = m_developments.begin(); it != m_developments.end();) {
        it = present.count(it->first) != 0 ? std::next(it) : m_developments.erase(it);
    }
    if (m_development == nullptr || keys != m_laidOut) {
        ++m_layouts;
        m_development = std::make_shared<const SceneSet>(
            layOutDevelopments(m_document->project(), developments));
        m_laidOut = std::move(keys);
    }
    return m_development;
}

void SceneCache::developInBackground(int surfaceIndex) {
    if (m_document == nullptr || surfaceIndex < 0 || surfaceIndex >= m_document->surfaceCount()) {
        return;
    }
    m_wanted.insert(m_document->surface(surfaceIndex).id());
    startNextJob();
}

void SceneCache::startNextJob() {
    if (m_jobRunning || m_document == nullptr) {
        return;
    }
    while (!m_wanted.empty()) {
        const quint32 id = *m_wanted.begin();
        const int index = m_document->project().indexOf(id);
        if (index < 0) {
            m_wanted.erase(id);
            continue;
        }
        const Key key = keyOf(index);
        const auto done = m_developments.find(id);
        if (done != m_developments.end() && done->second.key == key) {
            m_wanted.erase(id); // caught up
            continue;
        }
        // The job works on its own copy of the surface; the result comes back queued.
        m_jobRunning = true;
        const quint64 generation = m_generation;
        m_pool.start([this, surface = m_document->surface(index), index, key, generation] {
            auto development =
                std::make_shared<const SurfaceDevelopment>(developSurfaceForView(surface, index));
            QMetaObject::invokeMethod(
                this,
                [this, key, generation, development] { onDeveloped(key, generation, development); },
                Qt::QueuedConnection);
        });
        return;
    }
}

void SceneCache::onDeveloped(Key key, quint64 generation,
                             std::shared_ptr<const SurfaceDevelopment> development) {
    m_jobRunning = false;
    ++m_developmentBuilds;
    if (generation == m_generation) {
        DevelopmentEntry& entry = m_developments[key.surface];
        if (!entry.development || entry.key.revision == kNever ||
            entry.key.revision < key.revision) {
            entry = {key, std::move(development)};
        }
    }
    startNextJob();
    emit developmentReady();
}

} // namespace devsurf::views
