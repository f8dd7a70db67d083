#pragma once

#include "io/project_file.h"
#include "model/document/document.h"
#include "model/strip.h"

#include <QByteArray>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

// Helpers shared by the document tests. The geometric comparison does not use any code under
// test: it measures distances from sample points to ruling segments directly.
#include "model/document/commands/command_or_error.h"

#include <QUndoCommand>

namespace devsurf::test {

// The examples the command tests run every edit on.
inline constexpr const char* kExamples[] = {"sheet", "annulus", "cylinder", "mixed"};

// The first face of the given type (kInvalidId if none).
inline model::FaceId firstFaceOfType(const model::CompositeSurface& s, model::FaceType type) {
    for (const auto& [id, loop] : s.faces()) {
        if (s.faceType(id) == type) {
            return id;
        }
    }
    return model::kInvalidId;
}

inline std::string bytesOf(const document::Document& doc) {
    return io::encodeProject(doc.project());
}

inline std::string firstProblem(const model::CompositeSurface& s) {
    const auto problems = s.validate();
    return problems.empty() ? std::string() : model::technicalKey(problems.front());
}

// Pushes the edit; empty when it was pushed, otherwise the refusal's heading and the technical
// key of its problem (the application words it, app/gui/edit_refusal.h).
inline QString pushOrExplain(document::Document& doc, document::CommandOrError result) {
    if (document::push(doc, result)) {
        return QString();
    }
    QString text = result.error().isEmpty() ? QStringLiteral("refused") : result.error();
    if (result.problem()) {
        text +=
            QStringLiteral(": ") + QString::fromStdString(model::technicalKey(*result.problem()));
    }
    return text;
}

inline double pointSegmentDistance(const model::Vec3& p, const model::Vec3& a,
                                   const model::Vec3& b) {
    const model::Vec3 d = b - a;
    const double len2 = d.squaredNorm();
    double s = len2 > 0 ? model::dot(p - a, d) / len2 : 0.0;
    s = std::clamp(s, 0.0, 1.0);
    return (p - (a + d * s)).norm();
}

struct StripBox {
    model::Strip strip;
    model::Vec3 lo;
    model::Vec3 hi;
    int intervals = 1;
};

inline std::vector<StripBox> boxesOf(const model::CompositeSurface& s) {
    std::vector<StripBox> boxes;
    for (model::Strip& strip : model::stripsOf(s)) {
        StripBox box;
        box.lo = model::Vec3(1e300, 1e300, 1e300);
        box.hi = -box.lo;
        auto grow = [&box](const model::Vec3& p) {
            for (int i = 0; i < 3; ++i) {
                box.lo[i] = std::min(box.lo[i], p[i]);
                box.hi[i] = std::max(box.hi[i], p[i]);
            }
        };
        for (const model::Vec3& p : strip.a.controlPoints()) {
            grow(p);
        }
        if (strip.isCone()) {
            grow(strip.apex);
        } else {
            for (const model::Vec3& p : strip.b.controlPoints()) {
                grow(p);
            }
        }
        box.intervals = static_cast<int>(strip.a.knots().size());
        box.strip = std::move(strip);
        boxes.push_back(std::move(box));
    }
    return boxes;
}

// Distance from p to the union of the strips' and cones' surfaces: a dense scan over the rulings
// u = const and a golden-section refinement around the closest one.
inline double distanceToStrips(const std::vector<StripBox>& boxes, const model::Vec3& p,
                               double slack) {
    double best = std::numeric_limits<double>::infinity();
    for (const StripBox& box : boxes) {
        bool inside = true;
        for (int i = 0; i < 3; ++i) {
            inside = inside && p[i] >= box.lo[i] - slack && p[i] <= box.hi[i] + slack;
        }
        if (!inside) {
            continue;
        }
        const model::Strip& s = box.strip;
        auto g = [&](double u) { return pointSegmentDistance(p, s.aPoint(u), s.bPoint(u)); };
        const int scan = 16 * box.intervals;
        int bestK = 0;
        double bestG = g(0.0);
        for (int k = 1; k <= scan; ++k) {
            const double value = g(static_cast<double>(k) / scan);
            if (value < bestG) {
                bestG = value;
                bestK = k;
            }
        }
        double lo = std::max(0.0, static_cast<double>(bestK - 1) / scan);
        double hi = std::min(1.0, static_cast<double>(bestK + 1) / scan);
        const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
        for (int it = 0; it < 90; ++it) {
            const double x1 = hi - ratio * (hi - lo);
            const double x2 = lo + ratio * (hi - lo);
            if (g(x1) < g(x2)) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        best = std::min({best, bestG, g(0.5 * (lo + hi))});
    }
    return best;
}

// The largest distance from samples of from's strips and cones to to's strips and cones.
inline double maxDeviation(const model::CompositeSurface& from, const model::CompositeSurface& to,
                           double slack, int samplesU = 9, int samplesV = 5) {
    const auto boxes = boxesOf(to);
    double worst = 0.0;
    for (const model::Strip& s : model::stripsOf(from)) {
        for (int i = 0; i <= samplesU; ++i) {
            for (int j = 0; j <= samplesV; ++j) {
                const double u = static_cast<double>(i) / samplesU;
                const double v = static_cast<double>(j) / samplesV;
                worst = std::max(worst, distanceToStrips(boxes, s.point(u, v), slack));
            }
        }
    }
    return worst;
}

inline double sizeOf(const model::CompositeSurface& s) {
    model::Vec3 lo(1e300, 1e300, 1e300);
    model::Vec3 hi = -lo;
    for (const auto& [id, p] : s.vertices()) {
        for (int i = 0; i < 3; ++i) {
            lo[i] = std::min(lo[i], p[i]);
            hi[i] = std::max(hi[i], p[i]);
        }
    }
    return (hi - lo).norm();
}

} // namespace devsurf::test
