#pragma once

// Hand-made cutting patterns whose geometry the tests know exactly, so that the writers are
// checked against numbers that do not come from the code under test.

#include "model/pattern/cutting_pattern.h"

namespace devsurf::test {

// Piece A (sheet 0): a 270° annulus sector, radii 100 and 250 mm, centre (300, 300), sampled
// every degree (chord error 0.0095 mm on the outer arc), with radial mountain/valley creases
// every 30°, a crease arc at radius 175 mm, rulings every 10° between them, and a label.
// Piece B (sheet 1): a 120 × 80 mm rectangle at (10, 10) with a 5 mm seam allowance below
// (cut outline from y = 5), a valley crease at x = 70 and a seam line at y = 10.
model::CuttingPattern fixturePattern();

// The same with piece B overlapping itself and a problem sentence.
model::CuttingPattern fixturePatternWithOverlap();

inline constexpr double kFixtureCentre = 300.0;
inline constexpr double kFixtureInner = 100.0;
inline constexpr double kFixtureOuter = 250.0;
inline constexpr double kFixtureCrease = 175.0;

} // namespace devsurf::test
