#include "interchange_json.h"

#include "file_error.h"
#include "model/creases.h"
#include "model/development.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"
#include "output_file.h"

#include <cstdio>
#include <map>

namespace devsurf::io {

namespace {

class JsonWriter {
public:
    std::string text;

    void number(double value) {
        char buffer[40];
        std::snprintf(buffer, sizeof buffer, "%.17g", value);
        text += buffer;
    }
    void integer(long long value) { text += std::to_string(value); }
    void string(const std::string& value) {
        text += '"';
        for (char c : value) {
            switch (c) {
            case '"':
                text += "\\\"";
                break;
            case '\\':
                text += "\\\\";
                break;
            case '\n':
                text += "\\n";
                break;
            case '\t':
                text += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buffer[8];
                    std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
                    text += buffer;
                } else {
                    text += c;
                }
            }
        }
        text += '"';
    }
    void key(const char* name) {
        string(name);
        text += ": ";
    }
    void point(const model::Vec3& p) {
        text += '[';
        number(p.x);
        text += ", ";
        number(p.y);
        text += ", ";
        number(p.z);
        text += ']';
    }
    void point(const model::Vec2& p) {
        text += '[';
        number(p.x);
        text += ", ";
        number(p.y);
        text += ']';
    }
    template <class T, class F> void array(const std::vector<T>& items, F&& each) {
        text += '[';
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (i != 0) {
                text += ", ";
            }
            each(items[i]);
        }
        text += ']';
    }
};

void writeCurve(JsonWriter& w, const model::BSplineCurve& curve) {
    w.text += "{";
    w.key("degree");
    w.integer(curve.degree());
    w.text += ", ";
    w.key("knots");
    w.array(curve.exportKnots(), [&w](double k) { w.number(k); });
    w.text += ", ";
    w.key("controlPoints");
    w.array(curve.exportControlPoints(), [&w](const model::Vec3& p) { w.point(p); });
    w.text += ", ";
    w.key("closed");
    w.text += curve.isClosed() ? "true" : "false";
    w.text += "}";
}

void writeSurface(JsonWriter& w, const model::CompositeSurface& surface, int samples) {
    using namespace model;
    const std::vector<Strip> strips = stripsOf(surface);
    const SampledMesh mesh = sampleSurface(surface, samples);
    w.text += "{\n      ";
    w.key("name");
    w.string(surface.name());
    w.text += ",\n      ";
    w.key("strips");
    w.text += "[";
    for (std::size_t i = 0; i < strips.size(); ++i) {
        const Strip& s = strips[i];
        w.text += i == 0 ? "\n        {" : ",\n        {";
        w.key("face");
        w.integer(s.face);
        w.text += ", ";
        w.key("type");
        w.string(s.isCone() ? "cone" : "strip");
        w.text += ", ";
        w.key("a");
        writeCurve(w, s.a);
        w.text += ", ";
        w.key("b");
        if (s.isCone()) {
            w.text += "null";
        } else {
            writeCurve(w, s.b);
        }
        w.text += ", ";
        w.key("apex");
        if (s.isCone()) {
            w.point(s.apex);
        } else {
            w.text += "null";
        }
        w.text += "}";
    }
    w.text += "],\n      ";

    w.key("planarFaces");
    w.text += "[";
    bool first = true;
    for (const auto& [faceId, loop] : surface.faces()) {
        if (surface.faceType(faceId) != FaceType::Planar) {
            continue;
        }
        w.text += first ? "\n        {" : ",\n        {";
        first = false;
        w.key("face");
        w.integer(faceId);
        w.text += ", ";
        w.key("polygon");
        w.array(loop, [&](VertexId v) { w.point(surface.position(v)); });
        w.text += "}";
    }
    w.text += "],\n      ";

    w.key("creases");
    w.text += "[";
    first = true;
    for (const Crease& crease : creasesOf(surface, strips, mesh)) {
        if (crease.left.strip == CreaseSide::kNoStrip ||
            crease.right.strip == CreaseSide::kNoStrip) {
            continue;
        }
        const EdgeRecord& record = surface.edge(crease.edge);
        auto writeSide = [&w](const CreaseSide& side) {
            w.text += "{";
            w.key("strip");
            w.integer(static_cast<long long>(side.strip));
            w.text += ", ";
            w.key("side");
            w.string(side.sideA ? "a" : "b");
            w.text += ", ";
            w.key("reversed");
            w.text += side.reversed ? "true" : "false";
            w.text += ", ";
            w.key("flipNormal");
            w.text += side.flipNormal ? "true" : "false";
            w.text += "}";
        };
        w.text += first ? "\n        {" : ",\n        {";
        first = false;
        w.key("edge");
        w.integer(crease.edge);
        w.text += ", ";
        w.key("curve");
        writeCurve(w, BSplineCurve::uniform(record.space, record.controlPoints));
        w.text += ", ";
        w.key("left");
        writeSide(crease.left);
        w.text += ", ";
        w.key("right");
        writeSide(crease.right);
        w.text += ", ";
        w.key("condition");
        w.string(creaseConditionName(record.condition));
        w.text += ", ";
        w.key("assignment");
        w.string(foldAssignmentLetter(crease.assignment));
        w.text += ", ";
        w.key("foldAngle");
        w.number(crease.foldAngleDegrees);
        w.text += "}";
    }
    w.text += "],\n      ";

    w.key("rulings");
    w.text += "[";
    first = true;
    for (const auto& [edgeId, record] : surface.edges()) {
        if (record.isSpline() || surface.facesOfEdge(edgeId).size() != 2) {
            continue;
        }
        w.text += first ? "\n        {" : ",\n        {";
        first = false;
        w.key("edge");
        w.integer(edgeId);
        w.text += ", ";
        w.key("from");
        w.point(surface.position(record.from));
        w.text += ", ";
        w.key("to");
        w.point(surface.position(record.to));
        w.text += ", ";
        w.key("smooth");
        w.text += record.smooth ? "true" : "false";
        w.text += "}";
    }
    w.text += "],\n      ";

    const Development development = unfoldSampledMesh(mesh);
    w.key("mesh");
    w.text += "{\n        ";
    w.key("vertices");
    w.array(mesh.vertices, [&w](const Vec3& p) { w.point(p); });
    w.text += ",\n        ";
    w.key("faces");
    w.array(mesh.faces,
            [&w](const std::vector<int>& face) { w.array(face, [&w](int i) { w.integer(i); }); });
    w.text += "},\n      ";
    w.key("development");
    w.text += "{\n        ";
    w.key("vertices");
    w.array(development.vertices, [&w](const Vec2& p) { w.point(p); });
    w.text += ",\n        ";
    w.key("period");
    if (development.period) {
        w.point(*development.period);
    } else {
        w.text += "null";
    }
    w.text += ",\n        ";
    w.key("closureError");
    w.number(development.closureError);
    w.text += "}}";
}

} // namespace

void saveInterchangeJsonFile(const model::Project& project, const QString& path,
                             int samplesPerInterval) {
    const std::string text = interchangeJson(project, samplesPerInterval);
    writeFileAtomically(path, QByteArray(text.data(), static_cast<qsizetype>(text.size())));
}

std::string interchangeJson(const model::Project& project, int samplesPerInterval) {
    JsonWriter w;
    w.text += "{\n  ";
    w.key("format");
    w.string("devsurf-interchange");
    w.text += ",\n  ";
    w.key("version");
    w.integer(kInterchangeVersion);
    w.text += ",\n  ";
    w.key("units");
    w.string(project.units);
    w.text += ",\n  ";
    w.key("surfaces");
    w.text += "[";
    for (std::size_t i = 0; i < project.surfaces.size(); ++i) {
        w.text += i == 0 ? "\n    " : ",\n    ";
        writeSurface(w, project.surfaces[i], samplesPerInterval);
    }
    w.text += "]\n}\n";
    return w.text;
}

} // namespace devsurf::io
