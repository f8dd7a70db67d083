#include "model/reference/point_index.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <random>

using namespace devsurf::model;
using namespace devsurf::model::reference;

class TstPointIndex : public QObject {
    Q_OBJECT
private slots:
    void pointIndexAgreesWithBruteForce() {
        std::mt19937 random(7);
        std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
        std::vector<Vec3> points(3000);
        for (Vec3& p : points) {
            p = Vec3(coordinate(random), coordinate(random), coordinate(random));
        }
        points.push_back(points[10]); // a duplicate
        const PointIndex index(points);
        std::vector<PointIndex::Neighbour> found;
        for (int trial = 0; trial < 50; ++trial) {
            const Vec3 q(coordinate(random), coordinate(random), coordinate(random));
            std::vector<double> sorted;
            for (const Vec3& p : points) {
                sorted.push_back((p - q).squaredNorm());
            }
            std::vector<double> byDistance = sorted;
            std::sort(byDistance.begin(), byDistance.end());
            QCOMPARE(index.nearest(q).squaredDistance, byDistance[0]);
            QCOMPARE(sorted[index.nearest(q).index], byDistance[0]);
            const auto nearest = index.nearest(q, 12);
            QCOMPARE(nearest.size(), std::size_t{12});
            for (std::size_t k = 0; k < nearest.size(); ++k) {
                QCOMPARE(nearest[k].squaredDistance, byDistance[k]);
            }
            const double radius = 0.3;
            index.withinRadius(q, radius, found);
            const auto inside = static_cast<std::size_t>(
                std::count_if(sorted.begin(), sorted.end(),
                              [radius](double d2) { return d2 < radius * radius; }));
            QCOMPARE(found.size(), inside);
            for (std::size_t k = 0; k < found.size(); ++k) {
                QCOMPARE(found[k].squaredDistance, byDistance[k]);
            }
        }
        QCOMPARE(index.nearest(Vec3(0, 0, 0), 5000).size(), points.size());
        QVERIFY_THROWS_EXCEPTION(std::logic_error, PointIndex({}).nearest(Vec3()));
    }
};

DEVSURF_REGISTER_TEST(TstPointIndex);
#include "tst_point_index.moc"
