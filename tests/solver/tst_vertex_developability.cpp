// Vertex developability (docs/math.md §7): the angle defect measure, its rows' Jacobians, valid
// designs staying put, and a star whose angles do not sum to 2π driven back to 2π.

#include "model/composite_surface.h"
#include "model/examples.h"
#include "model/math_constants.h"
#include "solver/core/guided_projection.h"
#include "solver/formulation/perturbation.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/vertex_stars.h"
#include "solver_test_models.h"
#include "solver_test_problems.h"
#include "test_registry.h"

#include <QtTest>

#include <cmath>
#include <random>
#include <string>

using namespace devsurf;
using model::Vec3;
using solver::testing::familyRows;
using solver::testing::largestMove;

namespace {

using devsurf::model::kPi;

// Four SRSR strips around the centre O = (0, 0, h) of the square [−100, 100]² (z = 0): the
// S-edges O–E and O–W form a crease through O, the rulings O–N and O–S are straight. The strips'
// other S-edges run along y = ±100. Lifting O by h makes the star at O a cone: the angles between
// its spokes (to the first control points of O–E, O–W and to N, S) sum to less than 2π.
model::CompositeSurface makeStar(double h) {
    const model::SplineSpace space{3, 2, 2};
    model::CompositeSurface s;
    const model::VertexId o = s.addVertex({0, 0, h});
    const model::VertexId e = s.addVertex({100, 0, 0});
    const model::VertexId n = s.addVertex({0, 100, 0});
    const model::VertexId w = s.addVertex({-100, 0, 0});
    const model::VertexId so = s.addVertex({0, -100, 0});
    const model::VertexId ne = s.addVertex({100, 100, 0});
    const model::VertexId nw = s.addVertex({-100, 100, 0});
    const model::VertexId sw = s.addVertex({-100, -100, 0});
    const model::VertexId se = s.addVertex({100, -100, 0});
    s.addFace({o, e, ne, n});
    s.addFace({o, n, nw, w});
    s.addFace({o, w, sw, so});
    s.addFace({o, so, se, e});
    auto spline = [&](model::VertexId a, model::VertexId b) {
        s.setSpline(a, b, space,
                    solver::testing::lineControls(space, s.position(a), s.position(b)));
    };
    spline(o, e);
    spline(o, w);
    spline(n, ne);
    spline(n, nw);
    spline(so, sw);
    spline(so, se);
    return s;
}

double largestDefect(const model::CompositeSurface& s) {
    double worst = 0.0;
    for (const solver::VertexAngleDefect& d : solver::vertexAngleDefects(s)) {
        worst = std::max(worst, d.defect);
    }
    return worst;
}

// The lift h of O that makes the defect at O equal to `defect`, by bisection on the measure.
double liftForDefect(double defect) {
    double low = 0.0;
    double high = 50.0;
    for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (low + high);
        (largestDefect(makeStar(mid)) < defect ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

struct Solved {
    model::CompositeSurface surface;
    double developability = 0.0;
};

// Ten iterations (the default options) with three corners fixed.
// `iterations` iterations with three corners fixed, at ε₂ = `eps2`.
Solved solve(const model::CompositeSurface& start, bool vertexDevelopability, int iterations,
             double eps2) {
    solver::FormulationOptions options;
    options.vertexDevelopability = vertexDevelopability;
    options.vertexSpokeGuard = vertexDevelopability ? 0.5 : 0.0;
    for (model::VertexId v : {5u, 6u, 7u}) {
        options.handles.push_back({v, true, {}});
    }
    const solver::SurfaceFormulation f(start, options);
    std::vector<double> x = f.initialState();
    solver::Options solverOptions;
    solverOptions.maxIterations = iterations;
    solverOptions.eps2 = eps2;
    solver::GuidedProjection projection;
    const solver::Summary summary = projection.solve(f.problem(), x, solverOptions);
    Solved solved{start, 0.0};
    if (!summary.succeeded() || !f.writeBack(x, solved.surface)) {
        solved.developability = 1.0;
        return solved;
    }
    solved.developability = solver::measureQuality(solved.surface).developabilityMax;
    return solved;
}

solver::FormulationOptions withVertexDevelopability() {
    solver::FormulationOptions options;
    options.vertexDevelopability = true;
    return options;
}

} // namespace

class TstVertexDevelopability : public QObject {
    Q_OBJECT

private slots:
    void defectMeasuresTheConeAngle() {
        // The star at O is the only interior crease vertex; flat, its angles sum to 2π.
        const model::CompositeSurface flat = makeStar(0.0);
        QVERIFY(flat.validate().empty());
        const auto stars = solver::creaseVertexStars(flat);
        QCOMPARE(static_cast<int>(stars.size()), 1);
        QCOMPARE(stars.front().vertex, model::VertexId{0});
        QCOMPARE(static_cast<int>(stars.front().spokes.size()), 4);
        QVERIFY(largestDefect(flat) < 1e-14);
        // Lifted by h: spokes (±l, 0, −h/6) and (0, ±100, −h) with l = 100/6 (the first
        // control point of a straight cubic C² curve with two intervals lies at a sixth of it).
        const double h = 10.0;
        const double l = 100.0 / 6.0;
        const double angle =
            std::acos(h * h / 6.0 / (std::hypot(l, h / 6.0) * std::hypot(100.0, h)));
        const double expected = 2.0 * kPi - 4.0 * angle;
        const double measured = largestDefect(makeStar(h));
        QVERIFY2(std::abs(measured - expected) < 1e-12,
                 qPrintable(QString("%1 vs %2").arg(measured).arg(expected)));
    }

    void jacobiansMatchFiniteDifferences() {
        const solver::SurfaceFormulation f(makeStar(7.0), withVertexDevelopability());
        const solver::Problem& problem = f.problem();
        QCOMPARE(familyRows(problem, "vertexDevelopability"), 8); // 4 spokes + 4 rims
        QCOMPARE(familyRows(problem, "vertexSpokeGuard"), 4);
        std::mt19937 rng(3);
        const std::vector<double> x = solver::testing::randomVector(rng, problem.variableCount());
        for (int t = 0; t < problem.termCount(); ++t) {
            const solver::Term& term = problem.term(t);
            const double error = solver::testing::jacobianError(
                solver::testing::analyticJacobian(term, x),
                solver::testing::finiteDifferenceJacobian(term, x, 1e-6));
            QVERIFY2(error < 1e-6, term.typeName());
        }
        solver::FormulationOptions off;
        off.vertexDevelopability = false;
        QCOMPARE(familyRows(solver::SurfaceFormulation(makeStar(7.0), off).problem(),
                            "vertexDevelopability"),
                 0);
    }

    void almostStraightCreaseIsMadeTangentContinuous() {
        // Lifted by h the crease E–O–W kinks at O by 2 atan(h / 100): 0.1 rad for h = 5, 0.02
        // rad for h = 1 (below vertexSmoothCreaseAngle = 0.05), where the star gets the
        // tangent-continuity rows instead of its flat copy (whose rows stay, scaled to zero).
        // The star's crease has no condition, and such a plain crease is made smooth only when
        // it is straight (vertexSmoothPlainCreaseAngle): the test takes the angle of a crease
        // with a condition for it, and checks the plain rule at the end.
        for (const double h : {5.0, 1.0}) {
            solver::FormulationOptions options = withVertexDevelopability();
            options.vertexSmoothPlainCreaseAngle = options.vertexSmoothCreaseAngle;
            const solver::SurfaceFormulation f(makeStar(h), options);
            const solver::Problem& problem = f.problem();
            QCOMPARE(familyRows(problem, "smoothCreaseVertices"), 3);
            QCOMPARE(familyRows(problem, "vertexDevelopability"), 8);
            std::mt19937 rng(5);
            const std::vector<double> x =
                solver::testing::randomVector(rng, problem.variableCount());
            for (int t = 0; t < problem.termCount(); ++t) {
                const solver::Term& term = problem.term(t);
                const auto analytic = solver::testing::analyticJacobian(term, x);
                const double error = solver::testing::jacobianError(
                    analytic, solver::testing::finiteDifferenceJacobian(term, x, 1e-6));
                QVERIFY2(error < 1e-6, term.typeName());
                if (std::string(term.typeName()) == "TangentContinuityTerm") {
                    // Zero-scaled at h = 5, real rows at h = 1.
                    double largest = 0.0;
                    for (const auto& entry : analytic) {
                        largest = std::max(largest, std::abs(entry.second));
                    }
                    QCOMPARE(largest > 0.0, h < 2.0);
                }
            }
            // Pulling O up to 11 (a kink of 0.22 rad if the crease stayed straight on either
            // side), with three corners fixed: the crease stays straight through O and the star
            // developable.
            if (h < 2.0) {
                solver::FormulationOptions pullOptions = options;
                for (model::VertexId v : {5u, 6u, 7u}) {
                    pullOptions.handles.push_back({v, true, {}});
                }
                pullOptions.handles.push_back({0, false, Vec3(0, 0, 11.0)});
                const solver::SurfaceFormulation pulled(makeStar(h), pullOptions);
                std::vector<double> y = pulled.initialState();
                solver::GuidedProjection projection;
                solver::Options solverOptions;
                solverOptions.maxIterations = 30;
                solverOptions.eps2 = 1e-3;
                QVERIFY(projection.solve(pulled.problem(), y, solverOptions).succeeded());
                model::CompositeSurface out = makeStar(h);
                QVERIFY(pulled.writeBack(y, out));
                QVERIFY2(largestDefect(out) < 1e-8,
                         qPrintable(QString::number(largestDefect(out))));
                QVERIFY(out.position(0).z > 5.0);
            }
        }
        // By default the plain crease kinked by 0.02 rad keeps its kink (its flat copy): the
        // annulus's rings kink by 0.025 rad and less from size 21 on, and were made smooth,
        // which their flat start broke (docs/tuning.md, "A plain crease keeps its kink").
        const solver::SurfaceFormulation plain(makeStar(1.0), withVertexDevelopability());
        QVERIFY(solver::FormulationOptions().vertexSmoothPlainCreaseAngle < 0.02);
        for (int t = 0; t < plain.problem().termCount(); ++t) {
            const solver::Term& term = plain.problem().term(t);
            if (std::string(term.typeName()) == "TangentContinuityTerm") {
                std::mt19937 rng(5);
                const std::vector<double> x =
                    solver::testing::randomVector(rng, plain.problem().variableCount());
                for (const auto& entry : solver::testing::analyticJacobian(term, x)) {
                    QCOMPARE(entry.second, 0.0); // zero-scaled: not imposed
                }
            }
        }
    }

    void validDesignsStayPut() {
        // The star's flat copy starts with the start's angles: on a developable design every
        // row vanishes at the start, and 10 iterations without pins leave the design in place.
        for (const char* name : {"sheet", "annulus", "cylinder", "mixed"}) {
            const model::CompositeSurface surface = model::makeExample(name, 0).surfaces.front();
            const auto defects = solver::vertexAngleDefects(surface);
            qInfo("%s: %d interior crease vertices, largest defect %.1e", name,
                  static_cast<int>(defects.size()), largestDefect(surface));
            QVERIFY(largestDefect(surface) < 1e-12);
            const solver::SurfaceFormulation f(surface, withVertexDevelopability());
            QCOMPARE(familyRows(f.problem(), "vertexDevelopability") > 0, !defects.empty());
            std::vector<double> x = f.initialState();
            solver::GuidedProjection projection;
            QVERIFY(projection.solve(f.problem(), x, solver::Options{}).succeeded());
            model::CompositeSurface out = surface;
            QVERIFY(f.writeBack(x, out));
            double move = 0.0;
            for (const auto& [id, p] : surface.vertices()) {
                move = std::max(move, (out.position(id) - p).norm());
            }
            for (const auto& [id, record] : surface.edges()) {
                for (std::size_t i = 0; i < record.controlPoints.size(); ++i) {
                    move = std::max(
                        move, (out.edge(id).controlPoints[i] - record.controlPoints[i]).norm());
                }
            }
            const double diameter = solver::surfaceDiameter(surface);
            QVERIFY2(
                move <= 1e-6 * diameter,
                qPrintable(QString("%1: moved %2 of the diameter").arg(name).arg(move / diameter)));
        }
    }

    void starWithAnAngleDefectIsMadeDevelopable() {
        // O lifted by 11.25 (of a 200 wide square): the star's angles sum to 2π − 0.05 and the
        // four strips are not developable. Solved at ε₂ = 1e-3 (as tst_formulation solves noisy
        // starts); the default ε₂ = 0.01 is reported too (it needs more iterations here).
        const double h = liftForDefect(0.05);
        const model::CompositeSurface start = makeStar(h);
        const double before = largestDefect(start);
        QVERIFY(std::abs(before - 0.05) < 1e-9);
        const Solved with = solve(start, true, 10, 1e-3);
        const Solved without = solve(start, false, 10, 1e-3);
        const Solved defaults10 = solve(start, true, 10, 0.01);
        const Solved defaults30 = solve(start, true, 30, 0.01);
        const double after = largestDefect(with.surface);
        const double afterWithout = largestDefect(without.surface);
        qInfo("lift %.3f; angle defect at O: %.3e at the start, after 10 iterations %.3e with "
              "vertex developability (det %.1e), %.3e without (det %.1e); at the default "
              "eps2 %.3e after 10, %.3e after 30 iterations",
              h, before, after, with.developability, afterWithout, without.developability,
              largestDefect(defaults10.surface), largestDefect(defaults30.surface));
        QVERIFY2(after <= 1e-8, qPrintable(QString::number(after)));
        QVERIFY(with.developability < 1e-8);
        // Developable strips alone leave a cone point at O.
        QVERIFY(afterWithout > 1e-4);
        QVERIFY(largestDefect(defaults30.surface) <= 1e-8);
    }
};

DEVSURF_REGISTER_TEST(TstVertexDevelopability);
#include "tst_vertex_developability.moc"
