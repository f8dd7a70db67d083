#include "solver/core/blas_info.h"

#include "test_registry.h"

#include <QTest>

#include <cstdlib>
#include <optional>
#include <string>

using namespace devsurf::solver;

namespace {

CpuFeatures features(bool avx2, bool fma, bool avx512) {
    CpuFeatures cpu;
    cpu.avx2 = avx2;
    cpu.fma = fma;
    cpu.avx512 = avx512;
    return cpu;
}

const CpuFeatures kSse = features(false, false, false);
const CpuFeatures kAvx2Fma = features(true, true, false);
const CpuFeatures kAvx512 = features(true, true, true);

// Sets an environment variable for the lifetime of an instance, then restores it.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : m_name(name) {
        if (const char* old = std::getenv(name)) {
            m_old = old;
        }
        if (value) {
            setenv(name, value, 1);
        } else {
            unsetenv(name);
        }
    }
    ~ScopedEnv() {
        if (m_old) {
            setenv(m_name, m_old->c_str(), 1);
        } else {
            unsetenv(m_name);
        }
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* m_name;
    std::optional<std::string> m_old;
};

} // namespace

// The kernel decision of useBestBlasKernel() as a pure function of OpenBLAS's kernel name and
// the CPU's features, and who chose the kernel as detectBlas() reports it.
class TstBlasKernel : public QObject {
    Q_OBJECT

private slots:
    void genericKernelOnAnAvx512CpuAsksForSkylakeX() {
        QCOMPARE(recommendedCoreType("Prescott", kAvx512), std::string("SkylakeX"));
        QCOMPARE(recommendedCoreType("Nehalem", kAvx512), std::string("SkylakeX"));
    }

    void genericKernelOnAnAvx2CpuAsksForHaswell() {
        QCOMPARE(recommendedCoreType("Prescott", kAvx2Fma), std::string("Haswell"));
        QCOMPARE(recommendedCoreType("Sandybridge", kAvx2Fma), std::string("Haswell"));
        QCOMPARE(recommendedCoreType("Core2", kAvx2Fma), std::string("Haswell"));
    }

    void anAvxKernelOnAnAvx512CpuAsksForSkylakeX() {
        QCOMPARE(recommendedCoreType("Sandybridge", kAvx512), std::string("SkylakeX"));
        QCOMPARE(recommendedCoreType("Excavator", kAvx512), std::string("SkylakeX"));
    }

    void anAvx2KernelStaysOnAnAvx512Cpu() {
        QCOMPARE(recommendedCoreType("Haswell", kAvx512), std::string());
        QCOMPARE(recommendedCoreType("Zen", kAvx512), std::string());
    }

    void aKernelThatFitsTheCpuIsKept() {
        QCOMPARE(recommendedCoreType("SkylakeX", kAvx512), std::string());
        QCOMPARE(recommendedCoreType("Cooperlake", kAvx512), std::string());
        QCOMPARE(recommendedCoreType("Haswell", kAvx2Fma), std::string());
        QCOMPARE(recommendedCoreType("Zen", kAvx2Fma), std::string());
        QCOMPARE(recommendedCoreType("Prescott", kSse), std::string());
        QCOMPARE(recommendedCoreType("Sandybridge", kSse), std::string());
    }

    void avx2WithoutFmaIsNotEnoughForHaswell() {
        QCOMPARE(recommendedCoreType("Prescott", features(true, false, false)), std::string());
    }

    void kernelNamesAreMatchedWithoutCase() {
        QCOMPARE(recommendedCoreType("PRESCOTT", kAvx2Fma), std::string("Haswell"));
        QCOMPARE(recommendedCoreType("skylakex", kAvx512), std::string());
    }

    void anUnknownKernelIsLeftAlone() {
        QCOMPARE(recommendedCoreType("", kAvx512), std::string());
        QCOMPARE(recommendedCoreType("ARMV8", kAvx512), std::string());
        QCOMPARE(recommendedCoreType("Zen5", kAvx512), std::string());
    }

    void whoChoseTheKernel() {
        if (detectBlas().kernel.empty()) {
            QSKIP("the BLAS in this process names no kernel (not OpenBLAS)");
        }
        {
            const ScopedEnv core("OPENBLAS_CORETYPE", nullptr);
            const ScopedEnv ours("DEVSURF_OPENBLAS_CORETYPE", nullptr);
            QCOMPARE(detectBlas().kernelChosenBy, std::string("OpenBLAS"));
        }
        {
            const ScopedEnv core("OPENBLAS_CORETYPE", "Haswell");
            const ScopedEnv ours("DEVSURF_OPENBLAS_CORETYPE", nullptr);
            QCOMPARE(detectBlas().kernelChosenBy, std::string("OPENBLAS_CORETYPE"));
        }
        {
            const ScopedEnv core("OPENBLAS_CORETYPE", "Haswell");
            const ScopedEnv ours("DEVSURF_OPENBLAS_CORETYPE", "Haswell");
            QCOMPARE(detectBlas().kernelChosenBy, std::string("DevSurf"));
        }
        {
            // The user changed it after DevSurf had chosen (a child process inherits both).
            const ScopedEnv core("OPENBLAS_CORETYPE", "Sandybridge");
            const ScopedEnv ours("DEVSURF_OPENBLAS_CORETYPE", "Haswell");
            QCOMPARE(detectBlas().kernelChosenBy, std::string("OPENBLAS_CORETYPE"));
        }
    }

    void anExplicitCoreTypeIsNeverOverridden() {
        // With OPENBLAS_CORETYPE set, useBestBlasKernel() returns: no re-exec, the variable
        // and the marker untouched.
        const ScopedEnv core("OPENBLAS_CORETYPE", "Prescott");
        const ScopedEnv ours("DEVSURF_OPENBLAS_CORETYPE", nullptr);
        char name[] = "tst_solver";
        char* argv[] = {name, nullptr};
        useBestBlasKernel(argv);
        QCOMPARE(std::string(std::getenv("OPENBLAS_CORETYPE")), std::string("Prescott"));
        QVERIFY(!std::getenv("DEVSURF_OPENBLAS_CORETYPE"));
    }
};

DEVSURF_REGISTER_TEST(TstBlasKernel);
#include "tst_blas_kernel.moc"
