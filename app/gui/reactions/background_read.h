#pragma once

#include <QObject>
#include <QString>

#include <atomic>
#include <functional>
#include <memory>

class QProgressDialog;
class QThread;
class QTimer;
class QWidget;

namespace devsurf::app {

// A file read on a worker thread behind a window-modal progress dialog that can cancel (the
// import reactions). The dialog shows only if reading takes a while. done() follows on the GUI
// thread once the reader returned; destroying the object before that cancels the reader and
// waits for it.
class BackgroundRead : public QObject {
    Q_OBJECT
public:
    // Reports progress (0 … 1) to the dialog; false: cancelled, the reader should stop.
    using Progress = std::function<bool(double fraction)>;

    // `objectName` names the dialog (tests find it); `read` runs on the worker thread.
    BackgroundRead(QWidget* window, const QString& label, const QString& title,
                   const QString& objectName, std::function<void(const Progress&)> read,
                   QObject* parent);
    ~BackgroundRead() override;

    // Whether the user cancelled (also when the reader had already finished).
    bool wasCancelled() const;

signals:
    void done();

private:
    struct Shared {
        std::atomic<int> permille{0};
        std::atomic<bool> cancel{false};
    };
    std::shared_ptr<Shared> m_shared;
    QThread* m_thread = nullptr;
    QProgressDialog* m_progress = nullptr; // until the reader returns
    bool m_cancelledInDialog = false;
    QTimer* m_poll = nullptr;
};

} // namespace devsurf::app
