// The 3D view's colour map of the reference shapes by their distance to the design: the
// measurements come from ReferenceDistances (in the background); this file applies them to
// the shapes drawn and writes the legend.

#include "reference_distances.h"
#include "scene_view.h"
#include "scene_view_private.h"

namespace devsurf::views {

void SceneView::setColourReferenceByDistance(bool on) {
    if (d->kind != Kind::Spatial) {
        return;
    }
    d->byDistance = on;
    if (ReferenceDistances* source = ReferenceDistances::of(d->document)) {
        // Starts a measurement if none is current; none for hidden shapes (a drag would
        // measure at every step for nothing).
        source->use(this, on && d->scene->showsReferenceShapes());
    }
    showReferenceDistances();
}

bool SceneView::coloursReferenceByDistance() const {
    return d->byDistance;
}

void SceneView::showReferenceDistances() {
    if (d->kind != Kind::Spatial) {
        return;
    }
    ReferenceDistances* source = d->byDistance && d->scene->showsReferenceShapes()
                                     ? ReferenceDistances::of(d->document)
                                     : nullptr;
    const std::shared_ptr<const ReferenceDistanceResult> result =
        source != nullptr ? source->latest() : nullptr;
    const std::size_t shapes =
        d->document != nullptr ? d->document->project().referenceShapes.size() : 0;
    const bool usable = result != nullptr &&
                        result->failure == ReferenceDistanceResult::Failure::None &&
                        result->reports.size() == shapes && shapes > 0;
    if (source == nullptr || !source->hasInput()) {
        d->distanceMap = DistanceMap::Hidden;
    } else if (!usable) {
        d->distanceMap = DistanceMap::Measuring;
    } else {
        d->distanceMap = source->isCurrent() ? DistanceMap::Current : DistanceMap::Stale;
    }
    std::vector<const std::vector<double>*> distances;
    const bool colour =
        d->distanceMap == DistanceMap::Current || d->distanceMap == DistanceMap::Stale;
    if (colour) {
        d->distanceColouring.setRange(result->tolerance, result->largest);
        for (const model::reference::DistanceReport& report : result->reports) {
            distances.push_back(&report.targetDistances);
        }
    }
    // A frame only when colours changed: a large shape takes a while to draw, and a
    // measurement just started changes nothing in the scene, only the legend.
    if (d->scene->setReferenceColours(distances, colour ? &d->distanceColouring : nullptr,
                                      d->distanceMap == DistanceMap::Stale)) {
        rerender();
    }
    d->overlay->setDistanceLegend(distanceLegend());
}

SceneView::DistanceMap SceneView::distanceMap() const {
    return d->distanceMap;
}

std::pair<double, double> SceneView::distanceLegendRange() const {
    if (d->distanceMap != DistanceMap::Current && d->distanceMap != DistanceMap::Stale) {
        return {0.0, 0.0};
    }
    return {0.0, d->distanceColouring.high()};
}

double SceneView::distanceLegendTolerance() const {
    return distanceLegendRange().second > 0.0 ? d->distanceColouring.tolerance() : 0.0;
}

QRect SceneView::distanceLegendRect() const {
    return d->overlay->distanceLegendRect().toAlignedRect();
}

QColor SceneView::referencePointColour(int shape, int point) const {
    return d->scene->referencePointColour(shape, point);
}

QColor SceneView::distanceColour(double millimetres) const {
    return distanceLegendRange().second > 0.0 ? d->distanceColouring.colour(millimetres) : QColor();
}

std::optional<DistanceLegend> SceneView::distanceLegend() const {
    if (d->distanceMap == DistanceMap::Hidden || !d->scene->showsReferenceShapes()) {
        return std::nullopt;
    }
    DistanceLegend legend;
    legend.title = tr("Distance to design\n(mm)");
    legend.toleranceLabel = tr("covered");
    if (d->distanceMap == DistanceMap::Measuring) {
        legend.note = tr("Measuring…");
        return legend;
    }
    legend.colours = d->distanceColouring.colours();
    legend.high = d->distanceColouring.high();
    legend.tolerance = d->distanceColouring.tolerance();
    if (d->distanceMap == DistanceMap::Stale) {
        legend.note = tr("Updating…");
        legend.stale = true;
    }
    return legend;
}

} // namespace devsurf::views
