#include "background_read.h"

#include <QProgressDialog>
#include <QThread>
#include <QTimer>

#include <algorithm>

namespace devsurf::app {

BackgroundRead::BackgroundRead(QWidget* window, const QString& label, const QString& title,
                               const QString& objectName, std::function<void(const Progress&)> read,
                               QObject* parent)
    : QObject(parent), m_shared(std::make_shared<Shared>()) {
    std::shared_ptr<Shared> shared = m_shared;
    m_thread = QThread::create([shared, read = std::move(read)] {
        read([&shared](double fraction) {
            shared->permille = static_cast<int>(1000.0 * std::clamp(fraction, 0.0, 1.0));
            return !shared->cancel.load();
        });
    });
    connect(m_thread, &QThread::finished, this, [this] {
        m_poll->stop();
        m_cancelledInDialog = m_progress->wasCanceled();
        // Hidden and reset (which stops the timer that would show it once its minimum
        // duration is up, over the message that may follow), then deleted later: this can
        // run inside the dialog's own setValue(), which processes events while the dialog
        // is modal, and deleting it there crashed on return.
        m_progress->hide();
        m_progress->reset();
        m_progress->deleteLater();
        m_progress = nullptr;
        emit done();
    });
    // Window-modal, so the design is not edited meanwhile.
    m_progress = new QProgressDialog(label, tr("Cancel"), 0, 1000, window);
    m_progress->setObjectName(objectName);
    m_progress->setWindowTitle(title);
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->setMinimumDuration(400);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    m_progress->setValue(0);
    connect(m_progress, &QProgressDialog::canceled, this, [shared] { shared->cancel = true; });
    m_poll = new QTimer(this);
    connect(m_poll, &QTimer::timeout, this, [this] {
        if (!m_shared->cancel && m_progress != nullptr) {
            m_progress->setValue(std::min(m_shared->permille.load(), 999));
        }
    });
    m_poll->start(50);
    m_thread->start();
}

BackgroundRead::~BackgroundRead() {
    // Destroyed while reading: stop the reader and wait for it.
    m_shared->cancel = true;
    m_thread->wait();
    delete m_thread;
    if (m_progress != nullptr) {
        m_progress->deleteLater();
    }
}

bool BackgroundRead::wasCancelled() const {
    return m_shared->cancel.load() || m_cancelledInDialog ||
           (m_progress != nullptr && m_progress->wasCanceled());
}

} // namespace devsurf::app
