#include "model/document/commands/move_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"
#include "solver/core/options.h"
#include "solver/quality/quality_measures.h"
#include "test_registry.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"

#include <QHBoxLayout>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

using devsurf::document::Pick;
using devsurf::model::FaceId;
using devsurf::model::Vec3;
using devsurf::views::ColourBy;

namespace {

// The normalised residual |det(a−b, a′, b′)| / (|a−b| |a′| |b′|) with the derivatives taken by
// central differences, independently of solver/quality.
double residualByDifferences(const devsurf::model::Strip& strip, double u) {
    const double h = 1e-6;
    const Vec3 aPrime = (strip.a.evaluate(u + h) - strip.a.evaluate(u - h)) / (2.0 * h);
    const Vec3 bPrime = (strip.b.evaluate(u + h) - strip.b.evaluate(u - h)) / (2.0 * h);
    const Vec3 m = strip.a.evaluate(u) - strip.b.evaluate(u);
    return std::abs(dot(m, cross(aPrime, bPrime))) / (m.norm() * aPrime.norm() * bPrime.norm());
}

} // namespace

// The 3D view colours with the measures the Solver panel reports: the legend's value of a patch
// is the panel's value (solver::developabilityByFace, which SolveController::reportOf lists as
// the least developable patches), bit for bit.
class TstQualityLegend : public QObject {
    Q_OBJECT

    devsurf::document::Document m_document;
    devsurf::document::Selection m_selection;
    QWidget m_window;
    devsurf::views::SurfaceView* m_view = nullptr;

private slots:
    void initTestCase() {
        auto* layout = new QHBoxLayout(&m_window);
        m_view = new devsurf::views::SurfaceView(&m_document, &m_selection);
        layout->addWidget(m_view);
        m_window.resize(500, 400);
        m_window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&m_window));
    }

    void legendValueOfAPatchIsThePanelsValue_data() {
        QTest::addColumn<QString>("example");
        QTest::addColumn<int>("vertex"); // moved by about `lift` (none if negative)
        QTest::addColumn<double>("lift");
        QTest::newRow("annulus lifted") << "annulus" << 20 << 20.0;
        QTest::newRow("sheet lifted") << "sheet" << 5 << 15.0;
        QTest::newRow("cylinder pushed") << "cylinder" << 3 << 10.0;
        QTest::newRow("mixed lifted") << "mixed" << 1 << 5.0;
        QTest::newRow("fig6 lifted") << "fig6" << 2 << 5.0;
        QTest::newRow("fig6") << "fig6" << -1 << 0.0;
        QTest::newRow("fig8 lifted") << "fig8" << 2 << 5.0;
        QTest::newRow("fig8") << "fig8" << -1 << 0.0;
    }

    void legendValueOfAPatchIsThePanelsValue() {
        QFETCH(QString, example);
        QFETCH(int, vertex);
        QFETCH(double, lift);
        m_document.resetProject(devsurf::model::makeExample(example.toStdString()));
        if (vertex >= 0) {
            auto edit = devsurf::document::MoveVerticesCommand::createTranslation(
                m_document, 0, {static_cast<devsurf::model::VertexId>(vertex)},
                Vec3(0.5 * lift, 0.3 * lift, lift));
            QVERIFY(!edit.isRefused());
            m_document.undoStack()->push(edit.takeCommand().release());
        }
        m_view->setColourBy(ColourBy::Developability);
        m_view->grabImage();
        const devsurf::model::CompositeSurface& surface = m_document.surface(0);

        std::map<FaceId, double> panel;
        for (const auto& [face, value] : devsurf::solver::developabilityByFace(surface)) {
            panel[face] = value;
        }
        QVERIFY(!panel.empty());
        double worst = 0.0;
        for (const auto& [face, loop] : surface.faces()) {
            (void)loop;
            const double legend = m_view->legendValue({Pick::Kind::Face, 0, face});
            const auto listed = panel.find(face);
            if (listed == panel.end()) {
                QCOMPARE(legend, 0.0); // cones and planar patches: developable by construction
                continue;
            }
            QCOMPARE(legend, listed->second);
            worst = std::max(worst, legend);

            // And the value is the residual: the largest of its 20 samples per interval,
            // recomputed here with difference quotients.
            const devsurf::model::Strip strip = devsurf::model::stripOfFace(surface, face);
            const int n = 20 * surface.edge(strip.aSide.edge).space.intervals;
            double independent = 0.0;
            for (int i = 0; i < n; ++i) {
                independent = std::max(independent, residualByDifferences(strip, (i + 0.5) / n));
            }
            QVERIFY2(std::abs(legend - independent) <= 1e-6 * independent + 1e-9,
                     qPrintable(QStringLiteral("patch %1: legend %2, by differences %3")
                                    .arg(face)
                                    .arg(legend, 0, 'e', 6)
                                    .arg(independent, 0, 'e', 6)));
        }
        qInfo("%s: the least developable patch at %.17g in the legend and the panel",
              qPrintable(example), worst);
        if (vertex >= 0) {
            QVERIFY2(worst > 1e-4, qPrintable(QString::number(worst))); // really not developable
        }
        // The scale is the same for every design: a colour means one value everywhere.
        QCOMPARE(m_view->legendRange(), std::make_pair(1e-12, 1e-2));

        // Flatness and the angle defect: the largest value drawn is measureQuality's.
        const devsurf::solver::QualityMeasures measures = devsurf::solver::measureQuality(surface);
        for (const ColourBy by : {ColourBy::Flatness, ColourBy::AngleDefect}) {
            m_view->setColourBy(by);
            m_view->grabImage();
            double largest = 0.0;
            for (const auto& [face, loop] : surface.faces()) {
                (void)loop;
                largest = std::max(largest, m_view->legendValue({Pick::Kind::Face, 0, face}));
            }
            QCOMPARE(largest,
                     by == ColourBy::Flatness ? measures.flatnessMax : measures.curvatureMax);
        }
        m_view->setColourBy(ColourBy::Patch);
        QVERIFY(std::isnan(m_view->legendValue({Pick::Kind::Face, 0, panel.begin()->first})));
    }

    void theLegendMarksTheToleranceInGreen() {
        m_document.resetProject(devsurf::model::makeExample("fig8"));
        m_view->setColourBy(ColourBy::Developability);
        m_view->grabImage();
        const double tolerance = devsurf::solver::Options{}.reportTolerance;
        QCOMPARE(m_view->legendTolerance(), tolerance);
        QVERIFY(!m_view->legendToleranceLabel().isEmpty());
        // Below the tolerance green, above it from yellow to red.
        for (const double value : {0.0, 1e-12, 1e-10, 0.9 * tolerance}) {
            const QColor colour = m_view->legendColour(value);
            QVERIFY2(colour.green() > colour.red() && colour.green() > colour.blue(),
                     qPrintable(colour.name()));
        }
        for (const double value : {2.0 * tolerance, 1e-6, 1e-4, 1e-2, 1.0}) {
            const QColor colour = m_view->legendColour(value);
            QVERIFY2(colour.red() > colour.blue() && colour.red() >= colour.green(),
                     qPrintable(colour.name()));
        }
        QVERIFY(m_view->legendColour(1e-2).green() < m_view->legendColour(1e-7).green());
        m_view->setColourBy(ColourBy::Patch);
        m_view->grabImage();
        QCOMPARE(m_view->legendTolerance(), 0.0);
        QVERIFY(m_view->legendRect().isEmpty());
    }

    void afterFitTheLegendDoesNotOverlapTheDesign_data() {
        QTest::addColumn<QString>("example");
        QTest::addColumn<int>("colourBy");
        QTest::newRow("sheet developability") << "sheet" << int(ColourBy::Developability);
        QTest::newRow("annulus flatness") << "annulus" << int(ColourBy::Flatness);
        QTest::newRow("cylinder angle defect") << "cylinder" << int(ColourBy::AngleDefect);
        QTest::newRow("fig8 developability") << "fig8" << int(ColourBy::Developability);
    }

    void afterFitTheLegendDoesNotOverlapTheDesign() {
        QFETCH(QString, example);
        QFETCH(int, colourBy);
        m_document.resetProject(devsurf::model::makeExample(example.toStdString()));
        m_view->setColourBy(static_cast<ColourBy>(colourBy));
        m_view->fitAll();
        m_view->grabImage();
        const QRect legend = m_view->legendRect();
        const QRect viewport = m_view->glWidget()->rect();
        QVERIFY(!legend.isEmpty());
        QVERIFY(viewport.contains(legend));
        // The design as drawn: every point of the sampled mesh the view shows.
        const devsurf::model::SampledMesh mesh =
            devsurf::model::sampleSurface(m_document.surface(0), 8);
        QRect drawn;
        for (const Vec3& point : mesh.vertices) {
            const QPoint at = m_view->projectToWidget(point);
            drawn = drawn.united(QRect(at, QSize(1, 1)));
        }
        QVERIFY2(!drawn.intersects(legend),
                 qPrintable(QStringLiteral("design %1,%2 %3×%4, legend %5,%6 %7×%8")
                                .arg(drawn.x())
                                .arg(drawn.y())
                                .arg(drawn.width())
                                .arg(drawn.height())
                                .arg(legend.x())
                                .arg(legend.y())
                                .arg(legend.width())
                                .arg(legend.height())));
        QVERIFY(viewport.contains(drawn));
        // And it still fills the view: the fit is not simply zoomed far out.
        QVERIFY2(drawn.width() > viewport.width() / 2 || drawn.height() > viewport.height() / 2,
                 qPrintable(QStringLiteral("%1×%2").arg(drawn.width()).arg(drawn.height())));
        m_view->setColourBy(ColourBy::Patch);
    }
};

DEVSURF_REGISTER_TEST(TstQualityLegend);
#include "tst_quality_legend.moc"
