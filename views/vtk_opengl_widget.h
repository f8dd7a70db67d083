#pragma once

#include <QOpenGLWidget>
#include <QSurfaceFormat>

#include <memory>

class vtkGenericOpenGLRenderWindow;
class vtkRenderWindowInteractor;

namespace devsurf::views {

// A QOpenGLWidget that drives a vtkGenericOpenGLRenderWindow (the Qt 6 replacement for VTK's
// Qt 5-only QVTKOpenGLNativeWidget). VTK renders into its own framebuffer inside our GL
// context; paintGL() blits that framebuffer into the widget's. Qt input events are translated
// into the render window's interactor, whose timers are QTimers.
//
// The default surface format must be set before the QApplication is constructed:
//     QSurfaceFormat::setDefaultFormat(VtkOpenGLWidget::defaultFormat());
class VtkOpenGLWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit VtkOpenGLWidget(QWidget* parent = nullptr);
    ~VtkOpenGLWidget() override;

    // OpenGL 3.2 core, double buffered, no multisampling (VTK's framebuffer does its own).
    static QSurfaceFormat defaultFormat();

    vtkGenericOpenGLRenderWindow* renderWindow() const;
    vtkRenderWindowInteractor* interactor() const;

    // Device pixels per widget pixel (VTK works in device pixels).
    double effectiveDevicePixelRatio() const;

    // Asks for a VTK render at the next paint (after the scene changed).
    void requestRender();

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;
    bool event(QEvent* event) override;

private:
    void releaseGraphics();
    void updateSize();

    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace devsurf::views
