#include "mark_region_tool.h"

#include "model/document/commands/add_surfaces_command.h"
#include "model/document/document.h"
#include "model/reference/initial_strip.h"
#include "model/reference/lasso_marking.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "workspace.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QTextEdit>

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace devsurf::app {

namespace {

// A lasso no wider or higher than this (logical pixels) is a click: it clears the mark.
constexpr double kMarkClickSlack = 3.0;
// While dragging, a point joins the lasso once the mouse moved this far from the last one.
constexpr double kLassoStep = 2.0;

// The spline space of the approximation's strips (solver::initialStrips): cubic curves,
// degree-2 rulings space.
model::SplineSpace stripSpace() {
    return model::SplineSpace{3, 2, MarkRegionTool::kIntervals};
}

} // namespace

MarkRegionTool::MarkRegionTool(QAction* mark, QAction* stripAction, Workspace* workspace,
                               views::SurfaceView* view)
    : QObject(mark), m_mark(mark), m_addStrip(stripAction), m_workspace(workspace), m_view(view) {
    m_mark->setCheckable(true);
    connect(m_mark, &QAction::toggled, this, &MarkRegionTool::onToggled);
    connect(m_addStrip, &QAction::triggered, this, [this] { addStrip(); });
    document::Document* doc = workspace->document();
    // The mark holds indices into the shapes: another shape, or none, makes it meaningless.
    connect(doc, &document::Document::changed, this, [this](document::Changes changes) {
        if (changes.testFlag(document::Change::ReferenceShapes)) {
            cancelLasso();
            clearMark();
        }
        updateActions();
    });
    connect(doc, &document::Document::projectReset, this, [this] {
        cancelLasso();
        clearMark();
        updateActions();
    });
    updateActions();
}

std::size_t MarkRegionTool::markedCount() const {
    std::size_t count = 0;
    for (const auto& points : m_marked) {
        count += points.size();
    }
    return count;
}

std::vector<model::Vec3> MarkRegionTool::markedPositions() const {
    std::vector<model::Vec3> positions;
    const auto& shapes = m_workspace->document()->project().referenceShapes;
    for (std::size_t s = 0; s < m_marked.size() && s < shapes.size(); ++s) {
        for (std::size_t i : m_marked[s]) {
            positions.push_back(shapes[s].points[i]);
        }
    }
    return positions;
}

void MarkRegionTool::updateActions() {
    const bool shapes = !m_workspace->document()->project().referenceShapes.empty();
    if (!shapes && m_mark->isChecked()) {
        m_mark->setChecked(false);
    }
    m_mark->setEnabled(shapes);
    const QString markTip =
        shapes ? tr("Mark a region of the reference shape: drag a lasso around it in the 3D view "
                    "(Shift adds to the mark, a click clears it, Esc leaves the tool), then Enter "
                    "adds a flat strip over it (L).")
               : tr("Mark a region of the reference shape with a lasso: import one first (File ▸ "
                    "Import Reference Shape…).");
    m_mark->setToolTip(markTip);
    m_mark->setStatusTip(markTip);
    const bool marked = markedCount() > 0;
    m_addStrip->setEnabled(marked);
    const QString stripTip =
        marked ? tr("Add a flat strip fitted to the marked points (their PCA plane), one undo "
                    "step; Tools ▸ Approximate Reference Shape… with the design's surfaces then "
                    "pulls it onto the shape.")
               : tr("Add a flat strip over a marked region of the reference shape: mark one "
                    "first (Tools ▸ Mark Region of Reference Shape).");
    m_addStrip->setToolTip(stripTip);
    m_addStrip->setStatusTip(stripTip);
}

void MarkRegionTool::onToggled(bool on) {
    if (on) {
        // An application filter: the view's mouse events before the view (and its camera)
        // sees them, and Esc and Enter before the window's shortcuts.
        qApp->installEventFilter(this);
        emit statusMessage(
            tr("Mark region: drag a lasso around part of the reference shape in the 3D view; "
               "Shift adds to the mark, Enter adds a strip over it, Esc leaves the tool."));
    } else {
        qApp->removeEventFilter(this);
        cancelLasso();
    }
}

bool MarkRegionTool::takesKeysOf(QObject* watched) const {
    // Esc and Enter wherever the keyboard focus is in the window (the view, or a panel after
    // the menu turned the tool on), except in a field that edits text.
    auto* widget = qobject_cast<QWidget*>(watched);
    if (widget == nullptr || widget->window() != m_view->window()) {
        return false;
    }
    return widget == m_view->glWidget() || (qobject_cast<QLineEdit*>(widget) == nullptr &&
                                            qobject_cast<QAbstractSpinBox*>(widget) == nullptr &&
                                            qobject_cast<QTextEdit*>(widget) == nullptr &&
                                            qobject_cast<QPlainTextEdit*>(widget) == nullptr &&
                                            qobject_cast<QComboBox*>(widget) == nullptr);
}

bool MarkRegionTool::eventFilter(QObject* watched, QEvent* event) {
    if (!m_mark->isChecked()) {
        return false;
    }
    const QEvent::Type type = event->type();
    if ((type == QEvent::ShortcutOverride || type == QEvent::KeyPress)
            ? !takesKeysOf(watched)
            : watched != m_view->glWidget()) {
        return false;
    }
    switch (type) {
    case QEvent::ShortcutOverride:
    case QEvent::KeyPress: {
        auto* key = static_cast<QKeyEvent*>(event);
        const bool escape = key->key() == Qt::Key_Escape;
        const bool enter = (key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) &&
                           key->modifiers() == Qt::NoModifier;
        if (!escape && !enter) {
            return false;
        }
        if (event->type() == QEvent::ShortcutOverride) {
            event->accept(); // Esc is ours, not Select None's
            return true;
        }
        if (escape) {
            if (m_drawing) {
                cancelLasso();
                emit statusMessage(tr("Lasso dropped; the mark is as it was."));
            } else {
                m_mark->setChecked(false);
            }
        } else if (!m_drawing) {
            addStrip();
        }
        return true;
    }
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (me->button() != Qt::LeftButton) {
            return m_drawing;
        }
        m_drawing = true;
        m_shiftAtPress = me->modifiers().testFlag(Qt::ShiftModifier);
        m_lasso = {me->position()};
        m_view->setLasso(m_lasso);
        return true;
    }
    case QEvent::MouseMove: {
        if (!m_drawing) {
            return false;
        }
        const QPointF at = static_cast<QMouseEvent*>(event)->position();
        if ((at - m_lasso.back()).manhattanLength() >= kLassoStep) {
            m_lasso.push_back(at);
            m_view->setLasso(m_lasso);
        }
        return true;
    }
    case QEvent::MouseButtonRelease: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (!m_drawing || me->button() != Qt::LeftButton) {
            return m_drawing;
        }
        m_lasso.push_back(me->position());
        // Shift held at the press or at the release adds.
        finishLasso(m_shiftAtPress || me->modifiers().testFlag(Qt::ShiftModifier));
        return true;
    }
    default:
        return false;
    }
}

void MarkRegionTool::cancelLasso() {
    m_drawing = false;
    m_lasso.clear();
    m_view->setLasso({});
}

void MarkRegionTool::finishLasso(bool add) {
    std::vector<model::Vec2> polygon;
    double left = m_lasso.front().x(), right = left;
    double top = m_lasso.front().y(), bottom = top;
    for (const QPointF& p : m_lasso) {
        polygon.emplace_back(p.x(), p.y());
        left = std::min(left, p.x());
        right = std::max(right, p.x());
        top = std::min(top, p.y());
        bottom = std::max(bottom, p.y());
    }
    cancelLasso();
    if (right - left <= kMarkClickSlack && bottom - top <= kMarkClickSlack) {
        if (!add && markedCount() > 0) {
            clearMark();
            emit statusMessage(tr("Mark cleared."));
        }
        return;
    }
    if (!m_view->showsReferenceShapes()) {
        emit statusMessage(tr("The reference shapes are hidden: show them (View ▸ Reference "
                              "Shapes) to mark a region."));
        return;
    }
    const auto& shapes = m_workspace->document()->project().referenceShapes;
    const model::reference::LassoCamera camera = m_view->lassoCamera();
    m_marked.resize(shapes.size());
    for (std::size_t s = 0; s < shapes.size(); ++s) {
        std::vector<std::size_t> inside =
            model::reference::pointsInLasso(shapes[s], polygon, camera);
        if (add) {
            std::vector<std::size_t> both;
            std::set_union(m_marked[s].begin(), m_marked[s].end(), inside.begin(), inside.end(),
                           std::back_inserter(both));
            inside = std::move(both);
        }
        m_marked[s] = std::move(inside);
    }
    showMark();
    const std::size_t count = markedCount();
    if (count == 0) {
        emit statusMessage(tr("No point of the reference shape facing the camera lies inside the "
                              "lasso; nothing is marked."));
        return;
    }
    std::size_t shapesMarked = 0;
    std::size_t shapeIndex = 0;
    for (std::size_t s = 0; s < m_marked.size(); ++s) {
        if (!m_marked[s].empty()) {
            ++shapesMarked;
            shapeIndex = s;
        }
    }
    const int n = static_cast<int>(count);
    const QString marked = shapesMarked == 1
                               ? tr("%Ln point(s) of %1 marked.", nullptr, n)
                                     .arg(QString::fromStdString(shapes[shapeIndex].name))
                               : tr("%Ln point(s) of the reference shapes marked.", nullptr, n);
    emit statusMessage(
        tr("%1 Enter adds a strip over them; Shift and a lasso add to the mark.").arg(marked));
}

void MarkRegionTool::clearMark() {
    if (m_marked.empty()) {
        return;
    }
    m_marked.clear();
    showMark();
}

void MarkRegionTool::showMark() {
    m_view->setMarkedPoints(markedPositions());
    updateActions();
}

bool MarkRegionTool::addStrip() {
    const std::vector<model::Vec3> points = markedPositions();
    if (points.empty()) {
        emit statusMessage(tr("No region is marked: draw a lasso around part of the reference "
                              "shape first (Tools ▸ Mark Region of Reference Shape)."));
        return false;
    }
    if (points.size() < 3) {
        emit statusMessage(tr("Too few points are marked for a strip: mark at least three points "
                              "that do not lie on a line."));
        return false;
    }
    model::CompositeSurface strip;
    try {
        strip = model::reference::initialStrip(points, stripSpace());
    } catch (const std::invalid_argument&) {
        emit statusMessage(tr("The marked points lie on a line, so no plane fits them: mark a "
                              "region that is wide in two directions."));
        return false;
    }
    document::Document* doc = m_workspace->document();
    // Named as the approximation names its strips, by the surface's number in the design.
    const int number = doc->surfaceCount() + 1;
    strip.setName("strip " + std::to_string(number));
    if (!m_workspace->apply(document::AddSurfacesCommand::create(
                                *doc, {std::move(strip)}, tr("Add Strip Over Marked Region")),
                            tr("Cannot add the strip"))) {
        return false;
    }
    const int n = static_cast<int>(points.size());
    clearMark();
    emit statusMessage(tr("Added strip %1 over %Ln marked point(s); Tools ▸ Approximate "
                          "Reference Shape… with the design's surfaces pulls it onto the shape.",
                          nullptr, n)
                           .arg(number));
    emit stripAdded();
    return true;
}

} // namespace devsurf::app
