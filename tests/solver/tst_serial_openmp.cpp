#include "solver/core/serial_openmp.h"

#include "test_registry.h"

#include <QTest>

#include <omp.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>

using namespace devsurf::solver;

namespace {

// What one parallel region of four threads saw: how many times its body ran, on which threads,
// and the team size the body was told.
struct Region {
    int bodies = 0;
    std::set<std::thread::id> threads;
    int teamSize = 0;
};

Region runRegion() {
    Region region;
    std::mutex mutex;
#pragma omp parallel num_threads(4)
    {
        const std::lock_guard<std::mutex> lock(mutex);
        ++region.bodies;
        region.threads.insert(std::this_thread::get_id());
        region.teamSize = omp_get_num_threads();
    }
    return region;
}

// Allows active parallel regions for the lifetime of an instance (the solver turns them off).
class ActiveRegions {
public:
    ActiveRegions() : m_saved(omp_get_max_active_levels()) { omp_set_max_active_levels(1); }
    ~ActiveRegions() { omp_set_max_active_levels(m_saved); }

private:
    int m_saved;
};

} // namespace

class TstSerialOpenMp : public QObject {
    Q_OBJECT

private slots:
    void regionsRunOnTheCallingThreadInside() {
        const SerialOpenMpRegions serial;
        {
            const ActiveRegions active; // even where OpenMP would start a team
            const Region region = runRegion();
            QCOMPARE(region.bodies, 1);
            QCOMPARE(region.teamSize, 1);
            QCOMPARE(region.threads, std::set<std::thread::id>{std::this_thread::get_id()});
        }
    }

    void regionsGoToOpenMpOutside() {
        QVERIFY(!serialOpenMpRegionsActive());
        const ActiveRegions active;
        const Region region = runRegion();
        QCOMPARE(region.bodies, 4);
        QCOMPARE(region.teamSize, 4);
        QCOMPARE(region.threads.size(), std::size_t{4});
    }

    void onlyTheThreadInsideIsSerial() {
        const ActiveRegions active;
        const SerialOpenMpRegions serial;
        Region other;
        std::thread thread([&other] { other = runRegion(); });
        thread.join();
        QCOMPARE(other.bodies, 4);
        QCOMPARE(runRegion().bodies, 1);
    }

    void nestedInstancesKeepItOnUntilTheOutermostEnds() {
        {
            const SerialOpenMpRegions outer;
            {
                const SerialOpenMpRegions inner;
                QVERIFY(serialOpenMpRegionsActive());
            }
            QVERIFY(serialOpenMpRegionsActive());
        }
        QVERIFY(!serialOpenMpRegionsActive());
    }
};

DEVSURF_REGISTER_TEST(TstSerialOpenMp);
#include "tst_serial_openmp.moc"
