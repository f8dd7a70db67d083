// DXF curves written by ezdxf (a writer DevSurf did not write) read back through the import:
// every point on the known geometry, chords within the tolerance, units scaled; damaged files
// give an error, never a crash.

#include "curve_test_util.h"
#include "io/curves/curve_sampling.h"
#include "test_registry.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <chrono>

using namespace devsurf;
using devsurf::model::distance;
using model::Vec3;

namespace {

constexpr double kTolerance = 0.05;

const model::ReferenceCurve* named(const std::vector<model::ReferenceCurve>& curves,
                                   const std::string& name) {
    for (const model::ReferenceCurve& curve : curves) {
        if (curve.name == name) {
            return &curve;
        }
    }
    return nullptr;
}

// The largest distance of a chord's middle from the curve c(t), t in [0, 1], found by a fine
// search (the curve's own formula, not the import's evaluation).
template <class Curve> double largestChordError(const std::vector<Vec3>& points, Curve c) {
    double largest = 0.0;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const Vec3 middle = (points[i] + points[i + 1]) * 0.5;
        double best = 1e300;
        for (int k = 0; k <= 20000; ++k) {
            best = std::min(best, distance(middle, c(k / 20000.0)));
        }
        largest = std::max(largest, best);
    }
    return largest;
}

} // namespace

class TstDxfCurves : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    io::CurveImportResult m_curves;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QProcess python;
        python.start(
            QStringLiteral("/usr/bin/python3"),
            {QStringLiteral(DEVSURF_SOURCE_DIR "/tests/io/write_curves_dxf.py"), m_dir.path()});
        QVERIFY(python.waitForFinished(60000));
        QVERIFY2(python.exitCode() == 0, python.readAllStandardError().constData());
        m_curves =
            io::importCurveFile(m_dir.filePath(QStringLiteral("curves.dxf")), {kTolerance, {}});
        QVERIFY2(!m_curves.error, m_curves.error ? m_curves.error->detail.c_str() : "");
    }

    void everyCurveEntityIsOneCurve() {
        std::vector<std::string> names;
        for (const model::ReferenceCurve& curve : m_curves.curves) {
            names.push_back(curve.name);
        }
        const std::vector<std::string> expected{"LINE 1",   "POLYLINE 2", "POLYLINE 3",
                                                "SPLINE 4", "SPLINE 5",   "CIRCLE 6",
                                                "ARC 7",    "ARC 8",      "ELLIPSE 9"};
        QCOMPARE(names, expected);
        // The text and the block insert are not curves; the line inside the block definition is
        // not drawn where it is defined.
        QCOMPARE(m_curves.skipped, 2);
        QCOMPARE(named(m_curves.curves, "LINE 1")->source, std::string("LINES"));
        QCOMPARE(named(m_curves.curves, "SPLINE 5")->source, std::string("SPLINES"));
    }

    void ellipsesLieOnTheirCurves() {
        const auto* ellipse = named(m_curves.curves, "ELLIPSE 9");
        QCOMPARE(ellipse->source, std::string("ELLIPSES"));
        QVERIFY(model::distance(ellipse->points.front(), {80, -40, 0}) < 1e-9);
        QVERIFY(model::distance(ellipse->points.back(), {20, -40, 0}) < 1e-9);
        QVERIFY(ellipse->points.size() > 8);
        for (const Vec3& p : ellipse->points) {
            const double u = (p.x - 50) / 30, v = (p.y + 40) / 15;
            QVERIFY(std::abs(u * u + v * v - 1.0) < 1e-9);
            QVERIFY(p.y >= -40 - 1e-9 && p.z == 0.0);
        }
        // Within the tolerance between samples: the middle of every chord is near the curve.
        for (std::size_t i = 0; i + 1 < ellipse->points.size(); ++i) {
            const Vec3 m = (ellipse->points[i] + ellipse->points[i + 1]) * 0.5;
            const double t = std::atan2((m.y + 40) / 15, (m.x - 50) / 30);
            const Vec3 on(50 + 30 * std::cos(t), -40 + 15 * std::sin(t), 0);
            QVERIFY(model::distance(m, on) < kTolerance * 1.01);
        }
    }

    void lineAndPolylinesKeepTheirPoints() {
        const auto* line = named(m_curves.curves, "LINE 1");
        QCOMPARE(line->points, (std::vector<Vec3>{{0, 0, 0}, {100, 50, 25}}));
        const auto* poly3d = named(m_curves.curves, "POLYLINE 3");
        QCOMPARE(poly3d->points, (std::vector<Vec3>{{0, 0, 0}, {10, 20, 30}, {40, 50, 60}}));
        QCOMPARE(poly3d->source, std::string("POLY3D"));
        // The LWPOLYLINE at elevation 5: a half circle (bulge 1) below the x axis, then a line.
        const auto* lw = named(m_curves.curves, "POLYLINE 2");
        QCOMPARE(lw->source, std::string("LW"));
        QCOMPARE(lw->points.front(), Vec3(0, 0, 5));
        QCOMPARE(lw->points.back(), Vec3(20, 10, 5));
        QCOMPARE(lw->points[lw->points.size() - 2], Vec3(20, 0, 5));
        QVERIFY(lw->points.size() > 8);
        bool passesBottom = false;
        for (std::size_t i = 0; i + 1 < lw->points.size(); ++i) {
            const Vec3& p = lw->points[i];
            QCOMPARE(p.z, 5.0);
            QVERIFY(p.y <= 1e-9);
            QVERIFY2(std::abs(distance(p, {10, 0, 5}) - 10.0) < 1e-9,
                     qPrintable(QString::number(i)));
            passesBottom = passesBottom || std::abs(p.y + 10.0) < 0.5;
        }
        QVERIFY(passesBottom);
    }

    void splinesLieOnTheirCurves() {
        const auto* cubic = named(m_curves.curves, "SPLINE 4");
        auto c = [](double t) { return Vec3(30 * t, 30 * t * t, 30 * t * t * t); };
        QCOMPARE(cubic->points.front(), Vec3(0, 0, 0));
        QCOMPARE(cubic->points.back(), Vec3(30, 30, 30));
        for (const Vec3& p : cubic->points) {
            const double t = p.x / 30.0;
            QVERIFY(distance(p, c(t)) < 1e-9);
        }
        const double error = largestChordError(cubic->points, c);
        QVERIFY2(error <= kTolerance, qPrintable(QString::number(error)));
        QVERIFY2(error > kTolerance / 10, "sampled far finer than asked");
        // The rational quarter circle: every point at radius 20, chords within the tolerance.
        const auto* quarter = named(m_curves.curves, "SPLINE 5");
        QVERIFY(distance(quarter->points.front(), {20, 0, 0}) < 1e-12);
        QVERIFY(distance(quarter->points.back(), {0, 20, 0}) < 1e-12);
        for (std::size_t i = 0; i < quarter->points.size(); ++i) {
            const Vec3& p = quarter->points[i];
            QVERIFY(std::abs(distance(p, {0, 0, 0}) - 20.0) < 1e-9);
            QCOMPARE(p.z, 0.0);
            if (i > 0) {
                const double half = 0.5 * distance(p, quarter->points[i - 1]);
                const double sagitta = 20.0 - std::sqrt(400.0 - half * half);
                QVERIFY(sagitta <= kTolerance);
            }
        }
    }

    void circlesAndArcs() {
        const auto* circle = named(m_curves.curves, "CIRCLE 6");
        QCOMPARE(circle->source, std::string("CIRCLES"));
        QVERIFY(distance(circle->points.front(), circle->points.back()) < 1e-9); // closed
        for (std::size_t i = 0; i < circle->points.size(); ++i) {
            QVERIFY(std::abs(distance(circle->points[i], {100, 100, 0}) - 25.0) < 1e-9);
            if (i > 0) {
                const double half = 0.5 * distance(circle->points[i], circle->points[i - 1]);
                QVERIFY(25.0 - std::sqrt(625.0 - half * half) <= kTolerance);
            }
        }
        const auto* arc = named(m_curves.curves, "ARC 7");
        QVERIFY(distance(arc->points.front(), {10, 0, 0}) < 1e-9);
        QVERIFY(distance(arc->points.back(), {0, 10, 0}) < 1e-9);
        // Extrusion -z: the object coordinate system's x axis is the world's -x.
        const auto* flipped = named(m_curves.curves, "ARC 8");
        for (const Vec3& p : flipped->points) {
            QVERIFY(std::abs(distance(p, {-10, 0, 0}) - 5.0) < 1e-9);
            QVERIFY(std::abs(p.z) < 1e-12);
        }
        QVERIFY(distance(flipped->points.front(), {-15, 0, 0}) < 1e-9);
        QVERIFY(distance(flipped->points.back(), {-5, 0, 0}) < 1e-9);
    }

    void unitsBecomeMillimetres() {
        const io::CurveImportResult cm =
            io::importCurveFile(m_dir.filePath(QStringLiteral("cm.dxf")));
        QVERIFY(!cm.error);
        QCOMPARE(cm.curves.size(), std::size_t(1));
        QCOMPARE(cm.curves[0].points, (std::vector<Vec3>{{0, 0, 0}, {10, 20, 30}}));
    }

    void progressRisesAndCancelStops() {
        const QString path = m_dir.filePath(QStringLiteral("curves.dxf"));
        std::vector<double> fractions;
        io::CurveImportOptions options;
        options.progress = [&fractions](double f) {
            fractions.push_back(f);
            return true;
        };
        QVERIFY(!io::importCurveFile(path, options).error);
        QVERIFY(!fractions.empty());
        QVERIFY(std::is_sorted(fractions.begin(), fractions.end()));
        QCOMPARE(fractions.back(), 1.0);
        options.progress = [](double) { return false; };
        const io::CurveImportResult cancelled = io::importCurveFile(path, options);
        QVERIFY(cancelled.error);
        QCOMPARE(cancelled.error->code, io::CurveImportError::Code::Cancelled);
        QVERIFY(cancelled.curves.empty());
    }

    void unreadableFilesGiveTypedErrors() {
        using Code = io::CurveImportError::Code;
        auto codeOf = [](const QString& path) {
            const io::CurveImportResult r = io::importCurveFile(path);
            return r.error ? r.error->code : Code::Damaged;
        };
        QVERIFY(io::importCurveFile(m_dir.filePath("missing.dxf")).error);
        QCOMPARE(codeOf(m_dir.filePath("missing.dxf")), Code::Unreadable);
        QVERIFY(test::writeBytes(m_dir.filePath("curves.txt"), "0\nEOF\n"));
        QCOMPARE(codeOf(m_dir.filePath("curves.txt")), Code::UnknownFormat);
        QVERIFY(test::writeBytes(m_dir.filePath("empty.dxf"), ""));
        QVERIFY(io::importCurveFile(m_dir.filePath("empty.dxf")).error);
        QVERIFY(test::writeBytes(
            m_dir.filePath("text.dxf"),
            "0\nSECTION\n2\nENTITIES\n0\nTEXT\n8\n0\n1\nhello\n0\nENDSEC\n0\nEOF\n"));
        QCOMPARE(codeOf(m_dir.filePath("text.dxf")), Code::NoCurves);
        // Counts dxflib would trust are refused before it reads them.
        const std::string huge =
            "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n1073741825\n10\n1\n20\n2\n0\nEOF\n";
        const io::CurveImportResult r = io::readDxfCurves(huge, {});
        QVERIFY(r.error && r.error->code == Code::Damaged);
        const std::string bulgeFirst =
            "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n2\n42\n1\n10\n1\n20\n2\n0\nEOF\n";
        QVERIFY(io::readDxfCurves(bulgeFirst, {}).error);
        // A spline whose knots do not fit its control points is skipped, not evaluated.
        io::Nurbs bad{3, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, {}};
        QVERIFY(!io::isValidNurbs(bad));
        QVERIFY(!io::sampleNurbs(bad, 0.1, 1000));
    }

    void damagedFilesNeverCrash() {
        const std::string good = test::readBytes(m_dir.filePath(QStringLiteral("curves.dxf")));
        QVERIFY(!good.empty());
        std::mt19937 rng(44);
        int failed = 0;
        int read = 0;
        const auto start = std::chrono::steady_clock::now();
        const int total = 500;
        for (int i = 0; i < total; ++i) {
            const io::CurveImportResult r = io::readDxfCurves(test::mutated(good, rng, i), {});
            if (r.error) {
                QVERIFY(r.curves.empty());
                ++failed;
            } else {
                for (const model::ReferenceCurve& curve : r.curves) {
                    QVERIFY(curve.points.size() >= 2 && curve.points.size() <= io::kMaxCurvePoints);
                    for (const Vec3& p : curve.points) {
                        QVERIFY(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
                    }
                }
                ++read;
            }
        }
        QCOMPARE(failed + read, total);
        QVERIFY(failed > 0);
        qInfo("%d damaged DXF files: %d refused, %d read (%lld ms)", total, failed, read,
              static_cast<long long>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                         std::chrono::steady_clock::now() - start)
                                         .count()));
    }
};

DEVSURF_REGISTER_TEST(TstDxfCurves);
#include "tst_dxf_curves.moc"
