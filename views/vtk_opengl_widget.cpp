#include "vtk_opengl_widget.h"

#include "vtk_qt_interactor.h"

#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkRendererCollection.h>

#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QScopedValueRollback>
#include <QScreen>
#include <QWheelEvent>

#include <cmath>
#include <vector>

namespace devsurf::views {

namespace {

// VTK's key symbols for keys that carry no printable Latin-1 text.
const char* keySymbol(int key) {
    switch (key) {
    case Qt::Key_Backspace:
        return "BackSpace";
    case Qt::Key_Tab:
        return "Tab";
    case Qt::Key_Return:
    case Qt::Key_Enter:
        return "Return";
    case Qt::Key_Shift:
        return "Shift_L";
    case Qt::Key_Control:
        return "Control_L";
    case Qt::Key_Alt:
        return "Alt_L";
    case Qt::Key_Escape:
        return "Escape";
    case Qt::Key_Space:
        return "space";
    case Qt::Key_PageUp:
        return "Prior";
    case Qt::Key_PageDown:
        return "Next";
    case Qt::Key_End:
        return "End";
    case Qt::Key_Home:
        return "Home";
    case Qt::Key_Left:
        return "Left";
    case Qt::Key_Up:
        return "Up";
    case Qt::Key_Right:
        return "Right";
    case Qt::Key_Down:
        return "Down";
    case Qt::Key_Insert:
        return "Insert";
    case Qt::Key_Delete:
        return "Delete";
    default:
        return nullptr;
    }
}

} // namespace

struct VtkOpenGLWidget::Private {
    explicit Private(VtkOpenGLWidget* owner) : q(owner) {}

    void onWindowEvent(vtkObject*, unsigned long eventId, void* callData) {
        switch (eventId) {
        case vtkCommand::WindowMakeCurrentEvent:
            // The context only, not QOpenGLWidget::makeCurrent(): that also binds the widget's
            // framebuffer behind the back of VTK's cached GL state, and VTK would then draw
            // into (and attach its buffers to) Qt's framebuffer.
            if (QOpenGLContext* context = q->context()) {
                context->makeCurrent(context->surface());
            }
            break;
        case vtkCommand::WindowIsCurrentEvent: {
            QOpenGLContext* current = QOpenGLContext::currentContext();
            *static_cast<bool*>(callData) = current != nullptr && current == q->context() &&
                                            current->surface() == q->context()->surface();
            break;
        }
        case vtkCommand::WindowFrameEvent:
            // VTK rendered outside paintGL (an interactor style, a direct Render()): show it.
            // Rendering to the back buffer without swapping means the result is not meant to
            // be shown (e.g. a selection pass).
            if (window->GetDoubleBuffer() && !window->GetSwapBuffers()) {
                return;
            }
            renderPending = false;
            if (!inPaint) {
                q->update();
            }
            break;
        default:
            break;
        }
    }

    void setEventPosition(const QPointF& pos, Qt::KeyboardModifiers modifiers, bool repeat) {
        const double dpr = q->effectiveDevicePixelRatio();
        iren->SetEventInformationFlipY(static_cast<int>(std::lround(pos.x() * dpr)),
                                       static_cast<int>(std::lround(pos.y() * dpr)),
                                       (modifiers & Qt::ControlModifier) ? 1 : 0,
                                       (modifiers & Qt::ShiftModifier) ? 1 : 0, 0, repeat ? 1 : 0);
        iren->SetAltKey((modifiers & Qt::AltModifier) ? 1 : 0);
    }

    VtkOpenGLWidget* q;
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    vtkNew<VtkQtInteractor> iren;
    std::vector<unsigned long> observers;
    QMetaObject::Connection contextConnection;
    bool initialized = false; // the render window is bound to the current GL context
    bool renderPending = true;
    bool inPaint = false;
    int wheelDelta = 0;
};

VtkOpenGLWidget::VtkOpenGLWidget(QWidget* parent)
    : QOpenGLWidget(parent), d(std::make_unique<Private>(this)) {
    setFocusPolicy(Qt::StrongFocus);
    setUpdateBehavior(QOpenGLWidget::NoPartialUpdate);
    setMouseTracking(true);
    setMinimumSize(16, 16);

    // Until initializeGL there is no context: VTK must not try to render.
    d->window->SetReadyForRendering(false);
    // We blit ourselves into the widget's framebuffer.
    d->window->SetFrameBlitModeToNoBlit();
    d->window->SetInteractor(d->iren);
    d->iren->Initialize();
}

VtkOpenGLWidget::~VtkOpenGLWidget() {
    // ~QOpenGLWidget announces the context's destruction after this subclass is gone; a slot of
    // ours running then would touch a destroyed object. Disconnect first, then release VTK's GL
    // resources while the context still exists.
    QObject::disconnect(d->contextConnection);
    if (d->initialized && context() != nullptr) {
        makeCurrent();
        releaseGraphics();
        doneCurrent();
    }
    d->window->SetInteractor(nullptr);
}

QSurfaceFormat VtkOpenGLWidget::defaultFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 2);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
    format.setRedBufferSize(8);
    format.setGreenBufferSize(8);
    format.setBlueBufferSize(8);
    format.setAlphaBufferSize(8);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(0);
    // VTK's own framebuffer handles multisampling; the widget's never needs it.
    format.setSamples(0);
    return format;
}

vtkGenericOpenGLRenderWindow* VtkOpenGLWidget::renderWindow() const {
    return d->window;
}

vtkRenderWindowInteractor* VtkOpenGLWidget::interactor() const {
    return d->iren;
}

double VtkOpenGLWidget::effectiveDevicePixelRatio() const {
    return devicePixelRatioF();
}

void VtkOpenGLWidget::requestRender() {
    d->renderPending = true;
    update();
}

void VtkOpenGLWidget::initializeGL() {
    QOpenGLWidget::initializeGL();
    if (d->initialized) {
        // A new context without the old one being announced as destroyed: start clean.
        releaseGraphics();
    }
    vtkOpenGLState* state = d->window->GetState();
    state->Reset();
    // Qt leaves GL_LESS; VTK's shaders expect GL_LEQUAL.
    state->vtkglDepthFunc(GL_LEQUAL);

    d->observers.push_back(d->window->AddObserver(vtkCommand::WindowMakeCurrentEvent, d.get(),
                                                  &Private::onWindowEvent));
    d->observers.push_back(
        d->window->AddObserver(vtkCommand::WindowIsCurrentEvent, d.get(), &Private::onWindowEvent));
    d->observers.push_back(
        d->window->AddObserver(vtkCommand::WindowFrameEvent, d.get(), &Private::onWindowEvent));

    // VTK renders into its own framebuffer objects inside the widget's context.
    d->window->SetUseOffScreenBuffers(false);
    // Core profile: wide lines are emulated by VTK instead of relying on glLineWidth.
    d->window->SetForceMaximumHardwareLineWidth(1);
    d->window->SetReadyForRendering(true);
    d->window->SetOwnContext(0);
    d->window->OpenGLInitContext();
    d->initialized = true;
    d->renderPending = true;

    // Reparenting to another top-level window destroys this context and makes a new one: the
    // VTK window must release everything it created in the old one first.
    QObject::disconnect(d->contextConnection);
    d->contextConnection = connect(
        context(), &QOpenGLContext::aboutToBeDestroyed, this,
        [this] {
            if (d->initialized) {
                makeCurrent();
                releaseGraphics();
                doneCurrent();
            }
        },
        Qt::DirectConnection);
    updateSize();
}

void VtkOpenGLWidget::releaseGraphics() {
    d->window->Finalize();
    for (unsigned long id : d->observers) {
        d->window->RemoveObserver(id);
    }
    d->observers.clear();
    d->window->SetReadyForRendering(false);
    d->initialized = false;
}

void VtkOpenGLWidget::resizeGL(int /*width*/, int /*height*/) {
    updateSize();
}

void VtkOpenGLWidget::updateSize() {
    const double dpr = effectiveDevicePixelRatio();
    const int w = static_cast<int>(std::lround(width() * dpr));
    const int h = static_cast<int>(std::lround(height() * dpr));
    d->iren->UpdateSize(w, h); // also resizes the render window
    d->window->SetSize(w, h);
    if (QScreen* s = screen()) {
        const QSize screenSize = s->size() * dpr;
        d->window->SetScreenSize(screenSize.width(), screenSize.height());
    }
    // Text and point sizes in VTK follow the window's DPI.
    d->window->SetDPI(static_cast<int>(std::lround(72 * dpr)));
    d->renderPending = true;
}

void VtkOpenGLWidget::paintGL() {
    QOpenGLWidget::paintGL();
    QOpenGLExtraFunctions* f = context()->extraFunctions();
    if (!d->initialized) {
        f->glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    // The device pixel ratio may have changed with the screen without a resizeGL.
    const double dpr = effectiveDevicePixelRatio();
    const QSize deviceSize(static_cast<int>(std::lround(width() * dpr)),
                           static_cast<int>(std::lround(height() * dpr)));
    const int* current = d->window->GetSize();
    if (current[0] != deviceSize.width() || current[1] != deviceSize.height()) {
        updateSize();
    }

    vtkOpenGLState* state = d->window->GetState();
    state->Reset();
    state->Push();
    state->vtkglDepthFunc(GL_LEQUAL);
    if (d->renderPending) {
        QScopedValueRollback<bool> guard(d->inPaint, true);
        d->iren->Render();
        d->renderPending = false;
    }
    // Rendering may have made another context current (e.g. another widget updating).
    makeCurrent();

    f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    f->glDrawBuffers(1, &drawBuffer);
    const GLboolean scissor = f->glIsEnabled(GL_SCISSOR_TEST);
    if (scissor == GL_TRUE) {
        state->vtkglDisable(GL_SCISSOR_TEST);
        f->glDisable(GL_SCISSOR_TEST);
    }
    int* sourceSize = d->window->GetRenderFramebuffer()->GetLastSize();
    d->window->BlitDisplayFramebuffer(0, 0, 0, sourceSize[0], sourceSize[1], 0, 0,
                                      deviceSize.width(), deviceSize.height(), GL_COLOR_BUFFER_BIT,
                                      GL_LINEAR);

    // An alpha below one would let the compositor blend the view with what lies behind it
    // (Mesa does); force it opaque.
    GLboolean mask[4];
    f->glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    GLfloat clear[4];
    f->glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    GLint viewport[4];
    f->glGetIntegerv(GL_VIEWPORT, viewport);
    f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    f->glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    f->glViewport(0, 0, deviceSize.width(), deviceSize.height());
    f->glClear(GL_COLOR_BUFFER_BIT);
    f->glColorMask(mask[0], mask[1], mask[2], mask[3]);
    f->glClearColor(clear[0], clear[1], clear[2], clear[3]);
    f->glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);

    if (scissor == GL_TRUE) {
        state->vtkglEnable(GL_SCISSOR_TEST);
        f->glEnable(GL_SCISSOR_TEST);
    }
    state->Pop();
}

bool VtkOpenGLWidget::event(QEvent* e) {
    vtkRenderWindowInteractor* iren = d->iren;
    const bool enabled = iren->GetEnabled() != 0 && d->initialized;
    switch (e->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseMove: {
        if (!enabled) {
            break;
        }
        auto* me = static_cast<QMouseEvent*>(e);
        d->setEventPosition(me->position(), me->modifiers(),
                            e->type() == QEvent::MouseButtonDblClick);
        if (e->type() == QEvent::MouseMove) {
            iren->InvokeEvent(vtkCommand::MouseMoveEvent, me);
        } else {
            const bool press = e->type() != QEvent::MouseButtonRelease;
            unsigned long id = 0;
            switch (me->button()) {
            case Qt::LeftButton:
                id = press ? vtkCommand::LeftButtonPressEvent : vtkCommand::LeftButtonReleaseEvent;
                break;
            case Qt::MiddleButton:
                id = press ? vtkCommand::MiddleButtonPressEvent
                           : vtkCommand::MiddleButtonReleaseEvent;
                break;
            case Qt::RightButton:
                id =
                    press ? vtkCommand::RightButtonPressEvent : vtkCommand::RightButtonReleaseEvent;
                break;
            default:
                break;
            }
            if (id != 0) {
                iren->InvokeEvent(id, me);
            }
        }
        e->accept();
        return true;
    }
    case QEvent::Wheel: {
        if (!enabled) {
            break;
        }
        auto* we = static_cast<QWheelEvent*>(e);
        d->setEventPosition(we->position(), we->modifiers(), false);
        // Touchpads send many small deltas; VTK zooms one notch per 120 (one wheel click).
        d->wheelDelta += we->angleDelta().y();
        if (d->wheelDelta >= 120) {
            iren->InvokeEvent(vtkCommand::MouseWheelForwardEvent, we);
            d->wheelDelta = 0;
        } else if (d->wheelDelta <= -120) {
            iren->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, we);
            d->wheelDelta = 0;
        }
        e->accept();
        return true;
    }
    case QEvent::KeyPress:
    case QEvent::KeyRelease: {
        if (!enabled) {
            break;
        }
        auto* ke = static_cast<QKeyEvent*>(e);
        const QString text = ke->text();
        char ascii = 0;
        if (text.size() == 1 && text.at(0).unicode() > 32 && text.at(0).unicode() < 127) {
            ascii = static_cast<char>(text.at(0).toLatin1());
        }
        const QByteArray asciiSymbol(1, ascii);
        const char* symbol = ascii != 0 ? asciiSymbol.constData() : keySymbol(ke->key());
        iren->SetKeyEventInformation((ke->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                     (ke->modifiers() & Qt::ShiftModifier) ? 1 : 0, ascii,
                                     ke->isAutoRepeat() ? 1 : 0, symbol ? symbol : "None");
        iren->SetAltKey((ke->modifiers() & Qt::AltModifier) ? 1 : 0);
        if (e->type() == QEvent::KeyPress) {
            iren->InvokeEvent(vtkCommand::KeyPressEvent, ke);
            if (ascii != 0) {
                iren->InvokeEvent(vtkCommand::CharEvent, ke);
            }
        } else {
            iren->InvokeEvent(vtkCommand::KeyReleaseEvent, ke);
        }
        break; // let Qt shortcuts see keys too
    }
    case QEvent::Enter:
        if (enabled) {
            iren->InvokeEvent(vtkCommand::EnterEvent, e);
        }
        break;
    case QEvent::Leave:
        if (enabled) {
            iren->InvokeEvent(vtkCommand::LeaveEvent, e);
        }
        break;
    default:
        break;
    }
    return QOpenGLWidget::event(e);
}

} // namespace devsurf::views
