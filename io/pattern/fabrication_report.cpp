#include "fabrication_report.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cstdio>

namespace devsurf::io {

bool FabricationReport::hasOverlaps() const {
    return std::any_of(pieces.begin(), pieces.end(), [](const PieceReport& piece) {
        return piece.selfOverlapping || !piece.overlapsWith.empty();
    });
}

FabricationReport fabricationReport(const model::CuttingPattern& pattern,
                                    std::vector<std::string> problemTexts) {
    FabricationReport report;
    report.sheetSize = pattern.sheetSize;
    report.sheetCount = pattern.sheetCount;
    report.problems = std::move(problemTexts);
    const auto count = static_cast<int>(pattern.pieces.size());
    for (const model::PatternPiece& piece : pattern.pieces) {
        PieceReport row;
        row.name = piece.name;
        row.sheet = piece.sheet;
        row.size = piece.size;
        row.area = piece.area;
        row.maxIsometryError = piece.maxIsometryError;
        row.selfOverlapping = piece.selfOverlapping;
        const model::Vec2 sheet = pattern.sheetSize;
        const bool fitsUpright = piece.size.x <= sheet.x && piece.size.y <= sheet.y;
        const bool fitsTurned = piece.size.y <= sheet.x && piece.size.x <= sheet.y;
        row.fitsSheet = piece.sheet >= 0 || fitsUpright || fitsTurned;
        report.totalArea += piece.area;
        report.maxIsometryError = std::max(report.maxIsometryError, piece.maxIsometryError);
        report.pieces.push_back(row);
    }
    for (const model::PatternOverlap& overlap : pattern.overlaps) {
        if (overlap.first < 0 || overlap.first >= count || overlap.second < 0 ||
            overlap.second >= count) {
            continue;
        }
        PieceReport& first = report.pieces[std::size_t(overlap.first)];
        PieceReport& second = report.pieces[std::size_t(overlap.second)];
        if (overlap.first == overlap.second) {
            first.selfOverlapping = true;
            continue;
        }
        first.overlapsWith.push_back(second.name);
        second.overlapsWith.push_back(first.name);
    }
    return report;
}

namespace {

std::string format(const char* pattern, double a, double b = 0.0) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, a, b);
    return buffer;
}

std::string overlapText(const PieceReport& piece) {
    std::string text;
    if (piece.selfOverlapping) {
        text = "itself";
    }
    for (const std::string& other : piece.overlapsWith) {
        text += (text.empty() ? "" : ", ") + other;
    }
    return text.empty() ? "none" : text;
}

} // namespace

std::string fabricationReportText(const FabricationReport& report) {
    std::string text = "Cutting pattern: " + std::to_string(report.pieces.size()) +
                       (report.pieces.size() == 1 ? " piece" : " pieces") + " on " +
                       std::to_string(report.sheetCount) +
                       (report.sheetCount == 1 ? " sheet" : " sheets") + " of " +
                       format("%.0f x %.0f mm", report.sheetSize.x, report.sheetSize.y) + "\n";
    text += format("Total area: %.0f mm², largest isometry error: %.3g mm\n", report.totalArea,
                   report.maxIsometryError);
    char line[256];
    std::snprintf(line, sizeof line, "%-8s %5s %19s %12s %11s %4s  %s\n", "piece", "sheet",
                  "size (mm)", "area (mm²)", "isometry", "fits", "overlaps");
    text += line;
    for (const PieceReport& piece : report.pieces) {
        const std::string sheet = piece.sheet >= 0 ? std::to_string(piece.sheet + 1) : "-";
        std::snprintf(
            line, sizeof line, "%-8s %5s %19s %11.0f %8.2g mm %4s  %s\n", piece.name.c_str(),
            sheet.c_str(), format("%.1f x %.1f", piece.size.x, piece.size.y).c_str(), piece.area,
            piece.maxIsometryError, piece.fitsSheet ? "yes" : "no", overlapText(piece).c_str());
        text += line;
    }
    for (const std::string& problem : report.problems) {
        text += "Problem: " + problem + "\n";
    }
    return text;
}

QByteArray fabricationReportJson(const FabricationReport& report) {
    QJsonArray pieces;
    for (const PieceReport& piece : report.pieces) {
        QJsonArray overlaps;
        for (const std::string& other : piece.overlapsWith) {
            overlaps.append(QString::fromStdString(other));
        }
        QJsonObject object;
        object[QStringLiteral("name")] = QString::fromStdString(piece.name);
        object[QStringLiteral("sheet")] =
            piece.sheet >= 0 ? QJsonValue(piece.sheet + 1) : QJsonValue(QJsonValue::Null);
        object[QStringLiteral("width")] = piece.size.x;
        object[QStringLiteral("height")] = piece.size.y;
        object[QStringLiteral("area")] = piece.area;
        object[QStringLiteral("maxIsometryError")] = piece.maxIsometryError;
        object[QStringLiteral("selfOverlapping")] = piece.selfOverlapping;
        object[QStringLiteral("overlapsWith")] = overlaps;
        object[QStringLiteral("fitsSheet")] = piece.fitsSheet;
        pieces.append(object);
    }
    QJsonArray problems;
    for (const std::string& problem : report.problems) {
        problems.append(QString::fromStdString(problem));
    }
    QJsonObject root;
    root[QStringLiteral("units")] = QStringLiteral("mm");
    root[QStringLiteral("sheetWidth")] = report.sheetSize.x;
    root[QStringLiteral("sheetHeight")] = report.sheetSize.y;
    root[QStringLiteral("sheetCount")] = report.sheetCount;
    root[QStringLiteral("totalArea")] = report.totalArea;
    root[QStringLiteral("maxIsometryError")] = report.maxIsometryError;
    root[QStringLiteral("hasOverlaps")] = report.hasOverlaps();
    root[QStringLiteral("pieces")] = pieces;
    root[QStringLiteral("problems")] = problems;
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

} // namespace devsurf::io
