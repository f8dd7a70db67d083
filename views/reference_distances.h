#pragma once

// How far the document's reference shapes are from its design (issue 42's distance report),
// measured in the background and shared by everyone who shows it: the 3D view's colour map
// and the distance report.

#include "model/reference/distance_report.h"

#include <QObject>
#include <QPointer>
#include <QThreadPool>

#include <atomic>
#include <memory>
#include <set>
#include <vector>

namespace devsurf::document {
class Document;
} // namespace devsurf::document

namespace devsurf::views {

// One measurement of every reference shape against every surface of the design.
struct ReferenceDistanceResult {
    // Why a shape could not be measured.
    // Cancelled: the shapes changed or the document closed meanwhile (never kept as latest()).
    enum class Failure { None, NoSurface, InvalidSurface, Cancelled };
    Failure failure = Failure::None;
    // One report per reference shape, in the project's order (empty on failure).
    std::vector<model::reference::DistanceReport> reports;
    // The largest target → surface distance over every shape (mm).
    double largest = 0.0;
    // The smallest coverage tolerance of the shapes (mm; the colour map's mark).
    double tolerance = 0.0;
    double milliseconds = 0.0; // how long the measurement took
};

// Measures while at least one user wants it (use()): after every change of a surface or of the
// reference shapes a job on its own thread takes copies of the surfaces and the shapes' points
// and runs measureDistance(); the GUI never waits. One job runs at a time; changes that arrive
// meanwhile are coalesced into the next one, so a drag measures its latest state only.
//
// While a job runs for a changed design the last result stays available as stale (latest() with
// isCurrent() false), so a colour map can be shown marked as out of date rather than vanish and
// return with every solver step. A change of the reference shapes themselves drops it: its
// distances belong to other points.
class ReferenceDistances : public QObject {
    Q_OBJECT
public:
    // The object shared by every user of the document (a child of it, created on first use).
    static ReferenceDistances* of(document::Document* document);

    explicit ReferenceDistances(document::Document* document);
    ~ReferenceDistances() override;

    // Starts or stops wanting measurements for `user`; measuring stops when nobody wants them.
    void use(const QObject* user, bool on);
    bool isUsed() const { return !m_users.empty(); }

    // The last measurement taken in, null before the first one or after the shapes changed.
    std::shared_ptr<const ReferenceDistanceResult> latest() const { return m_latest; }
    // Whether latest() belongs to the document as it is now.
    bool isCurrent() const;
    // Whether a measurement is under way (or waits to start) for the document as it is now.
    bool isMeasuring() const { return m_running || m_wanted; }
    // Whether there is something to measure: a reference shape and a surface.
    bool hasInput() const;

    // Blocks until no job runs (tests and benches; the results arrive through the event loop).
    bool waitForJobs(int msecs) { return m_pool.waitForDone(msecs); }

signals:
    // latest(), isCurrent() or isMeasuring() changed.
    void changed();

private:
    // What a measurement depends on: each surface (id and revision) and the shapes' generation.
    struct Key {
        std::vector<std::pair<quint32, quint64>> surfaces;
        quint64 shapes = 0;
        bool operator==(const Key& other) const {
            return surfaces == other.surfaces && shapes == other.shapes;
        }
        bool operator!=(const Key& other) const { return !(*this == other); }
    };
    Key currentKey() const;
    void onDocumentChanged(unsigned changes);
    // Starts a job for the current state unless one runs or the latest result is current.
    void startJob();
    void onMeasured(Key key, std::shared_ptr<const ReferenceDistanceResult> result);

    QPointer<document::Document> m_document;
    std::set<const QObject*> m_users;
    quint64 m_shapesGeneration = 0;
    std::shared_ptr<const ReferenceDistanceResult> m_latest;
    Key m_latestKey;
    bool m_running = false;
    bool m_wanted = false; // a change arrived while a job ran
    // The running job's cancel flag: set when the shapes change (its result would be dropped)
    // or this object goes, so that closing a document does not wait for a whole measurement.
    std::shared_ptr<std::atomic<bool>> m_cancel;
    QThreadPool m_pool;
};

} // namespace devsurf::views
