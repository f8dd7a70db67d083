#include "vtk_qt_interactor.h"

#include <vtkCommand.h>
#include <vtkObjectFactory.h>

#include <QTimer>

namespace devsurf::views {

vtkStandardNewMacro(VtkQtInteractor);

VtkQtInteractor::VtkQtInteractor() = default;

VtkQtInteractor::~VtkQtInteractor() {
    for (auto& entry : m_timers) {
        delete entry.second;
    }
}

void VtkQtInteractor::Initialize() {
    this->Initialized = 1;
    this->Enable();
}

int VtkQtInteractor::InternalCreateTimer(int /*timerId*/, int timerType, unsigned long duration) {
    const int platformId = m_nextPlatformId++;
    auto* timer = new QTimer;
    timer->setSingleShot(timerType == OneShotTimer);
    timer->setInterval(static_cast<int>(duration));
    QObject::connect(timer, &QTimer::timeout, timer, [this, platformId] { onTimeout(platformId); });
    m_timers[platformId] = timer;
    timer->start();
    return platformId;
}

int VtkQtInteractor::InternalDestroyTimer(int platformTimerId) {
    auto it = m_timers.find(platformTimerId);
    if (it == m_timers.end()) {
        return 0;
    }
    it->second->stop();
    // deleteLater: this may run inside the timer's own timeout.
    it->second->deleteLater();
    m_timers.erase(it);
    return 1;
}

void VtkQtInteractor::onTimeout(int platformTimerId) {
    if (m_timers.count(platformTimerId) == 0) {
        return;
    }
    int vtkTimerId = GetVTKTimerId(platformTimerId);
    if (vtkTimerId != 0) {
        InvokeEvent(vtkCommand::TimerEvent, &vtkTimerId);
    }
}

} // namespace devsurf::views
