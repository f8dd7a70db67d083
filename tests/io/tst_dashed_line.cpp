// The dashes printed patterns draw themselves (io/pattern/dashed_line.h).
#include "io/pattern/dashed_line.h"
#include "test_registry.h"

#include <QTest>

using devsurf::io::DashedLine;
using devsurf::io::dashLine;

class TstDashedLine : public QObject {
    Q_OBJECT

private slots:
    void dashesRepeatAlongAPolyline() {
        // 10 mm with a bend at 4 mm; 2 on, 1 off: dashes at 0–2, 3–5 (across the bend), 6–8,
        // 9–10.
        const QPolygonF line{QPointF(0, 0), QPointF(4, 0), QPointF(4, 6)};
        const DashedLine d = dashLine(line, false, {2.0, 1.0});
        QCOMPARE(d.dashes.size(), std::size_t(4));
        QVERIFY(d.dots.empty());
        QCOMPARE(d.dashes[0], QPolygonF({QPointF(0, 0), QPointF(2, 0)}));
        QCOMPARE(d.dashes[1], QPolygonF({QPointF(3, 0), QPointF(4, 0), QPointF(4, 1)}));
        QCOMPARE(d.dashes[2], QPolygonF({QPointF(4, 2), QPointF(4, 4)}));
        QCOMPARE(d.dashes[3], QPolygonF({QPointF(4, 5), QPointF(4, 6)}));
    }

    void aDashOfNoLengthIsADot() {
        // Dash-dot 6, 2, 0, 2 over 20 mm: dashes 0–6 and 10–16, dots at 8 and 18.
        const DashedLine d = dashLine({QPointF(0, 0), QPointF(20, 0)}, false, {6.0, 2.0, 0.0, 2.0});
        QCOMPARE(d.dashes.size(), std::size_t(2));
        QCOMPARE(d.dashes[1], QPolygonF({QPointF(10, 0), QPointF(16, 0)}));
        QCOMPARE(d.dots.size(), std::size_t(2));
        QCOMPARE(d.dots[0], QPointF(8, 0));
        QCOMPARE(d.dots[1], QPointF(18, 0));
        // Dots only (the score lines): 0, 1.5, 3.
        const DashedLine dots = dashLine({QPointF(0, 0), QPointF(0, 3)}, false, {0.0, 1.5});
        QVERIFY(dots.dashes.empty());
        QCOMPARE(dots.dots.size(), std::size_t(3));
        QCOMPARE(dots.dots[2], QPointF(0, 3));
    }

    void aClosedLineIsDashedBackToItsStart() {
        const QPolygonF square{QPointF(0, 0), QPointF(4, 0), QPointF(4, 4), QPointF(0, 4)};
        const DashedLine d = dashLine(square, true, {3.0, 1.0});
        QCOMPARE(d.dashes.size(), std::size_t(4)); // 16 mm: four periods
        QCOMPARE(d.dashes.back().back(), QPointF(0, 1));
    }

    void noPatternIsTheWholeLine() {
        const QPolygonF line{QPointF(0, 0), QPointF(1, 1)};
        QCOMPARE(dashLine(line, false, {}).dashes.size(), std::size_t(1));
        QCOMPARE(dashLine(line, false, {0.0, 0.0}).dashes.front(), line);
    }
};

DEVSURF_REGISTER_TEST(TstDashedLine);
#include "tst_dashed_line.moc"
