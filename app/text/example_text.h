#pragma once

#include <QString>

#include <string>

namespace devsurf::app {

// What a built-in example is (model::builtInExamples), as the example dialog and
// `devsurf-cli examples` show it.
QString exampleDescription(const std::string& name);
// The description of an example holding the sheet it starts as (model::ExampleSheet::Held)
// where that changes its pins and how to fold it; empty where it does not.
QString heldExampleDescription(const std::string& name);

} // namespace devsurf::app
