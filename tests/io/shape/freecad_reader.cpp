#include "freecad_reader.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

namespace devsurf::test {

namespace {

// FreeCAD's side: Part.read (OpenCASCADE's readers as FreeCAD sets them up), then per face a
// 4 x 4 grid of parameters, kept where the parameter lies in the face's domain. The area of a
// B-spline face is integrated here with FreeCAD's derivatives (Gauss–Legendre per knot span):
// FreeCAD's own Shape.Area is off by up to 5e-5 where a patch narrows to a point; a plane's
// area is FreeCAD's (exact from its boundary).
const char* const kScript = R"(
import json, Part
from numpy.polynomial.legendre import leggauss

def spans(knots, low, high):
    cuts = sorted(set([low, high] + [k for k in knots if low < k < high]))
    return list(zip(cuts[:-1], cuts[1:]))

def face_area(face):
    surface = face.Surface
    if not isinstance(surface, Part.BSplineSurface):
        return face.Area
    u0, u1, v0, v1 = face.ParameterRange
    un, uw = leggauss(16)
    vn, vw = leggauss(8)
    area = 0.0
    for a, b in spans(surface.getUKnots(), u0, u1):
        for c, d in spans(surface.getVKnots(), v0, v1):
            for x, wx in zip(un, uw):
                for y, wy in zip(vn, vw):
                    u = a + (b - a) * (x + 1) / 2
                    v = c + (d - c) * (y + 1) / 2
                    n = surface.getDN(u, v, 1, 0).cross(surface.getDN(u, v, 0, 1))
                    area += wx * wy * (b - a) * (d - c) / 4 * n.Length
    return area

def read(path):
    result = {}
    try:
        shape = Part.read(path)
        result["faces"] = len(shape.Faces)
        result["shells"] = len(shape.Shells)
        result["closed"] = [s.isClosed() for s in shape.Shells]
        result["area"] = sum(face_area(f) for f in shape.Faces)
        result["freecad_area"] = shape.Area
        points = []
        for face in shape.Faces:
            u0, u1, v0, v1 = face.ParameterRange
            for i in range(4):
                for j in range(4):
                    u = u0 + (u1 - u0) * (i + 0.37) / 4.0
                    v = v0 + (v1 - v0) * (j + 0.61) / 4.0
                    if face.isPartOfDomain(u, v):
                        p = face.valueAt(u, v)
                        points.append([p.x, p.y, p.z])
        result["points"] = points
    except Exception as error:
        result["error"] = str(error)
    return result

with open(OUTPUT, "w") as out:
    json.dump([read(path) for path in INPUTS], out)
)";

QString pythonString(const QString& text) {
    QString quoted = text;
    quoted.replace(QLatin1String("\\"), QLatin1String("\\\\"));
    quoted.replace(QLatin1String("\""), QLatin1String("\\\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

} // namespace

std::vector<CadReadBack> readWithFreeCad(const QStringList& paths) {
    std::vector<CadReadBack> backs(static_cast<std::size_t>(paths.size()));
    auto failAll = [&backs](const QString& error) {
        for (CadReadBack& back : backs) {
            back.error = error;
        }
        return backs;
    };
    const QString freecad = QStandardPaths::findExecutable(QStringLiteral("freecadcmd"));
    if (freecad.isEmpty()) {
        return failAll(
            QStringLiteral("freecadcmd is not installed (Debian package freecad-python3)"));
    }
    QTemporaryDir folder;
    const QString script = folder.filePath(QStringLiteral("read.py"));
    const QString output = folder.filePath(QStringLiteral("result.json"));
    QFile file(script);
    if (!folder.isValid() || !file.open(QIODevice::WriteOnly)) {
        return failAll(QStringLiteral("cannot write the script"));
    }
    QStringList inputs;
    for (const QString& path : paths) {
        inputs << pythonString(path);
    }
    file.write(("INPUTS = [" + inputs.join(QLatin1String(", ")) +
                "]\nOUTPUT = " + pythonString(output) + "\n")
                   .toUtf8());
    file.write(kScript);
    file.close();
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("HOME"), folder.path()); // FreeCAD writes its settings
    process.setProcessEnvironment(environment);
    process.start(freecad, {script});
    if (!process.waitForFinished(300000) || process.exitStatus() != QProcess::NormalExit) {
        return failAll(QStringLiteral("freecadcmd did not finish"));
    }
    QFile json(output);
    if (!json.open(QIODevice::ReadOnly)) {
        return failAll(QStringLiteral("freecadcmd wrote no result: ") +
                       QString::fromUtf8(process.readAllStandardError()));
    }
    const QJsonArray results = QJsonDocument::fromJson(json.readAll()).array();
    if (results.size() != paths.size()) {
        return failAll(QStringLiteral("freecadcmd's result is incomplete"));
    }
    for (std::size_t i = 0; i < backs.size(); ++i) {
        const QJsonObject result = results[static_cast<int>(i)].toObject();
        CadReadBack& back = backs[i];
        if (result.contains(QStringLiteral("error"))) {
            back.error = result[QStringLiteral("error")].toString();
            continue;
        }
        back.faces = result[QStringLiteral("faces")].toInt(-1);
        back.shells = result[QStringLiteral("shells")].toInt(-1);
        for (const QJsonValue closed : result[QStringLiteral("closed")].toArray()) {
            back.shellClosed.push_back(closed.toBool());
        }
        back.area = result[QStringLiteral("area")].toDouble();
        back.freeCadArea = result[QStringLiteral("freecad_area")].toDouble();
        for (const QJsonValue point : result[QStringLiteral("points")].toArray()) {
            const QJsonArray p = point.toArray();
            back.points.push_back({p[0].toDouble(), p[1].toDouble(), p[2].toDouble()});
        }
        back.ok = true;
    }
    return backs;
}

CadReadBack readWithFreeCad(const QString& path) {
    return readWithFreeCad(QStringList{path}).front();
}

} // namespace devsurf::test
