#include "reference_distances.h"

#include "model/document/document.h"
#include "model/model_error.h"

#include <QElapsedTimer>

#include <algorithm>
#include <exception>

namespace devsurf::views {

namespace {

// Measures every shape against every surface; runs on the job's thread, on copies.
std::shared_ptr<const ReferenceDistanceResult>
measure(const std::vector<model::CompositeSurface>& surfaces,
        const std::vector<model::ReferenceShape>& shapes, const std::atomic<bool>* cancel) {
    QElapsedTimer clock;
    clock.start();
    auto result = std::make_shared<ReferenceDistanceResult>();
    model::reference::DistanceOptions options;
    options.cancel = cancel;
    try {
        for (const model::ReferenceShape& shape : shapes) {
            options.triangles = &shape.triangles; // a mesh: to its triangles
            result->reports.push_back(
                model::reference::measureDistance(surfaces, shape.points, options));
        }
    } catch (const model::reference::DistanceCancelled&) {
        result->failure = ReferenceDistanceResult::Failure::Cancelled;
    } catch (const model::ModelError&) {
        result->failure = ReferenceDistanceResult::Failure::InvalidSurface;
    } catch (const std::exception&) {
        // measureDistance refuses a design without faces; the shapes were checked on import.
        result->failure = ReferenceDistanceResult::Failure::NoSurface;
    }
    if (result->failure != ReferenceDistanceResult::Failure::None) {
        result->reports.clear();
    }
    for (const model::reference::DistanceReport& report : result->reports) {
        result->largest = std::max(result->largest, report.targetToSurface.max);
        result->tolerance = result->tolerance > 0.0 ? std::min(result->tolerance, report.tolerance)
                                                    : report.tolerance;
    }
    result->milliseconds = static_cast<double>(clock.nsecsElapsed()) * 1e-6;
    return result;
}

} // namespace

ReferenceDistances* ReferenceDistances::of(document::Document* document) {
    if (document == nullptr) {
        return nullptr;
    }
    if (auto* found =
            document->findChild<ReferenceDistances*>(QString(), Qt::FindDirectChildrenOnly)) {
        return found;
    }
    return new ReferenceDistances(document);
}

ReferenceDistances::ReferenceDistances(document::Document* document)
    : QObject(document), m_document(document) {
    m_pool.setMaxThreadCount(1);
    connect(document, &document::Document::changed, this,
            [this](document::Changes changes) { onDocumentChanged(changes.toInt()); });
    connect(document, &document::Document::projectReset, this,
            [this] { onDocumentChanged(static_cast<unsigned>(document::Change::Everything)); });
}

ReferenceDistances::~ReferenceDistances() {
    // A running job posts its result to this object: stop it and let it finish first (the
    // posted event is dropped with the object).
    if (m_cancel) {
        m_cancel->store(true);
    }
    m_pool.waitForDone();
}

void ReferenceDistances::use(const QObject* user, bool on) {
    if (on) {
        if (m_users.insert(user).second) {
            connect(user, &QObject::destroyed, this, [this, user] { m_users.erase(user); });
        }
        startJob();
    } else if (m_users.erase(user) != 0) {
        disconnect(user, &QObject::destroyed, this, nullptr);
    }
}

bool ReferenceDistances::hasInput() const {
    if (m_document == nullptr || m_document->project().referenceShapes.empty()) {
        return false;
    }
    const auto& surfaces = m_document->project().surfaces;
    return std::any_of(surfaces.begin(), surfaces.end(),
                       [](const model::CompositeSurface& s) { return !s.faces().empty(); });
}

ReferenceDistances::Key ReferenceDistances::currentKey() const {
    Key key;
    key.shapes = m_shapesGeneration;
    if (m_document != nullptr) {
        for (int i = 0; i < m_document->surfaceCount(); ++i) {
            key.surfaces.emplace_back(m_document->surface(i).id(), m_document->surfaceRevision(i));
        }
    }
    return key;
}

bool ReferenceDistances::isCurrent() const {
    return m_latest != nullptr && m_latestKey == currentKey();
}

void ReferenceDistances::onDocumentChanged(unsigned changes) {
    if ((changes & static_cast<unsigned>(document::Change::ReferenceShapes)) != 0) {
        // Other points: the distances measured belong to none of them, nor will the running
        // job's.
        ++m_shapesGeneration;
        m_latest.reset();
        if (m_running && m_cancel) {
            m_cancel->store(true);
        }
    }
    if (isCurrent()) {
        return; // e.g. pins or reference curves changed
    }
    startJob();
    emit changed();
}

void ReferenceDistances::startJob() {
    if (m_users.empty() || m_document == nullptr || isCurrent()) {
        return;
    }
    if (m_running) {
        m_wanted = true;
        return;
    }
    m_wanted = false;
    if (!hasInput()) {
        // Nothing to measure: no result, which every user shows as none.
        const bool had = m_latest != nullptr;
        m_latest.reset();
        if (had) {
            emit changed();
        }
        return;
    }
    std::vector<model::ReferenceShape> shapes = m_document->project().referenceShapes;
    m_running = true;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    m_pool.start([this, key = currentKey(), surfaces = m_document->project().surfaces,
                  shapes = std::move(shapes), cancel = m_cancel] {
        std::shared_ptr<const ReferenceDistanceResult> result =
            measure(surfaces, shapes, cancel.get());
        QMetaObject::invokeMethod(
            this, [this, key, result] { onMeasured(key, result); }, Qt::QueuedConnection);
    });
}

void ReferenceDistances::onMeasured(Key key,
                                    std::shared_ptr<const ReferenceDistanceResult> result) {
    m_running = false;
    // A result for shapes since replaced is dropped; one for an older design is kept as stale.
    if (key.shapes == m_shapesGeneration &&
        result->failure != ReferenceDistanceResult::Failure::Cancelled) {
        m_latest = std::move(result);
        m_latestKey = std::move(key);
    }
    startJob();
    emit changed();
}

} // namespace devsurf::views
