#pragma once

#include <QString>

#include <string>

namespace devsurf::app {

// What a built-in example is (model::builtInExamples), as the example dialog and
// `devsurf-cli examples` show it.
QString exampleDescription(const std::string& name);

} // namespace devsurf::app
