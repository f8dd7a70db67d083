#pragma once

// What a builder must know before cutting, per piece: size, area, the largest isometry error,
// overlaps and whether it fits the sheet. Printed by the CLI, shown before export, and the
// first page of the PDF.

#include "model/pattern/cutting_pattern.h"

#include <QByteArray>

#include <string>
#include <vector>

namespace devsurf::io {

struct PieceReport {
    std::string name;
    int sheet = -1; // -1: not placed
    model::Vec2 size;
    double area = 0.0;
    double maxIsometryError = 0.0;
    bool selfOverlapping = false;
    std::vector<std::string> overlapsWith; // names of other pieces it overlaps
    bool fitsSheet = true;
};

struct FabricationReport {
    std::vector<PieceReport> pieces;
    model::Vec2 sheetSize;
    int sheetCount = 0;
    double totalArea = 0.0;
    double maxIsometryError = 0.0;
    std::vector<std::string> problems;
    // Any piece overlapping itself or another: the pattern cannot be cut as it is.
    bool hasOverlaps() const;
};

// `problemTexts`: the pattern's problems as the front end words them (app::patternProblemTexts).
FabricationReport fabricationReport(const model::CuttingPattern& pattern,
                                    std::vector<std::string> problemTexts);

// A plain-text table, one line per piece, then the problems.
std::string fabricationReportText(const FabricationReport& report);

// The same as JSON (units mm and mm²).
QByteArray fabricationReportJson(const FabricationReport& report);

} // namespace devsurf::io
