#pragma once

#include <QObject>

#include <functional>
#include <memory>

// Each area (tests/model, tests/io, ...) builds one test executable that runs every Qt Test
// class registered in it. A test class registers itself with DEVSURF_REGISTER_TEST(Class).
namespace devsurf::test {

using TestFactory = std::function<std::unique_ptr<QObject>()>;

bool registerTest(const char* name, TestFactory factory);

// Runs all registered test classes (or only those named as leading arguments, e.g.
// `tst_model TstBSpline -v2`). Returns the number of failed test classes.
int runAll(int argc, char** argv);

} // namespace devsurf::test

#define DEVSURF_REGISTER_TEST(Class)                                                               \
    static const bool devsurfRegistered##Class =                                                   \
        ::devsurf::test::registerTest(#Class, [] { return std::unique_ptr<QObject>(new Class); })
