#pragma once

#include "spline_space.h"
#include "vec3.h"

#include <array>
#include <utility>
#include <vector>

namespace devsurf::model {

// The intermediate points of de Boor's algorithm at one parameter u (paper Fig. 4).
struct DeBoorPoints {
    Vec3 point;
    // a¹₀, a¹₁: round m-1 of de Boor; for m == 1 the two control points of the span.
    Vec3 firstDerivativePoints[2];
    // a²₀, a²₁, a²₂: round m-2; only meaningful if hasSecondDerivativePoints (m >= 2).
    Vec3 secondDerivativePoints[3];
    bool hasSecondDerivativePoints = false;
    // a'(u) = firstDerivativeScale * (a¹₁ - a¹₀).
    double firstDerivativeScale = 0.0;
    // a''(u) = Σ secondDerivativeWeights[i] * a²ᵢ (all zero for m == 1). The weights sum to 0.
    double secondDerivativeWeights[3] = {0.0, 0.0, 0.0};

    Vec3 firstDerivative() const {
        return (firstDerivativePoints[1] - firstDerivativePoints[0]) * firstDerivativeScale;
    }
    Vec3 secondDerivative() const {
        return secondDerivativePoints[0] * secondDerivativeWeights[0] +
               secondDerivativePoints[1] * secondDerivativeWeights[1] +
               secondDerivativePoints[2] * secondDerivativeWeights[2];
    }
};

// For a fixed u, every de Boor point as a linear combination of m+1 control points; the solver
// precomputes these once per parameter value (docs/math.md §1).
struct DeBoorRows {
    std::vector<int> indices;                // m+1 control point indices (wrapped mod N if closed)
    std::vector<double> point;               // m+1 coefficients
    std::vector<double> firstDerivative[2];  // m+1 coefficients each
    std::vector<double> secondDerivative[3]; // m+1 coefficients each (empty if m < 2)
    double firstDerivativeScale = 0.0;
    double secondDerivativeWeights[3] = {0.0, 0.0, 0.0}; // as in DeBoorPoints
    int span = -1;          // knot span j, t_j <= parameter < t_{j+1} (last span at the end)
    double parameter = 0.0; // u after clamping (open) or reduction modulo the period (closed)
};

// A B-spline curve of degree m, open or closed (periodic).
//
// Open curves: knots t_0 .. t_{N+m} for N control points, domain [t_m, t_N]. Curves made by
// uniform() are clamped; general curves need not be.
//
// Closed curves: N distinct control points P_0 .. P_{N-1} and the periodic knot sequence
// t_0 .. t_{N+2m} with t_{i+N} = t_i + T (T = period). Basis function i (support
// [t_i, t_{i+m+1}]) carries control point P_{i mod N}, i = 0 .. N+m-1, and the domain is one
// period [t_m, t_{m+N}]. The representation is kept canonical: t_m is the first of the knots
// equal to the domain start (t_{m-1} < t_m), and knots outside [t_m, t_{m+N}) are their base
// knot plus a whole multiple of T, so periodic copies agree bit for bit.
//
// Parameters outside the domain are clamped to it for open curves and reduced modulo the
// period for closed ones. At a knot the span to its right is used (the last non-empty span at
// the domain end), which decides derivative points where the curve is not smooth.
//
// Invalid arguments throw std::invalid_argument; using an empty curve throws std::logic_error.
class BSplineCurve {
public:
    BSplineCurve() = default; // empty curve

    // General (possibly non-uniform) curve. For closed curves, knots and control points may
    // be given either as described above (knots.size() == N + 2m + 1) or in the interchange
    // form of exportKnots()/exportControlPoints() (the first m control points repeated at the
    // end, knots.size() == controlPoints.size() + m + 1).
    BSplineCurve(int degree, std::vector<double> knots, std::vector<Vec3> controlPoints,
                 bool closed);
    static BSplineCurve uniform(const SplineSpace& space, std::vector<Vec3> controlPoints,
                                bool closed = false);

    int degree() const { return m_degree; }
    bool isClosed() const { return m_closed; }
    bool isEmpty() const { return m_controlPoints.empty(); }
    const std::vector<double>& knots() const { return m_knots; }
    const std::vector<Vec3>& controlPoints() const { return m_controlPoints; }
    double domainBegin() const;
    double domainEnd() const;
    double period() const { return m_closed ? m_period : 0.0; } // 0 for open curves

    Vec3 evaluate(double u) const;
    Vec3 derivative(double u, int order) const; // order >= 0; zero vector for order > degree
    // evaluate(u) and derivative(u, 1) from one de Boor pass (for dense sampling).
    void pointAndTangent(double u, Vec3& point, Vec3& tangent) const;
    DeBoorPoints deBoorPoints(double u) const;
    DeBoorRows deBoorRows(double u) const;

    // Boehm's algorithm; the geometry is unchanged. The resulting multiplicity of u may not
    // exceed the degree; u must lie in the domain (open) or is reduced modulo the period
    // (closed, where every periodic copy is inserted so the curve stays periodic). u within
    // 1e-12 of the domain length of an existing knot is snapped to that knot.
    void insertKnot(double u, int times = 1);
    // Open curves only: two clamped curves on [begin, u] and [u, end] with the original
    // parameters. Throws unless begin < u < end.
    std::pair<BSplineCurve, BSplineCurve> split(double u) const;
    // Closed curves only: the clamped open curve on [u, u + period] (parameters as given).
    BSplineCurve openedAt(double u) const;
    // Same point set, parameter u -> begin + end - u.
    BSplineCurve reversed() const;
    // Open curves: an equivalent curve whose end knots have multiplicity m + 1.
    BSplineCurve clamped() const;

    // Interchange form: open curves as they are; closed curves unclamped with the first m
    // control points repeated at the end. knots.size() == controlPoints.size() + m + 1.
    std::vector<double> exportKnots() const;
    std::vector<Vec3> exportControlPoints() const;

private:
    int controlCount() const { return static_cast<int>(m_controlPoints.size()); }
    const Vec3& controlAt(int i) const; // wraps modulo N for closed curves
    // The m + 1 control points of span j (the start of de Boor's algorithm), into `points`
    // (on the stack up to degree 15, every curve DevSurf makes; on the heap beyond). Returns
    // their first element.
    Vec3* spanPoints(int j, std::array<Vec3, 16>& onStack, std::vector<Vec3>& onHeap) const;
    double knotAt(int i) const; // any index of the periodic sequence for closed curves
    void requireNonEmpty() const;
    // Clamps or reduces u into the domain and returns the span containing it.
    int locate(double& u) const;
    double snapToKnot(double u) const;
    double reduceClosed(double u, bool snap) const;
    void checkInsertion(double u, int existing, int times) const;
    void insertKnotOpen(double u, int times);
    void insertKnotClosed(double u, int times);
    // base: the knots t_m .. t_{m+N-1} of one period; base knots within tolerance of the next
    // period's start are moved to the front (with the control points) to restore the invariant.
    void setClosedCanonical(std::vector<double> base, double period, std::vector<Vec3> points,
                            double tolerance);

    int m_degree = 0;
    bool m_closed = false;
    double m_period = 0.0;
    std::vector<double> m_knots;
    std::vector<Vec3> m_controlPoints;
};

} // namespace devsurf::model
