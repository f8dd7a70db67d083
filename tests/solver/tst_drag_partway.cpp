// A drag whose release would end broken follows part of the way (solver/session/drag_partway.h):
// through the solve job as the Drag tool runs it, measured from the geometry.
#include "model/composite_surface.h"
#include "model/examples.h"
#include "model/math_constants.h"
#include "sampled_developability.h"
#include "solver/quality/shape_change.h"
#include "solver/session/solve_job.h"
#include "solver/session/verdict.h"
#include "test_registry.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

using namespace devsurf;
using model::Vec3;
using test::sampledDevelopability;

namespace {
using devsurf::model::kPi;
} // namespace

class TstDragPartway : public QObject {
    Q_OBJECT

private slots:
    void aTurnTooFarIsFollowedPartway() {
        // The paper's Fig. 8, bottom row, without a held sheet: fig8 lifted 85 mm, then its
        // middle turned 30° about the vertical, both through the solve job as the Drag tool
        // runs them. The whole turn ends broken (a patch folds over); instead of taking it all
        // back, the design follows the longest start of the turn that ends developable: the
        // middle turns part of the way and lags behind the mouse.
        const model::CompositeSurface flat = model::makeExample("fig8").surfaces.front();
        const std::vector<model::VertexId> middle{5, 6, 9, 10};
        solver::SolveJob job;
        auto drag = [&](const model::CompositeSurface& start, std::uint64_t id,
                        const std::function<Vec3(model::VertexId, double)>& at) {
            solver::JobOutcome outcome;
            constexpr int kMoves = 20;
            for (int k = 1; k <= kMoves + 1; ++k) {
                solver::JobRequest request;
                request.kind = solver::JobKind::VertexDrag;
                request.drag = id;
                request.settle = k > kMoves;
                request.surfaces = {start};
                for (model::VertexId v : middle) {
                    request.pulled[0].push_back(
                        {v, false, at(v, std::min(k, kMoves) / static_cast<double>(kMoves))});
                }
                outcome = job.run(request);
                if (!outcome.ok) {
                    break;
                }
            }
            return outcome;
        };
        const solver::JobOutcome lift = drag(flat, 21, [&](model::VertexId v, double t) {
            return flat.position(v) + Vec3(0.0, 0.0, 85.0 * t);
        });
        QVERIFY2(lift.ok, lift.failure.detail.c_str());
        QVERIFY(!lift.assessments.front().takenBack);
        const model::CompositeSurface lifted = lift.surfaces.front();
        const Vec3 axis(150.0, 171.65, 0.0);
        auto turned = [&](model::VertexId v, double t) {
            const double angle = 30.0 * kPi / 180.0 * t;
            const Vec3 p = lifted.position(v) - axis;
            return axis + Vec3(std::cos(angle) * p.x - std::sin(angle) * p.y,
                               std::sin(angle) * p.x + std::cos(angle) * p.y, p.z);
        };
        const solver::JobOutcome turn = drag(lifted, 22, turned);
        QVERIFY2(turn.ok, turn.failure.detail.c_str());
        const solver::SurfaceAssessment& a = turn.assessments.front();
        QVERIFY(a.takenBack);
        QVERIFY(solver::broken(*a.takenBack));
        QVERIFY2(a.followed > 0.0 && a.followed < 1.0, qPrintable(QString::number(a.followed)));
        QVERIFY(!solver::broken(a));
        const model::CompositeSurface& s = turn.surfaces.front();
        // Turned part of the way, measured from the geometry: each middle vertex moved from
        // the lifted state towards its turned target, and lags behind it.
        for (model::VertexId v : middle) {
            const Vec3 wanted = turned(v, 1.0) - lifted.position(v);
            const Vec3 moved = s.position(v) - lifted.position(v);
            QVERIFY2(model::dot(moved, wanted) > 0.05 * wanted.norm() * wanted.norm(),
                     qPrintable(QString("vertex %1 moved %2 of %3 mm")
                                    .arg(v)
                                    .arg(moved.norm())
                                    .arg(wanted.norm())));
        }
        QVERIFY2(a.largestHandleGap > 1.0, qPrintable(QString::number(a.largestHandleGap)));
        const double developability = sampledDevelopability(s);
        qInfo("followed %.0f %%, held back %.1f mm, det %.2g", 100.0 * a.followed,
              a.largestHandleGap, developability);
        QVERIFY2(developability < 1e-5, qPrintable(QString::number(developability)));
        QVERIFY(solver::foldOvers(s).empty());
    }
};

DEVSURF_REGISTER_TEST(TstDragPartway);

#include "tst_drag_partway.moc"
