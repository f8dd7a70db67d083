#include "test_registry.h"
#include "translations.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"

#include <QApplication>
#include <QStandardPaths>

// The application tests run the real main window: OpenGL format first, then a QApplication.
// They run in English, or in the language DEVSURF_TEST_LANGUAGE names (e.g. "de"): the tests
// assert on state, not on wording, so a translation cannot break them.
int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(devsurf::views::VtkOpenGLWidget::defaultFormat());
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("DevSurfTests"));
    // A run in another language keeps its settings and recovery files apart (CTest may run
    // both at once).
    const QString language = qEnvironmentVariable("DEVSURF_TEST_LANGUAGE");
    QApplication::setApplicationName(language.isEmpty() ? QStringLiteral("tst_app")
                                                        : QStringLiteral("tst_app_") + language);
    devsurf::test::installTestLanguage();
    return devsurf::test::runAll(argc, argv);
}
