#include "scene_view_private.h"

#include <QMouseEvent>

namespace devsurf::views {

using document::Pick;

std::optional<Pick> SceneView::pickAt(const QPoint& widgetPos) const {
    if (!d->gl->rect().contains(widgetPos)) {
        return std::nullopt;
    }
    const double dpr = d->gl->effectiveDevicePixelRatio();
    return d->scene->pick(d->displayX(widgetPos.x()), d->displayY(widgetPos.y()),
                          kPickRadius * dpr);
}

QString SceneView::describe(const Pick& pick) const {
    if (d->document == nullptr) {
        return {};
    }
    const auto& surfaces = d->document->project().surfaces;
    if (pick.surface < 0 || pick.surface >= static_cast<int>(surfaces.size())) {
        return {};
    }
    const model::CompositeSurface& surface = surfaces[static_cast<std::size_t>(pick.surface)];
    QString text;
    switch (pick.kind) {
    case Pick::Kind::Vertex:
        text = surface.hasVertex(pick.id) && surface.isPinned(pick.id)
                   ? tr("vertex %1, pinned").arg(pick.id)
                   : tr("vertex %1").arg(pick.id);
        break;
    case Pick::Kind::Edge: {
        if (!surface.hasEdge(pick.id)) {
            return {};
        }
        const bool spline = surface.edge(pick.id).isSpline();
        const std::size_t faces = surface.facesOfEdge(pick.id).size();
        if (!spline) {
            text = tr("edge %1 (R)").arg(pick.id);
        } else if (faces == 2) {
            text = tr("edge %1 (S, crease)").arg(pick.id);
        } else {
            text = tr("edge %1 (S, boundary)").arg(pick.id);
        }
        break;
    }
    case Pick::Kind::Face: {
        if (!surface.hasFace(pick.id)) {
            return {};
        }
        QString type;
        switch (surface.faceType(pick.id)) {
        case model::FaceType::StripSRSR:
            type = tr("strip (SRSR)");
            break;
        case model::FaceType::StripSRS:
            type = tr("pointed strip (SRS)");
            break;
        case model::FaceType::ConeSRR:
            type = tr("cone (SRR)");
            break;
        case model::FaceType::Planar:
            type = tr("planar patch");
            break;
        case model::FaceType::Invalid:
            type = tr("invalid patch");
            break;
        }
        text = tr("patch %1 (%2)").arg(pick.id).arg(type);
        break;
    }
    }
    if (surfaces.size() > 1) {
        text = tr("surface %1: %2").arg(pick.surface + 1).arg(text);
    }
    return text;
}

void SceneView::selectInRectangle(const QRect& rect, bool add) {
    if (d->selection == nullptr) {
        return;
    }
    std::set<Pick> picks = add ? d->selection->picks() : std::set<Pick>{};
    for (const SurfaceScene& scene : d->scene->scenes()) {
        for (const auto& [id, position] : scene.vertices) {
            if (rect.contains(projectToWidget(position))) {
                picks.insert(Pick{Pick::Kind::Vertex, scene.surface, id});
            }
        }
    }
    d->selection->set(std::move(picks));
}

bool SceneView::eventFilter(QObject* watched, QEvent* event) {
    if (watched != d->gl) {
        return QWidget::eventFilter(watched, event);
    }
    switch (event->type()) {
    case QEvent::Resize:
        d->overlay->setGeometry(d->gl->rect());
        break;
    case QEvent::MouseButtonPress: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (me->button() == Qt::RightButton) {
            d->rightPressPos = me->position().toPoint();
            d->rightPressed = true;
        }
        if (me->button() != Qt::LeftButton) {
            break;
        }
        d->pressPos = me->position().toPoint();
        d->pressed = true;
        if (me->modifiers() & Qt::ControlModifier) {
            // Rectangle selection instead of the camera's spin.
            d->banding = true;
            d->band->setGeometry(QRect(d->pressPos, QSize()));
            d->band->show();
            return true;
        }
        break;
    }
    case QEvent::MouseMove: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (d->banding) {
            d->band->setGeometry(QRect(d->pressPos, me->position().toPoint()).normalized());
            return true;
        }
        if (me->buttons() == Qt::NoButton) {
            const std::optional<Pick> pick = pickAt(me->position().toPoint());
            const QString text = pick ? describe(*pick) : QString();
            if (text != d->hover) {
                d->hover = text;
                emit hoverChanged(text);
            }
        }
        break;
    }
    case QEvent::MouseButtonRelease: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (me->button() == Qt::RightButton && d->rightPressed) {
            d->rightPressed = false;
            const QPoint pos = me->position().toPoint();
            if ((pos - d->rightPressPos).manhattanLength() <= kClickSlop) {
                const std::optional<Pick> pick = pickAt(pos);
                if (pick && d->selection != nullptr && !d->selection->contains(*pick)) {
                    d->selection->set({*pick});
                }
                emit contextMenuRequested(pos);
            }
            break;
        }
        if (me->button() != Qt::LeftButton || !d->pressed) {
            break;
        }
        d->pressed = false;
        const QPoint pos = me->position().toPoint();
        const bool click = (pos - d->pressPos).manhattanLength() <= kClickSlop;
        const bool shift = me->modifiers() & Qt::ShiftModifier;
        const bool wasBanding = d->banding;
        if (d->banding) {
            d->banding = false;
            d->band->hide();
            if (!click) {
                selectInRectangle(QRect(d->pressPos, pos).normalized(), shift);
                return true;
            }
        }
        if (click && d->selection != nullptr) {
            const std::optional<Pick> pick = pickAt(pos);
            if (shift) {
                if (pick) {
                    d->selection->toggle(*pick);
                }
            } else if (pick) {
                d->selection->set({*pick});
            } else {
                d->selection->clear();
            }
        }
        if (wasBanding) {
            return true; // the press never reached VTK either
        }
        break;
    }
    case QEvent::Leave:
        if (!d->hover.isEmpty()) {
            d->hover.clear();
            emit hoverChanged(QString());
        }
        break;
    default:
        break;
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace devsurf::views
