#include "test_registry.h"

#include <QCoreApplication>
#include <QTest>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::test {
namespace {

std::vector<std::pair<std::string, TestFactory>>& registry() {
    static std::vector<std::pair<std::string, TestFactory>> tests;
    return tests;
}

} // namespace

bool registerTest(const char* name, TestFactory factory) {
    registry().emplace_back(name, std::move(factory));
    return true;
}

int runAll(int argc, char** argv) {
    std::vector<std::string> selected;
    std::vector<char*> passOn{argv[0]};
    for (int i = 1; i < argc; ++i) {
        bool isClass = false;
        for (const auto& entry : registry()) {
            if (entry.first == argv[i]) {
                isClass = true;
            }
        }
        if (isClass) {
            selected.emplace_back(argv[i]);
        } else {
            passOn.push_back(argv[i]);
        }
    }
    int failedClasses = 0;
    int ran = 0;
    for (const auto& entry : registry()) {
        if (!selected.empty() &&
            std::find(selected.begin(), selected.end(), entry.first) == selected.end()) {
            continue;
        }
        std::unique_ptr<QObject> object = entry.second();
        if (QTest::qExec(object.get(), static_cast<int>(passOn.size()), passOn.data()) != 0) {
            ++failedClasses;
        }
        ++ran;
    }
    if (ran == 0) {
        return 1; // a filter that matched nothing is a usage error, not a pass
    }
    return failedClasses;
}

} // namespace devsurf::test
