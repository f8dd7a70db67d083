#include "solver/formulation/curve_pairing.h"

#include "model/bspline_curve.h"
#include "model/strip_joining.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace devsurf::solver {

namespace {

// Closest-point search: samples per interval for the start, then Newton steps on t.
constexpr int kPairingStartSamples = 16;
constexpr int kNewtonSteps = 20;
// t this close to 0 or 1 is an end of the curve.
constexpr double kEnd = 1e-9;

// The intervals of a paired curve: an R-edge is a straight segment of one.
int intervalsOf(const model::CompositeSurface& surface, model::EdgeId edge) {
    const model::EdgeRecord& record = surface.edge(edge);
    return record.isSpline() ? record.space.intervals : 1;
}

// The parameter of the point of `curve` nearest p: the nearest of dense samples, refined by
// Newton's method on ⟨c(t) − p, c′(t)⟩ = 0 within [0, 1].
double closestParameter(const model::BSplineCurve& curve, int intervals, const model::Vec3& p) {
    const int count = kPairingStartSamples * intervals;
    double best = 0.0;
    double bestDistance = 1e300;
    for (int i = 0; i <= count; ++i) {
        const double t = static_cast<double>(i) / count;
        const double d = (curve.evaluate(t) - p).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = t;
        }
    }
    double t = best;
    for (int step = 0; step < kNewtonSteps; ++step) {
        const model::Vec3 gap = curve.evaluate(t) - p;
        const model::Vec3 d1 = curve.derivative(t, 1);
        const model::Vec3 d2 = curve.derivative(t, 2);
        const double slope = dot(gap, d1);
        const double curvature = dot(d1, d1) + dot(gap, d2);
        if (!(curvature > 0.0)) {
            break;
        }
        const double next = std::clamp(t - slope / curvature, 0.0, 1.0);
        if (std::abs(next - t) < 1e-15) {
            t = next;
            break;
        }
        t = next;
    }
    return t;
}

} // namespace

CurvePairingFit::CurvePairingFit(const model::CompositeSurface& surface,
                                 std::vector<CurvePair> pairs,
                                 std::vector<PairedCurveColumns> curves, int samplesPerInterval)
    : m_pairs(std::move(pairs)), m_curves(std::move(curves)) {
    if (m_curves.size() != 2 * m_pairs.size()) {
        throw std::invalid_argument("curve pairing: two curves per pair");
    }
    int size = 0;
    for (std::size_t c = 0; c < m_curves.size(); ++c) {
        const std::size_t other = c % 2 == 0 ? c + 1 : c - 1;
        const int intervals = intervalsOf(surface, m_curves[c].edge);
        const int count = std::max(1, samplesPerInterval * intervals);
        for (int k = 0; k <= count; ++k) {
            Sample sample;
            sample.from = static_cast<int>(c);
            sample.onto = static_cast<int>(other);
            sample.u = static_cast<double>(k) / count;
            sample.coefficients = size;
            size += static_cast<int>(m_curves[c].points.size() + m_curves[other].points.size());
            m_samples.push_back(sample);
        }
    }
    m_coefficients.assign(static_cast<std::size_t>(size), 0.0);
    refresh(surface);
}

void CurvePairingFit::refresh(const model::CompositeSurface& current) {
    std::vector<model::BSplineCurve> curves;
    for (const PairedCurveColumns& c : m_curves) {
        curves.push_back(model::edgeCurve(current, c.edge));
    }
    m_largestDistance = 0.0;
    for (Sample& sample : m_samples) {
        const model::BSplineCurve& from = curves[static_cast<std::size_t>(sample.from)];
        const model::BSplineCurve& onto = curves[static_cast<std::size_t>(sample.onto)];
        const int intervals =
            intervalsOf(current, m_curves[static_cast<std::size_t>(sample.onto)].edge);
        const model::Vec3 v = from.evaluate(sample.u);
        sample.t = closestParameter(onto, intervals, v);
        sample.atEnd = sample.t <= kEnd || sample.t >= 1.0 - kEnd;
        m_largestDistance = std::max(m_largestDistance, (onto.evaluate(sample.t) - v).norm());
        // P = I at an end, else I − T Tᵀ for the unit tangent T.
        model::Vec3 tangent = onto.derivative(sample.t, 1);
        const double length = tangent.norm();
        tangent = length > 0.0 && !sample.atEnd ? tangent / length : model::Vec3();
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) {
                sample.projector[3 * r + c] = (r == c ? 1.0 : 0.0) - tangent[r] * tangent[c];
            }
        }
        const std::size_t nFrom = m_curves[static_cast<std::size_t>(sample.from)].points.size();
        const std::size_t nOnto = m_curves[static_cast<std::size_t>(sample.onto)].points.size();
        double* basisFrom = m_coefficients.data() + sample.coefficients;
        double* basisOnto = basisFrom + nFrom;
        std::fill(basisFrom, basisOnto + nOnto, 0.0);
        const model::DeBoorRows rf = from.deBoorRows(sample.u);
        for (std::size_t i = 0; i < rf.indices.size(); ++i) {
            basisFrom[static_cast<std::size_t>(rf.indices[i])] += rf.point[i];
        }
        const model::DeBoorRows ro = onto.deBoorRows(sample.t);
        for (std::size_t i = 0; i < ro.indices.size(); ++i) {
            basisOnto[static_cast<std::size_t>(ro.indices[i])] += ro.point[i];
        }
    }
}

void CurvePairingTerm::buildPattern(PatternBuilder& builder) const {
    for (const CurvePairingFit::Sample& sample : m_fit.samples()) {
        const auto& from = m_fit.curves()[static_cast<std::size_t>(sample.from)].points;
        const auto& onto = m_fit.curves()[static_cast<std::size_t>(sample.onto)].points;
        for (int r = 0; r < 3; ++r) {
            builder.beginRow();
            for (int column : from) {
                builder.addColumns(column, 3);
            }
            for (int column : onto) {
                builder.addColumns(column, 3);
            }
        }
    }
}

void CurvePairingTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (const CurvePairingFit::Sample& sample : m_fit.samples()) {
        const auto& from = m_fit.curves()[static_cast<std::size_t>(sample.from)].points;
        const auto& onto = m_fit.curves()[static_cast<std::size_t>(sample.onto)].points;
        const double* basisFrom = m_fit.coefficients(sample);
        const double* basisOnto = basisFrom + from.size();
        double gap[3] = {0.0, 0.0, 0.0}; // v − b(t) at x
        for (std::size_t i = 0; i < from.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                gap[k] += basisFrom[i] * x[from[i] + k];
            }
        }
        for (std::size_t i = 0; i < onto.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                gap[k] -= basisOnto[i] * x[onto[i] + k];
            }
        }
        const double* P = sample.projector;
        for (int r = 0; r < 3; ++r) {
            *residuals++ = P[3 * r] * gap[0] + P[3 * r + 1] * gap[1] + P[3 * r + 2] * gap[2];
            for (std::size_t i = 0; i < from.size(); ++i) {
                for (int k = 0; k < 3; ++k) {
                    *jacobian++ = P[3 * r + k] * basisFrom[i];
                }
            }
            for (std::size_t i = 0; i < onto.size(); ++i) {
                for (int k = 0; k < 3; ++k) {
                    *jacobian++ = -P[3 * r + k] * basisOnto[i];
                }
            }
        }
    }
}

FamilyId addCurvePairing(const CurvePairingFit& fit, double weight, Problem& problem) {
    const FamilyId id = problem.addFamily("curvePairing", TermRole::Constraint, weight);
    problem.setFamilyJudgedApart(id, true);
    problem.add(id, std::make_unique<CurvePairingTerm>(fit));
    return id;
}

} // namespace devsurf::solver
