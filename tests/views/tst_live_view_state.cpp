#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "test_registry.h"
#include "views/development_view.h"
#include "views/surface_view.h"

#include <QHBoxLayout>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <set>

using devsurf::document::Document;
using devsurf::document::Pick;
using devsurf::document::Selection;
using devsurf::model::Vec3;
using devsurf::views::ColourBy;

namespace {

int distinctColours(const QImage& image) {
    std::set<QRgb> colours;
    for (int y = image.height() / 4; y < 3 * image.height() / 4; y += 3) {
        for (int x = image.width() / 4; x < 3 * image.width() / 4; x += 3) {
            colours.insert(image.pixel(x, y));
        }
    }
    return static_cast<int>(colours.size());
}

} // namespace

// What the views show for live solving: pins, the drag plane, quality colours.
class TstLiveViewState : public QObject {
    Q_OBJECT

    Document m_document;
    Selection m_selection;
    QWidget m_window;
    devsurf::views::SurfaceView* m_spatial = nullptr;
    devsurf::views::DevelopmentView* m_development = nullptr;

    void push(devsurf::document::CommandOrError edit) {
        QVERIFY(!edit.isRefused());
        m_document.undoStack()->push(edit.takeCommand().release());
    }

private slots:
    void init() {
        m_document.resetProject(devsurf::model::makeExample("annulus"));
        if (m_spatial == nullptr) {
            auto* layout = new QHBoxLayout(&m_window);
            m_spatial = new devsurf::views::SurfaceView(&m_document, &m_selection);
            m_development = new devsurf::views::DevelopmentView(&m_document, &m_selection);
            layout->addWidget(m_spatial);
            layout->addWidget(m_development);
            m_window.resize(900, 450);
            m_window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&m_window));
        }
        m_spatial->setColourBy(ColourBy::Patch);
        m_spatial->grabImage();
        m_development->grabImage();
    }

    void pinnedVerticesAreDrawnInBothViews() {
        QVERIFY(m_spatial->pinnedPicks().empty());
        push(devsurf::document::PinVerticesCommand::create(m_document, 0, {4, 9}, true));
        const std::set<Pick> pinned{{Pick::Kind::Vertex, 0, 4}, {Pick::Kind::Vertex, 0, 9}};
        QCOMPARE(m_spatial->pinnedPicks(), pinned);
        QCOMPARE(m_development->pinnedPicks(), pinned);
        m_document.undoStack()->undo();
        QVERIFY(m_spatial->pinnedPicks().empty());
        QVERIFY(m_development->pinnedPicks().empty());
    }

    void aWidgetPositionMapsBackToTheDragPlane() {
        const Vec3 vertex = m_document.surface(0).position(20);
        const Vec3 normal = m_spatial->viewDirection();
        const QPoint at = m_spatial->projectToWidget(vertex);
        const auto hit = m_spatial->widgetToPlane(at, vertex, normal);
        QVERIFY(hit.has_value());
        // Within the size of a pixel (the annulus is 300 mm across in a 450 px wide view).
        QVERIFY2((*hit - vertex).norm() < 2.0, qPrintable(QString::number((*hit - vertex).norm())));
        const auto above = m_spatial->widgetToPlane(at - QPoint(0, 20), vertex, normal);
        QVERIFY(above.has_value());
        QVERIFY(above->z > vertex.z); // up on the screen is up in the 3D view's start camera
    }

    void qualityColoursShowWhereTheSurfaceIsNotDevelopable() {
        const int patchColours = distinctColours(m_spatial->grabImage());
        m_spatial->setColourBy(ColourBy::Developability);
        QCOMPARE(m_spatial->colourBy(), ColourBy::Developability);
        const QString developabilityTitle = m_spatial->legendTitle();
        QVERIFY(!developabilityTitle.isEmpty());
        // One fixed scale for every design and measure.
        const std::pair<double, double> scale(1e-12, 1e-2);
        QCOMPARE(m_spatial->legendRange(), scale);
        // The flat annulus is developable everywhere: every patch below the tolerance.
        const double tolerance = m_spatial->legendTolerance();
        QVERIFY(tolerance > 0.0);
        auto worstPatch = [this] {
            double worst = 0.0;
            for (const auto& [face, loop] : m_document.surface(0).faces()) {
                (void)loop;
                worst = std::max(worst, m_spatial->legendValue({Pick::Kind::Face, 0, face}));
            }
            return worst;
        };
        QVERIFY(worstPatch() < tolerance);
        // Lifting a vertex twists the strips around it.
        push(devsurf::document::MoveVerticesCommand::createTranslation(m_document, 0, {20},
                                                                       Vec3(0.0, 0.0, 20.0)));
        QCOMPARE(m_spatial->legendRange(), scale);
        QVERIFY2(worstPatch() > 1e-4, qPrintable(QString::number(worstPatch())));
        const int qualityColours = distinctColours(m_spatial->grabImage());
        QVERIFY(qualityColours != patchColours);

        m_spatial->setColourBy(ColourBy::Flatness);
        QVERIFY(worstPatch() > 1e-4);
        QCOMPARE(m_spatial->legendRange(), scale);
        m_spatial->setColourBy(ColourBy::AngleDefect);
        QCOMPARE(m_spatial->colourBy(), ColourBy::AngleDefect);
        QVERIFY(!m_spatial->legendTitle().isEmpty());
        QVERIFY(m_spatial->legendTitle() != developabilityTitle);
        QVERIFY(worstPatch() > 1e-6);
        m_spatial->setColourBy(ColourBy::Patch);
        QVERIFY(m_spatial->legendTitle().isEmpty());
        // The development view always shows the patches.
        QCOMPARE(m_development->colourBy(), ColourBy::Patch);
    }
};

DEVSURF_REGISTER_TEST(TstLiveViewState);
#include "tst_live_view_state.moc"
