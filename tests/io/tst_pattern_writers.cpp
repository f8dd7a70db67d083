#include "dxf_check.h"
#include "io/file_error.h"
#include "io/pattern/fabrication_report.h"
#include "io/pattern/pattern_writers.h"
#include "io/pattern/spline_fit.h"
#include "pattern_fixtures.h"
#include "pattern_test_util.h"
#include "test_registry.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <cmath>

using namespace devsurf;
using model::PatternLayer;
using model::Vec2;

namespace {

double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double l2 = ab.x * ab.x + ab.y * ab.y;
    double t = l2 > 0 ? ((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / l2 : 0.0;
    t = std::min(1.0, std::max(0.0, t));
    return (p - (a + ab * t)).norm();
}

double polylineDistance(const Vec2& p, const std::vector<Vec2>& line) {
    double best = 1e300;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        best = std::min(best, segmentDistance(p, line[i], line[i + 1]));
    }
    return best;
}

// The spline sampled densely, evaluated here from its Bézier control points (Bernstein form).
std::vector<Vec2> sampleSpline(const io::CubicSpline& spline, int perSegment) {
    std::vector<Vec2> out;
    for (int s = 0; s < spline.segments(); ++s) {
        const Vec2* c = &spline.controlPoints[std::size_t(3 * s)];
        for (int i = 0; i <= perSegment; ++i) {
            const double t = double(i) / perSegment;
            const double u = 1 - t;
            out.push_back(c[0] * (u * u * u) + c[1] * (3 * u * u * t) + c[2] * (3 * u * t * t) +
                          c[3] * (t * t * t));
        }
    }
    return out;
}

double polygonArea(const std::vector<Vec2>& polygon) {
    double twice = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twice;
}

// Piece B sits on sheet 1: side by side after sheet 0 (600 mm wide) and the 20 mm spacing.
constexpr double kSheet1Offset = 620.0;

} // namespace

class TstPatternWriters : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const QString& name) const { return m_dir.filePath(name); }

    // Writes the DXF of the fixture and returns what ezdxf read back.
    QJsonObject readBackDxf(const io::PatternWriteOptions& options, const QString& name) {
        const model::CuttingPattern pattern = test::fixturePattern();
        const QString file = path(name + QStringLiteral(".dxf"));
        io::savePatternFile(pattern, io::PatternFormat::Dxf, file, options);
        return test::readBackDxf(file, pattern, options.tolerance,
                                 [](int sheet) { return sheet == 1 ? kSheet1Offset : 0.0; });
    }

private slots:
    void layerNamesAreThePatterns() {
        QSet<int> colours;
        for (int i = 0; i < model::kPatternLayerCount; ++i) {
            const auto layer = static_cast<PatternLayer>(i);
            QCOMPARE(io::layerStyle(layer).name, model::patternLayerName(layer));
            QCOMPARE(io::layerStyle(layer).layer, layer);
            colours.insert(io::layerStyle(layer).aci);
        }
        QCOMPARE(colours.size(), model::kPatternLayerCount);
    }

    void splineFitStaysWithinTolerance() {
        const double tolerance = 0.01;
        std::vector<std::pair<std::vector<Vec2>, bool>> curves;
        std::vector<Vec2> circle;
        for (int i = 0; i < 720; ++i) {
            const double a = 2 * M_PI * i / 720;
            circle.push_back({120 * std::cos(a), 120 * std::sin(a)});
        }
        curves.push_back({circle, true});
        std::vector<Vec2> wave;
        for (int i = 0; i <= 400; ++i) {
            wave.push_back({i * 0.5, 20 * std::sin(i * 0.5 / 15)});
        }
        wave.push_back({200, -30}); // a corner
        wave.push_back({150, -60});
        curves.push_back({wave, false});
        for (const auto& [points, closed] : curves) {
            const io::CubicSpline spline = io::fitCubicSpline(points, closed, tolerance);
            QVERIFY(spline.segments() > 0);
            QCOMPARE(spline.knots.size(), spline.controlPoints.size() + 4);
            QVERIFY(spline.segments() < int(points.size()) / 3); // it did compress
            const std::vector<Vec2> samples = sampleSpline(spline, 200);
            std::vector<Vec2> line = points;
            if (closed) {
                line.push_back(points.front());
            }
            double worst = 0;
            for (const Vec2& p : points) {
                worst = std::max(worst, polylineDistance(p, samples));
            }
            for (const Vec2& q : samples) {
                worst = std::max(worst, polylineDistance(q, line));
            }
            QVERIFY2(worst <= tolerance, qPrintable(QString::number(worst)));
            QVERIFY((samples.front() - points.front()).norm() < 1e-12);
            QVERIFY((samples.back() - line.back()).norm() < 1e-12);
        }
    }

    void dxfR2000ReadsBackWithEzdxf() {
        io::PatternWriteOptions options;
        const QJsonObject result = readBackDxf(options, QStringLiteral("r2000"));
        test::verifyDxf(result, "AC1015", "LWPOLYLINE", 0.01);
        // Labels: piece A's at 45° (DXF angles are degrees), B's two level.
        QCOMPARE(result["text_rotations"].toArray(), QJsonArray({0.0, 0.0, 45.0}));
    }

    void dxfR12ReadsBackWithEzdxf() {
        io::PatternWriteOptions options;
        options.r12 = true;
        test::verifyDxf(readBackDxf(options, QStringLiteral("r12")), "AC1009", "POLYLINE", 0.01);
    }

    void dxfSplinesReadBackWithinTolerance() {
        io::PatternWriteOptions options;
        options.splines = true;
        test::verifyDxf(readBackDxf(options, QStringLiteral("splines")), "AC1015", "SPLINE", 0.01);
        QVERIFY(!QTest::currentTestFailed());
    }

    void svgIsTrueSizeWithInkscapeLayers() {
        const QString file = path(QStringLiteral("p.svg"));
        io::PatternWriteOptions options;
        options.margin = 10.0;
        io::savePatternFile(test::fixturePattern(), io::PatternFormat::Svg, file, options);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&f);
        // Bounds: x from the sector's left (300 − 250) to piece B's right on sheet 1
        // (620 + 130); y from piece B's cut line (5) to the sector's top (300 + 250).
        const double width = (kSheet1Offset + 130.0 - 50.0) + 20.0;
        const double height = (550.0 - 5.0) + 20.0;
        const QString inkscape = QStringLiteral("http://www.inkscape.org/namespaces/inkscape");
        QStringList layers;
        QString hiddenLayers;
        QString currentLayer;
        int cutPaths = 0;
        bool firstCutPointSeen = false;
        while (!xml.atEnd()) {
            if (xml.readNext() != QXmlStreamReader::StartElement) {
                continue;
            }
            const auto attributes = xml.attributes();
            if (xml.name() == QLatin1String("svg")) {
                QCOMPARE(attributes.value("width").toString(), QString("%1mm").arg(width));
                QCOMPARE(attributes.value("height").toString(), QString("%1mm").arg(height));
                QCOMPARE(attributes.value("viewBox").toString(),
                         QString("0 0 %1 %2").arg(width).arg(height));
            } else if (xml.name() == QLatin1String("g")) {
                QCOMPARE(attributes.value(inkscape, "groupmode").toString(), QString("layer"));
                currentLayer = attributes.value(inkscape, "label").toString();
                layers << currentLayer;
                if (attributes.value("style").contains(QLatin1String("display:none"))) {
                    hiddenLayers += currentLayer;
                }
            } else if (xml.name() == QLatin1String("path") && currentLayer == "CUT") {
                ++cutPaths;
                if (!firstCutPointSeen) {
                    // The sector's first outline point (550, 300): x − 50 + 10, 550 + 10 − y.
                    QVERIFY(attributes.value("d").startsWith(QLatin1String("M510 260 L")));
                    firstCutPointSeen = true;
                }
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString() + QStringLiteral(" at line ") +
                                             QString::number(xml.lineNumber())));
        QCOMPARE(layers,
                 QStringList({"CUT", "MOUNTAIN", "VALLEY", "CREASE", "SCORE", "SEAM", "LABELS"}));
        QCOMPARE(hiddenLayers, QString("SCORE"));
        QCOMPARE(cutPaths, 2);
    }

    void foldParsesBackAndTilesThePieces() {
        const model::CuttingPattern pattern = test::fixturePattern();
        const QString file = path(QStringLiteral("p.fold"));
        io::savePatternFile(pattern, io::PatternFormat::Fold, file, {});
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonParseError error;
        const QJsonObject fold = QJsonDocument::fromJson(f.readAll(), &error).object();
        QCOMPARE(error.error, QJsonParseError::NoError);
        QCOMPARE(fold["file_spec"].toDouble(), 1.1);
        QCOMPARE(fold["frame_unit"].toString(), QString("mm"));
        const QJsonArray vertices = fold["vertices_coords"].toArray();
        const QJsonArray edges = fold["edges_vertices"].toArray();
        const QJsonArray assignment = fold["edges_assignment"].toArray();
        const QJsonArray angles = fold["edges_foldAngle"].toArray();
        const QJsonArray faces = fold["faces_vertices"].toArray();
        QVERIFY(!edges.isEmpty());
        QCOMPARE(assignment.size(), edges.size());
        QCOMPARE(angles.size(), edges.size());
        QMap<QString, int> counts;
        for (qsizetype e = 0; e < edges.size(); ++e) {
            const QJsonArray ends = edges[e].toArray();
            QCOMPARE(ends.size(), qsizetype(2));
            for (const QJsonValue& v : ends) {
                QVERIFY(v.toInt(-1) >= 0 && v.toInt(-1) < vertices.size());
            }
            QVERIFY(ends[0].toInt() != ends[1].toInt());
            const QString a = assignment[e].toString();
            QVERIFY2(QStringList({"B", "M", "V", "F", "U"}).contains(a), qPrintable(a));
            ++counts[a];
            // FOLD: valleys fold positive, mountains negative.
            if (a == "M") {
                QVERIFY(angles[e].toDouble() < 0);
            } else if (a == "V") {
                QVERIFY(angles[e].toDouble() > 0);
            }
        }
        QVERIFY(counts["B"] > 0 && counts["M"] > 0 && counts["V"] > 0 && counts["F"] > 0);
        // Faces: valid indices, and together exactly the pieces' area (the creases split them).
        double area = 0;
        for (const QJsonValue& face : faces) {
            std::vector<Vec2> polygon;
            for (const QJsonValue& v : face.toArray()) {
                QVERIFY(v.toInt(-1) >= 0 && v.toInt(-1) < vertices.size());
                const QJsonArray xy = vertices[v.toInt()].toArray();
                polygon.push_back({xy[0].toDouble(), xy[1].toDouble()});
            }
            QVERIFY(polygon.size() >= 3);
            area += std::abs(polygonArea(polygon));
        }
        const double expected = polygonArea(pattern.pieces[0].outline) + 120.0 * 85.0;
        QVERIFY2(std::abs(area - expected) < 1e-6 * expected, qPrintable(QString::number(area)));
        QVERIFY(faces.size() > 2 + 8);
    }

    void fabricationReportListsOverlapsAndProblems() {
        const io::FabricationReport clean = io::fabricationReport(test::fixturePattern(), {});
        QVERIFY(!clean.hasOverlaps());
        QCOMPARE(clean.pieces.size(), std::size_t(2));
        QVERIFY(clean.pieces[0].fitsSheet && clean.pieces[1].fitsSheet);

        const io::FabricationReport report = io::fabricationReport(
            test::fixturePatternWithOverlap(), {"Piece B overlaps itself (patch 0)."});
        QVERIFY(report.hasOverlaps());
        QVERIFY(report.pieces[1].selfOverlapping);
        const QString text = QString::fromStdString(io::fabricationReportText(report));
        QVERIFY(text.contains("itself"));
        QVERIFY(text.contains("Problem: Piece B overlaps itself"));
        const QJsonObject json =
            QJsonDocument::fromJson(io::fabricationReportJson(report)).object();
        QVERIFY(json["hasOverlaps"].toBool());
        QCOMPARE(json["pieces"].toArray().size(), qsizetype(2));
        QCOMPARE(json["pieces"].toArray()[0].toObject()["area"].toDouble(),
                 test::fixturePattern().pieces[0].area);
        QCOMPARE(json["problems"].toArray().size(), qsizetype(1));
    }

    void unwritablePathFailsWithOneSentence() {
        const QString file = path(QStringLiteral("no/such/folder/p.svg"));
        try {
            io::savePatternFile(test::fixturePattern(), io::PatternFormat::Svg, file, {});
            QFAIL("no error");
        } catch (const io::FileError& error) {
            QVERIFY(QString::fromStdString(error.what()).contains(file));
        }
        QVERIFY(!QFile::exists(file));
    }
};

DEVSURF_REGISTER_TEST(TstPatternWriters);
#include "tst_pattern_writers.moc"
