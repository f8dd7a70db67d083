#pragma once

// What a printed tile says about its lines: a legend of the line types (cut, mountain, valley,
// crease, seam, and score where rulings are drawn) and the fold angle along every mountain and
// valley fold. Drawn by the one pattern painter (pattern_painter.cpp), so the PDF, the printer
// and the print preview show them alike. The painter draws in millimetres; `dpi` is the
// device's resolution, against which font point sizes are resolved.

#include "model/pattern/cutting_pattern.h"

#include <QColor>
#include <QRectF>

#include <cstdint>

class QPainter;

namespace devsurf::io {

// The colour of a layer style's 0xRRGGBB value.
QColor colourOf(std::uint32_t rgb);

// Rows of line samples with their names at the bottom of `box` (page millimetres).
void paintLineLegend(QPainter& painter, const QRectF& box, const model::CuttingPattern& pattern,
                     double dpi);

// The fold angles of `piece` ("M 46.2°", "V 30.0°") at the middle of each fold, along it and
// beside it, in pattern coordinates (the painter maps them to the page with y up). Folds wholly
// outside `visible` (null: none) are left out.
void paintFoldAngles(QPainter& painter, const model::PatternPiece& piece, const QRectF& visible,
                     double dpi);

} // namespace devsurf::io
