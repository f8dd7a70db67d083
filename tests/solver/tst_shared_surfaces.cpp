// The surfaces of a request are shared between copies of it and copied only when changed
// (solver::SharedSurfaces): a drag's moves send the press without copying it.

#include "model/examples.h"
#include "solver/session/solve_job.h"
#include "test_registry.h"

#include <QTest>

using namespace devsurf;

class TstSharedSurfaces : public QObject {
    Q_OBJECT

private slots:
    void copiesShareUntilOneChanges() {
        const model::CompositeSurface sheet = model::makeExample("sheet").surfaces.front();
        solver::SharedSurfaces press{sheet, model::makeExample("annulus").surfaces.front()};
        QCOMPARE(press.size(), std::size_t(2));
        QVERIFY(press[0] == sheet);

        solver::JobRequest move;
        move.surfaces = press;
        QCOMPARE(&move.surfaces[0], &press[0]); // the same surfaces, not a copy

        // Changing one holder leaves the other as it was.
        move.surfaces.mutableSurfaces()[0].setPinned(sheet.vertices().begin()->first, true);
        QVERIFY(&move.surfaces[0] != &press[0]);
        QVERIFY(press[0] == sheet);
        QVERIFY(!(move.surfaces[0] == sheet));

        // A sole holder changes in place.
        const model::CompositeSurface* before = &move.surfaces[1];
        const model::VertexId vertex = before->vertices().begin()->first;
        move.surfaces.mutableSurfaces()[1].setPinned(vertex, !before->isPinned(vertex));
        QCOMPARE(&move.surfaces[1], before);
        move.surfaces.push_back(sheet);
        QCOMPARE(move.surfaces.size(), std::size_t(3));
        QCOMPARE(press.size(), std::size_t(2));
    }

    void anEmptyRequestHasNoSurfaces() {
        const solver::JobRequest request;
        QVERIFY(request.surfaces.empty());
        QVERIFY(request.surfaces.begin() == request.surfaces.end());
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, request.surfaces.at(0));
    }
};

DEVSURF_REGISTER_TEST(TstSharedSurfaces);
#include "tst_shared_surfaces.moc"
