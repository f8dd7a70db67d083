#include "solver/formulation/approximation_terms.h"

#include "model/reference/closest_point.h"
#include "model/reference/point_index.h"
#include "model/reference/surface_samples.h"
#include "model/strip.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace devsurf::solver {

namespace {

// Samples per spline interval for the start of the closest-point search.
constexpr int kClosestStartSamples = 8;
// (u, v) this close to 0 or 1 lie on the border of the strip.
constexpr double kBorder = 1e-9;
// Above this many points, the weights shrink as 1/√points (ApproximationWeights).
constexpr double kWeightedPoints = 100.0;

int stripSize(const ApproximatedStrip& s, int normals) {
    return 2 * static_cast<int>(s.a.size()) + static_cast<int>(s.b.size()) + normals;
}

} // namespace

ApproximationFit::ApproximationFit(const model::CompositeSurface& surface,
                                   const ApproximationTarget& target,
                                   std::vector<ApproximatedStrip> strips, const model::Vec3& centre,
                                   double scale)
    : m_strips(std::move(strips)), m_centre(centre), m_scale(scale),
      m_borderReach(target.borderReach), m_falloff(target.falloff) {
    if (m_strips.empty() || target.points.empty()) {
        return;
    }
    std::map<model::FaceId, int> stripOf;
    for (std::size_t i = 0; i < m_strips.size(); ++i) {
        stripOf[m_strips[i].face] = static_cast<int>(i);
    }
    // Each point to the strip of its nearest sample.
    const model::reference::SurfaceSamples samples =
        model::reference::sampleDensely({surface}, kClosestStartSamples);
    const model::reference::PointIndex index(samples.positions);
    int size = 0;
    for (std::size_t j = 0; j < target.points.size(); ++j) {
        const auto nearest = index.nearest(target.points[j]);
        const model::FaceId face = samples.pieces[samples.piece[nearest.index]].face;
        const auto it = stripOf.find(face);
        if (it == stripOf.end()) {
            continue;
        }
        Foot foot;
        foot.strip = it->second;
        foot.q = (target.points[j] - m_centre) / m_scale;
        const model::Vec3 m = j < target.normals.size() ? target.normals[j] : model::Vec3();
        const double length = m.norm();
        foot.m = length > 0.0 ? m / length : m;
        foot.coefficients = size;
        size += stripSize(m_strips[static_cast<std::size_t>(foot.strip)], normalCount(foot.strip));
        m_feet.push_back(foot);
        m_modelPoints.push_back(target.points[j]);
    }
    m_coefficients.assign(static_cast<std::size_t>(size), 0.0);
    refresh(surface);
}

std::size_t ApproximationFit::pullingCount() const {
    return static_cast<std::size_t>(std::count_if(
        m_feet.begin(), m_feet.end(), [](const Foot& foot) { return foot.weight > 1e-6; }));
}

void ApproximationFit::refresh(const model::CompositeSurface& current) {
    if (m_feet.empty()) {
        return;
    }
    const model::reference::SurfaceSamples samples =
        model::reference::sampleDensely({current}, kClosestStartSamples);
    // Per strip: its samples and a KD-tree on them.
    struct StripSamples {
        model::Strip strip;
        std::vector<std::size_t> sample;
        std::unique_ptr<model::reference::PointIndex> index;
    };
    std::vector<StripSamples> perStrip(m_strips.size());
    std::map<model::FaceId, std::size_t> stripOf;
    for (std::size_t s = 0; s < m_strips.size(); ++s) {
        perStrip[s].strip = model::stripOfFace(current, m_strips[s].face);
        stripOf[m_strips[s].face] = s;
    }
    // One pass over the samples, each to its strip.
    std::vector<std::vector<model::Vec3>> positions(m_strips.size());
    for (std::size_t i = 0; i < samples.positions.size(); ++i) {
        const auto it = stripOf.find(samples.pieces[samples.piece[i]].face);
        if (it != stripOf.end()) {
            perStrip[it->second].sample.push_back(i);
            positions[it->second].push_back(samples.positions[i]);
        }
    }
    for (std::size_t s = 0; s < m_strips.size(); ++s) {
        perStrip[s].index = std::make_unique<model::reference::PointIndex>(std::move(positions[s]));
    }
    for (std::size_t j = 0; j < m_feet.size(); ++j) {
        Foot& foot = m_feet[j];
        const StripSamples& on = perStrip[static_cast<std::size_t>(foot.strip)];
        const ApproximatedStrip& columns = m_strips[static_cast<std::size_t>(foot.strip)];
        const model::Vec3& q = m_modelPoints[j];
        const std::size_t start = on.sample[on.index->nearest(q).index];
        const model::reference::ClosestPoint closest =
            model::reference::closestPointOnStrip(on.strip, q, samples.u[start], samples.v[start]);
        foot.u = closest.u;
        foot.v = closest.v;
        const bool border = foot.u <= kBorder || foot.u >= 1.0 - kBorder || foot.v <= kBorder ||
                            foot.v >= 1.0 - kBorder;
        if (!border) {
            const double d = m_falloff > 0.0 ? closest.distance / m_falloff : 0.0;
            foot.weight = 1.0 / (1.0 + d * d);
        } else if (m_borderReach > 0.0) {
            const double d = closest.distance / m_borderReach;
            foot.weight = std::exp(-d * d);
        } else {
            foot.weight = 0.0;
        }
        // pa, pb: the basis at u of a and b; da: of a′; cn: of the normal spline.
        const std::size_t na = columns.a.size();
        const std::size_t nb = columns.b.size();
        double* pa = m_coefficients.data() + foot.coefficients;
        double* pb = pa + na;
        double* da = pb + nb;
        double* cn = da + na;
        std::fill(pa, cn + normalCount(foot.strip), 0.0);
        const model::DeBoorRows ra = on.strip.a.deBoorRows(foot.u);
        for (std::size_t i = 0; i < ra.indices.size(); ++i) {
            const auto k = static_cast<std::size_t>(ra.indices[i]);
            pa[k] += ra.point[i];
            da[k] +=
                ra.firstDerivativeScale * (ra.firstDerivative[1][i] - ra.firstDerivative[0][i]);
        }
        const model::DeBoorRows rb = on.strip.b.deBoorRows(foot.u);
        for (std::size_t i = 0; i < rb.indices.size(); ++i) {
            pb[static_cast<std::size_t>(rb.indices[i])] += rb.point[i];
        }
        const model::DeBoorRows rn = columns.normalCurve.deBoorRows(foot.u);
        for (std::size_t i = 0; i < rn.indices.size(); ++i) {
            cn[static_cast<std::size_t>(rn.indices[i])] += rn.point[i];
        }
    }
}

ApproximationTerm::ApproximationTerm(const ApproximationFit& fit, Equation equation)
    : m_fit(fit), m_equation(equation) {}

int ApproximationTerm::rowCount() const {
    const int perPoint = m_equation == Equation::Position   ? 3
                         : m_equation == Equation::Tangency ? 2
                                                            : 1;
    return perPoint * static_cast<int>(m_fit.pointCount());
}

void ApproximationTerm::buildPattern(PatternBuilder& builder) const {
    for (const ApproximationFit::Foot& foot : m_fit.feet()) {
        const ApproximatedStrip& s = m_fit.strips()[static_cast<std::size_t>(foot.strip)];
        switch (m_equation) {
        case Equation::Position:
            for (int k = 0; k < 3; ++k) {
                builder.beginRow();
                for (int column : s.a) {
                    builder.addColumn(column + k);
                }
                for (int column : s.b) {
                    builder.addColumn(column + k);
                }
            }
            break;
        case Equation::Tangency:
            builder.beginRow();
            for (int column : s.a) {
                builder.addColumns(column, 3);
            }
            for (int column : s.b) {
                builder.addColumns(column, 3);
            }
            builder.beginRow();
            for (int column : s.a) {
                builder.addColumns(column, 3);
            }
            break;
        case Equation::NormalDistance:
            builder.beginRow();
            for (int column : s.a) {
                builder.addColumns(column, 3);
            }
            for (int column : s.b) {
                builder.addColumns(column, 3);
            }
            break;
        }
    }
}

void ApproximationTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (const ApproximationFit::Foot& foot : m_fit.feet()) {
        const ApproximatedStrip& s = m_fit.strips()[static_cast<std::size_t>(foot.strip)];
        const std::size_t na = s.a.size();
        const std::size_t nb = s.b.size();
        const int nn = m_fit.normalCount(foot.strip);
        const double* pa = m_fit.coefficients(foot);
        const double* pb = pa + na;
        const double* da = pb + nb;
        const double* cn = da + na;
        const double w = foot.weight;
        // a(u), b(u), a′(u) at the current state.
        double a[3] = {0.0, 0.0, 0.0};
        double b[3] = {0.0, 0.0, 0.0};
        double d[3] = {0.0, 0.0, 0.0};
        for (std::size_t i = 0; i < na; ++i) {
            for (int k = 0; k < 3; ++k) {
                a[k] += pa[i] * x[s.a[i] + k];
                d[k] += da[i] * x[s.a[i] + k];
            }
        }
        for (std::size_t i = 0; i < nb; ++i) {
            for (int k = 0; k < 3; ++k) {
                b[k] += pb[i] * x[s.b[i] + k];
            }
        }
        const double v = foot.v;
        double gap[3]; // s(u, v) − q
        for (int k = 0; k < 3; ++k) {
            gap[k] = (1.0 - v) * a[k] + v * b[k] - foot.q[k];
        }
        switch (m_equation) {
        case Equation::Position: // (9)
            for (int k = 0; k < 3; ++k) {
                *residuals++ = w * gap[k];
                for (std::size_t i = 0; i < na; ++i) {
                    *jacobian++ = w * (1.0 - v) * pa[i];
                }
                for (std::size_t i = 0; i < nb; ++i) {
                    *jacobian++ = w * v * pb[i];
                }
            }
            break;
        case Equation::Tangency: { // (10)
            double across = 0.0;
            double along = 0.0;
            for (int k = 0; k < 3; ++k) {
                across += foot.m[k] * (a[k] - b[k]);
                along += foot.m[k] * d[k];
            }
            *residuals++ = w * across;
            for (std::size_t i = 0; i < na; ++i) {
                for (int k = 0; k < 3; ++k) {
                    *jacobian++ = w * foot.m[k] * pa[i];
                }
            }
            for (std::size_t i = 0; i < nb; ++i) {
                for (int k = 0; k < 3; ++k) {
                    *jacobian++ = -w * foot.m[k] * pb[i];
                }
            }
            *residuals++ = w * along;
            for (std::size_t i = 0; i < na; ++i) {
                for (int k = 0; k < 3; ++k) {
                    *jacobian++ = w * foot.m[k] * da[i];
                }
            }
            break;
        }
        case Equation::NormalDistance: { // (11)
            // n(u_j) at x, as a unit vector and held fixed in the step (see the header).
            double n[3] = {0.0, 0.0, 0.0};
            for (int j = 0; j < nn; ++j) {
                for (int k = 0; k < 3; ++k) {
                    n[k] += cn[j] * x[s.normalOffset + 3 * j + k];
                }
            }
            const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (double& c : n) {
                c = length > 0.0 ? c / length : 0.0;
            }
            *residuals++ = w * (gap[0] * n[0] + gap[1] * n[1] + gap[2] * n[2]);
            for (std::size_t i = 0; i < na; ++i) {
                for (int k = 0; k < 3; ++k) {
                    *jacobian++ = w * (1.0 - v) * pa[i] * n[k];
                }
            }
            for (std::size_t i = 0; i < nb; ++i) {
                for (int k = 0; k < 3; ++k) {
                    *jacobian++ = w * v * pb[i] * n[k];
                }
            }
            break;
        }
        }
    }
}

std::vector<FamilyId> addApproximation(const ApproximationFit& fit,
                                       const ApproximationWeights& weights, Problem& problem) {
    if (fit.pointCount() == 0) {
        return {};
    }
    const double points = static_cast<double>(fit.pointCount());
    const double density = points > kWeightedPoints ? std::sqrt(kWeightedPoints / points) : 1.0;
    const struct {
        const char* name;
        double weight;
        ApproximationTerm::Equation equation;
    } families[] = {
        {"approximationPosition", weights.position, ApproximationTerm::Equation::Position},
        {"approximationTangency", weights.tangency, ApproximationTerm::Equation::Tangency},
        {"approximationNormal", weights.normalDistance,
         ApproximationTerm::Equation::NormalDistance},
    };
    std::vector<FamilyId> ids;
    for (const auto& family : families) {
        const FamilyId id =
            problem.addFamily(family.name, TermRole::Constraint, density * family.weight);
        problem.setFamilyJudgedApart(id, true);
        problem.add(id, std::make_unique<ApproximationTerm>(fit, family.equation));
        ids.push_back(id);
    }
    return ids;
}

} // namespace devsurf::solver
