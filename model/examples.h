#pragma once

#include "project.h"

#include <cstdint>
#include <string>
#include <vector>

namespace devsurf::model {

struct ExampleInfo {
    std::string name; // app::exampleDescription says what it is
    int defaultSize;
    int minSize;
    int maxSize;
    // It holds no sheet as built but can be made to hold the sheet it starts as
    // (ExampleSheet::Held): flat, or for the cylinder the cylinder its unfolding rolls onto;
    // and whether it holds a sheet as built (fig13, column, fig12).
    bool canHoldItsSheet = false;
    bool holdsSheetAsBuilt = false;
};

// How a new design from an example treats its sheet (§5). AsBuilt: as the example comes (the
// command line's default; fig13 and column hold theirs). Held (File ▸ New from Example's
// default): an example that starts flat holds the sheet it starts as, confined to the
// smallest sheet of its shape around it (a rectangle for sheet, fig8 and fig6, an annulus for
// the annulus, free for mixed), its curved-fold creases kept where they lie in it (the
// cylinder holds the cylinder its unfolding rolls onto, as column does); of two pins
// at the ends of a straight line in the sheet only the first stays pinned, since a held sheet
// keeps that line straight and could then only turn about it (model/held_by_pins.h).
enum class ExampleSheet : std::uint8_t { AsBuilt, Held };

// The built-in examples: sheet, annulus, cylinder, mixed, fig8, fig6, fig13, torus, column,
// fig12. Each is exactly developable as built; fig8, fig6, fig13, column and fig12 carry
// curved-fold conditions and pinned vertices; fig13 keeps its development on a disk, column
// around a cylinder, fig12 on the lobed ring it folds from (an outline); the torus unfolds
// into no one sheet.
const std::vector<ExampleInfo>& builtInExamples();

// Builds an example; size is its resolution (see builtInExamples()), 0 means the default.
// Throws ModelError for an unknown name or a size out of range.
Project makeExample(const std::string& name, int size = 0,
                    ExampleSheet sheet = ExampleSheet::AsBuilt);

} // namespace devsurf::model
