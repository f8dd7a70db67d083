#pragma once

// Reads a STEP or IGES file with FreeCAD's command-line interpreter (freecadcmd), a reader we
// did not write: face and shell counts, closedness, area, and points sampled on the faces.

#include "model/vec3.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace devsurf::test {

struct CadReadBack {
    bool ok = false;
    QString error;
    int faces = 0;
    int shells = 0;
    std::vector<bool> shellClosed;
    double area = 0.0;               // integrated with FreeCAD's evaluation of the faces
    double freeCadArea = 0.0;        // FreeCAD's Shape.Area
    std::vector<model::Vec3> points; // sampled inside the faces
};

// The files are read in one run of freecadcmd (it takes about 0.4 s to start) from a fresh
// temporary folder; each result says why it failed (freecadcmd missing, the file unreadable).
std::vector<CadReadBack> readWithFreeCad(const QStringList& paths);
CadReadBack readWithFreeCad(const QString& path);

} // namespace devsurf::test
