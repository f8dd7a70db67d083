#pragma once

// Internal to views/: the 3D view's colour map of the reference shapes by their distance to the
// design, with its legend.

#include "distance_legend.h"

#include <vtkSmartPointer.h>

#include <QColor>

#include <array>
#include <vector>

class vtkUnsignedCharArray;

namespace devsurf::views {

// A linear scale in mm from 0 to a round length at or above the largest distance: green up to
// the coverage tolerance (the target points counted as covered), then yellow to red, as the
// quality colouring (toleranceScale).
class DistanceColouring {
public:
    // The scale for distances up to `largest` with the tolerance marked; the top is the
    // smallest 1, 2 or 5 × 10^k mm at or above both the largest distance and twice the
    // tolerance, so that the mark always lies on the bar.
    void setRange(double tolerance, double largest);
    double high() const { return m_high; }
    double tolerance() const { return m_tolerance; }
    const std::vector<QColor>& colours() const { return m_colours; }
    QColor colour(double distance) const;
    // One colour per distance; `stale` ones faded towards grey (the design changed since).
    vtkSmartPointer<vtkUnsignedCharArray> pointColours(const std::vector<double>& distances,
                                                       bool stale) const;

    static constexpr int kColours = 256;

private:
    double m_tolerance = 1.0;
    double m_high = 2.0;
    std::vector<QColor> m_colours;
};

} // namespace devsurf::views
