#pragma once

// The legend of the 3D view's colour map of reference shapes by distance (DistanceColouring):
// what it shows and how it is painted over the view (ViewOverlay).

#include <QColor>
#include <QRectF>
#include <QString>

#include <vector>

class QFont;
class QPainter;

namespace devsurf::views {

// What the legend of the colour map shows, drawn beside the quality legend's place.
struct DistanceLegend {
    QString title;
    std::vector<QColor> colours; // empty while nothing was measured yet
    double high = 0.0;           // mm at the top of the bar
    double tolerance = 0.0;      // mm, marked across the bar
    QString toleranceLabel;      // beside the colours below the mark
    QString note;                // e.g. "Updating…", under the title; empty when current
    bool stale = false;          // the bar faded as the points are
    bool operator==(const DistanceLegend& o) const {
        return title == o.title && colours == o.colours && high == o.high &&
               tolerance == o.tolerance && toleranceLabel == o.toleranceLabel && note == o.note &&
               stale == o.stale;
    }
};

// Paints the legend into `box` (widget coordinates): the title, the note, the bar with 0 at the
// bottom and a label at round lengths, the tolerance marked.
void paintDistanceLegend(QPainter& painter, const QRectF& box, const DistanceLegend& legend,
                         const QFont& font);

// The tolerance on a legend's colour bar (this one and the quality legend): a heavy line across
// `bar` at height `mark`, and `label` in bold green on white beside the bar within `box`,
// centred at height labelCentre. Leaves the painter's font at `font`.
void paintLegendTolerance(QPainter& painter, const QRectF& box, const QRectF& bar, double mark,
                          double labelCentre, const QString& label, const QFont& font);

// A stale colour: faded half way towards grey.
QColor fadedColour(const QColor& colour);

} // namespace devsurf::views
