#include "scene_cache.h"

#include "model/document/document.h"

#include <algorithm>
#include <exception>

namespace devsurf::views {

namespace {

// The scenes of every surface in one set (a copy of each); null: the surface is not valid.
std::shared_ptr<const SceneSet>
sceneSetOf(const std::vector<std::shared_ptr<const SurfaceScene>>& scenes) {
    auto result = std::make_shared<SceneSet>();
    for (int i = 0; i < static_cast<int>(scenes.size()); ++i) {
        if (const auto& scene = scenes[static_cast<std::size_t>(i)]) {
            result->scenes.push_back(*scene);
            result->scenes.back().surface = i;
        } else {
            result->invalidSurfaces.push_back(i);
        }
    }
    return result;
}

} // namespace

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
    m_pool.setMaxThreadCount(2); // one sampling and one development at a time
    connect(document, &document::Document::projectReset, this, [this] {
        ++m_generation;
        m_wanted.clear();
        m_spatialWanted.clear();
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
    return spatial(false);
}

std::shared_ptr<const SceneSet> SceneCache::latestSpatialScenes() {
    return spatial(true);
}

std::shared_ptr<const SceneSet> SceneCache::spatial(bool latest) {
    if (m_document == nullptr) {
        return std::make_shared<const SceneSet>();
    }
    if (m_spatial != nullptr && m_spatialRevision == m_document->revision()) {
        return m_spatial;
    }
    std::vector<Key> keys;
    std::set<quint32> present;
    bool current = true;
    for (int i = 0; i < m_document->surfaceCount(); ++i) {
        const Key key = keyOf(i);
        present.insert(key.surface);
        SpatialEntry& entry = m_spatialEntries[key.surface];
        const bool stale = !(entry.key == key);
        const bool waitForJob =
            latest && m_spatialWanted.count(key.surface) != 0 && entry.key.revision != kNever;
        if (stale && !waitForJob) {
            ++m_spatialBuilds;
            entry.key = key;
            try {
                entry.scene = std::make_shared<const SurfaceScene>(
                    buildSpatialScene(m_document->surface(i), i));
            } catch (const std::exception&) {
                // An invalid surface (e.g. mid-way through an edit) is skipped, not fatal.
                entry.scene.reset();
            }
            m_spatialWanted.erase(key.surface); // sampled at its current revision
        }
        current = current && entry.key == key;
        keys.push_back(entry.key);
    }
    for (auto it = m_spatialEntries.begin(); it != m_spatialEntries.end();) {
        it = present.count(it->first) != 0 ? std::next(it) : m_spatialEntries.erase(it);
    }
    if (m_spatialReady != nullptr && keys == m_spatialReadyKeys && keys != m_sampled) {
        m_spatial = std::move(m_spatialReady); // put together in the background
        m_sampled = std::move(keys);
    } else if (m_spatial == nullptr || keys != m_sampled) {
        // Unchanged surfaces are copied, not resampled.
        std::vector<std::shared_ptr<const SurfaceScene>> scenes;
        for (const Key& each : keys) {
            scenes.push_back(m_spatialEntries[each.surface].scene);
        }
        m_spatial = sceneSetOf(scenes);
        m_sampled = std::move(keys);
    }
    m_spatialRevision = current ? m_document->revision() : kNever;
    return m_spatial;
}

void SceneCache::sampleInBackground(int surfaceIndex) {
    if (m_document == nullptr || surfaceIndex < 0 || surfaceIndex >= m_document->surfaceCount()) {
        return;
    }
    m_spatialWanted.insert(m_document->surface(surfaceIndex).id());
    startNextSpatialJob();
}

void SceneCache::startNextSpatialJob() {
    if (m_spatialJobRunning || m_document == nullptr) {
        return;
    }
    while (!m_spatialWanted.empty()) {
        const quint32 id = *m_spatialWanted.begin();
        const int index = m_document->project().indexOf(id);
        if (index < 0) {
            m_spatialWanted.erase(id);
            continue;
        }
        const Key key = keyOf(index);
        const auto done = m_spatialEntries.find(id);
        if (done != m_spatialEntries.end() && done->second.key == key) {
            m_spatialWanted.erase(id); // caught up
            continue;
        }
        // The job puts the set of scenes together as well where every other surface's scene
        // is current (their scenes are shared, read only).
        const int count = m_document->surfaceCount();
        std::vector<Key> keys;
        std::vector<std::shared_ptr<const SurfaceScene>> scenes(static_cast<std::size_t>(count));
        for (int i = 0; i < count && keys.size() == static_cast<std::size_t>(i); ++i) {
            const Key other = keyOf(i);
            const auto known = m_spatialEntries.find(other.surface);
            if (i == index) {
                keys.push_back(key);
            } else if (known != m_spatialEntries.end() && known->second.key == other) {
                keys.push_back(other);
                scenes[static_cast<std::size_t>(i)] = known->second.scene;
            }
        }
        if (keys.size() != static_cast<std::size_t>(count)) {
            keys.clear();
        }
        // The job works on its own copy of the surface; the result comes back queued.
        m_spatialJobRunning = true;
        const quint64 generation = m_generation;
        m_pool.start([this, surface = m_document->surface(index), index, key, generation,
                      keys = std::move(keys), scenes = std::move(scenes)]() mutable {
            std::shared_ptr<const SurfaceScene> scene;
            try {
                scene = std::make_shared<const SurfaceScene>(buildSpatialScene(surface, index));
            } catch (const std::exception&) {
                // Not valid: drawn as such once taken in.
            }
            std::shared_ptr<const SceneSet> set;
            if (!keys.empty()) {
                scenes[static_cast<std::size_t>(index)] = scene;
                set = sceneSetOf(scenes);
            }
            QMetaObject::invokeMethod(
                this,
                [this, key, generation, scene, keys = std::move(keys), set] {
                    onSampled(key, generation, scene, keys, set);
                },
                Qt::QueuedConnection);
        });
        return;
    }
}

void SceneCache::onSampled(Key key, quint64 generation, std::shared_ptr<const SurfaceScene> scene,
                           std::vector<Key> keys, std::shared_ptr<const SceneSet> set) {
    m_spatialJobRunning = false;
    ++m_spatialBuilds;
    if (generation == m_generation) {
        SpatialEntry& entry = m_spatialEntries[key.surface];
        if (entry.key.revision == kNever || entry.key.revision < key.revision) {
            entry = {key, std::move(scene)};
            m_spatialRevision = kNever; // the set handed out is rebuilt with it
            m_spatialReadyKeys = std::move(keys);
            m_spatialReady =
                set != nullptr && !m_spatialReadyKeys.empty() ? std::move(set) : nullptr;
        }
    }
    startNextSpatialJob();
    emit spatialReady();
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
    if (m_ready != nullptr && keys == m_readyKeys && keys != m_laidOut) {
        ++m_layouts; // laid out in the background
        m_development = std::move(m_ready);
        m_laidOut = std::move(keys);
    } else if (m_development == nullptr || keys != m_laidOut) {
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
        // The job lays the pieces out as well where every other surface's development is
        // current (their developments are shared, read only).
        const int count = m_document->surfaceCount();
        std::vector<Key> keys;
        std::vector<std::shared_ptr<const SurfaceDevelopment>> developments(
            static_cast<std::size_t>(count));
        for (int i = 0; i < count && keys.size() == static_cast<std::size_t>(i); ++i) {
            const Key other = keyOf(i);
            const auto known = m_developments.find(other.surface);
            if (i == index) {
                keys.push_back(key);
            } else if (known != m_developments.end() && known->second.key == other &&
                       known->second.development != nullptr) {
                keys.push_back(other);
                developments[static_cast<std::size_t>(i)] = known->second.development;
            }
        }
        if (keys.size() != static_cast<std::size_t>(count)) {
            keys.clear();
        }
        // The job works on its own copy of the project; the result comes back queued.
        m_jobRunning = true;
        const quint64 generation = m_generation;
        m_pool.start([this, project = m_document->project(), index, key, generation,
                      keys = std::move(keys), developments = std::move(developments)]() mutable {
            auto development = std::make_shared<const SurfaceDevelopment>(
                developSurfaceForView(project.surfaces[static_cast<std::size_t>(index)], index));
            std::shared_ptr<const SceneSet> laidOut;
            if (!keys.empty()) {
                developments[static_cast<std::size_t>(index)] = development;
                std::vector<const SurfaceDevelopment*> all;
                for (const auto& each : developments) {
                    all.push_back(each.get());
                }
                laidOut = std::make_shared<const SceneSet>(layOutDevelopments(project, all));
            }
            QMetaObject::invokeMethod(
                this,
                [this, key, generation, development, keys = std::move(keys), laidOut] {
                    onDeveloped(key, generation, development, keys, laidOut);
                },
                Qt::QueuedConnection);
        });
        return;
    }
}

void SceneCache::onDeveloped(Key key, quint64 generation,
                             std::shared_ptr<const SurfaceDevelopment> development,
                             std::vector<Key> keys, std::shared_ptr<const SceneSet> laidOut) {
    m_jobRunning = false;
    ++m_developmentBuilds;
    if (generation == m_generation) {
        DevelopmentEntry& entry = m_developments[key.surface];
        if (!entry.development || entry.key.revision == kNever ||
            entry.key.revision < key.revision) {
            entry = {key, std::move(development)};
            m_readyKeys = std::move(keys);
            m_ready = laidOut != nullptr && !m_readyKeys.empty() ? std::move(laidOut) : nullptr;
        }
    }
    startNextJob();
    emit developmentReady();
}

} // namespace devsurf::views
