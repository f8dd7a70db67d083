#include "interchange_json.h"
#include "model/derived_geometry.h"

#include "file_error.h"
#include "model/creases.h"
#include "model/development.h"
#include "model/sampled_mesh.h"
#include "model/sheet_creases.h"
#include "model/strip.h"
#include "output_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>

#include <array>
#include <vector>

namespace devsurf::io {

namespace {

// Doubles become JSON numbers as QJsonDocument writes them: the shortest decimal form that
// reads back as the same IEEE double.
QJsonArray point(const model::Vec3& p) {
    return {p.x, p.y, p.z};
}

QJsonArray point(const model::Vec2& p) {
    return {p.x, p.y};
}

template <class T, class F> QJsonArray array(const std::vector<T>& items, F&& each) {
    QJsonArray result;
    for (const T& item : items) {
        result.append(each(item));
    }
    return result;
}

QJsonValue integer(long long value) {
    return QJsonValue(static_cast<qint64>(value));
}

QJsonObject curveObject(const model::BSplineCurve& curve) {
    return {
        {"degree", integer(curve.degree())},
        {"knots", array(curve.exportKnots(), [](double k) { return QJsonValue(k); })},
        {"controlPoints",
         array(curve.exportControlPoints(), [](const model::Vec3& p) { return point(p); })},
        {"closed", curve.isClosed()},
    };
}

QJsonObject creaseSideObject(const model::CreaseSide& side) {
    return {
        {"strip", integer(static_cast<long long>(side.strip))},
        {"side", side.sideA ? "a" : "b"},
        {"reversed", side.reversed},
        {"flipNormal", side.flipNormal},
    };
}

// The sheet a kept development is confined to: its shape, sizes, placement and, for an
// outline, its loops as the development's plane sees them.
QJsonObject sheetJson(const model::SheetDomain& d) {
    static const char* const names[] = {"free",    "rectangle", "disk",
                                        "annulus", "outline",   "cylinder"};
    QJsonObject sheet{{"shape", names[static_cast<int>(d.shape)]}};
    switch (d.shape) {
    case model::SheetShape::Free:
        return sheet;
    case model::SheetShape::Rectangle:
        sheet["width"] = d.width;
        sheet["height"] = d.height;
        break;
    case model::SheetShape::Disk:
        sheet["radius"] = d.radius;
        break;
    case model::SheetShape::Annulus:
        sheet["radius"] = d.radius;
        sheet["innerRadius"] = d.innerRadius;
        break;
    case model::SheetShape::Outline:
        break;
    case model::SheetShape::Cylinder:
        // The development's coordinates are read modulo this translation.
        sheet["radius"] = d.radius;
        sheet["period"] = point(*model::domainPeriod(d));
        break;
    }
    sheet["centre"] = point(d.centre);
    sheet["angle"] = d.angle;
    QJsonArray loops;
    for (const model::DomainLoop& loop : model::domainLoops(d)) {
        if (!loop.circle) {
            loops.append(array(loop.polygon, [](const model::Vec2& p) { return point(p); }));
        }
    }
    if (!loops.isEmpty()) {
        sheet["loops"] = loops;
    }
    // The crease curves as the development's plane sees them, with the creases held on each.
    const std::vector<model::DomainLoop> placed = model::creaseCurveLoops(d);
    QJsonArray curves;
    for (std::size_t c = 0; c < placed.size(); ++c) {
        QJsonArray edges;
        for (const auto& [edge, curve] : d.creaseCurveOf) {
            if (curve == static_cast<int>(c)) {
                edges.append(integer(edge));
            }
        }
        curves.append(QJsonObject{
            {"points", array(placed[c].polygon, [](const model::Vec2& p) { return point(p); })},
            {"closed", !placed[c].open},
            {"edges", edges},
        });
    }
    if (!curves.isEmpty()) {
        sheet["creaseCurves"] = curves;
    }
    return sheet;
}

QJsonObject surfaceObject(const model::CompositeSurface& surface, int samples) {
    using namespace model;
    const auto derived = DerivedGeometry::of(surface, samples);
    const std::vector<Strip>& strips = derived->strips();
    const SampledMesh& mesh = derived->mesh();

    QJsonArray stripArray;
    for (const Strip& s : strips) {
        stripArray.append(QJsonObject{
            {"face", integer(s.face)},
            {"type", s.isCone() ? "cone" : "strip"},
            {"a", curveObject(s.a)},
            {"b", s.isCone() ? QJsonValue() : QJsonValue(curveObject(s.b))},
            {"apex", s.isCone() ? QJsonValue(point(s.apex)) : QJsonValue()},
        });
    }

    QJsonArray planarFaces;
    for (const auto& [faceId, loop] : surface.faces()) {
        if (surface.faceType(faceId) == FaceType::Planar) {
            planarFaces.append(QJsonObject{
                {"face", integer(faceId)},
                {"polygon", array(loop, [&](VertexId v) { return point(surface.position(v)); })},
            });
        }
    }

    QJsonArray creases;
    for (const Crease& crease : creasesOf(surface, strips, mesh)) {
        if (crease.left.strip == CreaseSide::kNoStrip ||
            crease.right.strip == CreaseSide::kNoStrip) {
            continue;
        }
        const EdgeRecord& record = surface.edge(crease.edge);
        creases.append(QJsonObject{
            {"edge", integer(crease.edge)},
            {"curve", curveObject(BSplineCurve::uniform(record.space, record.controlPoints))},
            {"left", creaseSideObject(crease.left)},
            {"right", creaseSideObject(crease.right)},
            {"condition", QString::fromLatin1(creaseConditionName(record.condition))},
            {"assignment", QString::fromLatin1(foldAssignmentLetter(crease.assignment))},
            {"foldAngle", crease.foldAngleDegrees},
        });
    }

    QJsonArray rulings;
    for (const auto& [edgeId, record] : surface.edges()) {
        if (!record.isSpline() && surface.facesOfEdge(edgeId).size() == 2) {
            rulings.append(QJsonObject{
                {"edge", integer(edgeId)},
                {"from", point(surface.position(record.from))},
                {"to", point(surface.position(record.to))},
                {"smooth", record.smooth},
            });
        }
    }

    const Development& development = derived->development();
    return {
        {"name", QString::fromStdString(surface.name())},
        {"strips", stripArray},
        {"planarFaces", planarFaces},
        {"creases", creases},
        {"rulings", rulings},
        {"mesh",
         QJsonObject{
             {"vertices", array(mesh.vertices, [](const Vec3& p) { return point(p); })},
             {"faces", array(mesh.faces,
                             [](const std::vector<int>& face) {
                                 return array(face, [](int i) { return integer(i); });
                             })},
         }},
        {"development",
         QJsonObject{
             {"vertices", array(development.vertices, [](const Vec2& p) { return point(p); })},
             {"period", development.period ? QJsonValue(point(*development.period)) : QJsonValue()},
             {"closureError", development.closureError},
         }},
        {"keptDevelopment", !surface.keepsDevelopment()
                                ? QJsonValue()
                                : QJsonValue(QJsonObject{
                                      {"samplesPerInterval", kDevelopmentSamplesPerInterval},
                                      {"vertices", array(surface.development(),
                                                         [](const Vec2& p) { return point(p); })},
                                      {"sheet", sheetJson(surface.sheetDomain())},
                                  })},
    };
}

} // namespace

void saveInterchangeJsonFile(const model::Project& project, const QString& path,
                             int samplesPerInterval) {
    const std::string text = interchangeJson(project, samplesPerInterval);
    writeFileAtomically(path, QByteArray(text.data(), static_cast<qsizetype>(text.size())));
}

std::string interchangeJson(const model::Project& project, int samplesPerInterval) {
    QJsonArray surfaces;
    for (const model::CompositeSurface& surface : project.surfaces) {
        surfaces.append(surfaceObject(surface, samplesPerInterval));
    }
    QJsonArray curves;
    for (const model::ReferenceCurve& curve : project.referenceCurves) {
        curves.append(QJsonObject{
            {"name", QString::fromStdString(curve.name)},
            {"source", QString::fromStdString(curve.source)},
            {"points", array(curve.points, [](const model::Vec3& p) { return point(p); })},
        });
    }
    QJsonArray shapes;
    for (const model::ReferenceShape& shape : project.referenceShapes) {
        shapes.append(QJsonObject{
            {"name", QString::fromStdString(shape.name)},
            {"source", QString::fromStdString(shape.source)},
            {"pointCount", integer(static_cast<long long>(shape.points.size()))},
            {"points", array(shape.points, [](const model::Vec3& p) { return point(p); })},
            {"normals", array(shape.normals, [](const model::Vec3& n) { return point(n); })},
            {"triangles", array(shape.triangles,
                                [](const std::array<int, 3>& t) {
                                    return QJsonArray{integer(t[0]), integer(t[1]), integer(t[2])};
                                })},
        });
    }
    const QJsonObject root{
        {"format", "devsurf-interchange"},
        {"version", kInterchangeVersion},
        {"units", QString::fromStdString(project.units)},
        {"surfaces", surfaces},
        {"referenceCurves", curves},
        {"referenceShapes", shapes},
    };
    return QJsonDocument(root).toJson(QJsonDocument::Compact).toStdString();
}

} // namespace devsurf::io
