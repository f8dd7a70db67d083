#include "pattern_fixtures.h"

#include <cmath>

namespace devsurf::test {

using model::PatternLayer;
using model::PatternPath;
using model::Vec2;

namespace {

Vec2 polar(double radius, int degrees) {
    const double a = degrees * M_PI / 180.0;
    return {kFixtureCentre + radius * std::cos(a), kFixtureCentre + radius * std::sin(a)};
}

PatternPath path(PatternLayer layer, std::vector<Vec2> points, bool closed = false) {
    PatternPath p;
    p.layer = layer;
    p.points = std::move(points);
    p.closed = closed;
    return p;
}

model::PatternPiece sector() {
    model::PatternPiece piece;
    piece.name = "A";
    piece.surface = 0;
    piece.faces = {0, 1, 2};
    piece.sheet = 0;
    // Counter-clockwise: outer arc 0° → 270°, then the inner arc back.
    for (int d = 0; d <= 270; ++d) {
        piece.outline.push_back(polar(kFixtureOuter, d));
    }
    for (int d = 270; d >= 0; --d) {
        piece.outline.push_back(polar(kFixtureInner, d));
    }
    piece.paths.push_back(path(PatternLayer::Cut, piece.outline, true));
    std::vector<Vec2> arc;
    for (int d = 0; d <= 270; ++d) {
        arc.push_back(polar(kFixtureCrease, d));
    }
    piece.paths.push_back(path(PatternLayer::Crease, arc));
    for (int d = 30; d < 270; d += 30) {
        PatternPath crease =
            path(d % 60 == 0 ? PatternLayer::Valley : PatternLayer::Mountain,
                 {polar(kFixtureInner, d), polar(kFixtureCrease, d), polar(kFixtureOuter, d)});
        crease.foldAngleDegrees = d % 60 == 0 ? -20.0 : 20.0;
        piece.paths.push_back(crease);
    }
    for (int d = 10; d < 270; d += 10) {
        if (d % 30 != 0) {
            piece.paths.push_back(
                path(PatternLayer::Score, {polar(kFixtureInner, d), polar(kFixtureCrease, d)}));
        }
    }
    piece.labels.push_back({polar(0.5 * (kFixtureInner + kFixtureOuter), 135), 8.0, 45.0, "A"});
    piece.area = 0.75 * M_PI * (kFixtureOuter * kFixtureOuter - kFixtureInner * kFixtureInner);
    piece.size = {2.0 * kFixtureOuter, 2.0 * kFixtureOuter};
    piece.maxIsometryError = 2e-7;
    return piece;
}

model::PatternPiece rectangle() {
    model::PatternPiece piece;
    piece.name = "B";
    piece.surface = 1;
    piece.faces = {0};
    piece.sheet = 1;
    piece.outline = {{10.0, 5.0}, {130.0, 5.0}, {130.0, 90.0}, {10.0, 90.0}};
    piece.paths.push_back(path(PatternLayer::Cut, piece.outline, true));
    piece.paths.push_back(path(PatternLayer::Seam, {{10.0, 10.0}, {130.0, 10.0}}));
    PatternPath valley = path(PatternLayer::Valley, {{70.0, 10.0}, {70.0, 90.0}});
    valley.foldAngleDegrees = -90.0;
    piece.paths.push_back(valley);
    piece.labels.push_back({{40.0, 50.0}, 6.0, 0.0, "B"});
    piece.labels.push_back({{70.0, 7.0}, 2.0, 0.0, "B–A 1"});
    piece.area = 120.0 * 80.0;
    piece.size = {120.0, 85.0};
    piece.maxIsometryError = 0.0;
    return piece;
}

} // namespace

model::CuttingPattern fixturePattern() {
    model::CuttingPattern pattern;
    pattern.pieces = {sector(), rectangle()};
    pattern.sheetSize = {600.0, 600.0};
    pattern.sheetCount = 2;
    return pattern;
}

model::CuttingPattern fixturePatternWithOverlap() {
    model::CuttingPattern pattern = fixturePattern();
    pattern.pieces[1].selfOverlapping = true;
    pattern.overlaps.push_back({1, 1, {0}});
    model::PatternProblem problem;
    problem.code = model::PatternProblemCode::PieceOverlapsItself;
    problem.piece = 1;
    problem.faces = {0};
    pattern.problems.push_back(problem);
    return pattern;
}

} // namespace devsurf::test
