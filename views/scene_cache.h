#pragma once

// What the 3D view and the development view draw, built once per surface revision and shared
// by every view of a document.

#include "scene_geometry.h"

#include <QObject>
#include <QPointer>
#include <QThreadPool>

#include <limits>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace devsurf::document {
class Document;
} // namespace devsurf::document

namespace devsurf::views {

// The scenes of a document's surfaces (the sampled mesh for the 3D view, the development for
// the development view), computed on first request at a document revision and kept per
// surface: a surface is rebuilt only when Document::surfaceRevision() says it changed, so a
// drag of one surface resamples and re-develops that surface once, however many views draw it.
// Only the layout of the development's pieces side by side is redone for every revision.
class SceneCache : public QObject {
    Q_OBJECT
public:
    // The cache shared by every view of the document (a child of it, created on first use).
    static SceneCache* of(document::Document* document);

    explicit SceneCache(document::Document* document);
    ~SceneCache() override;

    // At the document's current revision; the same object for as long as it does not change.
    std::shared_ptr<const SceneSet> spatialScenes();
    std::shared_ptr<const SceneSet> developmentScenes();

    // For a change of a large surface: samples it for the 3D view at its latest revision on a
    // background thread (one job at a time, later revisions coalesced), then emits spatialReady().
    void sampleInBackground(int surfaceIndex);
    // The 3D scenes as far as they are known: a surface being sampled in the background as last
    // sampled, every other one at the current revision. Equals spatialScenes() once no sampling
    // is pending.
    std::shared_ptr<const SceneSet> latestSpatialScenes();
    bool spatialPending() const { return !m_spatialWanted.empty(); }

    // For a drag: develops the surface at its latest revision on a background thread (one job
    // at a time; revisions that arrive meanwhile are coalesced into the next job), then emits
    // developmentReady().
    void developInBackground(int surfaceIndex);
    // The development as far as it is known: a surface being developed in the background is
    // laid out as last developed, every other one at the current revision. Equals
    // developmentScenes() once no development is pending.
    std::shared_ptr<const SceneSet> latestDevelopmentScenes();
    bool developmentPending() const { return !m_wanted.empty(); }

    // How many times a surface was sampled for the 3D view, developed for the development
    // view, and how many times the development's pieces were laid out, since the cache exists.
    int spatialBuilds() const { return m_spatialBuilds; }
    int developmentBuilds() const { return m_developmentBuilds; }
    int layouts() const { return m_layouts; }

    // For benches: waits until no background job runs (their results are taken in by the event
    // loop, as queued calls to this object). False if msecs passed first.
    bool waitForBackgroundJobs(int msecs) { return m_pool.waitForDone(msecs); }

signals:
    // A background development finished (latestDevelopmentScenes() has changed).
    void developmentReady();
    // A background sampling finished (latestSpatialScenes() has changed).
    void spatialReady();

private:
    static constexpr quint64 kNever = std::numeric_limits<quint64>::max();
    // A surface as last built: its id and the revision it was built at.
    struct Key {
        quint32 surface = 0;
        quint64 revision = kNever;
        bool operator==(const Key& other) const {
            return surface == other.surface && revision == other.revision;
        }
    };
    struct SpatialEntry {
        Key key;
        std::shared_ptr<const SurfaceScene> scene; // null: the surface is not valid
    };
    struct DevelopmentEntry {
        Key key;
        std::shared_ptr<const SurfaceDevelopment> development;
    };
    Key keyOf(int surfaceIndex) const;
    // The 3D scenes (current, or latest known for the surfaces in m_spatialWanted).
    std::shared_ptr<const SceneSet> spatial(bool latest);
    void startNextSpatialJob();
    void onSampled(Key key, quint64 generation, std::shared_ptr<const SurfaceScene> scene,
                   std::vector<Key> keys, std::shared_ptr<const SceneSet> set);
    // Lays out the developments (current, or latest known for the surfaces in m_wanted).
    std::shared_ptr<const SceneSet> development(bool latest);
    void startNextJob();
    void onDeveloped(Key key, quint64 generation,
                     std::shared_ptr<const SurfaceDevelopment> development, std::vector<Key> keys,
                     std::shared_ptr<const SceneSet> laidOut);

    QPointer<document::Document> m_document;
    // The newest 3D scene of every surface (by id), the set of them last handed out and the
    // document revision it is current at (kNever while a surface in it is behind).
    std::map<quint32, SpatialEntry> m_spatialEntries;
    std::vector<Key> m_sampled;
    std::shared_ptr<const SceneSet> m_spatial;
    quint64 m_spatialRevision = kNever;
    std::set<quint32> m_spatialWanted; // surfaces (by id) to sample in the background
    bool m_spatialJobRunning = false;
    // A set of 3D scenes put together by the last background sampling, and the keys it holds:
    // taken instead of putting it together again when those are the keys wanted.
    std::vector<Key> m_spatialReadyKeys;
    std::shared_ptr<const SceneSet> m_spatialReady;
    // The newest development of every surface (by id), and the last layout of them.
    std::map<quint32, DevelopmentEntry> m_developments;
    std::vector<Key> m_laidOut;
    std::shared_ptr<const SceneSet> m_development;
    // A layout made by the last background development, and the keys it was made for: taken
    // instead of laying out again when those are the keys wanted.
    std::vector<Key> m_readyKeys;
    std::shared_ptr<const SceneSet> m_ready;
    // Surfaces (by id) to develop in the background, whether a job runs, and the project
    // generation (a new project drops the results of jobs started before it).
    std::set<quint32> m_wanted;
    bool m_jobRunning = false;
    quint64 m_generation = 0;
    QThreadPool m_pool;
    int m_spatialBuilds = 0;
    int m_developmentBuilds = 0;
    int m_layouts = 0;
};

} // namespace devsurf::views
