#include "test_registry.h"

#include <QApplication>

// The pattern writers paint text (PDF, printing): they need a QApplication; offscreen unless a
// display was chosen.
int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    QApplication app(argc, argv);
    return devsurf::test::runAll(argc, argv);
}
