#include "test_registry.h"
#include "views/vtk_opengl_widget.h"

#include <QApplication>
#include <QStandardPaths>

// The application tests run the real main window: OpenGL format first, then a QApplication.
int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(devsurf::views::VtkOpenGLWidget::defaultFormat());
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("DevSurfTests"));
    QApplication::setApplicationName(QStringLiteral("tst_app"));
    return devsurf::test::runAll(argc, argv);
}
