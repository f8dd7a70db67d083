#include "dashed_line.h"

#include <QLineF>

#include <numeric>

namespace devsurf::io {

DashedLine dashLine(const QPolygonF& line, bool closed, const std::vector<double>& pattern) {
    DashedLine out;
    QPolygonF points = line;
    if (closed && !points.isEmpty()) {
        points << points.front();
    }
    const double period = std::accumulate(pattern.begin(), pattern.end(), 0.0);
    if (pattern.size() < 2 || !(period > 0.0)) {
        out.dashes.push_back(points);
        return out;
    }
    std::size_t entry = 0;         // the pattern entry in force; even: on
    double left = pattern.front(); // of that entry
    QPolygonF dash;
    auto on = [&entry] { return entry % 2 == 0; };
    // Moves to the next entry at `at`: ends or starts a dash, or puts a dot.
    auto advance = [&](const QPointF& at) {
        if (on()) {
            if (pattern[entry] <= 0.0) {
                out.dots.push_back(at);
            } else {
                dash << at;
                out.dashes.push_back(dash);
                dash.clear();
            }
        }
        entry = (entry + 1) % pattern.size();
        left = pattern[entry];
        if (on() && pattern[entry] > 0.0) {
            dash << at;
        }
    };
    if (!points.isEmpty() && pattern.front() > 0.0) {
        dash << points.front();
    }
    for (int i = 1; i < points.size(); ++i) {
        const QLineF segment(points[i - 1], points[i]);
        const double length = segment.length();
        double done = 0.0;
        // Every pattern entry that ends on this segment; a dot ends where it starts.
        while (length - done >= left) {
            done += left;
            advance(segment.pointAt(length > 0.0 ? done / length : 0.0));
        }
        left -= length - done;
        if (on() && !dash.isEmpty() && dash.back() != points[i]) {
            dash << points[i];
        }
    }
    if (dash.size() >= 2) {
        out.dashes.push_back(dash);
    }
    return out;
}

} // namespace devsurf::io
