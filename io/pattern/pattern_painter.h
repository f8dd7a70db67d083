#pragma once

// The one painter of printed patterns: the PDF writer and the printer (print dialog, print
// preview) both call it, so what is previewed is what is printed and what the PDF holds.
// Pages: the fabrication report, an overview of the tiling per sheet, then the tiles at 1:1.

#include "page_plan.h"
#include "pattern_writers.h"

#include <QPageSize>

class QPagedPaintDevice;

namespace devsurf::io {

// Sets the device's page (size, the plan's orientation, no margins: the plan keeps its own)
// before painting starts.
void preparePagedDevice(QPagedPaintDevice& device, const QPageSize& pageSize, const PagePlan& plan);

// Pages painted for a pattern: report pages + one overview per sheet + tiles.
int patternPageCount(const model::CuttingPattern& pattern, const PagePlan& plan);

// Paints every page; the report page lists `problemTexts` (the pattern's problems as the front
// end words them). Returns false if the painter could not start on the device or the progress
// callback cancelled.
bool paintPatternPages(QPagedPaintDevice& device, const model::CuttingPattern& pattern,
                       const PagePlan& plan, const std::vector<std::string>& problemTexts,
                       const PatternProgress& progress = {});

QPageSize pageSizeOf(Paper paper);

} // namespace devsurf::io
