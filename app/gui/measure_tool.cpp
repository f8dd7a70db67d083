#include "measure_tool.h"

#include "model/bspline_curve.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/edge_measure.h"
#include "model/sheet_position.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "workspace.h"

#include <QAction>
#include <QClipboard>
#include <QGuiApplication>
#include <QLocale>
#include <QMouseEvent>

namespace devsurf::app {

namespace {

// A click moves the mouse at most this far (pixels) between press and release.
constexpr int kMeasureClickSlack = 3;

QString millimetres(double value) {
    return QLocale().toString(value, 'f', 2);
}

} // namespace

MeasureTool::MeasureTool(QAction* action, QAction* copy, Workspace* workspace,
                         views::SurfaceView* view)
    : QObject(action), m_action(action), m_copy(copy), m_workspace(workspace), m_view(view) {
    m_action->setCheckable(true);
    m_copy->setEnabled(false);
    connect(m_action, &QAction::toggled, this, [this](bool on) {
        if (on) {
            m_view->glWidget()->installEventFilter(this);
            emit statusMessage(tr("Measure: click two points of the surface in the 3D view."));
        } else {
            m_view->glWidget()->removeEventFilter(this);
            clear();
        }
    });
    connect(m_copy, &QAction::triggered, this, [this] {
        if (!m_text.isEmpty()) {
            QGuiApplication::clipboard()->setText(m_text);
            emit statusMessage(tr("Copied: %1").arg(m_text));
        }
    });
    connect(workspace->selection(), &document::Selection::selectionChanged, this, [this] {
        if (m_action->isChecked()) {
            measureSelectedEdges();
        }
    });
    // The points belong to the shape they were picked on.
    connect(workspace->document(), &document::Document::changed, this, [this] { clear(); });
    connect(workspace->document(), &document::Document::projectReset, this, [this] { clear(); });
}

bool MeasureTool::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_view->glWidget() || !m_action->isChecked()) {
        return false;
    }
    if (event->type() == QEvent::MouseButtonPress) {
        auto* me = static_cast<QMouseEvent*>(event);
        m_pressed = me->button() == Qt::LeftButton;
        m_pressAt = me->position().toPoint();
    } else if (event->type() == QEvent::MouseButtonRelease && m_pressed) {
        m_pressed = false;
        const QPoint at = static_cast<QMouseEvent*>(event)->position().toPoint();
        if ((at - m_pressAt).manhattanLength() <= kMeasureClickSlack) {
            pick(at);
        }
    }
    return false; // the view still selects and turns the camera
}

void MeasureTool::pick(const QPoint& widgetPos) {
    const auto hit = m_view->surfacePointAt(widgetPos);
    if (!hit) {
        emit statusMessage(tr("Measure: no surface under the mouse; click on the surface."));
        return;
    }
    if (m_points.size() == 2) {
        m_points.clear();
    }
    m_points.push_back({hit->first, hit->second});
    show();
}

bool MeasureTool::measureSelectedEdges() {
    std::vector<document::Pick> edges;
    for (const document::Pick& pick : m_workspace->selection()->picks()) {
        if (pick.kind != document::Pick::Kind::Edge) {
            return false;
        }
        edges.push_back(pick);
    }
    const document::Document* doc = m_workspace->document();
    if (edges.empty() || edges.size() > 2 || edges.front().surface < 0 ||
        edges.front().surface >= doc->surfaceCount() ||
        edges.back().surface != edges.front().surface) {
        return false;
    }
    const model::CompositeSurface& surface = doc->surface(edges.front().surface);
    for (const document::Pick& edge : edges) {
        if (!surface.hasEdge(edge.id)) {
            return false;
        }
    }
    const QLocale locale;
    model::Vec3 anchor; // where the view writes it: the edge's middle, or the common vertex
    if (edges.size() == 1) {
        const model::EdgeRecord& record = surface.edge(edges.front().id);
        if (record.isSpline()) {
            const model::BSplineCurve spline =
                model::BSplineCurve::uniform(record.space, record.controlPoints);
            anchor = spline.evaluate(0.5 * (spline.domainBegin() + spline.domainEnd()));
        } else {
            anchor = (surface.position(record.from) + surface.position(record.to)) * 0.5;
        }
        m_text = tr("Edge %1: %2 mm long")
                     .arg(edges.front().id)
                     .arg(millimetres(model::edgeLength(surface, edges.front().id)));
    } else {
        const auto angle = model::edgeAngle(surface, edges[0].id, edges[1].id);
        if (!angle) {
            return false;
        }
        m_text = tr("Edges %1 and %2 meet at vertex %3 at %4°")
                     .arg(edges[0].id)
                     .arg(edges[1].id)
                     .arg(angle->vertex)
                     .arg(locale.toString(angle->degrees, 'f', 2));
        anchor = surface.position(angle->vertex);
    }
    m_points.clear();
    m_space = -1.0; // no point-to-point distance now
    m_sheet = -1.0;
    m_view->setMeasurement({anchor}, m_text);
    m_copy->setEnabled(true);
    emit statusMessage(tr("Measured: %1. Ctrl+C copies it.").arg(m_text));
    return true;
}

void MeasureTool::clear() {
    if (m_points.empty() && m_text.isEmpty()) {
        return;
    }
    m_points.clear();
    m_text.clear();
    m_space = -1.0;
    m_sheet = -1.0;
    m_copy->setEnabled(false);
    m_view->setMeasurement({}, QString());
}

void MeasureTool::show() {
    std::vector<model::Vec3> drawn;
    for (const Point& point : m_points) {
        drawn.push_back(point.space);
    }
    if (m_points.size() < 2) {
        m_text.clear();
        m_copy->setEnabled(false);
        m_view->setMeasurement(drawn, QString());
        emit statusMessage(tr("Measure: first point picked; click the second."));
        return;
    }
    const Point& a = m_points[0];
    const Point& b = m_points[1];
    m_space = distance(a.space, b.space);
    m_sheet = -1.0;
    const document::Document* doc = m_workspace->document();
    if (a.face.surface == b.face.surface && a.face.surface >= 0 &&
        a.face.surface < doc->surfaceCount()) {
        const model::CompositeSurface& surface = doc->surface(a.face.surface);
        const auto onSheetA = model::sheetPosition(surface, a.face.id, a.space);
        const auto onSheetB = model::sheetPosition(surface, b.face.id, b.space);
        if (onSheetA && onSheetB) {
            m_sheet = (*onSheetA - *onSheetB).norm();
        }
    }
    m_text =
        m_sheet >= 0.0
            ? tr("3D %1 mm, along the sheet %2 mm").arg(millimetres(m_space), millimetres(m_sheet))
            : tr("3D %1 mm (the points lie on different surfaces)").arg(millimetres(m_space));
    m_copy->setEnabled(true);
    m_view->setMeasurement(drawn, m_text);
    emit statusMessage(tr("Distance: %1. Ctrl+C copies it.").arg(m_text));
}

} // namespace devsurf::app
