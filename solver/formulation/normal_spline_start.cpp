#include "solver/formulation/normal_spline_start.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace devsurf::solver {

using model::Vec3;

namespace {

// The least-squares linear field p + u q to the rows of `unit` at `samples`, evaluated at the
// samples into `linear`. False if the field comes closer to zero than kLinearStartNormalMinimum
// on [0, 1] (the sampled normals spread too far for one linear field to stand for them).
bool linearField(const std::vector<double>& samples, const Eigen::MatrixXd& unit,
                 Eigen::MatrixXd& linear) {
    Eigen::MatrixXd values(unit.rows(), 2);
    for (Eigen::Index r = 0; r < unit.rows(); ++r) {
        values(r, 0) = 1.0;
        values(r, 1) = samples[static_cast<std::size_t>(r)];
    }
    const Eigen::MatrixXd pq =
        (values.transpose() * values).ldlt().solve(values.transpose() * unit);
    const Eigen::RowVectorXd p = pq.row(0);
    const Eigen::RowVectorXd q = pq.row(1);
    // The point of the segment p + u q, u ∈ [0, 1], nearest to zero.
    const double t =
        q.squaredNorm() > 0.0 ? std::clamp(-p.dot(q) / q.squaredNorm(), 0.0, 1.0) : 0.0;
    if (!((p + t * q).norm() >= kLinearStartNormalMinimum)) {
        return false;
    }
    linear = values * pq;
    return true;
}

} // namespace

Vec3 initialStripNormal(const model::Strip& strip, double u) {
    const Vec3 tangent = strip.a.derivative(u, 1);
    Vec3 n = cross(tangent, strip.bPoint(u) - strip.aPoint(u));
    if (n.norm() < 1e-12 * (1.0 + tangent.squaredNorm()) && !strip.isCone()) {
        n = cross(tangent, strip.b.derivative(u, 1)); // a collapsed ruling (SRS end)
    }
    const double length = n.norm();
    return length > 0.0 ? n / length : n;
}

model::SplineSpace normalSplineSpace(const model::SplineSpace& curves, bool exact) {
    if (!exact) {
        return {3, 2, curves.intervals};
    }
    return {2 * curves.degree - 1, std::max(0, curves.smoothness - 1), curves.intervals};
}

bool isDevelopableStart(const model::Strip& strip, double limit) {
    if (strip.isCone()) {
        return true;
    }
    std::vector<double> breaks = strip.a.knots();
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const int count = 50 * std::max(1, static_cast<int>(breaks.size()) - 1);
    for (int i = 0; i <= count; ++i) {
        const double u = static_cast<double>(i) / count;
        Vec3 a;
        Vec3 ta;
        Vec3 b;
        Vec3 tb;
        strip.a.pointAndTangent(u, a, ta);
        strip.b.pointAndTangent(u, b, tb);
        const Vec3 d = a - b;
        if (std::abs(det(d, ta, tb)) > limit * d.norm() * ta.norm() * tb.norm()) {
            return false;
        }
    }
    return true;
}

std::vector<Vec3> fitStartNormals(const model::Strip& strip, const model::BSplineCurve& normalCurve,
                                  const std::vector<double>& samples, bool developable,
                                  bool linearIfNoisy) {
    const int controls = static_cast<int>(normalCurve.controlPoints().size());
    // Least squares fit to N(u) = a′ × (b − a) at the samples. If N itself lies in the normal
    // spline's space (always in the exact space, see FormulationOptions::exactNormalSpace) its
    // exact fit, scaled to unit length at u = 0 (at u = 1 if u = 0 is the tip of an SRS face,
    // where N vanishes), is kept and a developable strip stays put. Otherwise the unit field N/|N|
    // is fitted: it gives every row of (4) the same scale from the start, whereas on a noisy start
    // |N| varies by orders of magnitude along a strip and fitting N made the first steps large
    // where |N| is large (measured: 10× the initial residual).
    std::vector<Vec3> field;
    double typical = 0.0;
    for (double u : samples) {
        field.push_back(cross(strip.a.derivative(u, 1), strip.bPoint(u) - strip.aPoint(u)));
        typical = std::max(typical, field.back().norm());
    }
    const auto rowCount = static_cast<Eigen::Index>(samples.size());
    Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(rowCount, controls);
    Eigen::MatrixXd unitField(rowCount, 3);
    Eigen::MatrixXd scaledField(rowCount, 3); // N / |N(end)|
    // |n| = 1 at u = 0, or at u = 1 where N nearly vanishes at u = 0 (as the formulation's
    // unit row does).
    const double atStart = field[field.size() - 2].norm();
    const double atEnd = field[field.size() - 1].norm();
    const double endLength = atStart >= 1e-3 * atEnd ? atStart : atEnd;
    // Only a developable start keeps N itself: on a rough start |N| varies by orders of
    // magnitude along a strip and fitting N made the first steps large where |N| is large
    // (measured: 10× the initial residual, and worse convergence in the exact space).
    const bool exactPossible = developable && typical > 0.0 && endLength > 1e-9 * typical;
    for (std::size_t s = 0; s < samples.size(); ++s) {
        const auto row = static_cast<Eigen::Index>(s);
        const model::DeBoorRows rows = normalCurve.deBoorRows(samples[s]);
        for (std::size_t i = 0; i < rows.indices.size(); ++i) {
            basis(row, rows.indices[i]) += rows.point[i];
        }
        // A degenerate sample (a collapsed ruling) gets a unit normal from a′ × b′.
        const bool regular = field[s].norm() > 1e-9 * typical;
        const Vec3 unit =
            regular ? field[s] / field[s].norm() : initialStripNormal(strip, samples[s]);
        for (int k = 0; k < 3; ++k) {
            unitField(row, k) = unit[k];
            scaledField(row, k) = exactPossible ? field[s][k] / endLength : 0.0;
        }
    }
    const Eigen::MatrixXd normal =
        basis.transpose() * basis + 1e-12 * Eigen::MatrixXd::Identity(controls, controls);
    const Eigen::LDLT<Eigen::MatrixXd> factor = normal.ldlt();
    Eigen::MatrixXd fitted;
    bool exactFit = false;
    if (exactPossible) {
        fitted = factor.solve(basis.transpose() * scaledField);
        const double misfit = (basis * fitted - scaledField).cwiseAbs().maxCoeff();
        exactFit = misfit <= 1e-9 * scaledField.cwiseAbs().maxCoeff();
    }
    if (!exactFit) {
        fitted = factor.solve(basis.transpose() * unitField);
        // Noise (kNoisyStartNormals): the best linear field instead.
        Eigen::MatrixXd linear;
        if (linearIfNoisy &&
            (basis * fitted - unitField).squaredNorm() >=
                kNoisyStartNormals * kNoisyStartNormals * static_cast<double>(rowCount) &&
            linearField(samples, unitField, linear)) {
            fitted = factor.solve(basis.transpose() * linear);
        }
    }
    std::vector<Vec3> result;
    for (int i = 0; i < controls; ++i) {
        result.emplace_back(fitted(i, 0), fitted(i, 1), fitted(i, 2));
    }
    return result;
}

} // namespace devsurf::solver
