#include "model/reference/strip_trim.h"

#include "model/reference/initial_strip.h"
#include "model/strip.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace devsurf::model::reference {

OverhangMeasure::OverhangMeasure(std::vector<Vec3> points, std::vector<Vec3> normals, double rho)
    : m_index(std::move(points)), m_normals(std::move(normals)), m_rho(rho) {
    if (m_index.empty()) {
        throw std::invalid_argument("an overhang needs reference points");
    }
    if (m_normals.size() != m_index.size()) {
        throw std::invalid_argument("give one normal per point");
    }
    if (!(rho >= 0.0) || !std::isfinite(rho)) {
        throw std::invalid_argument("the spacing must be a finite number of at least 0");
    }
}

double OverhangMeasure::operator()(const Vec3& p) const {
    const PointIndex::Neighbour n = m_index.nearest(p);
    const Vec3 d = p - m_index.points()[n.index];
    const Vec3& m = m_normals[n.index];
    const double along = dot(d, m);
    const double sideways = (d - m * along).norm();
    const double beyond = std::max(0.0, sideways - m_rho);
    return std::sqrt(along * along + beyond * beyond);
}

namespace {

// The only strip of a surface of one SRSR face, or nullopt.
std::optional<Strip> onlyStrip(const CompositeSurface& surface) {
    if (surface.faces().size() != 1) {
        return std::nullopt;
    }
    const FaceId face = surface.faces().begin()->first;
    if (surface.faceType(face) != FaceType::StripSRSR) {
        return std::nullopt;
    }
    return stripOfFace(surface, face);
}

} // namespace

std::optional<StripTrim> overhangTrim(const CompositeSurface& surface,
                                      const OverhangMeasure& overhang, double tolerance) {
    const std::optional<Strip> strip = onlyStrip(surface);
    if (!strip) {
        return std::nullopt;
    }
    constexpr double du = 1.0 / kTrimStepsAlong;
    constexpr double dw = 1.0 / kTrimStepsAcross;
    constexpr int n = kTrimSamples;
    const auto sample = [&](double u, double w) { return overhang(strip->point(u, w)); };
    StripTrim trim;
    // The mean overhang of the sliver a cut removes: along an end, its ruling segment; across,
    // the line the cut turns about its other end, each point weighted by the sliver's
    // thickness there.
    const auto endMean = [&](double t) {
        const double u = trim.u(t);
        double sum = 0.0;
        for (int k = 0; k < n; ++k) {
            const double f = static_cast<double>(k) / (n - 1);
            sum += sample(u, trim.low(t) + (trim.high(t) - trim.low(t)) * f);
        }
        return sum / n;
    };
    const auto lineMean = [&](bool high, int end) {
        double sum = 0.0;
        double weights = 0.0;
        for (int k = 0; k < n; ++k) {
            const double t = static_cast<double>(k) / (n - 1);
            const double weight = end == 0 ? 1.0 - t : t;
            sum += weight * sample(trim.u(t), high ? trim.high(t) : trim.low(t));
            weights += weight;
        }
        return sum / weights;
    };
    const double keep = kTrimKeep - 1e-9;
    for (;;) {
        struct Cut {
            double mean;
            double* value;
            double step;
        };
        std::vector<Cut> cuts;
        if (trim.u1 - trim.u0 - du >= keep) {
            cuts.push_back({endMean(0.0), &trim.u0, du});
            cuts.push_back({endMean(1.0), &trim.u1, -du});
        }
        for (int end : {0, 1}) {
            if (trim.w1[end] - trim.w0[end] - dw >= keep) {
                cuts.push_back({lineMean(false, end), &trim.w0[end], dw});
                cuts.push_back({lineMean(true, end), &trim.w1[end], -dw});
            }
        }
        const auto worst = std::max_element(
            cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.mean < b.mean; });
        if (worst == cuts.end() || !(worst->mean > tolerance)) {
            break;
        }
        *worst->value += worst->step;
    }
    return trim;
}

CompositeSurface trimmedStrip(const CompositeSurface& surface, const StripTrim& trim) {
    const std::optional<Strip> strip = onlyStrip(surface);
    if (!strip) {
        throw std::invalid_argument("only a surface of one strip can be trimmed");
    }
    const auto inUnit = [](double x) { return 0.0 <= x && x <= 1.0; };
    if (!(inUnit(trim.u0) && inUnit(trim.u1) && trim.u0 < trim.u1) ||
        !(inUnit(trim.w0[0]) && inUnit(trim.w0[1]) && inUnit(trim.w1[0]) && inUnit(trim.w1[1]) &&
          trim.w0[0] < trim.w1[0] && trim.w0[1] < trim.w1[1])) {
        throw std::invalid_argument("the trim must keep part of [0, 1] × [0, 1]");
    }
    const SplineSpace& space = surface.edge(strip->aSide.edge).space;
    const std::vector<Vec3> aPoints =
        fitControlPoints(space, [&](double t) { return strip->point(trim.u(t), trim.low(t)); });
    const std::vector<Vec3> bPoints =
        fitControlPoints(space, [&](double t) { return strip->point(trim.u(t), trim.high(t)); });
    // As the initial strips: the normal a′ × (b − a) as before.
    return stripOfCurves(surface.name(), space, aPoints, bPoints);
}

} // namespace devsurf::model::reference
