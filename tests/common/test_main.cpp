#include "test_registry.h"

#include <QCoreApplication>

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    return devsurf::test::runAll(argc, argv);
}
