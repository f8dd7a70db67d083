#pragma once

#include "project.h"

#include <string>
#include <vector>

namespace devsurf::model {

struct ExampleInfo {
    std::string name; // app::exampleDescription says what it is
    int defaultSize;
    int minSize;
    int maxSize;
};

// The built-in examples: sheet, annulus, cylinder, mixed, fig8, fig6, fig13, torus, column.
// Each is exactly developable as built; fig8, fig6, fig13 and column carry curved-fold
// conditions and pinned vertices; fig13 keeps its development on a disk, column around a
// cylinder; the torus unfolds into no one sheet.
const std::vector<ExampleInfo>& builtInExamples();

// Builds an example; size is its resolution (see builtInExamples()), 0 means the default.
// Throws ModelError for an unknown name or a size out of range.
Project makeExample(const std::string& name, int size = 0);

} // namespace devsurf::model
