#include "folded_strip.h"
#include "helical_band.h"
#include "model/bspline_curve.h"
#include "model/examples.h"
#include "model/math_constants.h"
#include "model/pattern/cutting_pattern.h"
#include "model/pattern/pattern_seams.h"
#include "model/pattern/sampling_bound.h"
#include "model/sampled_mesh.h"
#include "pattern_test_geometry.h"
#include "surface_transform.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>

using namespace devsurf::model;

namespace {

using devsurf::model::kPi;

double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double l2 = d.x * d.x + d.y * d.y;
    double t = l2 > 0 ? ((p.x - a.x) * d.x + (p.y - a.y) * d.y) / l2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return (p - (a + d * t)).norm();
}

double distanceToLoop(const Vec2& p, const std::vector<Vec2>& loop, bool closed = true) {
    double best = 1e300;
    const std::size_t segments = closed ? loop.size() : loop.size() - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        best = std::min(best, segmentDistance(p, loop[i], loop[(i + 1) % loop.size()]));
    }
    return best;
}

// 18 flat trapezoids between the circles of radius 100 and 160, 30° each, winding 540° round
// in the plane z = 0.
CompositeSurface stackedBand() {
    const SplineSpace space{3, 2, 1};
    CompositeSurface s;
    std::vector<VertexId> inner;
    std::vector<VertexId> outer;
    for (int i = 0; i <= 18; ++i) {
        const double phi = kPi * i / 6.0;
        inner.push_back(s.addVertex({100.0 * std::cos(phi), 100.0 * std::sin(phi), 0.0}));
        outer.push_back(s.addVertex({160.0 * std::cos(phi), 160.0 * std::sin(phi), 0.0}));
    }
    for (int i = 0; i < 18; ++i) {
        s.addFace({inner[i], outer[i], outer[i + 1], inner[i + 1]});
        for (const std::vector<VertexId>* chain : {&inner, &outer}) {
            const VertexId a = (*chain)[i];
            const VertexId b = (*chain)[i + 1];
            s.setSpline(a, b, space,
                        devsurf::test::straightControlPoints(space, s.position(a), s.position(b)));
        }
    }
    return s;
}

// A flat ring of 8 strips between radii 100 and 160 mm that winds once round and by `excess`
// radians more, open where its two ends meet: its development (the ring itself) overlaps at
// the ends by that wedge.
CompositeSurface ringWinding(double excess) {
    const int steps = 8;
    const SplineSpace space{3, 2, 2};
    CompositeSurface s;
    std::vector<VertexId> inner;
    std::vector<VertexId> outer;
    auto at = [&](double radius, double phi) {
        return Vec3(radius * std::cos(phi), radius * std::sin(phi), 0.0);
    };
    const double turn = 2.0 * kPi + excess;
    for (int i = 0; i <= steps; ++i) {
        const double phi = turn * i / steps;
        inner.push_back(s.addVertex(at(100.0, phi)));
        outer.push_back(s.addVertex(at(160.0, phi)));
    }
    for (int i = 0; i < steps; ++i) {
        s.addFace({inner[i], outer[i], outer[i + 1], inner[i + 1]});
        for (const double radius : {100.0, 160.0}) {
            const VertexId a = radius == 100.0 ? inner[i] : outer[i];
            const VertexId b = radius == 100.0 ? inner[i + 1] : outer[i + 1];
            const int count = space.controlPointCount(false);
            std::vector<Vec3> points;
            for (int k = 0; k < count; ++k) {
                points.push_back(
                    at(radius, turn * (i + static_cast<double>(k) / (count - 1)) / steps));
            }
            points.front() = s.position(a);
            points.back() = s.position(b);
            s.setSpline(a, b, space, points);
        }
    }
    return s;
}

PatternOptions sideBySide() {
    PatternOptions options;
    options.layout = false;
    return options;
}

int countPaths(const PatternPiece& piece, PatternLayer layer) {
    return static_cast<int>(
        std::count_if(piece.paths.begin(), piece.paths.end(),
                      [layer](const PatternPath& p) { return p.layer == layer; }));
}

} // namespace

class TstCuttingPattern : public QObject {
    Q_OBJECT
private slots:
    void layerNames() {
        QCOMPARE(QString(patternLayerName(PatternLayer::Cut)), QString("CUT"));
        QCOMPARE(QString(patternLayerName(PatternLayer::Mountain)), QString("MOUNTAIN"));
        QCOMPARE(QString(patternLayerName(PatternLayer::Valley)), QString("VALLEY"));
        QCOMPARE(QString(patternLayerName(PatternLayer::Crease)), QString("CREASE"));
        QCOMPARE(QString(patternLayerName(PatternLayer::Score)), QString("SCORE"));
        QCOMPARE(QString(patternLayerName(PatternLayer::Seam)), QString("SEAM"));
        QCOMPARE(QString(patternLayerName(PatternLayer::Labels)), QString("LABELS"));
    }

    void chordErrorWithinTolerance() {
        // The flat annulus lies in the pattern as in space (seen from above), moved: every point
        // of its boundary curves is within the tolerance of the cut loops.
        for (const double tolerance : {0.01, 0.5}) {
            PatternOptions options = sideBySide();
            options.tolerance = tolerance;
            const Project project = makeExample("annulus");
            const CompositeSurface& surface = project.surfaces.front();
            const PatternPiece piece = buildCuttingPattern(project, options).pieces.front();
            const auto& [id, p0] = piece.vertices.front();
            const Vec2 shift = p0 - Vec2(surface.position(id).x, surface.position(id).y);
            double worst = 0;
            for (const auto& [edge, record] : surface.edges()) {
                if (surface.facesOfEdge(edge).size() != 1) {
                    continue;
                }
                const BSplineCurve curve =
                    BSplineCurve::uniform(record.space, record.controlPoints);
                for (int i = 0; i <= 200; ++i) {
                    const Vec3 q = curve.evaluate(i / 200.0);
                    const Vec2 p = Vec2(q.x, q.y) + shift;
                    double d = distanceToLoop(p, piece.outline);
                    for (const auto& hole : piece.holes) {
                        d = std::min(d, distanceToLoop(p, hole));
                    }
                    worst = std::max(worst, d);
                }
            }
            QVERIFY2(worst <= tolerance + 1e-9, qPrintable(QString::number(worst)));
            QVERIFY(worst > 0.05 * tolerance); // not sampled needlessly finely
        }
    }

    void cylinderIsCutOpenAlongARuling() {
        const Project project = makeExample("cylinder", 6);
        const CompositeSurface& surface = project.surfaces.front();
        const CuttingPattern pattern = buildCuttingPattern(project, sideBySide());
        QVERIFY(pattern.problems.empty());
        QCOMPARE(pattern.pieces.size(), std::size_t(1));
        const PatternPiece& piece = pattern.pieces.front();
        QVERIFY(piece.holes.empty());
        QVERIFY(piece.maxIsometryError <= 1e-6);
        // Unrolled: the circumference wide, 3 rows of 60 mm high, z up.
        QVERIFY(std::abs(piece.size.y - 180.0) < 1e-6);
        // The circumference: the length of the bottom curves, sampled finely.
        double perimeter = 0;
        for (const auto& [edge, record] : surface.edges()) {
            if (record.isSpline() && record.controlPoints.front().z == 0.0) {
                const BSplineCurve curve =
                    BSplineCurve::uniform(record.space, record.controlPoints);
                for (int i = 0; i < 2000; ++i) {
                    perimeter +=
                        distance(curve.evaluate(i / 2000.0), curve.evaluate((i + 1) / 2000.0));
                }
            }
        }
        QVERIFY2(std::abs(piece.size.x - perimeter) < 0.01, // chords are a little shorter

                 qPrintable(QString("%1 %2").arg(piece.size.x).arg(perimeter)));
        std::map<VertexId, std::vector<Vec2>> copies;
        for (const auto& [id, p] : piece.vertices) {
            copies[id].push_back(p);
        }
        int twice = 0;
        for (const auto& [id, points] : copies) {
            // Orientation as in the 3D view: height in space is height in the pattern.
            for (const Vec2& p : points) {
                QVERIFY(std::abs(p.y - surface.position(id).z) < 1e-6);
            }
            if (points.size() == 2) {
                ++twice;
                QVERIFY(std::abs(std::abs(points[0].x - points[1].x) - piece.size.x) < 1e-6);
            }
        }
        QCOMPARE(twice, 4); // the cut ruling's 4 vertices lie on both sides
        // Each of the 3 cut edges has the same label on both sides, at the same height.
        std::map<std::string, std::vector<PatternLabel>> labels;
        for (const PatternLabel& label : piece.labels) {
            labels[label.text].push_back(label);
        }
        for (const char* text : {"A1", "A2", "A3"}) {
            QCOMPARE(labels[text].size(), std::size_t(2));
            QVERIFY(std::abs(labels[text][0].position.y - labels[text][1].position.y) < 1e-6 ||
                    std::abs(labels[text][0].angleDegrees - labels[text][1].angleDegrees) > 1);
        }
        // Flat creases (the circles between the rows) are unassigned creases.
        QCOMPARE(countPaths(piece, PatternLayer::Crease), 2 * 6);
        QCOMPARE(
            countPaths(piece, PatternLayer::Mountain) + countPaths(piece, PatternLayer::Valley), 0);
    }

    void liftedAnnulusStaysTwoDimensional() {
        for (const char* name : {"annulus", "sheet"}) {
            Project project = makeExample(name);
            CompositeSurface& surface = project.surfaces.front();
            const VertexId lifted = surface.vertices().begin()->first;
            surface.moveVertex(lifted, surface.position(lifted) + Vec3(0, 0, 1));
            const CuttingPattern pattern = buildCuttingPattern(project, sideBySide());
            QCOMPARE(pattern.pieces.size(), std::size_t(1));
            const Vec2 size = pattern.pieces.front().size;
            QVERIFY2(size.x > 250 && size.y > 250, name);
        }
    }

    void foldDirections() {
        // The 3 × 3 sheet folded along its crease y = 100 by 30°: the part beyond it rises
        // towards the normal side (+z): a valley; folded down: a mountain.
        for (const double degrees : {30.0, -30.0}) {
            Project project = makeExample("sheet", 3);
            const double angle = degrees * kPi / 180;
            devsurf::test::foldBeyond(project.surfaces.front(), 100.0, angle);
            PatternOptions options = sideBySide();
            options.rulings = true;
            const CuttingPattern pattern = buildCuttingPattern(project, options);
            QVERIFY(pattern.problems.empty());
            const PatternPiece& piece = pattern.pieces.front();
            QVERIFY(piece.maxIsometryError <= 1e-6);
            const PatternLayer expected =
                degrees > 0 ? PatternLayer::Valley : PatternLayer::Mountain;
            QCOMPARE(countPaths(piece, expected), 3);
            QCOMPARE(countPaths(piece, PatternLayer::Crease), 3); // y = 200 stays flat
            for (const PatternPath& path : piece.paths) {
                if (path.layer == expected) {
                    QVERIFY(path.foldAngleDegrees.has_value());
                    QVERIFY(std::abs(*path.foldAngleDegrees + degrees) < 1e-6);
                }
            }
            QVERIFY(countPaths(piece, PatternLayer::Score) > 0);
        }
    }

    void selfOverlapIsDetected() {
        Project project;
        project.surfaces.push_back(devsurf::test::helicalBand());
        QVERIFY(project.surfaces.front().validate().empty());
        const CuttingPattern pattern = buildCuttingPattern(project, sideBySide());
        QCOMPARE(pattern.pieces.size(), std::size_t(1));
        QVERIFY(pattern.pieces.front().selfOverlapping);
        QCOMPARE(pattern.overlaps.size(), std::size_t(1));
        QCOMPARE(pattern.overlaps.front().first, 0);
        QCOMPARE(pattern.overlaps.front().second, 0);
        QVERIFY(!pattern.overlaps.front().faces.empty());
        QCOMPARE(pattern.problems.size(), std::size_t(1));
        QCOMPARE(pattern.problems.front().code, PatternProblemCode::PieceOverlapsItself);
        QCOMPARE(pattern.problems.front().faces, pattern.overlaps.front().faces);
        // Half a turn does not overlap.
        for (const ExampleInfo& info : builtInExamples()) {
            QVERIFY(!buildCuttingPattern(makeExample(info.name), sideBySide())
                         .pieces.front()
                         .selfOverlapping);
        }
    }

    void selfOverlappingPatchesNameWhereTheDevelopmentOverlapsItself() {
        // The band's development winds one and a half times round: some of its patches lie on
        // top of others. Every patch named is one of the band's.
        const CompositeSurface band = devsurf::test::helicalBand();
        const std::vector<FaceId> patches = selfOverlappingPatches(band);
        QVERIFY(!patches.empty());
        QVERIFY(std::is_sorted(patches.begin(), patches.end()));
        QVERIFY(std::adjacent_find(patches.begin(), patches.end()) == patches.end());
        for (FaceId face : patches) {
            QVERIFY(band.hasFace(face));
        }
        // A strip folded back onto itself within its plane unfolds into one that does not
        // (the fold-over is a fold, solver::foldOvers names it).
        QVERIFY(selfOverlappingPatches(devsurf::test::flatStrip(-150.0)).empty());
        // No built-in example overlaps itself; an invalid surface has nothing to develop.
        for (const ExampleInfo& info : builtInExamples()) {
            QVERIFY2(selfOverlappingPatches(makeExample(info.name).surfaces.front()).empty(),
                     info.name.c_str());
        }
        QVERIFY(selfOverlappingPatches(CompositeSurface()).empty());
        // A ring that winds round by a hair more than once overlaps itself by that hair where
        // its ends meet (as a solved annulus that does not quite close up, cut open): not
        // counted; by a visible wedge (0.05 rad, 8 mm at its rim) it is.
        QVERIFY(selfOverlappingPatches(ringWinding(1e-5)).empty());
        QVERIFY(!selfOverlappingPatches(ringWinding(0.05)).empty());
        QVERIFY(selfOverlappingPatches(ringWinding(-0.05)).empty());
        // A band of 18 flat trapezoids wound one and a half times round in the plane: its
        // second half lies exactly on its first (vertex on vertex, edge on edge), so the outline
        // runs along itself without crossing, but the patches stacked there are named.
        const std::vector<FaceId> stacked = selfOverlappingPatches(stackedBand());
        QVERIFY(!stacked.empty());
        QVERIFY(stacked.size() <= 12);
    }

    // Issue 46, point 7: the examples are within the sampling bound; an annulus with one
    // control point 1 km up is not, and the bound names the coarser tolerance that is.
    void samplingBoundNamesACoarserTolerance() {
        for (const ExampleInfo& info : builtInExamples()) {
            QVERIFY2(!pattern::oversampledSurface(makeExample(info.name), 0.01), info.name.c_str());
        }
        Project far = makeExample("annulus");
        CompositeSurface& surface = far.surfaces.front();
        for (const auto& [id, edge] : surface.edges()) {
            if (edge.isSpline() && edge.controlPoints.size() > 2) {
                std::vector<Vec3> points = edge.controlPoints;
                points[1].z = 0.999e6;
                surface.setControlPoints(id, points);
                break;
            }
        }
        QVERIFY(surface.validate().empty());
        const auto over = pattern::oversampledSurface(far, 0.01);
        QVERIFY(over.has_value());
        QCOMPARE(over->surface, 0);
        QCOMPARE(over->samples, pattern::curveSampleCount(surface, 0.01));
        QVERIFY(over->samples > pattern::kMaxCurveSamples);
        QVERIFY(over->reach >= 0.999e6);
        QCOMPARE(over->coarser, 0.1);
        QVERIFY(pattern::curveSampleCount(surface, 0.1) <= pattern::kMaxCurveSamples);
        QVERIFY(!pattern::oversampledSurface(far, 0.1));
    }

    void layoutKeepsTheGap() {
        Project project;
        for (const char* name : {"annulus", "cylinder", "mixed", "sheet", "sheet", "mixed"}) {
            project.surfaces.push_back(makeExample(name).surfaces.front());
        }
        // A sheet turned by 30° in space: the layout turns it back to save material.
        const double turn = 30.0 * kPi / 180;
        devsurf::test::transformSurface(project.surfaces[3], [turn](const Vec3& p) {
            return Vec3(std::cos(turn) * p.x - std::sin(turn) * p.y,
                        std::sin(turn) * p.x + std::cos(turn) * p.y, p.z);
        });
        PatternOptions options;
        options.sheetSize = Vec2(700, 600);
        options.gap = 7;
        const CuttingPattern pattern = buildCuttingPattern(project, options);
        QVERIFY(pattern.problems.empty());
        QVERIFY(pattern.overlaps.empty());
        QCOMPARE(pattern.pieces.size(), std::size_t(6));
        QVERIFY(pattern.sheetCount >= 2);
        for (const PatternPiece& piece : pattern.pieces) {
            QVERIFY(piece.sheet >= 0 && piece.sheet < pattern.sheetCount);
            for (const Vec2& p : piece.outline) {
                QVERIFY(p.x >= 7 - 1e-9 && p.y >= 7 - 1e-9 && p.x <= 693 + 1e-9 &&
                        p.y <= 593 + 1e-9);
            }
        }
        const PatternPiece& turned = pattern.pieces[3];
        QVERIFY(std::abs(turned.size.x - 300) < 1e-6 && std::abs(turned.size.y - 300) < 1e-6);
        for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
            for (std::size_t j = i + 1; j < pattern.pieces.size(); ++j) {
                const PatternPiece& a = pattern.pieces[i];
                const PatternPiece& b = pattern.pieces[j];
                if (a.sheet != b.sheet) {
                    continue;
                }
                double nearest = 1e300;
                for (const Vec2& p : a.outline) {
                    nearest = std::min(nearest, distanceToLoop(p, b.outline));
                }
                for (const Vec2& p : b.outline) {
                    nearest = std::min(nearest, distanceToLoop(p, a.outline));
                }
                QVERIFY2(nearest >= 7 - 1e-6,
                         qPrintable(QString("%1 %2: %3").arg(i).arg(j).arg(nearest)));
                // Neither lies inside the other (the pieces' bounding boxes are apart).
                const auto [loA, hiA] =
                    std::minmax_element(a.outline.begin(), a.outline.end(),
                                        [](const Vec2& p, const Vec2& q) { return p.x < q.x; });
                const auto [loB, hiB] =
                    std::minmax_element(b.outline.begin(), b.outline.end(),
                                        [](const Vec2& p, const Vec2& q) { return p.x < q.x; });
                const auto [bottomA, topA] =
                    std::minmax_element(a.outline.begin(), a.outline.end(),
                                        [](const Vec2& p, const Vec2& q) { return p.y < q.y; });
                const auto [bottomB, topB] =
                    std::minmax_element(b.outline.begin(), b.outline.end(),
                                        [](const Vec2& p, const Vec2& q) { return p.y < q.y; });
                QVERIFY(hiA->x + 7 <= loB->x + 1e-6 || hiB->x + 7 <= loA->x + 1e-6 ||
                        topA->y + 7 <= bottomB->y + 1e-6 || topB->y + 7 <= bottomA->y + 1e-6);
            }
        }
    }

    void pieceLargerThanTheSheetIsReported() {
        Project project;
        project.surfaces.push_back(makeExample("annulus").surfaces.front());
        project.surfaces.push_back(makeExample("mixed").surfaces.front());
        PatternOptions options;
        options.sheetSize = Vec2(420, 297);
        const CuttingPattern pattern = buildCuttingPattern(project, options);
        QCOMPARE(pattern.pieces.size(), std::size_t(2));
        QCOMPARE(pattern.pieces[0].sheet, -1);
        // Not squeezed: as large as the ring (diameter 500 mm, turned to its smallest box).
        QVERIFY(pattern.pieces[0].size.x > 490 && pattern.pieces[0].size.y > 490);
        QVERIFY(pattern.pieces[1].sheet == 0);
        QCOMPARE(pattern.problems.size(), std::size_t(1));
        QCOMPARE(pattern.problems.front().code, PatternProblemCode::PieceTooLarge);
        QCOMPARE(pattern.problems.front().piece, 0);
        QCOMPARE(pattern.pieces[0].name, std::string("A"));
        QVERIFY(pattern.problems.front().size.x > 490 &&
                pattern.problems.front().sheetSize.x == 420);
    }

    void seamAllowanceIsOffsetByItsWidth() {
        const Project project = makeExample("cylinder", 6);
        const PatternPiece plain = buildCuttingPattern(project, sideBySide()).pieces.front();
        PatternOptions options = sideBySide();
        options.seamAllowance = 5.0;
        const PatternPiece piece = buildCuttingPattern(project, options).pieces.front();
        // One strip of 5 mm along the 180 mm seam, on one side only.
        QVERIFY(std::abs(shoelace(piece.outline) - shoelace(plain.outline) - 5.0 * 180.0) < 1e-6);
        QCOMPARE(countPaths(piece, PatternLayer::Seam), 1);
        for (const PatternPath& seam : piece.paths) {
            if (seam.layer != PatternLayer::Seam) {
                continue;
            }
            QVERIFY(!seam.closed);
            // The original edge: on the plain outline, 5 mm inside the new one except at its
            // ends, where the strip starts.
            for (std::size_t i = 0; i < seam.points.size(); ++i) {
                QVERIFY(distanceToLoop(seam.points[i], plain.outline) < 1e-9);
                const double d = distanceToLoop(seam.points[i], piece.outline);
                QVERIFY(i == 0 || i + 1 == seam.points.size() ? d < 1e-9
                                                              : std::abs(d - 5.0) < 1e-9);
            }
        }
        // The labels of the seam are still on both sides.
        int labels = 0;
        for (const PatternLabel& label : piece.labels) {
            labels += label.text == "A1" ? 1 : 0;
        }
        QCOMPARE(labels, 2);

        options.glueTabs = true;
        const PatternPiece tabbed = buildCuttingPattern(project, options).pieces.front();
        // Three trapezoids: 60 mm at the edge, 50 mm at 5 mm out.
        QVERIFY(std::abs(shoelace(tabbed.outline) - shoelace(plain.outline) - 3 * 275.0) < 1e-6);
        QCOMPARE(countPaths(tabbed, PatternLayer::Seam), 3);
    }

    void offsetPolylineMitresConvexCornersAndCutsConcaveOnes() {
        using devsurf::model::pattern::offsetPolyline;
        const auto near = [](const std::vector<Vec2>& got, const std::vector<Vec2>& expected) {
            if (got.size() != expected.size()) {
                return false;
            }
            for (std::size_t i = 0; i < got.size(); ++i) {
                if ((got[i] - expected[i]).norm() > 1e-9) {
                    return false;
                }
            }
            return true;
        };
        // Right of the direction: around the outside of a left turn (a mitre at (12, −2)) ...
        QVERIFY(
            near(offsetPolyline({{0, 0}, {10, 0}, {10, 10}}, 2.0), {{0, -2}, {12, -2}, {12, 10}}));
        // ... inside a right turn, where the two offset lines meet at (8, −2) ...
        QVERIFY(
            near(offsetPolyline({{0, 0}, {10, 0}, {10, -10}}, 2.0), {{0, -2}, {8, -2}, {8, -10}}));
        // ... and left of it for a negative width; a repeated point changes nothing.
        QVERIFY(near(offsetPolyline({{0, 0}, {10, 0}, {10, 0}, {20, 0}}, -3.0), {{0, 3}, {20, 3}}));
        QVERIFY(offsetPolyline({{1, 1}, {1, 1}}, 2.0).empty());
    }

    void chosenEdgesGetAnAllowanceToo() {
        // The sheet's straight boundary edge from (0, 0) to (100, 0) and the annulus's outer
        // rim: curved edges are offset along their curve.
        const Project sheet = makeExample("sheet", 3);
        PatternOptions options = sideBySide();
        for (const auto& [id, record] : sheet.surfaces[0].edges()) {
            const Vec3 a = sheet.surfaces[0].position(record.from);
            const Vec3 b = sheet.surfaces[0].position(record.to);
            if (a.y == 0 && b.y == 0 && std::min(a.x, b.x) == 0) {
                options.gluedEdges.emplace_back(0, id);
            }
        }
        QCOMPARE(options.gluedEdges.size(), std::size_t(1));
        const PatternPiece plain = buildCuttingPattern(sheet, sideBySide()).pieces.front();
        options.seamAllowance = 4.0;
        const PatternPiece piece = buildCuttingPattern(sheet, options).pieces.front();
        QVERIFY(std::abs(shoelace(piece.outline) - shoelace(plain.outline) - 400.0) < 1e-6);
        QCOMPARE(countPaths(piece, PatternLayer::Seam), 1);

        const Project annulus = makeExample("annulus");
        PatternOptions rim = sideBySide();
        rim.seamAllowance = 4.0;
        const PatternPiece ring = buildCuttingPattern(annulus, rim).pieces.front();
        const CompositeSurface& surface = annulus.surfaces[0];
        for (const auto& [id, record] : surface.edges()) {
            if (surface.facesOfEdge(id).size() == 1 && surface.position(record.from).norm() > 200) {
                rim.gluedEdges.emplace_back(0, id);
                break;
            }
        }
        const PatternPiece glued = buildCuttingPattern(annulus, rim).pieces.front();
        for (const PatternPath& seam : glued.paths) {
            if (seam.layer != PatternLayer::Seam) {
                continue;
            }
            for (std::size_t i = 1; i + 1 < seam.points.size(); ++i) {
                QVERIFY(distanceToLoop(seam.points[i], ring.outline) < 1e-9);
                QVERIFY(std::abs(distanceToLoop(seam.points[i], glued.outline) - 4.0) < 0.01);
            }
        }
        QCOMPARE(countPaths(glued, PatternLayer::Seam), 1);
    }
};

DEVSURF_REGISTER_TEST(TstCuttingPattern);

#include "tst_cutting_pattern.moc"
