#pragma once

// Approximation of a reference shape (§4.2, eqs. 9–11; docs/math.md §6): fixed target points
// q_j with normals m_j pull the strips of a surface towards them through their closest points
// s(u_j, v_j), which are found again before every iteration.

#include "model/bspline_curve.h"
#include "model/composite_surface.h"
#include "solver/core/problem.h"
#include "solver/core/term.h"

#include <memory>
#include <optional>
#include <vector>

namespace devsurf::model::reference {
class OverhangMeasure;
}

namespace devsurf::solver {

// What a surface is pulled towards, in model coordinates: the thinned reference
// (model::reference::thinReference) or part of it.
struct ApproximationTarget {
    std::vector<model::Vec3> points;  // q_j
    std::vector<model::Vec3> normals; // m_j, unit, one per point (their sign does not matter)
    // A point whose closest point lies on the border of its strip (beyond the strip's edge)
    // pulls with weight exp(−(d/borderReach)²) at distance d (mm), so the strip grows by about
    // this much per iteration towards the uncovered reference (Fig. 11) while points far
    // beyond it (another part of the shape) do not drag it along. 0: such points do not pull.
    double borderReach = 0.0;
    // A point over the strip at distance d (mm) pulls with weight 1 / (1 + (d / falloff)²): far
    // points, which a flat start on a curved target has many of, pull less, so the first
    // linearised steps stay near where they are valid, and every weight tends to 1 as the
    // strip reaches its points. Without it a flat start on a patch of the bunny jumped away
    // (residual 9 in the first iteration). 0: weight 1 whatever the distance.
    double falloff = 0.0;
    // Where the damped pull starts when the pull from the surface fails (solve_job.cpp): for
    // a strip the automatic path laid flat, the cylinder that fits its points best
    // (model::reference::initialCylinderStrip). The damped pull moves a strip only a little,
    // so where it starts is most of where it ends. None: from the surface itself.
    std::optional<model::CompositeSurface> dampedStart;
    // Where a strip the automatic path laid is trimmed back once pulled: the overhang of its
    // samples from the whole thinned target, and the mean overhang (mm) of a side beyond which
    // that side is cut (model::reference::overhangTrim; approximation_recipe.h). Null: never.
    std::shared_ptr<const model::reference::OverhangMeasure> overhang;
    double trimTolerance = 0.0;
};

// The weights of the three families (constraint roles judged apart, so that the largest
// constraint residual stays that of developability and the other hard conditions). (9) and
// (10) are low against (11), as in the paper: (9) held strictly forbids the strip to slide
// along the target and converges linearly (the closest points are refreshed only between
// iterations), while (11), the distance to the tangent plane, converges fast; (9) is still
// needed to keep the strip from sliding off the points. (10) uses the PCA normals m_j, which
// are biased where a ball is cut by the target's border, so it stays lowest. Each weight is
// divided by √(points / 100) for more than 100 points, so a dense target does not outweigh
// developability. Measured on a parabolic cylinder (tests/solver/tst_approximation.cpp, 30
// iterations and the fade; max target → surface distance / diameter): (9, 10, 11) = (1, 0, 1):
// 4e-5; (0.01, 0, 1): the strip slid off (0.2); (1, 0, 100): 1e-8; (0.1, 0, 10): 6e-9;
// (0.1, 0.01, 10): 2e-7; (0.1, 0.1, 1): 2e-4.
struct ApproximationWeights {
    double position = 0.1;        // (9) s(u_j, v_j) − q_j = 0
    double tangency = 0.01;       // (10) ⟨m_j, a(u_j) − b(u_j)⟩ = ⟨m_j, a′(u_j)⟩ = 0
    double normalDistance = 10.0; // (11) ⟨s(u_j, v_j) − q_j, n(u_j)⟩ = 0
};

// The columns of one strip in the state: its curves' control points in the order the strip
// traverses them (offsets of x-coordinates) and its normal spline.
struct ApproximatedStrip {
    model::FaceId face = model::kInvalidId;
    std::vector<int> a;
    std::vector<int> b;
    int normalOffset = 0;            // control normal k at normalOffset + 3 k
    model::BSplineCurve normalCurve; // its space (control points unused)
};

// The closest points of the target on the strips and the coefficients of eqs. (9)–(11) at
// them; the terms below read them. Each target point belongs to the strip nearest it when the
// fit is made (points nearest a cone or a planar face are left out) and keeps it.
class ApproximationFit {
public:
    // `centre` and `scale` map model coordinates to the state's: (p − centre) / scale.
    ApproximationFit(const model::CompositeSurface& surface, const ApproximationTarget& target,
                     std::vector<ApproximatedStrip> strips, const model::Vec3& centre,
                     double scale);

    // Projects every target point onto its strip of `current` (a KD-tree on dense samples for
    // the start, then Newton on (u, v)) and recomputes the coefficients and the weights.
    // `current` must have the combinatorics of the surface the fit was made for.
    void refresh(const model::CompositeSurface& current);

    std::size_t pointCount() const { return m_feet.size(); }
    // Points that pull at all in the last refresh (weight above 1e-6).
    std::size_t pullingCount() const;

    struct Foot {
        int strip = 0;
        model::Vec3 q; // state coordinates
        model::Vec3 m;
        double u = 0.0;
        double v = 0.0;
        double weight = 1.0;  // 1 inside the strip, less beyond its border
        int coefficients = 0; // into m_coefficients: pa(na) pb(nb) da(na) cn(nn)
    };
    const std::vector<Foot>& feet() const { return m_feet; }
    const std::vector<ApproximatedStrip>& strips() const { return m_strips; }
    const double* coefficients(const Foot& foot) const {
        return m_coefficients.data() + foot.coefficients;
    }
    int normalCount(int strip) const {
        return static_cast<int>(
            m_strips[static_cast<std::size_t>(strip)].normalCurve.controlPoints().size());
    }

private:
    std::vector<ApproximatedStrip> m_strips;
    std::vector<model::Vec3> m_modelPoints; // q_j in model coordinates, per foot
    std::vector<Foot> m_feet;
    std::vector<double> m_coefficients;
    model::Vec3 m_centre;
    double m_scale = 1.0;
    double m_borderReach = 0.0;
    double m_falloff = 0.0;
};

// The rows of one of eqs. (9)–(11) for every point of an ApproximationFit, each multiplied by
// the point's weight. Their columns are every control point of the point's strip, so the
// pattern stays fixed while (u_j, v_j) move. In (11) the normal n(u_j) is taken at the current
// iterate, scaled to unit length, and held fixed in the step, as the closest point is: the
// signed distance of q_j from the tangent plane. Bilinear in the control normals, (11) and (4)
// were both satisfied by shrinking the normal spline between its unit end (measured on a
// parabolic cylinder: solver residual 1e-7, sampled det 1.3e-2).
class ApproximationTerm : public Term {
public:
    enum class Equation {
        Position,      // (9): 3 rows
        Tangency,      // (10): 2 rows
        NormalDistance // (11): 1 row
    };
    ApproximationTerm(const ApproximationFit& fit, Equation equation);

    const char* typeName() const override { return "ApproximationTerm"; }
    int rowCount() const override;
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;

private:
    const ApproximationFit& m_fit;
    Equation m_equation;
};

// Appends the families "approximationPosition", "approximationTangency" and
// "approximationNormal" (constraints judged apart) with the three terms. Returns their ids.
std::vector<FamilyId> addApproximation(const ApproximationFit& fit,
                                       const ApproximationWeights& weights, Problem& problem);

} // namespace devsurf::solver
