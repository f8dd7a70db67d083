#include "dxf_check.h"
#include "io/pattern/page_plan.h"
#include "io/pattern/pattern_writers.h"
#include "model/examples.h"
#include "model/pattern/cutting_pattern.h"
#include "model/project.h"
#include "pattern_test_util.h"
#include "test_registry.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <cmath>

using namespace devsurf;

namespace {

// One large sheet: every piece of every example lies on sheet 0, in the drawing's own frame.
model::PatternOptions bigSheet() {
    model::PatternOptions options;
    options.sheetSize = {2000.0, 2000.0};
    options.rulings = true;
    return options;
}

double faceArea(const QJsonArray& vertices, const QJsonArray& face) {
    double twice = 0.0;
    for (qsizetype i = 0; i < face.size(); ++i) {
        const QJsonArray a = vertices[face[i].toInt()].toArray();
        const QJsonArray b = vertices[face[(i + 1) % face.size()].toInt()].toArray();
        twice += a[0].toDouble() * b[1].toDouble() - b[0].toDouble() * a[1].toDouble();
    }
    return 0.5 * twice;
}

} // namespace

// The writers on the patterns of the built-in examples (built by model::buildCuttingPattern).
class TstPatternExamples : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void dxfOfEveryExampleReadsBack_data() {
        QTest::addColumn<QString>("example");
        for (const model::ExampleInfo& info : model::builtInExamples()) {
            QTest::newRow(info.name.c_str()) << QString::fromStdString(info.name);
        }
    }

    void dxfOfEveryExampleReadsBack() {
        QFETCH(QString, example);
        const model::CuttingPattern pattern =
            model::buildCuttingPattern(model::makeExample(example.toStdString()), bigSheet());
        QVERIFY(!pattern.pieces.empty());
        for (const model::PatternPiece& piece : pattern.pieces) {
            QCOMPARE(piece.sheet, 0);
        }
        const auto onSheet0 = [](int) { return 0.0; };
        struct Variant {
            const char* name;
            bool r12;
            bool splines;
            const char* version;
            const char* entity;
        };
        for (const Variant& v : {Variant{"r2000", false, false, "AC1015", "LWPOLYLINE"},
                                 Variant{"r12", true, false, "AC1009", "POLYLINE"},
                                 Variant{"splines", false, true, "AC1015", "SPLINE"}}) {
            io::PatternWriteOptions options;
            options.r12 = v.r12;
            options.splines = v.splines;
            const QString file = m_dir.filePath(example + QLatin1Char('-') + v.name + ".dxf");
            io::savePatternFile(pattern, io::PatternFormat::Dxf, file, options);
            test::verifyDxf(test::readBackDxf(file, pattern, options.tolerance, onSheet0),
                            v.version, v.entity, options.tolerance);
            if (QTest::currentTestFailed()) {
                return;
            }
        }
    }

    void svgAndFoldOfTheCylinder() {
        const model::CuttingPattern pattern =
            model::buildCuttingPattern(model::makeExample("cylinder"), bigSheet());
        const QString svg = m_dir.filePath(QStringLiteral("cylinder.svg"));
        io::PatternWriteOptions options;
        options.margin = 7.0;
        io::savePatternFile(pattern, io::PatternFormat::Svg, svg, options);
        QFile f(svg);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&f);
        QVERIFY(xml.readNextStartElement());
        const auto [lo, hi] = pattern.bounds(0);
        const double width = xml.attributes().value("width").toString().remove("mm").toDouble();
        const double height = xml.attributes().value("height").toString().remove("mm").toDouble();
        QVERIFY(std::abs(width - (hi.x - lo.x + 14.0)) < 1e-3);
        QVERIFY(std::abs(height - (hi.y - lo.y + 14.0)) < 1e-3);

        const QString fold = m_dir.filePath(QStringLiteral("cylinder.fold"));
        io::savePatternFile(pattern, io::PatternFormat::Fold, fold, {});
        QFile g(fold);
        QVERIFY(g.open(QIODevice::ReadOnly));
        const QJsonObject root = QJsonDocument::fromJson(g.readAll()).object();
        const QJsonArray vertices = root["vertices_coords"].toArray();
        const QJsonArray faces = root["faces_vertices"].toArray();
        for (const QJsonValue& edge : root["edges_vertices"].toArray()) {
            for (const QJsonValue& v : edge.toArray()) {
                QVERIFY(v.toInt(-1) >= 0 && v.toInt(-1) < vertices.size());
            }
        }
        // The rulings split the development into faces that together have its area.
        double area = 0.0;
        for (const QJsonValue& face : faces) {
            area += faceArea(vertices, face.toArray());
        }
        double expected = 0.0;
        for (const model::PatternPiece& piece : pattern.pieces) {
            expected += piece.area;
        }
        QVERIFY(faces.size() > 10);
        QVERIFY2(std::abs(area - expected) < 1e-3 * expected,
                 qPrintable(QStringLiteral("%1 vs %2").arg(area).arg(expected)));
    }

    void annulusPrintsOnSeveralA4Pages() {
        model::PatternOptions options;
        options.sheetSize = io::printableSheet(io::paperSize(io::Paper::A4));
        const model::CuttingPattern pattern =
            model::buildCuttingPattern(model::makeExample("annulus"), options);
        const QString pdf = m_dir.filePath(QStringLiteral("annulus.pdf"));
        io::savePatternFile(pattern, io::PatternFormat::Pdf, pdf, {});
        const test::ToolRun info = test::runTool(QStringLiteral("pdfinfo"), {pdf});
        const auto pages = QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(info.out);
        QVERIFY(pages.hasMatch());
        // 500 mm across: at least 3 × 3 tiles after the report and the overview.
        QVERIFY(pages.captured(1).toInt() >= 11);
        QVERIFY(info.out.contains(QStringLiteral("(A4)")));
    }
};

DEVSURF_REGISTER_TEST(TstPatternExamples);
#include "tst_pattern_examples.moc"
