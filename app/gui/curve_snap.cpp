#include "curve_snap.h"

#include "views/scene_view.h"

#include <QPointF>

#include <algorithm>
#include <cmath>

namespace devsurf::app {

std::optional<CurveSnap> snapToCurves(const views::SceneView& view,
                                      const std::vector<model::ReferenceCurve>& curves,
                                      const QPoint& widgetPos, double tolerance) {
    std::optional<CurveSnap> best;
    const QPointF p(widgetPos);
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const std::vector<model::Vec3>& points = curves[c].points;
        if (points.empty()) {
            continue;
        }
        QPointF a = view.projectToWidget(points.front());
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            const QPointF b = view.projectToWidget(points[i + 1]);
            const QPointF d = b - a;
            const double length2 = QPointF::dotProduct(d, d);
            const double s =
                length2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, d) / length2, 0.0, 1.0) : 0.0;
            const QPointF nearest = a + d * s;
            const double pixels = std::hypot(nearest.x() - p.x(), nearest.y() - p.y());
            if (pixels <= tolerance && (!best || pixels < best->pixels)) {
                best = CurveSnap{points[i] + (points[i + 1] - points[i]) * s, static_cast<int>(c),
                                 pixels};
            }
            a = b;
        }
    }
    return best;
}

} // namespace devsurf::app
