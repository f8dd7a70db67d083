#pragma once

// Internal to views/: includes VTK.

#include <vtkRenderWindowInteractor.h>

#include <QObject>

#include <map>

class QTimer;

namespace devsurf::views {

class QtInteractorTimers;

// A vtkRenderWindowInteractor without an event loop of its own: Qt's event loop drives it, the
// widget feeds it the translated input events, and its timers are QTimers.
class VtkQtInteractor : public vtkRenderWindowInteractor {
public:
    static VtkQtInteractor* New();
    vtkTypeMacro(VtkQtInteractor, vtkRenderWindowInteractor)

        // Enables the interactor without the render that the base class does: there may be no
        // GL context yet.
        void Initialize() override;
    // Qt's event loop runs the application; these must not start or stop one.
    void Start() override {}
    void TerminateApp() override {}

    // Called by a QTimer.
    void onTimeout(int platformTimerId);

protected:
    VtkQtInteractor();
    ~VtkQtInteractor() override;

    int InternalCreateTimer(int timerId, int timerType, unsigned long duration) override;
    int InternalDestroyTimer(int platformTimerId) override;

private:
    VtkQtInteractor(const VtkQtInteractor&) = delete;
    void operator=(const VtkQtInteractor&) = delete;

    std::map<int, QTimer*> m_timers; // by platform timer id
    int m_nextPlatformId = 1;
};

} // namespace devsurf::views
