#include "dxf_check.h"

#include "pattern_test_util.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>
#include <QTest>

namespace devsurf::test {

namespace {

const char* layerName(model::PatternLayer layer) {
    static const char* const names[] = {"CUT",   "MOUNTAIN", "VALLEY", "CREASE",
                                        "SCORE", "SEAM",     "LABELS"};
    return names[static_cast<int>(layer)];
}

} // namespace

QJsonObject readBackDxf(const QString& dxfFile, const model::CuttingPattern& pattern,
                        double tolerance, const std::function<double(int sheet)>& shift) {
    QJsonArray paths;
    for (const model::PatternPiece& piece : pattern.pieces) {
        const double dx = shift(piece.sheet);
        for (const model::PatternPath& p : piece.paths) {
            QJsonArray points;
            for (const model::Vec2& q : p.points) {
                points.append(QJsonArray{q.x + dx, q.y});
            }
            paths.append(QJsonObject{{"layer", QString::fromLatin1(layerName(p.layer))},
                                     {"closed", p.closed},
                                     {"points", points}});
        }
    }
    QFile expected(dxfFile + QStringLiteral(".expected.json"));
    if (!expected.open(QIODevice::WriteOnly)) {
        return {};
    }
    expected.write(QJsonDocument(QJsonObject{{"tolerance", tolerance}, {"paths", paths}}).toJson());
    expected.close();
    const ToolRun run = runTool(QStringLiteral("/usr/bin/python3"),
                                {QStringLiteral(DEVSURF_SOURCE_DIR "/tests/io/check_dxf.py"),
                                 dxfFile, expected.fileName()});
    if (!run.finished || run.exitCode != 0) {
        qWarning("ezdxf check failed: %s", qPrintable(run.err));
        return {};
    }
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

void verifyDxf(const QJsonObject& result, const char* version, const char* entity,
               double tolerance) {
    QVERIFY2(!result.isEmpty(), "the ezdxf check did not run (is python3-ezdxf installed?)");
    QCOMPARE(result["audit_errors"].toInt(-1), 0);
    QCOMPARE(result["dxfversion"].toString(), QString::fromLatin1(version));
    QCOMPARE(result["insunits"].toInt(), 4);
    const QJsonObject layers = result["layers"].toObject();
    QSet<int> colours;
    for (const char* name : {"CUT", "MOUNTAIN", "VALLEY", "CREASE", "SCORE", "SEAM", "LABELS"}) {
        QVERIFY2(layers.contains(name), name);
        colours.insert(layers[name].toObject()["color"].toInt());
    }
    QCOMPARE(colours.size(), 7);
    QVERIFY(!layers["SCORE"].toObject()["on"].toBool());
    QVERIFY(layers["CUT"].toObject()["on"].toBool());
    QCOMPARE(layers["CUT"].toObject()["linetype"].toString().toUpper(),
             QStringLiteral("CONTINUOUS"));
    for (const char* fold : {"MOUNTAIN", "VALLEY", "CREASE"}) {
        QVERIFY(layers[fold].toObject()["linetype"].toString().toUpper() != "CONTINUOUS");
    }
    QVERIFY(result["entity_types"].toArray().contains(QString::fromLatin1(entity)));
    QCOMPARE(result["missing"].toInt(-1), 0);
    QCOMPARE(result["not_closed"].toInt(-1), 0);
    QVERIFY(result["max_error"].toDouble(1.0) <= tolerance);
    QVERIFY(!result["texts"].toArray().isEmpty());
    qInfo("DXF %s (%s): ezdxf audit %d errors, %d fixes; max coordinate error %.3g mm", version,
          entity, result["audit_errors"].toInt(), result["audit_fixes"].toInt(),
          result["max_error"].toDouble());
}

} // namespace devsurf::test
