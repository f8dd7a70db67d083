// Pinned vertices that hold part of a sheet where it cannot bend: checked on flat and folded
// designs whose answer follows from their geometry (which pins are as far apart as in the flat
// sheet, and where the vertex lies between them).

#include "model/examples.h"
#include "model/held_by_pins.h"
#include "surface_transform.h"
#include "test_registry.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

using namespace devsurf::model;

namespace {

CompositeSurface exampleWithPins(const char* name, const std::set<VertexId>& pins) {
    CompositeSurface surface = makeExample(name).surfaces.front();
    for (const auto& [vertex, position] : surface.vertices()) {
        (void)position;
        surface.setPinned(vertex, pins.count(vertex) > 0);
    }
    return surface;
}

// Barycentric coordinates of p in the triangle abc, in the xy-plane.
std::array<double, 3> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    auto cross = [](const Vec3& u, const Vec3& v) { return u.x * v.y - u.y * v.x; };
    const double area = cross(b - a, c - a);
    return {cross(b - p, c - p) / area, cross(c - p, a - p) / area, cross(a - p, b - p) / area};
}

} // namespace

class TstHeldByPins : public QObject {
    Q_OBJECT

private slots:
    // fig8's four corners pinned: every chord between them is held straight, so each interior
    // vertex lies in a held triangle of three of them.
    void fourPinnedCornersHoldTheWholeSquare() {
        const CompositeSurface s = exampleWithPins("fig8", {0, 3, 12, 15});
        for (VertexId vertex : {5u, 6u, 9u, 10u}) {
            const auto held = findVertexHeldByPins(s, {vertex});
            QVERIFY2(held.has_value(), qPrintable(QString::number(vertex)));
            QCOMPARE(held->vertex, vertex);
            QCOMPARE(held->pins.size(), std::size_t(3));
            for (VertexId pin : held->pins) {
                QVERIFY(s.isPinned(pin));
            }
            const auto w = barycentric(s.position(vertex), s.position(held->pins[0]),
                                       s.position(held->pins[1]), s.position(held->pins[2]));
            QVERIFY(*std::min_element(w.begin(), w.end()) > 0.0);
        }
    }

    // The example's two bottom corners hold only the straight bottom edge between them.
    void twoPinnedCornersHoldOnlyTheLineBetweenThem() {
        const CompositeSurface s = exampleWithPins("fig8", {0, 3});
        for (VertexId vertex : {4u, 5u, 6u, 9u, 10u, 13u}) {
            QVERIFY2(!findVertexHeldByPins(s, {vertex}), qPrintable(QString::number(vertex)));
        }
        const auto held = findVertexHeldByPins(s, {5, 2});
        QVERIFY(held.has_value());
        QCOMPARE(held->vertex, VertexId(2)); // the first held one of the list
        QCOMPARE(held->pins, (std::vector<VertexId>{0, 3}));
        QVERIFY(std::abs(s.position(2).y) < 1e-12); // on that line indeed
    }

    // A dragged vertex that is itself pinned, or pins that are too few, hold nothing.
    void pinnedOrUnpinnedAloneHoldNothing() {
        QVERIFY(!findVertexHeldByPins(exampleWithPins("fig8", {0, 3, 12, 15}), {0}));
        QVERIFY(!findVertexHeldByPins(exampleWithPins("fig8", {0}), {1, 5}));
        QVERIFY(!findVertexHeldByPins(exampleWithPins("fig8", {}), {5}));
    }

    // The sheet folded along the crease y = 100: its corners across the fold are closer than in
    // the flat sheet, so only the bottom and top edges stay held.
    void aFoldHoldsOnlyWhatStaysStraight() {
        CompositeSurface s = exampleWithPins("sheet", {0, 3, 12, 15});
        devsurf::test::foldBeyond(s, 100.0, 0.6);
        QVERIFY(s.validate().empty());
        QVERIFY(distance(s.position(0), s.position(12)) < 299.0);
        for (VertexId vertex : {4u, 5u, 6u, 9u, 10u}) {
            QVERIFY2(!findVertexHeldByPins(s, {vertex}), qPrintable(QString::number(vertex)));
        }
        QCOMPARE(findVertexHeldByPins(s, {1})->pins, (std::vector<VertexId>{0, 3}));
        QCOMPARE(findVertexHeldByPins(s, {14})->pins, (std::vector<VertexId>{12, 15}));
    }

    // Two opposite vertices of the annulus's outer rim pinned: the straight line between them
    // passes through vertices of every ring on their side, but also across the hole, so it is
    // no line of the sheet and holds nothing, although the pins are as far apart as it is long.
    void aLineAcrossAHoleHoldsNothing() {
        CompositeSurface s = makeExample("annulus").surfaces.front();
        double outer = 0.0;
        for (const auto& [vertex, p] : s.vertices()) {
            (void)vertex;
            outer = std::max(outer, p.norm());
        }
        VertexId east = kInvalidId;
        VertexId west = kInvalidId;
        std::vector<VertexId> onTheLine;
        for (const auto& [vertex, p] : s.vertices()) {
            if (std::abs(p.y) > 1e-9) {
                continue;
            }
            if (std::abs(p.x - outer) < 1e-9) {
                east = vertex;
            } else if (std::abs(p.x + outer) < 1e-9) {
                west = vertex;
            } else {
                onTheLine.push_back(vertex);
            }
        }
        QVERIFY(east != kInvalidId && west != kInvalidId);
        QVERIFY(onTheLine.size() >= 4);
        s.setPinned(east, true);
        s.setPinned(west, true);
        QVERIFY(!findVertexHeldByPins(s, onTheLine));
        QVERIFY(findTautPinLines(s).empty());
    }

    void tautLinesBetweenPins() {
        // fig8 as it comes: its pinned bottom corners (0, 3) hold the bottom edge straight. The
        // square's four corners: every pair of them. fig13's pins, the crease's middle and the
        // rim point below it, are joined by a ruling: straight anyway, so none is reported.
        using Pairs = std::vector<std::pair<VertexId, VertexId>>;
        QCOMPARE(findTautPinLines(makeExample("fig8").surfaces.front()), (Pairs{{0, 3}}));
        const CompositeSurface corners = exampleWithPins("sheet", {0, 3, 12, 15});
        QCOMPARE(findTautPinLines(corners).size(), std::size_t(6));
        const CompositeSurface fig13 = makeExample("fig13").surfaces.front();
        QCOMPARE(fig13.pinnedVertices().size(), std::size_t(2));
        QVERIFY(findTautPinLines(fig13).empty());
        // One pin holds no line.
        QVERIFY(findTautPinLines(exampleWithPins("fig8", {0})).empty());
    }
};

DEVSURF_REGISTER_TEST(TstHeldByPins);
#include "tst_held_by_pins.moc"
