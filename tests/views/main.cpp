#include "test_registry.h"
#include "views/vtk_opengl_widget.h"

#include <QApplication>
#include <QLocale>
#include <QSurfaceFormat>
#include <QTranslator>

// GUI tests: the VTK widget needs its surface format before the application exists. With
// DEVSURF_TEST_LANGUAGE (e.g. "de") they run in that language, with the translation the
// application compiles in (DEVSURF_TRANSLATIONS_DIR): they assert on state, not on wording.
int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(devsurf::views::VtkOpenGLWidget::defaultFormat());
    QApplication app(argc, argv);
    QTranslator translator;
    const QString language = qEnvironmentVariable("DEVSURF_TEST_LANGUAGE");
    if (!language.isEmpty()) {
#ifdef DEVSURF_TRANSLATIONS_DIR
        QLocale::setDefault(QLocale(language));
        if (!translator.load(QLocale(), QStringLiteral("devsurf"), QStringLiteral("_"),
                             QStringLiteral(DEVSURF_TRANSLATIONS_DIR))) {
            qCritical("no translation for %s in %s", qPrintable(language),
                      DEVSURF_TRANSLATIONS_DIR);
            return 1;
        }
        QCoreApplication::installTranslator(&translator);
#else
        qCritical("built without the application's translations");
        return 1;
#endif
    }
    return devsurf::test::runAll(argc, argv);
}
