#include "test_registry.h"
#include "translations.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>

// The application tests run the real main window: OpenGL format first, then a QApplication.
// They run in English, or in the language DEVSURF_TEST_LANGUAGE names (e.g. "de"): the tests
// assert on state, not on wording, so a translation cannot break them.
int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(devsurf::views::VtkOpenGLWidget::defaultFormat());
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("DevSurfTests"));
    // Every run keeps its settings and recovery files apart, named by its process: CTest runs
    // the languages at once, and so may two checkouts on one machine. Removed at the end.
    const QString language = qEnvironmentVariable("DEVSURF_TEST_LANGUAGE");
    QApplication::setApplicationName(QStringLiteral("tst_app_%1_%2")
                                         .arg(language.isEmpty() ? QStringLiteral("en") : language)
                                         .arg(QCoreApplication::applicationPid()));
    devsurf::test::installTestLanguage();
    const int failed = devsurf::test::runAll(argc, argv);
    const QString settingsFile = QSettings().fileName();
    QFile::remove(settingsFile);
    const QString data = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    if (data.contains(QCoreApplication::applicationName())) {
        QDir(data).removeRecursively();
    }
    return failed;
}
