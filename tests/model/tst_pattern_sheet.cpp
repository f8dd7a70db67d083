#include "model/development.h"
#include "model/examples.h"
#include "model/pattern/cutting_pattern.h"
#include "model/pattern/pattern_sheet.h"
#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace devsurf::model;

namespace {

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a, ap = p - a;
    const double t =
        std::clamp((ap.x * ab.x + ap.y * ab.y) / (ab.x * ab.x + ab.y * ab.y), 0.0, 1.0);
    const Vec2 d = ap - ab * t;
    return std::hypot(d.x, d.y);
}

// Distance from p to the nearest of the closed loops.
double loopDistance(const Vec2& p, const std::vector<std::vector<Vec2>>& loops) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& loop : loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            best = std::min(best, pointSegmentDistance(p, loop[i], loop[(i + 1) % loop.size()]));
        }
    }
    return best;
}

// `name` holding its sheet as it unfolds now, confined to `domain` placed on it.
CompositeSurface heldOn(const std::string& name, SheetDomain domain) {
    CompositeSurface surface = makeExample(name).surfaces[0];
    if (keepDevelopment(surface)) {
        return surface;
    }
    const SampledMesh mesh = sampleSurface(surface, kDevelopmentSamplesPerInterval);
    surface.setSheetDomain(placeDomain(std::move(domain), mesh, surface.development()));
    return surface;
}

} // namespace

// The sheet drawn behind a piece (the development view) is placed where the piece lies.
class TstPatternSheet : public QObject {
    Q_OBJECT
private slots:
    void rectangleLiesUnderTheLaidOutSquare() {
        SheetDomain square;
        square.shape = SheetShape::Rectangle;
        square.width = square.height = 300.0;
        const CompositeSurface surface = heldOn("fig8", square);
        QVERIFY(surface.keepsDevelopment());
        Project project;
        project.surfaces.push_back(surface);
        // Laid out on sheets of paper: the layout turns the piece.
        PatternOptions options;
        options.sheetSize = Vec2{320.0, 420.0};
        const CuttingPattern pattern = buildCuttingPattern(project, options);
        QCOMPARE(pattern.pieces.size(), std::size_t(1));
        const PatternPiece& piece = pattern.pieces.front();
        const auto loops = pattern::sheetOnPiece(surface, piece, 0.05);
        QCOMPARE(loops.size(), std::size_t(1));
        QCOMPARE(loops.front().size(), std::size_t(4));
        // Its sides keep their lengths, and every vertex of the square's boundary, as the
        // pattern places it, lies on the sheet's boundary.
        for (std::size_t i = 0; i < 4; ++i) {
            const Vec2 side = loops.front()[(i + 1) % 4] - loops.front()[i];
            QVERIFY(std::abs(std::hypot(side.x, side.y) - 300.0) < 1e-6);
        }
        int onBoundary = 0;
        for (const auto& [id, position] : piece.vertices) {
            const Vec3& at = surface.position(id); // the example starts flat, 300 mm square
            const bool rim = std::min({at.x, at.y, 300.0 - at.x, 300.0 - at.y}) < 1e-9;
            if (rim) {
                QVERIFY2(loopDistance(position, loops) < 1e-6, qPrintable(QString::number(id)));
                ++onBoundary;
            }
        }
        QCOMPARE(onBoundary, 12);
    }

    void piecesAreCutFromTheKeptSheet() {
        // A surface holding its sheet is cut from that sheet, not from a fresh unfolding: its
        // kept development scaled by 1.001 (as if the sheet had been stretched) gives a piece
        // 1.001 times as large, its coarse vertices exactly where the sheet has them (up to the
        // piece's placement) and the samples between them moved along; a kept development that
        // matches the surface gives the unfolding's lengths.
        for (const double scale : {1.0, 1.001}) {
            CompositeSurface surface = makeExample("fig8").surfaces[0];
            QVERIFY(!keepDevelopment(surface).has_value());
            std::vector<Vec2> sheet = surface.development();
            for (Vec2& p : sheet) {
                p = p * scale;
            }
            surface.setDevelopment(sheet);
            Project project;
            project.surfaces.push_back(surface);
            PatternOptions options;
            options.samplesPerInterval = 8;
            const CuttingPattern pattern = buildCuttingPattern(project, options);
            QCOMPARE(pattern.pieces.size(), std::size_t(1));
            const PatternPiece& piece = pattern.pieces.front();
            QCOMPARE(piece.vertices.size(), surface.vertices().size());
            double worst = 0.0;
            for (const auto& [a, pa] : piece.vertices) {
                for (const auto& [b, pb] : piece.vertices) {
                    const Vec2 kept = sheet[a] - sheet[b]; // coarse vertices first, by id
                    worst = std::max(worst, std::abs((pa - pb).norm() - kept.norm()));
                }
            }
            QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
            // Its area too (the developed patches, 300 × 300 mm as designed).
            QVERIFY2(std::abs(piece.area - 300.0 * 300.0 * scale * scale) < 1e-3 * 300.0,
                     qPrintable(QString::number(piece.area)));
        }
    }

    void aHeldRingIsCutInOnePieceFromItsKeptSheet() {
        // fig12, a folded ring holding its sheet: its kept development closes up at the
        // sampling it is kept at, but the pattern's finer sampling of its curves turns a little
        // further around (unfolded afresh it misses closing by more than the pattern's
        // tolerance), so it would be cut open along a ruling with the two sides of that seam
        // overlapping. Laid onto the kept sheet it is one piece with its hole, not cut open,
        // not overlapping itself, its coarse vertices where the sheet has them and its lengths
        // those of the surface to within 0.01 mm.
        const CompositeSurface surface = makeExample("fig12").surfaces[0];
        PatternOptions options;
        options.samplesPerInterval = 8;
        const Development fresh = unfoldSampledMesh(sampleSurface(surface, 8));
        QVERIFY2(fresh.closureError > 10 * options.tolerance,
                 qPrintable(QString::number(fresh.closureError)));
        Project project;
        project.surfaces.push_back(surface);
        const CuttingPattern pattern = buildCuttingPattern(project, options);
        QCOMPARE(pattern.pieces.size(), std::size_t(1));
        const PatternPiece& piece = pattern.pieces.front();
        QVERIFY(!piece.selfOverlapping);
        QCOMPARE(piece.holes.size(), std::size_t(1));
        QCOMPARE(piece.vertices.size(), surface.vertices().size()); // none twice on a seam
        QVERIFY(selfOverlappingPatches(surface).empty());
        const std::vector<Vec2>& sheet = surface.development();
        double worst = 0.0;
        for (const auto& [a, pa] : piece.vertices) {
            for (const auto& [b, pb] : piece.vertices) {
                worst = std::max(worst, std::abs((pa - pb).norm() - (sheet[a] - sheet[b]).norm()));
            }
        }
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
        QVERIFY2(piece.maxIsometryError < 0.01,
                 qPrintable(QString::number(piece.maxIsometryError)));
    }

    void annulusKeepsItsHoleAndCircles() {
        SheetDomain ring;
        ring.shape = SheetShape::Annulus;
        ring.innerRadius = 100.0;
        ring.radius = 250.0;
        const CompositeSurface surface = heldOn("annulus", ring);
        Project project;
        project.surfaces.push_back(surface);
        PatternOptions options;
        options.layout = false;
        const PatternPiece piece = buildCuttingPattern(project, options).pieces.front();
        const auto loops = pattern::sheetOnPiece(surface, piece, 0.05);
        QCOMPARE(loops.size(), std::size_t(2));
        // Circles within the chord tolerance: every point at its radius from the centre of
        // the outer loop.
        Vec2 centre;
        for (const Vec2& p : loops[0]) {
            centre = centre + p;
        }
        centre = centre * (1.0 / static_cast<double>(loops[0].size()));
        for (std::size_t k = 0; k < 2; ++k) {
            const double radius = k == 0 ? 250.0 : 100.0;
            QVERIFY(loops[k].size() >= 32);
            for (const Vec2& p : loops[k]) {
                QVERIFY(std::abs(std::hypot(p.x - centre.x, p.y - centre.y) - radius) < 1e-9);
            }
        }
    }

    void nothingWithoutAShape() {
        CompositeSurface surface = makeExample("fig8").surfaces[0];
        Project project;
        project.surfaces.push_back(surface);
        PatternOptions options;
        options.layout = false;
        const PatternPiece piece = buildCuttingPattern(project, options).pieces.front();
        QVERIFY(pattern::sheetOnPiece(surface, piece, 0.05).empty()); // not held
        QVERIFY(!keepDevelopment(surface));
        QVERIFY(pattern::sheetOnPiece(surface, piece, 0.05).empty()); // held, free
    }
};

DEVSURF_REGISTER_TEST(TstPatternSheet);
#include "tst_pattern_sheet.moc"
