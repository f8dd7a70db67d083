#include "curve_test_util.h"
#include "io/curves/curve_import.h"
#include "test_registry.h"

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace devsurf;
using model::Vec3;

namespace {

// Written by hand as drawing programs write it: 200 × 100 mm over a viewBox of 400 × 200
// user units (0.5 mm each), a rectangle, a circle, a line turned and moved by a group's
// transform, an arc in a path, and text (not a curve).
const char* const kDrawing = R"(<?xml version='1.0' encoding='UTF-8'?>
<svg xmlns='http://www.w3.org/2000/svg' width='200mm' height='100mm' viewBox='0 0 400 200'>
  <rect x='20' y='20' width='100' height='50' fill='none' stroke='black'/>
  <circle cx='300' cy='100' r='60' fill='none' stroke='red'/>
  <g transform='translate(10,0) rotate(90)'><path d='M 0 0 L 20 0' stroke='blue'/></g>
  <path d='M 200 190 A 10 10 0 0 1 220 190' fill='none' stroke='green'/>
  <text x='10' y='190'>Sheet</text>
</svg>
)";

double length(const std::vector<Vec3>& points) {
    double sum = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        sum += model::distance(points[i - 1], points[i]);
    }
    return sum;
}

} // namespace

class TstSvgCurves : public QObject {
    Q_OBJECT
private slots:
    void shapesBecomeCurvesInMillimetres() {
        io::CurveImportOptions options;
        options.tolerance = 0.01;
        const io::CurveImportResult read = io::readSvgCurves(QByteArray(kDrawing), options);
        QVERIFY(!read.error);
        QCOMPARE(read.curves.size(), std::size_t(4));
        // The rectangle: closed, 50 × 25 mm, y pointing up.
        const std::vector<Vec3>& rect = read.curves[0].points;
        QCOMPARE(rect.front(), rect.back());
        QVERIFY(std::abs(length(rect) - 150.0) < 1e-9);
        for (const Vec3& p : rect) {
            QVERIFY(p.x >= 10 - 1e-9 && p.x <= 60 + 1e-9 && p.y <= -10 + 1e-9 && p.y >= -35 - 1e-9);
            QCOMPARE(p.z, 0.0);
        }
        // The circle: radius 30 mm about (150, −50), within the tolerance of the four cubic
        // arcs SVG draws it with (themselves within 2.7e-4 of the radius).
        const std::vector<Vec3>& circle = read.curves[1].points;
        QVERIFY(circle.size() > 16);
        QVERIFY(model::distance(circle.front(), circle.back()) < 1e-9);
        for (const Vec3& p : circle) {
            QVERIFY(std::abs(std::hypot(p.x - 150.0, p.y + 50.0) - 30.0) < 0.01 + 30 * 2.8e-4);
        }
        // The line: turned by 90° and moved by 10 user units, from (5, 0) to (5, −10) mm.
        const std::vector<Vec3>& line = read.curves[2].points;
        QCOMPARE(line.size(), std::size_t(2));
        QVERIFY(model::distance(line[0], Vec3(5, 0, 0)) < 1e-9);
        QVERIFY(model::distance(line[1], Vec3(5, -10, 0)) < 1e-9);
        // The arc: half a circle of radius 5 mm through (105, −95) … (110, −95) … (115, −95).
        const std::vector<Vec3>& arc = read.curves[3].points;
        QVERIFY(arc.size() > 4);
        for (const Vec3& p : arc) {
            QVERIFY(std::abs(std::hypot(p.x - 105.0, p.y + 95.0) - 5.0) < 0.01 + 5 * 2.8e-4);
        }
        QVERIFY(std::abs(length(arc) - 5.0 * 3.14159265358979) < 0.05);
    }

    void sizesWithoutAViewBoxAreCssPixels() {
        const char* const pixels =
            R"(<svg xmlns='http://www.w3.org/2000/svg' width='96' height='96'>
            <path d='M 0 0 L 96 0'/></svg>)";
        const io::CurveImportResult read = io::readSvgCurves(QByteArray(pixels), {});
        QVERIFY(!read.error);
        QVERIFY(std::abs(length(read.curves[0].points) - 25.4) < 1e-9);
        // By extension through importCurveFile.
        QTemporaryDir dir;
        QVERIFY(test::writeBytes(dir.filePath("drawing.SVG"), kDrawing));
        QCOMPARE(io::curveFormatOf(dir.filePath("drawing.SVG")), io::CurveFormat::Svg);
        QCOMPARE(io::importCurveFile(dir.filePath("drawing.SVG")).curves.size(), std::size_t(4));
    }

    void progressRisesAndCancelStops() {
        std::vector<double> fractions;
        io::CurveImportOptions options;
        options.progress = [&fractions](double f) {
            fractions.push_back(f);
            return true;
        };
        QVERIFY(!io::readSvgCurves(QByteArray(kDrawing), options).error);
        QVERIFY(std::is_sorted(fractions.begin(), fractions.end()));
        QCOMPARE(fractions.back(), 1.0);
        options.progress = [](double) { return false; };
        const io::CurveImportResult cancelled = io::readSvgCurves(QByteArray(kDrawing), options);
        QVERIFY(cancelled.error && cancelled.error->code == io::CurveImportError::Code::Cancelled);
        QVERIFY(cancelled.curves.empty());
    }

    void damagedFilesNeverCrash() {
        using Code = io::CurveImportError::Code;
        QCOMPARE(io::readSvgCurves(QByteArray("not xml at all"), {}).error->code, Code::Damaged);
        QCOMPARE(io::readSvgCurves(QByteArray("<html><body/></html>"), {}).error->code,
                 Code::Damaged);
        const char* const textOnly =
            R"(<svg xmlns='http://www.w3.org/2000/svg' width='10mm' height='10mm'><text>a</text></svg>)";
        QCOMPARE(io::readSvgCurves(QByteArray(textOnly), {}).error->code, Code::NoCurves);
        std::mt19937 rng(45);
        int read = 0;
        for (int i = 0; i < 400; ++i) {
            const std::string bytes = test::mutated(kDrawing, rng, i);
            const io::CurveImportResult r = io::readSvgCurves(
                QByteArray(bytes.data(), static_cast<qsizetype>(bytes.size())), {});
            if (r.error) {
                QVERIFY(r.curves.empty());
                continue;
            }
            ++read;
            for (const model::ReferenceCurve& curve : r.curves) {
                QVERIFY(curve.points.size() >= 2 && curve.points.size() <= io::kMaxCurvePoints);
                for (const Vec3& p : curve.points) {
                    QVERIFY(std::isfinite(p.x) && std::isfinite(p.y) && p.z == 0.0);
                }
            }
        }
        QVERIFY(read > 0); // not everything was refused
    }
};

DEVSURF_REGISTER_TEST(TstSvgCurves);
#include "tst_svg_curves.moc"
