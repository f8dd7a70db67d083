#include "sheet_text.h"

namespace devsurf::app {

QString SheetText::tautPins(model::VertexId first, model::VertexId second) {
    return tr("the pinned vertices %1 and %2 are as far apart as along the straight line between "
              "them in the sheet, so that line stays straight and the strips it lies on stay "
              "flat, and a curved crease beside a flat strip cannot fold (unpin one of them to "
              "let the sheet fold)")
        .arg(first)
        .arg(second);
}

} // namespace devsurf::app
