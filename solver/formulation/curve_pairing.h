#pragma once

// Pairing of boundary curves (§4.2, "Composite"; docs/math.md §6): two boundary curves of a
// surface (typically of two strips placed side by side, model::placeSideBySide) are pulled
// together until they can be welded into one shared curve (model::weldEdges). Sample points
// v_k = a(u_k) of one curve are asked to lie on the tangent line of the other curve b at their
// closest point b(t_k); t_k and the tangent are found again before every iteration, so each
// step's condition is linear: P_k (v_k − b(t_k)) = 0 with P_k = I − T_k T_kᵀ. Both curves are
// sampled, each onto the other.

#include "model/composite_surface.h"
#include "solver/core/problem.h"
#include "solver/core/term.h"

#include <vector>

namespace devsurf::solver {

// Two boundary edges of one surface to be brought together: two S-edges, or two R-edges (each
// the straight segment between its vertices, model::edgeCurve).
struct CurvePair {
    model::EdgeId first = model::kInvalidId;
    model::EdgeId second = model::kInvalidId;
};

// Samples per spline interval of each paired curve.
inline constexpr int kPairingSamplesPerInterval = 4;

// The columns of one paired curve in the state: its control points' x-coordinates, in the
// edge's stored orientation.
struct PairedCurveColumns {
    model::EdgeId edge = model::kInvalidId;
    std::vector<int> points;
};

// The samples of every paired curve, their closest points on the other curve of the pair and
// the coefficients of their rows. A sample whose closest point is an end of the other curve
// (it lies beyond that end) is pulled onto that end point instead (P = I): a point beyond
// the other curve cannot lie on it, and so the curves' ends come together as well.
class CurvePairingFit {
public:
    // `curves`: two per pair, in the order of `pairs`. `centre` and `scale` map model
    // coordinates to the state's: (p − centre) / scale (the projector is unit-free).
    CurvePairingFit(const model::CompositeSurface& surface, std::vector<CurvePair> pairs,
                    std::vector<PairedCurveColumns> curves,
                    int samplesPerInterval = kPairingSamplesPerInterval);

    // Finds the closest points again on `current` (the formulated surface's combinatorics).
    void refresh(const model::CompositeSurface& current);

    struct Sample {
        int from = 0; // index into curves(): the sampled curve
        int onto = 0; // the other curve of its pair
        double u = 0.0;
        double t = 0.0;       // the closest point's parameter on `onto`
        bool atEnd = false;   // t is an end of `onto`
        double projector[9];  // P, row-major
        int coefficients = 0; // into m_coefficients: basis of `from` at u, of `onto` at t
    };
    const std::vector<Sample>& samples() const { return m_samples; }
    const std::vector<PairedCurveColumns>& curves() const { return m_curves; }
    const double* coefficients(const Sample& sample) const {
        return m_coefficients.data() + sample.coefficients;
    }
    // The largest distance of a sample from its closest point on the other curve at the last
    // refresh (model units).
    double largestDistance() const { return m_largestDistance; }

private:
    std::vector<CurvePair> m_pairs;
    std::vector<PairedCurveColumns> m_curves;
    std::vector<Sample> m_samples;
    std::vector<double> m_coefficients;
    double m_largestDistance = 0.0;
};

// Three rows per sample: P (v − b(t)), with every control point of both curves as columns so
// that the pattern stays fixed while t moves. Linear in x for a given refresh.
class CurvePairingTerm : public Term {
public:
    explicit CurvePairingTerm(const CurvePairingFit& fit) : m_fit(fit) {}

    const char* typeName() const override { return "CurvePairingTerm"; }
    int rowCount() const override { return 3 * static_cast<int>(m_fit.samples().size()); }
    void buildPattern(PatternBuilder& builder) const override;
    void evaluate(const double* x, double* residuals, double* jacobian) const override;

private:
    const CurvePairingFit& m_fit;
};

// Appends the family "curvePairing" (a constraint judged apart) with the term. Returns its id.
FamilyId addCurvePairing(const CurvePairingFit& fit, double weight, Problem& problem);

} // namespace devsurf::solver
