#include "test_registry.h"
#include "views/vtk_opengl_widget.h"

#include <QApplication>
#include <QSurfaceFormat>

// GUI tests: the VTK widget needs its surface format before the application exists.
int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(devsurf::views::VtkOpenGLWidget::defaultFormat());
    QApplication app(argc, argv);
    return devsurf::test::runAll(argc, argv);
}
