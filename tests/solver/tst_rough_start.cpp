// Rough starts: the proximity to the start (TermRole::Proximity, Options::proximityFactor), its
// Jacobians and weighting, the damping of length changes (TermRole::Damping,
// kRoughSolveLengthDamping), unit normals projected back after every step (Options::project),
// and starts of the benchmark that degenerated or alternated before.
#include "model/examples.h"
#include "model/strip.h"
#include "solver/core/guided_projection.h"
#include "solver/core/normal_equations.h"
#include "solver/core/problem.h"
#include "solver/core/target_term.h"
#include "solver/formulation/normal_spline_start.h"
#include "solver/formulation/perturbation.h"
#include "solver/formulation/point_combinations.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/session/solve_session.h"
#include "solver_test_models.h"
#include "solver_test_problems.h"
#include "test_registry.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace devsurf;
using namespace devsurf::solver;
using namespace devsurf::solver::testing;

namespace {

// Three variables, one constraint row x₀ = 1 and a family of role `role` and weight `weight`
// pulling x towards (0.5, −1, 2).
Problem constraintAndTargets(TermRole role, double weight) {
    Problem p;
    p.addVariableBlock("x", 3);
    auto constraint = std::make_unique<TargetTerm>();
    constraint->addTarget(0, 1.0);
    p.add(p.addFamily("c", TermRole::Constraint, 1.0), std::move(constraint));
    auto targets = std::make_unique<TargetTerm>();
    const double start[3] = {0.5, -1.0, 2.0};
    targets->addPointTarget(0, 3, start);
    p.add(p.addFamily("targets", role, weight), std::move(targets));
    return p;
}

// The normal equations of `p` at x = 0, filled in place with ε₁, ε₂ and μ: their upper
// triangle (original order) and right-hand side, and whether the fill equals the scratch
// assembly.
struct FilledEquations {
    NormalEquations equations;
    std::vector<double> values;
    std::vector<double> rhs;
    Eigen::SparseMatrix<double> matrix;
    bool matchesScratch = false;
};

void fillAtZero(const Problem& p, double eps1, double eps2, double mu, FilledEquations& out) {
    const double x[3] = {0.0, 0.0, 0.0};
    if (!out.equations.build(p, nullptr) || !out.equations.evaluate(p, x)) {
        return;
    }
    out.values.assign(static_cast<std::size_t>(out.equations.normalNonZeros()), 0.0);
    out.rhs.assign(3, 0.0);
    out.equations.fill(p, eps1, eps2, out.values.data(), out.rhs.data(), mu);
    Eigen::SparseMatrix<double> scratch;
    Eigen::VectorXd scratchRhs;
    out.equations.assembleFromScratch(p, eps1, eps2, scratch, scratchRhs, mu);
    out.matrix = out.equations.toOriginalUpper(out.values.data());
    out.matchesScratch = Eigen::SparseMatrix<double>(out.matrix - scratch).norm() <= 1e-15;
}

// The configuration measured for rough starts (useRoughStartConfiguration).
Options roughStartOptions() {
    FormulationOptions unused;
    Options options;
    useRoughStartConfiguration(unused, options);
    options.maxIterations = 10;
    options.recordIterations = false;
    return options;
}

FormulationOptions roughStartFormulation() {
    FormulationOptions options;
    Options unused;
    useRoughStartConfiguration(options, unused);
    return options;
}

// `example` (of size `size`, 0: its default) shaken by Gaussian noise of σ = `sigma` model units
// with three boundary vertices pinned, as devsurf-bench --study starts.
model::CompositeSurface studyStart(const char* example, int size, double sigma, unsigned seed) {
    model::CompositeSurface surface = model::makeExample(example, size).surfaces.front();
    const auto anchors = spreadBoundaryVertices(surface, 3);
    perturbSurface(surface, sigma, seed, anchors);
    for (model::VertexId v : anchors) {
        surface.setPinned(v, true);
    }
    return surface;
}

// Empty if `result`, solved from `start`, is developable to 1e-10 (sampled), keeps every ruling
// at a quarter of its start length and every curve at a tenth of its mean speed, and folds over
// nowhere; else what failed.
QString solvedWithoutDegenerating(const model::CompositeSurface& start,
                                  const model::CompositeSurface& result) {
    const double det = measureQuality(result).developabilityMax;
    const ShapeChange change = measureShapeChange(start, result);
    if (det > 1e-10 || change.shortestRuling < 0.25 || change.slowestSpeed < 0.1 ||
        change.foldOverPlaces() != 0) {
        return QString("det %1, shortest ruling %2, slowest speed %3, %4 places folded over")
            .arg(det)
            .arg(change.shortestRuling)
            .arg(change.slowestSpeed)
            .arg(change.foldOverPlaces());
    }
    return {};
}

} // namespace

class TstRoughStart : public QObject {
    Q_OBJECT

private slots:
    void proximityWeightFollowsTheResidual() {
        Options options;
        QCOMPARE(proximityWeight(options, 0.5), 0.0); // off by default
        options.proximityFactor = 2.0;
        options.proximityMaximum = 0.5;
        QCOMPARE(proximityWeight(options, 0.1), 0.2);
        QCOMPARE(proximityWeight(options, 10.0), 0.5);
        QCOMPARE(proximityWeight(options, 0.0), 0.0);
        // Below the threshold μ falls with r²: continuous at the threshold.
        options.proximityThreshold = 0.01;
        QVERIFY(std::abs(proximityWeight(options, 0.005) - 2.0 * 0.005 * 0.5) < 1e-15);
        QVERIFY(std::abs(proximityWeight(options, 0.01) - 0.02) < 1e-15);
        QVERIFY(proximityWeight(options, 1e-12) < 1e-20);
    }

    void proximityRowsAreWeightedByMu() {
        // One constraint row and a proximity family: the refilled normal equations equal the
        // scratch assembly, and the proximity rows enter with weight w · μ.
        const Problem p = constraintAndTargets(TermRole::Proximity, 2.0);
        const double mu = 0.3;
        const double eps2 = 0.01;
        FilledEquations filled;
        fillAtZero(p, 0.0, eps2, mu, filled);
        NormalEquations& equations = filled.equations;
        QCOMPARE(equations.energy(), 0.0); // proximity is neither constraint nor energy
        QVERIFY(filled.matchesScratch);
        const Eigen::SparseMatrix<double>& refilled = filled.matrix;
        std::vector<double>& values = filled.values;
        std::vector<double>& rhs = filled.rhs;
        const double w2 = (2.0 * mu) * (2.0 * mu);
        QVERIFY(std::abs(refilled.coeff(0, 0) - (1.0 + w2 + eps2 * eps2)) < 1e-15);
        QVERIFY(std::abs(refilled.coeff(1, 1) - (w2 + eps2 * eps2)) < 1e-15);
        // g = −Σ w² φ J: the constraint pulls x₀ to 1, proximity towards the start.
        QVERIFY(std::abs(rhs[0] - (1.0 + w2 * 0.5)) < 1e-15);
        QVERIFY(std::abs(rhs[1] - w2 * -1.0) < 1e-15);
        QVERIFY(std::abs(rhs[2] - w2 * 2.0) < 1e-15);
        // μ = 0: the proximity rows vanish.
        equations.fill(p, 0.0, eps2, values.data(), rhs.data(), 0.0);
        QCOMPARE(rhs[1], 0.0);
    }

    void dampingRowsAreWeightedByEps2() {
        // A damping family enters like the damping ε₂ itself: its rows with weight w · ε₂, in
        // the refilled equations, the scratch assembly and a right-hand side alone; it is
        // neither constraint nor energy.
        const Problem p = constraintAndTargets(TermRole::Damping, 30.0);
        const double eps1 = 0.1;
        const double eps2 = 0.01;
        FilledEquations filled;
        fillAtZero(p, eps1, eps2, 0.7, filled);
        NormalEquations& equations = filled.equations;
        QCOMPARE(equations.energy(), 0.0);
        QCOMPARE(equations.constraintMerit(), 1.0);
        QVERIFY(filled.matchesScratch);
        const Eigen::SparseMatrix<double>& refilled = filled.matrix;
        const std::vector<double>& rhs = filled.rhs;
        const double w2 = (30.0 * eps2) * (30.0 * eps2);
        QVERIFY(std::abs(refilled.coeff(0, 0) - (1.0 + w2 + eps2 * eps2)) < 1e-15);
        QVERIFY(std::abs(refilled.coeff(2, 2) - (w2 + eps2 * eps2)) < 1e-15);
        QVERIFY(std::abs(rhs[0] - (1.0 + w2 * 0.5)) < 1e-15);
        QVERIFY(std::abs(rhs[2] - w2 * 2.0) < 1e-15);
        std::vector<double> alone(3);
        equations.fillRightHandSide(p, eps1, 0.7, eps2, equations.jacobianValues(), alone.data());
        for (int k = 0; k < 3; ++k) {
            QVERIFY(std::abs(alone[static_cast<std::size_t>(k)] -
                             rhs[static_cast<std::size_t>(k)]) < 1e-15);
        }
        std::vector<double> weights;
        equations.rowWeights(p, eps1, weights, 0.7, eps2);
        QCOMPARE(weights.back(), 30.0 * eps2);
    }

    void proximityJacobiansMatchFiniteDifferences() {
        // Every term of a formulation with the proximity of points and control normals, and
        // normalised rows, against central differences.
        FormulationOptions options = roughStartFormulation();
        options.normalProximityWeight = 1.0;
        const model::CompositeSurface mixed = model::makeExample("mixed", 1).surfaces.front();
        const SurfaceFormulation f(mixed, options);
        QVERIFY(f.problem().findFamily("proximity") >= 0);
        QVERIFY(f.problem().findFamily("normalProximity") >= 0);
        std::mt19937 rng(11);
        const std::vector<double> x = randomVector(rng, f.problem().variableCount());
        for (int t = 0; t < f.problem().termCount(); ++t) {
            const Term& term = f.problem().term(t);
            const double error =
                jacobianError(analyticJacobian(term, x), finiteDifferenceJacobian(term, x, 1e-6));
            QVERIFY2(error < 1e-6, term.typeName());
        }
    }

    void rowScalingWithProximity() {
        // The same random strip at 1e-3 and 1e3 with the rough-start configuration: the same
        // iterations to the same normalised residual (μ and the rows are dimensionless).
        Summary summaries[2];
        double det[2];
        int k = 0;
        for (double scale : {1e-3, 1e3}) {
            const model::CompositeSurface strip = makeRandomStrip(5u, scale);
            const SurfaceFormulation f(strip, roughStartFormulation());
            std::vector<double> x = f.initialState();
            Options options = roughStartOptions();
            options.maxIterations = 30;
            options.residualTolerance = 1e-10;
            GuidedProjection projection;
            summaries[k] = projection.solve(f.problem(), x, options);
            QVERIFY2(summaries[k].status == Status::Converged, summaries[k].briefReport().c_str());
            model::CompositeSurface out = strip;
            QVERIFY(f.writeBack(x, out));
            det[k] = measureQuality(out).developabilityMax;
            ++k;
        }
        QCOMPARE(summaries[0].iterationsCompleted, summaries[1].iterationsCompleted);
        const double r0 = summaries[0].finalMaxConstraintResidual;
        const double r1 = summaries[1].finalMaxConstraintResidual;
        QVERIFY2(std::abs(r0 - r1) <= 0.05 * std::max(r0, r1) + 1e-14,
                 qPrintable(QString("%1 vs %2").arg(r0).arg(r1)));
        QVERIFY(det[0] < 1e-6 && det[1] < 1e-6);
    }

    void validDesignsStayPutWithProximity() {
        // μ follows the residual, so an exactly developable design is not moved (no pins).
        for (const char* name : {"sheet", "cylinder", "mixed"}) {
            const model::CompositeSurface surface = model::makeExample(name, 0).surfaces.front();
            const SurfaceFormulation f(surface, roughStartFormulation());
            std::vector<double> x = f.initialState();
            GuidedProjection projection;
            QVERIFY(projection.solve(f.problem(), x, roughStartOptions()).succeeded());
            model::CompositeSurface out = surface;
            QVERIFY(f.writeBack(x, out));
            const double move = largestMove(surface, out) / surfaceDiameter(surface);
            QVERIFY2(move <= 1e-6, qPrintable(QString("%1 moved %2").arg(name).arg(move)));
        }
    }

    void projectRunsOnEveryIterateBeforeItsResiduals() {
        // One unit vector: Gauss–Newton leaves |δ|² in its unit row after every step; a
        // projection onto the sphere removes it before the residual is evaluated.
        auto solve = [](bool normalise, int* calls) {
            Problem p;
            p.addVariableBlock("n", 3);
            auto unit = std::make_unique<UnitNormTerm>(3);
            unit->addVector(0);
            p.add(p.addFamily("unit", TermRole::Constraint), std::move(unit));
            std::vector<double> x{0.5, 0.2, 0.1};
            Options options;
            options.maxIterations = 3;
            if (normalise) {
                options.project = [calls](double* v) {
                    ++*calls;
                    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                    for (int k = 0; k < 3; ++k) {
                        v[k] /= length;
                    }
                };
            }
            GuidedProjection solver;
            return solver.solve(p, x, options);
        };
        int calls = 0;
        const Summary plain = solve(false, &calls);
        QVERIFY(plain.iterations.front().maxConstraintResidual > 1e-3);
        const Summary projected = solve(true, &calls);
        QCOMPARE(calls, 3);
        QCOMPARE(projected.iterationsCompleted, 3);
        for (const IterationStats& it : projected.iterations) {
            QVERIFY2(it.maxConstraintResidual < 1e-15,
                     qPrintable(QString::number(it.maxConstraintResidual)));
        }
        QVERIFY(projected.finalMaxConstraintResidual < 1e-15);
    }

    void unitNormalsAreNormalisedInPlace() {
        // The mixed example has planar faces and cones: their normals are scaled to unit
        // length, keeping their directions; every other variable stays as it was.
        const model::CompositeSurface surface = model::makeExample("mixed").surfaces.front();
        const SurfaceFormulation f(surface, FormulationOptions{});
        const Problem& p = f.problem();
        QVERIFY(p.hasBlock("coneNormals") && p.hasBlock("planeNormals"));
        std::vector<double> x = f.initialState();
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> factor(0.2, 3.0);
        std::vector<bool> normal(x.size(), false);
        for (const char* name : {"coneNormals", "planeNormals"}) {
            const VariableBlock& block = p.block(name);
            QVERIFY(block.size > 0 && block.size % 3 == 0);
            for (int o = block.offset; o < block.offset + block.size; o += 3) {
                const double scale = factor(rng);
                for (int k = 0; k < 3; ++k) {
                    x[static_cast<std::size_t>(o + k)] *= scale;
                    normal[static_cast<std::size_t>(o + k)] = true;
                }
            }
        }
        const std::vector<double> before = x;
        f.normaliseUnitNormals(x.data());
        for (std::size_t i = 0; i < x.size(); ++i) {
            if (!normal[i]) {
                QCOMPARE(x[i], before[i]);
            }
        }
        for (const char* name : {"coneNormals", "planeNormals"}) {
            const VariableBlock& block = p.block(name);
            for (int o = block.offset; o < block.offset + block.size; o += 3) {
                const auto i = static_cast<std::size_t>(o);
                const model::Vec3 n(x[i], x[i + 1], x[i + 2]);
                const model::Vec3 m(before[i], before[i + 1], before[i + 2]);
                QVERIFY(std::abs(n.norm() - 1.0) < 1e-15);
                QVERIFY(cross(n, m).norm() < 1e-14 * m.norm() && dot(n, m) > 0.0);
            }
        }
    }

    void roughMixedConvergesWithUnitNormals() {
        // Seed 20150801 of the benchmark's 10 % edge-noise start on `mixed` (strips, cones
        // and planar faces), solved as Tools ▸ Solve does with three boundary vertices pinned.
        // Measured: det 1.3e-8 after 10 iterations while the cones' and planar faces' unit
        // rows kept the step's second-order error (residuals alternating 5e-4 … 2e-3),
        // 1e-15 with those normals normalised after every step.
        model::CompositeSurface surface = model::makeExample("mixed").surfaces.front();
        double sum = 0.0;
        int count = 0;
        for (const auto& [id, edge] : surface.edges()) {
            for (std::size_t i = 0; i + 1 < edge.controlPoints.size(); ++i) {
                sum += model::distance(edge.controlPoints[i], edge.controlPoints[i + 1]);
                ++count;
            }
        }
        const auto anchors = spreadBoundaryVertices(surface, 3);
        perturbSurface(surface, 0.1 * sum / count, 20150801u, anchors);
        for (model::VertexId v : anchors) {
            surface.setPinned(v, true);
        }
        SolveSession session(surface, {});
        QVERIFY(session.step(10).succeeded());
        const double det = measureQuality(session.surface()).developabilityMax;
        QVERIFY2(det <= 1e-10, qPrintable(QString::number(det)));
        const ShapeChange change = measureShapeChange(surface, session.surface());
        QVERIFY(change.shortestRuling >= 0.25 && change.slowestSpeed >= 0.1);
    }

    void roughSolveDampsLengthChangesUntilTheResidualFalls() {
        // Seed 20150807 of the benchmark's 1 % start on the sheet, solved as Tools ▸ Solve does
        // with three boundary vertices pinned. Measured without the damping of length changes:
        // once the pull towards the start had faded, fairness drew the control points of the
        // nearly flat result along their curves (the slowest speed fell to 0.031 of the
        // mean) and the residual stalled (det 5e-6 after 10 iterations). With it: 4e-14 and
        // speeds at 0.6, measured on the geometry.
        const model::CompositeSurface sheet = model::makeExample("sheet").surfaces.front();
        const model::CompositeSurface surface =
            studyStart("sheet", 0, 0.01 * surfaceDiameter(sheet), 20150807u);
        SolveSession session(surface, {});
        const Problem& problem = session.formulation().problem();
        const FamilyId lengths = problem.findFamily("isometry");
        QVERIFY(lengths >= 0);
        QVERIFY(problem.family(lengths).role == TermRole::Damping);
        QCOMPARE(problem.family(lengths).weight, kRoughSolveLengthDamping);
        // Full weight until the residual first falls to the limit, then halved before every
        // further iteration.
        double residual = 1.0;
        double weight = kRoughSolveLengthDamping;
        int fading = 0;
        for (int i = 0; i < 10; ++i) {
            const Summary summary = session.step(1);
            QVERIFY(summary.succeeded());
            if (residual <= kRoughSolveLengthDampingUntil) {
                weight *= kRoughSolveLengthDampingFade;
                ++fading;
            }
            QCOMPARE(problem.family(lengths).weight, weight);
            residual = std::min(residual, summary.finalMaxConstraintResidual);
        }
        QVERIFY(fading >= 3);
        const QString failed = solvedWithoutDegenerating(surface, session.surface());
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
        // A valid design and a drag are not damped so.
        SolveSession valid(model::makeExample("sheet").surfaces.front(), {});
        QCOMPARE(valid.formulation().problem().findFamily("isometry"), -1);
    }

    void noisyStripsStartFromLinearNormalFields() {
        // The annulus shaken by 1 % of its diameter: the unit normals a′ × (b − a) of its strips
        // zig-zag along them, the fit in the normal spline's space misses them by more than
        // kNoisyStartNormals, and such a strip starts from the best linear field. The cylinder
        // shaken by 0.01 %, whose normals turn smoothly along its strips, keeps the fit that
        // follows them.
        auto startNormals = [](const model::CompositeSurface& surface, const model::Strip& strip,
                               bool linearIfNoisy = true) {
            const int intervals = surface.edge(strip.aSide.edge).space.intervals;
            std::vector<double> samples = collocationValues(intervals, 3 * strip.a.degree() - 2);
            samples.push_back(0.0);
            samples.push_back(1.0);
            const model::SplineSpace space =
                normalSplineSpace(surface.edge(strip.aSide.edge).space, false);
            const model::BSplineCurve curve = model::BSplineCurve::uniform(
                space, std::vector<model::Vec3>(space.controlPointCount(false)));
            return model::BSplineCurve::uniform(
                space,
                fitStartNormals(strip, curve, samples, isDevelopableStart(strip), linearIfNoisy));
        };
        auto linear = [](const model::BSplineCurve& n) {
            double off = 0.0;
            for (double u : {0.2, 0.5, 0.7}) {
                off = std::max(
                    off,
                    (n.evaluate(u) - ((1.0 - u) * n.evaluate(0.0) + u * n.evaluate(1.0))).norm());
            }
            return off <= 1e-9;
        };
        model::CompositeSurface annulus = model::makeExample("annulus").surfaces.front();
        perturbSurface(annulus, 0.01 * surfaceDiameter(annulus), 20150805u, {});
        int linearStrips = 0;
        const std::vector<model::Strip> strips = model::stripsOf(annulus);
        for (const model::Strip& strip : strips) {
            QVERIFY(!isDevelopableStart(strip));
            linearStrips += linear(startNormals(annulus, strip)) ? 1 : 0;
            // Not asked for (the paper's configuration): the fit of the noisy normals.
            QVERIFY(!linear(startNormals(annulus, strip, false)));
        }
        // Measured: 32 of 48.
        QVERIFY2(linearStrips >= static_cast<int>(strips.size()) / 2,
                 qPrintable(QString("%1 of %2").arg(linearStrips).arg(strips.size())));

        model::CompositeSurface cylinder = model::makeExample("cylinder").surfaces.front();
        perturbSurface(cylinder, 1e-4 * surfaceDiameter(cylinder), 20150805u, {});
        for (const model::Strip& strip : model::stripsOf(cylinder)) {
            if (strip.isCone() || isDevelopableStart(strip)) {
                continue;
            }
            const model::BSplineCurve n = startNormals(cylinder, strip);
            QVERIFY(!linear(n));
            for (double u : {0.1, 0.5, 0.9}) {
                const model::Vec3 field = initialStripNormal(strip, u);
                const model::Vec3 start = n.evaluate(u) / n.evaluate(u).norm();
                QVERIFY2(model::distance(field, start) < 1e-2,
                         qPrintable(QString::number(model::distance(field, start))));
            }
        }
    }

    void roughAnnulusConvergesWithinTenIterations() {
        // Seed 20150805 of the benchmark's 1 % start on the annulus, solved as Tools ▸ Solve
        // does with three boundary vertices pinned. Measured with the spline fit of the noisy
        // normals: det 3.8e-4 after 10 iterations; from linear fields: 3e-13, rulings at 0.5 of
        // their start length, on the geometry.
        const model::CompositeSurface annulus = model::makeExample("annulus").surfaces.front();
        const model::CompositeSurface surface =
            studyStart("annulus", 0, 0.01 * surfaceDiameter(annulus), 20150805u);
        SolveSession session(surface, {});
        QVERIFY(session.step(10).succeeded());
        const QString failed = solvedWithoutDegenerating(surface, session.surface());
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
    }

    void stateUnitFollowsTheControlSpacingOfFineDesigns() {
        // The examples are coarser than the sessions' unit: their state is in diameters.
        for (const char* name : {"sheet", "annulus", "cylinder", "mixed", "fig6", "fig8"}) {
            const model::CompositeSurface s = model::makeExample(name).surfaces.front();
            const double diameter = surfaceDiameter(s);
            QCOMPARE(stateUnit(s, diameter, kSessionControlSpacingUnit), diameter);
            QCOMPARE(SurfaceFormulation(s, defaultSessionFormulationOptions()).scale(), diameter);
        }
        // The annulus of size 30 (control segments 0.0078 of its diameter) is measured in
        // segments over the unit; 0 keeps the diameter.
        const model::CompositeSurface fine = model::makeExample("annulus", 30).surfaces.front();
        const double diameter = surfaceDiameter(fine);
        const double spacing = meanControlSpacing(fine);
        QVERIFY(spacing < 0.01 * diameter);
        QCOMPARE(stateUnit(fine, diameter, kSessionControlSpacingUnit),
                 spacing / kSessionControlSpacingUnit);
        QCOMPARE(stateUnit(fine, diameter, 0.0), diameter);
        QCOMPARE(stateUnit(fine, 0.0, kSessionControlSpacingUnit), 1.0);
    }

    void fineAnnulusIsRegularisedLikeACoarseOne() {
        // The annulus of size 14 (control segments 0.016 of its diameter), seed 20150802 of the
        // benchmark's start of 10 % of its mean control segment, solved as Tools ▸ Solve does
        // with three boundary vertices pinned. Measured with the diameter as the state's unit:
        // det 1.5e-4 after 10 iterations and a ruling at 0.11 of its start length (the
        // regularisation, measured in diameters, is 6 times weaker against the constraints
        // than on the annulus of size 6). In units of its control spacing: 5e-13, rulings
        // 0.73, on the geometry.
        const model::CompositeSurface fine = model::makeExample("annulus", 14).surfaces.front();
        const model::CompositeSurface surface =
            studyStart("annulus", 14, 0.1 * meanControlSpacing(fine), 20150802u);
        auto solve = [&surface](double unit) {
            SessionOptions options;
            options.formulation.controlSpacingUnit = unit;
            SolveSession session(surface, {}, options);
            const Summary summary = session.step(10);
            return summary.succeeded() ? session.surface() : surface;
        };
        const model::CompositeSurface inDiameters = solve(0.0);
        QVERIFY2(!solvedWithoutDegenerating(surface, inDiameters).isEmpty(),
                 "the diameter as unit no longer fails here; choose another seed");
        const QString failed =
            solvedWithoutDegenerating(surface, solve(kSessionControlSpacingUnit));
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
    }

    void roughAnnulusKeepsItsRulingsAndSpeeds() {
        // Seed 20150804 of the benchmark's 1 % start on the annulus (σ = 1 % of the diameter,
        // 30 % of the ring width): with the default options its rulings collapse to nothing
        // and its creases cusp. With the proximity to the start, every ruling keeps a quarter
        // of its start length and every curve a tenth of its mean speed, measured on the
        // geometry, and the surface is developable to 1e-6.
        model::CompositeSurface surface = model::makeExample("annulus", 0).surfaces.front();
        const auto anchors = spreadBoundaryVertices(surface, 3);
        perturbSurface(surface, 0.01 * surfaceDiameter(surface), 20150804u, anchors);
        const double startDet = measureQuality(surface).developabilityMax;
        auto solve = [&](const FormulationOptions& base, const Options& options) {
            FormulationOptions formulation = base;
            for (auto v : anchors) {
                formulation.handles.push_back({v, true, {}});
            }
            const SurfaceFormulation f(surface, formulation);
            std::vector<double> x = f.initialState();
            GuidedProjection projection;
            const Summary summary = projection.solve(f.problem(), x, options);
            model::CompositeSurface out = surface;
            if (!summary.succeeded() || !f.writeBack(x, out)) {
                return surface;
            }
            return out;
        };
        Options defaults;
        defaults.maxIterations = 10;
        const model::CompositeSurface before = solve(FormulationOptions{}, defaults);
        const ShapeChange collapsed = measureShapeChange(surface, before);
        QVERIFY2(collapsed.shortestRuling < 0.25 || collapsed.slowestSpeed < 0.1,
                 "the default options no longer degenerate here; choose another seed");

        const model::CompositeSurface after = solve(roughStartFormulation(), roughStartOptions());
        const ShapeChange change = measureShapeChange(surface, after);
        QVERIFY2(change.shortestRuling >= 0.25,
                 qPrintable(QString("shortest ruling %1").arg(change.shortestRuling)));
        QVERIFY2(change.slowestSpeed >= 0.1,
                 qPrintable(QString("slowest speed %1").arg(change.slowestSpeed)));
        // Not crumpled: the creases fold less than the start's noise.
        QVERIFY(change.creaseFoldMean <= change.startNormalAngleMean);
        // Measured: det 7.8e-9, shortest ruling 0.40, slowest speed 0.13, creases flat (the
        // default options: det 0.19, rulings and speeds 0.000, creases folded by 98°).
        const double det = measureQuality(after).developabilityMax;
        QVERIFY2(det <= 1e-6 && det < 1e-4 * startDet,
                 qPrintable(QString("det %1 from %2").arg(det).arg(startDet)));
    }
};

DEVSURF_REGISTER_TEST(TstRoughStart);
#include "tst_rough_start.moc"
