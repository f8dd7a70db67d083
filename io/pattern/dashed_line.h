#pragma once

// A line's dashes as geometry. Printed patterns draw their dashes themselves instead of through
// a pen's dash pattern: Qt's raster engine (the print preview) draws a pen thinner than a pixel
// with its dash pattern counted in pixels, the PDF in pen widths, so the same pen gave long
// heavy dashes on screen and fine dots on paper.

#include <QPointF>
#include <QPolygonF>

#include <vector>

namespace devsurf::io {

struct DashedLine {
    std::vector<QPolygonF> dashes; // the drawn stretches, as polylines
    std::vector<QPointF> dots;     // where the pattern has a dash of length 0
};

// The dashes of `line` (closed: back to its first point) under `pattern`: lengths in the line's
// units, on, off, on, off, … repeated from the line's start; an "on" of 0 is a dot. An empty
// pattern or a pattern without length gives the whole line as one dash.
DashedLine dashLine(const QPolygonF& line, bool closed, const std::vector<double>& pattern);

} // namespace devsurf::io
