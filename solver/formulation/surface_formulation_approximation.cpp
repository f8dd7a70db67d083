// The approximation's part of SurfaceFormulation (§4.2): its closest-point fit over the strips,
// refreshed between iterations, and the weights that fade it. Split from
// surface_formulation.cpp, which assembles the surface's own terms.
#include "solver/formulation/surface_formulation.h"

#include "solver/formulation/crease_conditions.h"

#include <stdexcept>
#include <string>

namespace devsurf::solver {

void SurfaceFormulation::addApproximationFit(
    const model::CompositeSurface& surface, const std::vector<model::Strip>& strips,
    const std::map<model::FaceId, StripNormalSpline>& stripNormals) {
    std::vector<ApproximatedStrip> columns;
    for (const model::Strip& strip : strips) {
        const auto normals = stripNormals.find(strip.face);
        if (strip.isCone() || strip.bSide.edge == model::kInvalidId ||
            normals == stripNormals.end()) {
            continue;
        }
        ApproximatedStrip c;
        c.face = strip.face;
        for (int point : sidePoints(strip.aSide)) {
            c.a.push_back(pointOffset(point));
        }
        for (int point : sidePoints(strip.bSide)) {
            c.b.push_back(pointOffset(point));
        }
        c.normalOffset = normals->second.offset;
        c.normalCurve = normals->second.curve;
        columns.push_back(std::move(c));
    }
    m_approximation = std::make_unique<ApproximationFit>(surface, *m_options.approximation,
                                                         std::move(columns), m_centre, m_scale);
}

void SurfaceFormulation::refreshApproximation(const model::CompositeSurface& current) {
    if (m_approximation) {
        m_approximation->refresh(current);
    }
    if (m_pairing) {
        m_pairing->refresh(current);
    }
}

void SurfaceFormulation::addCurvePairs(const model::CompositeSurface& surface) {
    std::vector<PairedCurveColumns> curves;
    for (const CurvePair& pair : m_options.curvePairs) {
        for (model::EdgeId edge : {pair.first, pair.second}) {
            if (!surface.hasEdge(edge) || surface.facesOfEdge(edge).size() != 1 ||
                pair.first == pair.second || !surface.hasEdge(pair.first) ||
                !surface.hasEdge(pair.second) ||
                surface.edge(pair.first).isSpline() != surface.edge(pair.second).isSpline()) {
                throw std::invalid_argument("edge " + std::to_string(edge) +
                                            " is not a boundary curve that can be paired");
            }
            // A curve's control points; a ruling's two vertices (a straight segment).
            const model::EdgeRecord& record = surface.edge(edge);
            PairedCurveColumns c;
            c.edge = edge;
            const std::vector<int> points =
                record.isSpline()
                    ? m_edgePoints.at(edge)
                    : std::vector<int>{m_vertexPoint.at(record.from), m_vertexPoint.at(record.to)};
            for (int point : points) {
                c.points.push_back(pointOffset(point));
            }
            curves.push_back(std::move(c));
        }
    }
    m_pairing = std::make_unique<CurvePairingFit>(surface, m_options.curvePairs, std::move(curves));
    addCurvePairing(*m_pairing, m_options.curvePairingWeight, m_problem);
}

void SurfaceFormulation::scaleApproximationWeights(double factor) {
    for (FamilyId id : m_approximationFamilies) {
        m_problem.setFamilyWeight(id, m_problem.family(id).weight * factor);
    }
    // A cone's exact normal spline has control normals of different lengths: held at unit
    // length after the pull faded, they bent a cone patch 1.3e-4 of its diameter off its
    // points (4.3e-6 fading with it; docs/tuning.md).
    if (const FamilyId unit = m_problem.findFamily("unitControlNormals"); unit >= 0) {
        m_problem.setFamilyWeight(unit, m_problem.family(unit).weight * factor);
    }
}

} // namespace devsurf::solver
