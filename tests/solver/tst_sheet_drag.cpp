// Two-way editing (§5): a vertex's place in the held sheet dragged as the development view
// does, through the solve job. The surface follows its sheet, measured from the geometry; a
// place dragged farther than the sheet allows follows part of the way, as a vertex drag does.

#include "model/composite_surface.h"
#include "model/development.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/session/job_assessment.h"
#include "solver/session/solve_job.h"
#include "solver_test_drags.h"
#include "solver_test_models.h"
#include "test_registry.h"

#include <QtTest>

#include <cmath>
#include <optional>
#include <vector>

using namespace devsurf;
using model::Vec2;
using solver::testing::pairLengthError;

namespace {

constexpr int kSheetDragSamples = model::kDevelopmentSamplesPerInterval;

// solver::testing::heldSquare with its middle rows lifted 60 mm keeping lengths; `dragged` an
// inner vertex of the lower middle row.
struct BentSquare {
    model::CompositeSurface bent;
    model::VertexId dragged = model::kInvalidId;
};

BentSquare bentSquare() {
    const solver::testing::HeldSquare square = solver::testing::heldSquare();
    BentSquare result;
    if (square.held) {
        result.bent = solver::testing::dragUp(square.surface, square.middle, 60.0).surface;
        result.dragged = square.middle.at(1);
    }
    return result;
}

// `vertex`'s place in the sheet moved by `by` in 20 moves through the solve job, then released.
solver::JobOutcome dragInSheet(const model::CompositeSurface& start, model::VertexId vertex,
                               const Vec2& by) {
    const Vec2 from = *solver::sheetPlace(start, vertex);
    return solver::testing::dragThroughJob(start, 20, [&](solver::JobRequest& request, double t) {
        request.pulledSheet[0].push_back({vertex, from + by * t});
    });
}

// Developable, on the square, isometric to its development and folded over nowhere, measured
// from the geometry.
void checkKeptOnItsSheet(const model::CompositeSurface& result) {
    QVERIFY(result.validate().empty());
    QVERIFY(solver::measureQuality(result).developabilityMax < 1e-8);
    QVERIFY2(pairLengthError(result, result.development()) < 1e-6,
             qPrintable(QString::number(pairLengthError(result, result.development()))));
    const double gap = model::largestDomainGap(result.sheetDomain(),
                                               model::sampleSurface(result, kSheetDragSamples),
                                               result.development());
    QVERIFY2(gap < 1e-6, qPrintable(QString::number(gap)));
    QVERIFY(solver::foldOvers(result).empty());
}

} // namespace

class TstSheetDrag : public QObject {
    Q_OBJECT

private slots:
    void draggingThePlaceInTheSheetMovesTheSurface_data() {
        QTest::addColumn<double>("dx");
        QTest::addColumn<double>("dy");
        QTest::newRow("10 mm up") << 0.0 << 10.0;
        QTest::newRow("20 mm up") << 0.0 << 20.0;
        QTest::newRow("20 mm left") << -20.0 << 0.0;
    }

    void draggingThePlaceInTheSheetMovesTheSurface() {
        // The place follows the mouse, the vertex moves in space and the surface stays on its
        // sheet. (20 mm up pinched the top edge's curve at its corner in the first settling and
        // was taken back, while the second settling started from the drag's first move; it
        // starts from the last now.)
        QFETCH(double, dx);
        QFETCH(double, dy);
        const Vec2 by(dx, dy);
        const BentSquare start = bentSquare();
        QVERIFY(start.bent.validate().empty() && start.bent.keepsDevelopment());
        const solver::JobOutcome outcome = dragInSheet(start.bent, start.dragged, by);
        QVERIFY2(outcome.ok, outcome.failure.detail.c_str());
        const model::CompositeSurface& result = outcome.surfaces.front();
        const solver::SurfaceAssessment& a = outcome.assessments.front();
        QVERIFY(a.sheetHeld && !a.takenBack);
        QVERIFY2(a.largestHandleGap < 1e-3, qPrintable(QString::number(a.largestHandleGap)));
        const Vec2 place = *solver::sheetPlace(result, start.dragged);
        const Vec2 target = *solver::sheetPlace(start.bent, start.dragged) + by;
        QVERIFY((place - target).norm() < 1e-3); // measured here, not by the assessment
        const double moved =
            model::distance(result.position(start.dragged), start.bent.position(start.dragged));
        qInfo("moved %.1f mm in space", moved);
        QVERIFY2(moved > 10.0, qPrintable(QString::number(moved)));
        checkKeptOnItsSheet(result);
        // A surface that holds no sheet has no place in one to drag.
        solver::JobRequest unheld;
        unheld.kind = solver::JobKind::VertexDrag;
        unheld.surfaces = {model::makeExample("sheet").surfaces.front()};
        unheld.pulledSheet[0].push_back({start.dragged, target});
        QVERIFY(!solver::SolveJob().run(unheld).ok);
    }

    void aPlaceDraggedTooFarFollowsPartway() {
        // 40 mm up the sheet ends broken when released at the mouse; it follows part of the
        // way instead of being taken back to the press (measured: 60 %, 16 mm short), its place
        // nearer the target than at the press, the surface kept on its sheet.
        const BentSquare start = bentSquare();
        const Vec2 by(0.0, 40.0);
        const solver::JobOutcome outcome = dragInSheet(start.bent, start.dragged, by);
        QVERIFY2(outcome.ok, outcome.failure.detail.c_str());
        const solver::SurfaceAssessment& a = outcome.assessments.front();
        QVERIFY(a.takenBack);
        qInfo("followed %.0f %%, %.1f mm short", 100.0 * a.followed, a.largestHandleGap);
        QVERIFY2(a.followed > 0.0 && a.followed < 1.0, qPrintable(QString::number(a.followed)));
        const model::CompositeSurface& result = outcome.surfaces.front();
        const Vec2 before = *solver::sheetPlace(start.bent, start.dragged);
        const Vec2 place = *solver::sheetPlace(result, start.dragged);
        const Vec2 target = before + by;
        QVERIFY(std::abs((place - target).norm() - a.largestHandleGap) < 1e-9);
        QVERIFY((place - target).norm() < by.norm() - 5.0);
        checkKeptOnItsSheet(result);
    }

    void aPlacePulledOffTheSheetNeverEndsOffIt() {
        // A place on the square's top edge pulled 30 mm beyond it, out of the sheet: the sheet
        // cannot follow. Whatever the drag keeps (a part of the way, or the press) lies on the
        // square and reaches the tolerance. (The partway search used to settle its states with
        // the place still pulled off the edge and kept one at residual 1e-2, its boundary off
        // the square.)
        const BentSquare start = bentSquare();
        model::VertexId top = model::kInvalidId;
        for (const auto& [id, p] : start.bent.vertices()) {
            (void)p;
            const std::optional<Vec2> place = solver::sheetPlace(start.bent, id);
            if (place && !start.bent.isPinned(id) && std::abs(place->y - 300.0) < 1e-6 &&
                place->x > 1.0 && place->x < 299.0) {
                top = id;
            }
        }
        QVERIFY(top != model::kInvalidId);
        const solver::JobOutcome outcome = dragInSheet(start.bent, top, Vec2(0.0, 30.0));
        QVERIFY2(outcome.ok, outcome.failure.detail.c_str());
        const solver::SurfaceAssessment& a = outcome.assessments.front();
        qInfo("followed %.0f %%, residual %.2g, taken back %d", 100.0 * a.followed,
              a.summary.finalMaxConstraintResidual, a.takenBack ? 1 : 0);
        QVERIFY(a.summary.toleranceReached);
        checkKeptOnItsSheet(outcome.surfaces.front());
    }
};

DEVSURF_REGISTER_TEST(TstSheetDrag);
#include "tst_sheet_drag.moc"
