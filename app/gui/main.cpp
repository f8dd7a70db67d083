// DevSurf desktop application.

#include "example_dialog.h"
#include "main_window.h"
#include "solver/core/blas_info.h"
#include "translations.h"
#include "views/vtk_opengl_widget.h"
#include "workspace.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QIcon>
#include <QLocale>
#include <QTimer>

int main(int argc, char** argv) {
    // Before anything else: it may re-execute the program with a better BLAS kernel.
    devsurf::solver::useBestBlasKernel(argv);
    // The VTK views need their OpenGL format before the application exists.
    QSurfaceFormat::setDefaultFormat(devsurf::views::VtkOpenGLWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("DevSurf"));
    QApplication::setApplicationName(QStringLiteral("DevSurf"));
    QApplication::setApplicationVersion(QStringLiteral(DEVSURF_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/devsurf.svg")));

    // The language chosen in View ▸ Language, else the system's.
    devsurf::app::installInterfaceTranslations();

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Design developable surfaces and curved-crease origami."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("file"),
                                 QApplication::translate("main", "A project file to open."),
                                 QStringLiteral("[file.devsurf]"));
    QCommandLineOption example(QStringList{QStringLiteral("example")},
                               QApplication::translate("main", "Start with a built-in example."),
                               QStringLiteral("name"));
    parser.addOption(example);
    parser.process(app);

    devsurf::app::MainWindow window;
    window.show();
    auto* workspace = window.workspace();
    const QStringList files = parser.positionalArguments();
    if (!files.isEmpty()) {
        QTimer::singleShot(0, &window,
                           [workspace, path = files.front()] { workspace->open(path); });
    } else {
        const QString name =
            parser.isSet(example) ? parser.value(example) : QStringLiteral("annulus");
        workspace->newFromExample(name, 0, devsurf::app::ExampleDialog::rememberedSheet());
    }
    QTimer::singleShot(0, &window, [workspace] { workspace->offerRecovery(); });
    return QApplication::exec();
}
