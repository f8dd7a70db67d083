// The derived geometry shared by the views, the solver's measures, the writers and the command
// line (model::DerivedGeometry): computed once per surface state and sample density.
#include "model/derived_geometry.h"
#include "model/examples.h"
#include "model/model_error.h"
#include "test_registry.h"

#include <QTest>

#include <thread>

using namespace devsurf::model;

namespace {

bool sameMesh(const SampledMesh& a, const SampledMesh& b) {
    return a.vertices == b.vertices && a.faces == b.faces && a.faceOrigin == b.faceOrigin &&
           a.rulings == b.rulings;
}

} // namespace

class TstDerivedGeometry : public QObject {
    Q_OBJECT
private slots:
    void init() { DerivedGeometry::clearCache(); }

    void oneStateIsDerivedOnceAndEqualsTheDirectComputation() {
        const CompositeSurface fig8 = makeExample("fig8").surfaces.front();
        const auto first = DerivedGeometry::of(fig8, 8);
        QCOMPARE(DerivedGeometry::cachedCount(), std::size_t{1});
        // The same state, also as a copy under another name and id, is the same entry.
        CompositeSurface renamed = fig8;
        renamed.setName("another");
        renamed.setId(77);
        QCOMPARE(DerivedGeometry::of(fig8, 8).get(), first.get());
        QCOMPARE(DerivedGeometry::of(renamed, 8).get(), first.get());
        QCOMPARE(DerivedGeometry::cachedCount(), std::size_t{1});
        // What it holds is what the functions it stands for compute.
        const SampledMesh direct = sampleSurface(fig8, 8);
        QVERIFY(sameMesh(first->mesh(), direct));
        QVERIFY(first->development().vertices == unfoldSampledMesh(direct).vertices);
        const std::vector<Crease> creases = creasesOf(fig8, stripsOf(fig8), direct);
        QCOMPARE(first->creases().size(), creases.size());
        for (std::size_t i = 0; i < creases.size(); ++i) {
            QCOMPARE(first->creases()[i].edge, creases[i].edge);
            QCOMPARE(first->creases()[i].foldAngleDegrees, creases[i].foldAngleDegrees);
        }
    }

    void anotherStateOrDensityIsAnotherEntry() {
        CompositeSurface sheet = makeExample("sheet").surfaces.front();
        const auto flat = DerivedGeometry::of(sheet, 4);
        QVERIFY(DerivedGeometry::of(sheet, 5).get() != flat.get());
        const VertexId v = sheet.vertices().begin()->first;
        sheet.moveVertex(v, sheet.position(v) + Vec3{0.0, 0.0, 1e-9});
        const auto moved = DerivedGeometry::of(sheet, 4);
        QVERIFY(moved.get() != flat.get());
        QVERIFY(!(moved->mesh().vertices == flat->mesh().vertices));
        // An entry stays valid for whoever holds it, after the cache let it go.
        for (int k = 1; k <= static_cast<int>(DerivedGeometry::kCacheCapacity) + 5; ++k) {
            sheet.moveVertex(v, sheet.position(v) + Vec3{0.0, 0.0, 1.0});
            DerivedGeometry::of(sheet, 4);
        }
        QCOMPARE(DerivedGeometry::cachedCount(), DerivedGeometry::kCacheCapacity);
        QVERIFY(sameMesh(flat->mesh(), sampleSurface(makeExample("sheet").surfaces.front(), 4)));
    }

    void threadsShareTheCache() {
        const CompositeSurface annulus = makeExample("annulus").surfaces.front();
        std::shared_ptr<const DerivedGeometry> a;
        std::shared_ptr<const DerivedGeometry> b;
        std::thread first([&] { a = DerivedGeometry::of(annulus, 6); });
        std::thread second([&] { b = DerivedGeometry::of(annulus, 6); });
        first.join();
        second.join();
        QVERIFY(sameMesh(a->mesh(), b->mesh()));
        QVERIFY(a->development().vertices == b->development().vertices);
        const auto later = DerivedGeometry::of(annulus, 6);
        QVERIFY(later.get() == a.get() || later.get() == b.get());
    }

    void anInvalidSurfaceIsRefused() {
        QVERIFY_THROWS_EXCEPTION(ModelError, DerivedGeometry::of(CompositeSurface(), 4));
    }
};

DEVSURF_REGISTER_TEST(TstDerivedGeometry);
#include "tst_derived_geometry.moc"
