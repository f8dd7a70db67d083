#include "model/development.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "test_registry.h"

#include <QTest>

#include <cmath>
#include <set>

using namespace devsurf::model;

namespace {

double signedAreaXY(const SampledMesh& mesh, const std::vector<int>& face) {
    double area = 0.0;
    for (std::size_t i = 0; i < face.size(); ++i) {
        const Vec3& p = mesh.vertices[face[i]];
        const Vec3& q = mesh.vertices[face[(i + 1) % face.size()]];
        area += p.x * q.y - p.y * q.x;
    }
    return area / 2;
}

} // namespace

class TstDevelopment : public QObject {
    Q_OBJECT
private slots:
    void sampledMeshSharesCreaseSamples() {
        const CompositeSurface sheet = makeExample("sheet", 3).surfaces[0];
        const int samples = 4;
        const SampledMesh mesh = sampleSurface(sheet, samples);
        // 16 vertices + 12 S-edges × (3 intervals × 4 samples − 1) interior samples.
        QCOMPARE(mesh.vertices.size(), std::size_t(16 + 12 * (3 * samples - 1)));
        QCOMPARE(mesh.faces.size(), std::size_t(9 * 3 * samples));
        // Each interior sampled edge is used by exactly two faces: the mesh is connected.
        std::map<std::pair<int, int>, int> uses;
        for (const auto& face : mesh.faces) {
            for (std::size_t i = 0; i < face.size(); ++i) {
                const int a = face[i];
                const int b = face[(i + 1) % face.size()];
                ++uses[{std::min(a, b), std::max(a, b)}];
            }
        }
        for (const auto& entry : uses) {
            QVERIFY(entry.second == 1 || entry.second == 2);
        }
        // Oriented like the coarse faces: every flat example is counter-clockwise seen from +z.
        for (const char* name : {"sheet", "annulus", "mixed"}) {
            const SampledMesh flat = sampleSurface(makeExample(name).surfaces[0], samples);
            for (const auto& face : flat.faces) {
                QVERIFY2(signedAreaXY(flat, face) > 0, name);
            }
        }
    }

    void flatExamplesDevelopOntoThemselves() {
        for (const char* name : {"sheet", "annulus", "mixed"}) {
            const SampledMesh mesh = sampleSurface(makeExample(name).surfaces[0], 5);
            const Development dev = unfoldSampledMesh(mesh);
            QCOMPARE(dev.components, 1);
            QVERIFY(!dev.period);
            QVERIFY2(dev.closureError < 1e-8, name);
            QVERIFY(dev.maxEdgeLengthError < 1e-10);
            double worst = 0;
            for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
                worst = std::max(
                    worst, (dev.vertices[i] - Vec2(mesh.vertices[i].x, mesh.vertices[i].y)).norm());
            }
            QVERIFY2(worst < 1e-8, qPrintable(QString("%1: %2").arg(name).arg(worst)));
        }
    }

    void cylinderDevelopsWithAPeriod() {
        const CompositeSurface cylinder = makeExample("cylinder", 6).surfaces[0];
        const SampledMesh mesh = sampleSurface(cylinder, 6);
        const Development dev = unfoldSampledMesh(mesh);
        QVERIFY(dev.period.has_value());
        QVERIFY(dev.closureError < 1e-8);
        QVERIFY(dev.maxEdgeLengthError < 1e-10);
        // The period is the length of the sampled bottom polygon (all curves at z = 0).
        double perimeter = 0;
        for (const auto& polyline : mesh.splineEdges) {
            if (mesh.vertices[polyline.vertices.front()].z == 0.0) {
                for (std::size_t i = 0; i + 1 < polyline.vertices.size(); ++i) {
                    perimeter += distance(mesh.vertices[polyline.vertices[i]],
                                          mesh.vertices[polyline.vertices[i + 1]]);
                }
            }
        }
        QVERIFY(std::abs(dev.period->x - perimeter) < 1e-8 * perimeter);
        QVERIFY(std::abs(dev.period->y) < 1e-8 * perimeter);
        QVERIFY(std::abs(perimeter - 2 * 3.14159265358979 * 100) < 0.02 * perimeter);
    }

    void bentSurfaceIsNotExact() {
        // A sheet with one vertex lifted: some quads are no longer planar, so the unfolding
        // cannot close up and the error measures say so.
        CompositeSurface sheet = makeExample("sheet", 3).surfaces[0];
        sheet.moveVertex(5, sheet.position(5) + Vec3(0, 0, 40));
        const SampledMesh mesh = sampleSurface(sheet, 4);
        const Development dev = unfoldSampledMesh(mesh);
        QVERIFY(dev.closureError > 1e-3);
    }

    void liftedAnnulusHasNoPeriod() {
        // One vertex 1 mm out of the plane: the ring no longer closes exactly, but what is left
        // over varies along the seam; it is no translation to read the development modulo.
        for (const VertexId lifted : {VertexId(0), VertexId(20)}) {
            CompositeSurface annulus = makeExample("annulus").surfaces[0];
            annulus.moveVertex(lifted, annulus.position(lifted) + Vec3(0, 0, 1));
            const Development dev = unfoldSampledMesh(sampleSurface(annulus, 8));
            QVERIFY(!dev.period.has_value());
            double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
            for (const Vec2& p : dev.vertices) {
                minX = std::min(minX, p.x);
                maxX = std::max(maxX, p.x);
                minY = std::min(minY, p.y);
                maxY = std::max(maxY, p.y);
            }
            QVERIFY(maxX - minX > 450 && maxY - minY > 450);
        }
        // The cylinder keeps its period.
        QVERIFY(unfoldSampledMesh(sampleSurface(makeExample("cylinder").surfaces[0], 8)).period);
    }
};

DEVSURF_REGISTER_TEST(TstDevelopment);
#include "tst_development.moc"
