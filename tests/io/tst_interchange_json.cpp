#include "io/interchange_json.h"
#include "model/development.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"
#include "surface_transform.h"
#include "test_registry.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTest>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <set>
#include <vector>

using namespace devsurf;

namespace {

// Parsed by Qt's JSON reader, not by anything of ours.
QJsonObject parse(const std::string& text) {
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text), &error);
    if (error.error != QJsonParseError::NoError) {
        qWarning("%s", qPrintable(error.errorString()));
    }
    return doc.object();
}

model::Vec3 toVec3(const QJsonValue& value) {
    const QJsonArray a = value.toArray();
    return {a[0].toDouble(), a[1].toDouble(), a[2].toDouble()};
}

std::uint64_t bitsOf(double value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// The bit patterns of every number in a JSON text, read with strtod (not with Qt's reader).
std::set<std::uint64_t> numbersIn(const std::string& text) {
    std::set<std::uint64_t> numbers;
    static const QRegularExpression number(
        QStringLiteral(R"((?:^|[\[,:\s])(-?[0-9]+(?:\.[0-9]+)?(?:[eE][+-]?[0-9]+)?))"));
    QRegularExpressionMatchIterator it = number.globalMatch(QString::fromStdString(text));
    while (it.hasNext()) {
        numbers.insert(bitsOf(std::strtod(it.next().captured(1).toStdString().c_str(), nullptr)));
    }
    return numbers;
}

} // namespace

class TstInterchangeJson : public QObject {
    Q_OBJECT
private slots:
    void documentFollowsTheFormat() {
        for (const model::ExampleInfo& info : model::builtInExamples()) {
            const model::Project project = model::makeExample(info.name);
            const QJsonObject root = parse(io::interchangeJson(project, 4));
            QCOMPARE(root["format"].toString(), QString("devsurf-interchange"));
            QCOMPARE(root["version"].toInt(), 1);
            QCOMPARE(root["units"].toString(), QString("mm"));
            const QJsonObject surface = root["surfaces"].toArray()[0].toObject();
            const model::CompositeSurface& model = project.surfaces[0];
            const auto strips = model::stripsOf(model);
            const QJsonArray jsonStrips = surface["strips"].toArray();
            QCOMPARE(jsonStrips.size(), qsizetype(strips.size()));
            for (qsizetype i = 0; i < jsonStrips.size(); ++i) {
                const QJsonObject strip = jsonStrips[i].toObject();
                const QJsonObject a = strip["a"].toObject();
                QCOMPARE(a["knots"].toArray().size(),
                         a["controlPoints"].toArray().size() + a["degree"].toInt() + 1);
                QCOMPARE(strip["type"].toString() == "cone", strip["b"].isNull());
                QCOMPARE(strip["type"].toString() == "cone", !strip["apex"].isNull());
                // Full precision: coordinates read back bit for bit.
                const auto& points = strips[static_cast<std::size_t>(i)].a.controlPoints();
                const QJsonArray jsonPoints = a["controlPoints"].toArray();
                for (qsizetype k = 0; k < jsonPoints.size(); ++k) {
                    QVERIFY(toVec3(jsonPoints[k]) == points[static_cast<std::size_t>(k)]);
                }
            }
            // Each crease curve equals the side it names on both strips.
            for (const QJsonValue& value : surface["creases"].toArray()) {
                const QJsonObject crease = value.toObject();
                const QJsonArray curve = crease["curve"].toObject()["controlPoints"].toArray();
                for (const char* which : {"left", "right"}) {
                    const QJsonObject side = crease[which].toObject();
                    const QJsonObject strip = jsonStrips[side["strip"].toInt()]
                                                  .toObject()[side["side"].toString()]
                                                  .toObject();
                    const QJsonArray points = strip["controlPoints"].toArray();
                    QCOMPARE(points.size(), curve.size());
                    const bool reversed = side["reversed"].toBool();
                    for (qsizetype k = 0; k < curve.size(); ++k) {
                        QVERIFY(toVec3(curve[k]) ==
                                toVec3(points[reversed ? curve.size() - 1 - k : k]));
                    }
                }
            }
            const QJsonObject mesh = surface["mesh"].toObject();
            const QJsonObject development = surface["development"].toObject();
            QCOMPARE(development["vertices"].toArray().size(), mesh["vertices"].toArray().size());
            for (const QJsonValue& face : mesh["faces"].toArray()) {
                const qsizetype corners = face.toArray().size();
                QVERIFY(corners == 3 || corners == 4);
                for (const QJsonValue& index : face.toArray()) {
                    QVERIFY(index.toInt() >= 0 &&
                            index.toInt() < mesh["vertices"].toArray().size());
                }
            }
            QCOMPARE(development["period"].isNull(),
                     info.name != "cylinder" && info.name != "column");
        }
    }

    void creaseSidesNormalsAndFolds() {
        // From the JSON alone: both strips' normals (a′ × (b − a), flipped where told) point to
        // the same side, `left` lies on the left of the crease seen from there, and folding
        // the sheet up beyond y = 100 makes valleys (down: mountains) with the fold angle.
        auto mean = [](const QJsonArray& points) {
            model::Vec3 sum;
            for (const QJsonValue& p : points) {
                sum += toVec3(p);
            }
            return sum / static_cast<double>(points.size());
        };
        for (const double degrees : {0.0, 30.0, -30.0}) {
            for (const char* name : {"sheet", "annulus"}) {
                model::Project project = model::makeExample(name);
                if (degrees != 0.0) {
                    if (std::string(name) != "sheet") {
                        continue;
                    }
                    model::CompositeSurface& surface = project.surfaces.front();
                    devsurf::test::foldBeyond(surface, 100.0, degrees * M_PI / 180.0);
                    QVERIFY(surface.validate().empty());
                }
                const QJsonObject surface =
                    parse(io::interchangeJson(project, 2))["surfaces"].toArray()[0].toObject();
                const QJsonArray strips = surface["strips"].toArray();
                int folded = 0;
                for (const QJsonValue& value : surface["creases"].toArray()) {
                    const QJsonObject crease = value.toObject();
                    const QJsonArray curve = crease["curve"].toObject()["controlPoints"].toArray();
                    const model::Vec3 t = toVec3(curve.last()) - toVec3(curve.first());
                    model::Vec3 normals[2];
                    model::Vec3 away[2]; // from the crease to the strip's other curve
                    int k = 0;
                    for (const char* which : {"left", "right"}) {
                        const QJsonObject side = crease[which].toObject();
                        const QJsonObject strip = strips[side["strip"].toInt()].toObject();
                        const QJsonArray a = strip["a"].toObject()["controlPoints"].toArray();
                        const QJsonArray b = strip["b"].toObject()["controlPoints"].toArray();
                        model::Vec3 n =
                            cross(toVec3(a.last()) - toVec3(a.first()), mean(b) - mean(a));
                        normals[k] = side["flipNormal"].toBool() ? n * -1.0 : n;
                        away[k] =
                            side["side"].toString() == "a" ? mean(b) - mean(a) : mean(a) - mean(b);
                        ++k;
                    }
                    QVERIFY(dot(normals[0], normals[1]) > 0.0 || degrees != 0.0);
                    QVERIFY(dot(cross(normals[0], t), away[0]) > 0.0);
                    QVERIFY(dot(cross(normals[1], t), away[1]) < 0.0);
                    const QString assignment = crease["assignment"].toString();
                    const double foldAngle = crease["foldAngle"].toDouble();
                    if (assignment != "F") {
                        ++folded;
                        QVERIFY(std::abs(std::abs(foldAngle) - std::abs(degrees)) < 1e-6);
                        QCOMPARE(assignment, QString(degrees > 0 ? "V" : "M"));
                    } else {
                        QVERIFY(std::abs(foldAngle) < 0.1);
                    }
                }
                QCOMPARE(folded, degrees == 0.0 ? 0 : 3);
            }
        }
    }

    // Every double is written so that it reads back bit for bit: values without a short decimal
    // form (0.1, 1/3), tiny and subnormal numbers. The one exception is the sign of zero:
    // −0 is written as 0 (QJsonDocument does so), and reads back as +0, equal to −0.
    void everyDoubleReadsBackBitForBit() {
        model::Project project = model::makeExample("sheet");
        model::CompositeSurface& surface = project.surfaces.front();
        const std::vector<double> planted = {0.1,    1.0 / 3.0, 1e-300,           -0.0,
                                             5e-324, 2.0 / 3e7, 123456.789012345, -1.0 / 7.0};
        std::size_t next = 0;
        for (const auto& [id, record] : surface.edges()) {
            if (!record.isSpline() || record.controlPoints.size() < 4 || next >= planted.size()) {
                continue;
            }
            // Heights of interior control points: the sheet stays valid.
            std::vector<model::Vec3> points = record.controlPoints;
            for (std::size_t k = 1; k + 1 < points.size() && next < planted.size(); ++k) {
                points[k].z = planted[next++];
            }
            surface.setControlPoints(id, points);
        }
        QCOMPARE(next, planted.size());
        QVERIFY(surface.validate().empty());

        const std::string text = io::interchangeJson(project, 3);
        const std::set<std::uint64_t> written = numbersIn(text);
        // As written: the bits of the value, +0 for either zero.
        const auto expected = [](double value) { return bitsOf(value == 0.0 ? 0.0 : value); };
        for (double value : planted) {
            QVERIFY2(written.count(expected(value)) == 1,
                     qPrintable(QString::number(value, 'g', 17)));
        }
        QVERIFY(written.count(bitsOf(-0.0)) == 0);
        for (const auto& [id, record] : surface.edges()) {
            for (const model::Vec3& p : record.controlPoints) {
                for (double value : {p.x, p.y, p.z}) {
                    QVERIFY(written.count(expected(value)) == 1);
                }
            }
        }
        const model::SampledMesh mesh = model::sampleSurface(surface, 3);
        for (const model::Vec3& p : mesh.vertices) {
            for (double value : {p.x, p.y, p.z}) {
                QVERIFY2(written.count(expected(value)) == 1,
                         qPrintable(QString::number(value, 'g', 17)));
            }
        }

        // Qt's reader gives the same bits for the mesh as written.
        const QJsonArray vertices = parse(text)["surfaces"]
                                        .toArray()[0]
                                        .toObject()["mesh"]
                                        .toObject()["vertices"]
                                        .toArray();
        QCOMPARE(vertices.size(), qsizetype(mesh.vertices.size()));
        for (qsizetype i = 0; i < vertices.size(); ++i) {
            const model::Vec3 p = toVec3(vertices[i]);
            const model::Vec3& q = mesh.vertices[static_cast<std::size_t>(i)];
            QVERIFY(bitsOf(p.x) == expected(q.x) && bitsOf(p.y) == expected(q.y) &&
                    bitsOf(p.z) == expected(q.z));
        }
    }

    void creaseCountsMatchTheModel() {
        const QJsonObject root = parse(io::interchangeJson(model::makeExample("annulus"), 2));
        const QJsonObject surface = root["surfaces"].toArray()[0].toObject();
        // 6 rings: 5 interior circles of 8 arcs each are creases.
        QCOMPARE(surface["creases"].toArray().size(), qsizetype(5 * 8));
        QCOMPARE(surface["planarFaces"].toArray().size(), qsizetype(0));
        const QJsonObject mixed =
            parse(io::interchangeJson(model::makeExample("mixed"), 2))["surfaces"]
                .toArray()[0]
                .toObject();
        QCOMPARE(mixed["planarFaces"].toArray().size(), qsizetype(1));
        QCOMPARE(mixed["planarFaces"].toArray()[0].toObject()["polygon"].toArray().size(),
                 qsizetype(4));
    }

    void aCylinderSheetIsWrittenWithItsPeriod() {
        // The column holds its sheet around a cylinder: its shape, radius and the period the
        // development is read modulo, (2πr, 0) as it unrolls.
        const model::Project project = model::makeExample("column");
        const QJsonObject sheet = parse(io::interchangeJson(project, 4))["surfaces"]
                                      .toArray()[0]
                                      .toObject()["keptDevelopment"]
                                      .toObject()["sheet"]
                                      .toObject();
        QCOMPARE(sheet["shape"].toString(), QStringLiteral("cylinder"));
        const double radius = sheet["radius"].toDouble();
        QCOMPARE(radius, project.surfaces[0].sheetDomain().radius);
        const QJsonArray period = sheet["period"].toArray();
        QCOMPARE(period.size(), qsizetype(2));
        QVERIFY(std::abs(period[0].toDouble() - 2.0 * 3.14159265358979323846 * radius) < 1e-9);
        QVERIFY(std::abs(period[1].toDouble()) < 1e-9);
        QVERIFY(!sheet.contains("loops"));
    }

    void keptDevelopmentIsWritten() {
        model::Project project = model::makeExample("fig8");
        QVERIFY(parse(io::interchangeJson(project, 4))["surfaces"]
                    .toArray()[0]
                    .toObject()["keptDevelopment"]
                    .isNull());
        QVERIFY(!model::keepDevelopment(project.surfaces[0]).has_value());
        const QJsonObject kept = parse(io::interchangeJson(project, 4))["surfaces"]
                                     .toArray()[0]
                                     .toObject()["keptDevelopment"]
                                     .toObject();
        QCOMPARE(kept["samplesPerInterval"].toInt(), model::kDevelopmentSamplesPerInterval);
        const QJsonArray vertices = kept["vertices"].toArray();
        const std::vector<model::Vec2>& sheet = project.surfaces[0].development();
        QCOMPARE(static_cast<std::size_t>(vertices.size()), sheet.size());
        for (qsizetype i = 0; i < vertices.size(); ++i) {
            const QJsonArray p = vertices[i].toArray();
            QCOMPARE(p[0].toDouble(), sheet[static_cast<std::size_t>(i)].x);
            QCOMPARE(p[1].toDouble(), sheet[static_cast<std::size_t>(i)].y);
        }
        QCOMPARE(kept["sheet"].toObject()["shape"].toString(), QStringLiteral("free"));
        // A rectangle's sizes, placement and corners (counter-clockwise about its centre).
        model::SheetDomain square;
        square.shape = model::SheetShape::Rectangle;
        square.width = 300.0;
        square.height = 200.0;
        square.centre = {150.0, 100.0};
        project.surfaces[0].setSheetDomain(square);
        const QJsonObject shape = parse(io::interchangeJson(project, 4))["surfaces"]
                                      .toArray()[0]
                                      .toObject()["keptDevelopment"]
                                      .toObject()["sheet"]
                                      .toObject();
        QCOMPARE(shape["shape"].toString(), QStringLiteral("rectangle"));
        QCOMPARE(shape["width"].toDouble(), 300.0);
        QCOMPARE(shape["height"].toDouble(), 200.0);
        const QJsonArray corners = shape["loops"].toArray()[0].toArray();
        QCOMPARE(corners.size(), 4);
        QCOMPARE(corners[0].toArray()[0].toDouble(), 0.0);
        QCOMPARE(corners[2].toArray()[1].toDouble(), 200.0);
        QVERIFY(!shape.contains("creaseCurves"));
        // Crease curves drawn in it: placed in the development's plane, with their creases.
        square.creaseCurves = {{{{-150, 0}, {0, 10}, {150, 0}}, false}};
        square.creaseCurveOf = {{7, 0}, {9, 0}};
        project.surfaces[0].setSheetDomain(square);
        const QJsonArray curves = parse(io::interchangeJson(project, 4))["surfaces"]
                                      .toArray()[0]
                                      .toObject()["keptDevelopment"]
                                      .toObject()["sheet"]
                                      .toObject()["creaseCurves"]
                                      .toArray();
        QCOMPARE(curves.size(), 1);
        const QJsonObject curve = curves[0].toObject();
        QVERIFY(!curve["closed"].toBool());
        QCOMPARE(curve["points"].toArray().size(), 3);
        QCOMPARE(curve["points"].toArray()[1].toArray()[0].toDouble(), 150.0); // moved by centre
        QCOMPARE(curve["points"].toArray()[1].toArray()[1].toDouble(), 110.0);
        QCOMPARE(curve["edges"].toArray().size(), 2);
        QCOMPARE(curve["edges"].toArray()[1].toInt(), 9);
    }

    void referenceCurvesAreWritten() {
        model::Project project = model::makeExample("sheet");
        QVERIFY(parse(io::interchangeJson(project, 2))["referenceCurves"].toArray().isEmpty());
        project.referenceCurves.push_back({"SPLINE 1", "guides", {{0, 0, 0}, {0.1, 2, -3e-17}}});
        project.referenceCurves.push_back({"circle", "", {{1, 2, 3}, {4, 5, 6}, {1, 2, 3}}});
        const QJsonArray curves =
            parse(io::interchangeJson(project, 2))["referenceCurves"].toArray();
        QCOMPARE(curves.size(), 2);
        for (qsizetype c = 0; c < curves.size(); ++c) {
            const model::ReferenceCurve& curve =
                project.referenceCurves[static_cast<std::size_t>(c)];
            const QJsonObject object = curves[c].toObject();
            QCOMPARE(object["name"].toString().toStdString(), curve.name);
            QCOMPARE(object["source"].toString().toStdString(), curve.source);
            const QJsonArray points = object["points"].toArray();
            QCOMPARE(static_cast<std::size_t>(points.size()), curve.points.size());
            for (qsizetype i = 0; i < points.size(); ++i) {
                const model::Vec3& p = curve.points[static_cast<std::size_t>(i)];
                const QJsonArray q = points[i].toArray();
                QCOMPARE(q[0].toDouble(), p.x); // bit for bit
                QCOMPARE(q[1].toDouble(), p.y);
                QCOMPARE(q[2].toDouble(), p.z);
            }
        }
    }

    void referenceShapesAreWritten() {
        model::Project project = model::makeExample("sheet");
        QVERIFY(parse(io::interchangeJson(project, 2))["referenceShapes"].toArray().isEmpty());
        project.referenceShapes.push_back({"tet",
                                           "tet.stl",
                                           {{0, 0, 0}, {10, 0, 0}, {0, 1.0 / 3.0, 0}, {0, 0, -7}},
                                           {},
                                           {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}});
        project.referenceShapes.push_back(
            {"scan", "", {{1, 2, 3}, {-4, 5e-300, 6}}, {{0, 0, 1}, {0.6, 0.8, 0}}, {}});
        const QJsonArray shapes =
            parse(io::interchangeJson(project, 2))["referenceShapes"].toArray();
        QCOMPARE(shapes.size(), 2);
        for (qsizetype s = 0; s < shapes.size(); ++s) {
            const model::ReferenceShape& shape =
                project.referenceShapes[static_cast<std::size_t>(s)];
            const QJsonObject object = shapes[s].toObject();
            QCOMPARE(object["name"].toString().toStdString(), shape.name);
            QCOMPARE(object["source"].toString().toStdString(), shape.source);
            QCOMPARE(object["pointCount"].toInteger(), static_cast<qint64>(shape.points.size()));
            auto compare = [](const QJsonArray& json, const std::vector<model::Vec3>& points) {
                QCOMPARE(static_cast<std::size_t>(json.size()), points.size());
                for (qsizetype i = 0; i < json.size(); ++i) {
                    const model::Vec3& p = points[static_cast<std::size_t>(i)];
                    const QJsonArray q = json[i].toArray();
                    QCOMPARE(q[0].toDouble(), p.x); // bit for bit
                    QCOMPARE(q[1].toDouble(), p.y);
                    QCOMPARE(q[2].toDouble(), p.z);
                }
            };
            compare(object["points"].toArray(), shape.points);
            compare(object["normals"].toArray(), shape.normals);
            const QJsonArray triangles = object["triangles"].toArray();
            QCOMPARE(static_cast<std::size_t>(triangles.size()), shape.triangles.size());
            for (qsizetype t = 0; t < triangles.size(); ++t) {
                for (qsizetype k = 0; k < 3; ++k) {
                    QCOMPARE(triangles[t].toArray()[k].toInteger(),
                             static_cast<qint64>(shape.triangles[static_cast<std::size_t>(t)]
                                                                [static_cast<std::size_t>(k)]));
                }
            }
        }
    }
};

DEVSURF_REGISTER_TEST(TstInterchangeJson);
#include "tst_interchange_json.moc"
