#include "properties_panel.h"
#include "edit_refusal.h"
#include "model/derived_geometry.h"

#include "face_type_text.h"
#include "model/creases.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/commands/crease_condition_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"
#include "model/surface_statistics.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QUndoStack>
#include <QVBoxLayout>

namespace devsurf::app {

namespace {

QString spaceText(const model::SplineSpace& space) {
    return PropertiesPanel::tr("degree %1, C%2, %3 intervals")
        .arg(space.degree)
        .arg(space.smoothness)
        .arg(space.intervals);
}

// A crease: its two patches (left and right of the edge's direction, seen from the normal
// side), its condition and how it is folded; `found` is the crease as measured.
QString creaseText(const model::CompositeSurface& surface, model::EdgeId edge,
                   std::optional<model::Crease>& found) {
    const model::EdgeRecord& record = surface.edge(edge);
    QString text = PropertiesPanel::tr("A crease between patches %1 (left) and %2 (right); "
                                       "condition: %3.<br>");
    for (const model::Crease& crease : model::DerivedGeometry::of(surface, 8)->creases()) {
        if (crease.edge != edge) {
            continue;
        }
        found = crease;
        text = text.arg(crease.left.face)
                   .arg(crease.right.face)
                   .arg(document::CreaseConditionCommand::conditionText(record.condition));
        switch (crease.assignment) {
        case model::FoldAssignment::Mountain:
            return text + PropertiesPanel::tr("Mountain fold of %1° (up to %2°).")
                              .arg(crease.foldAngleDegrees, 0, 'f', 1)
                              .arg(crease.maxFoldAngleDegrees, 0, 'f', 1);
        case model::FoldAssignment::Valley:
            return text + PropertiesPanel::tr("Valley fold of %1° (up to %2°).")
                              .arg(-crease.foldAngleDegrees, 0, 'f', 1)
                              .arg(crease.maxFoldAngleDegrees, 0, 'f', 1);
        case model::FoldAssignment::Flat:
            return text + PropertiesPanel::tr("Not folded.");
        }
    }
    const auto faces = surface.facesOfEdge(edge);
    return text.arg(faces[0]).arg(faces[1]).arg(
        document::CreaseConditionCommand::conditionText(record.condition));
}

} // namespace

PropertiesPanel::PropertiesPanel(document::Document* document, document::Selection* selection,
                                 QWidget* parent)
    : QWidget(parent), m_document(document), m_selection(selection), m_summary(new QLabel(this)),
      m_pinned(new QLabel(this)), m_positionBox(new QWidget(this)) {
    m_summary->setWordWrap(true);
    m_summary->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // wraps, never widens
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_pinned->setObjectName(QStringLiteral("pinnedLine"));
    m_pinned->setWordWrap(true);
    m_pinned->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // wraps, never widens
    m_pinned->setText(tr("<b>Pinned</b>: the solver never moves this vertex. Tools ▸ Unpin "
                         "Vertices (Ctrl+Shift+K) releases it."));
    m_pinned->setVisible(false);
    auto* form = new QFormLayout(m_positionBox);
    const char* const names[3] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        auto* box = new QDoubleSpinBox(m_positionBox);
        box->setRange(-1e6, 1e6);
        box->setDecimals(4);
        box->setKeyboardTracking(false);
        box->setSuffix(QStringLiteral(" mm"));
        box->setObjectName(QStringLiteral("coordinate%1").arg(names[axis]));
        connect(box, &QDoubleSpinBox::valueChanged, this, &PropertiesPanel::coordinateEdited);
        form->addRow(QStringLiteral("%1:").arg(QLatin1String(names[axis])), box);
        m_coordinates[axis] = box;
    }
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_pinned);
    layout->addWidget(m_positionBox);
    layout->addStretch(1);
    connect(document, &document::Document::changed, this, &PropertiesPanel::refresh);
    connect(selection, &document::Selection::selectionChanged, this, &PropertiesPanel::refresh);
    refresh();
}

QString PropertiesPanel::summaryText() const {
    return m_summary->text();
}

void PropertiesPanel::refresh() {
    m_refreshing = true;
    const auto& picks = m_selection->picks();
    const auto& surfaces = m_document->project().surfaces;
    m_positionBox->setVisible(false);
    m_pinned->setVisible(false);
    m_described.reset();
    m_crease.reset();
    QString text;
    if (picks.empty()) {
        std::size_t faces = 0;
        std::size_t points = 0;
        for (const auto& surface : surfaces) {
            faces += surface.faces().size();
            points += surface.controlPointCount();
        }
        text = tr("Nothing selected.<br>%1, %2.<br><i>Click a vertex, edge or patch to select "
                  "it; Shift-click adds to the selection.</i>")
                   .arg(tr("%n patch(es)", nullptr, static_cast<int>(faces)),
                        tr("%n control point(s)", nullptr, static_cast<int>(points)));
    } else if (picks.size() > 1) {
        int counts[3] = {0, 0, 0};
        for (const auto& pick : picks) {
            ++counts[static_cast<int>(pick.kind)];
        }
        text =
            tr("Selected: %1, %2, %3.")
                .arg(tr("%n vertex(es)", nullptr, counts[0]), tr("%n edge(s)", nullptr, counts[1]),
                     tr("%n patch(es)", nullptr, counts[2]));
    } else {
        const document::Pick pick = *picks.begin();
        if (pick.surface < 0 || pick.surface >= static_cast<int>(surfaces.size())) {
            m_summary->setText({});
            m_refreshing = false;
            return;
        }
        const model::CompositeSurface& surface = surfaces[static_cast<std::size_t>(pick.surface)];
        m_described = pick;
        switch (pick.kind) {
        case document::Pick::Kind::Vertex:
            if (surface.hasVertex(pick.id)) {
                const model::Vec3 p = surface.position(pick.id);
                text = tr("<b>Vertex %1</b>").arg(pick.id);
                for (int axis = 0; axis < 3; ++axis) {
                    m_coordinates[axis]->setValue(p[axis]);
                }
                m_positionBox->setVisible(true);
                m_pinned->setVisible(surface.isPinned(pick.id));
            }
            break;
        case document::Pick::Kind::Edge:
            if (surface.hasEdge(pick.id)) {
                const model::EdgeRecord& edge = surface.edge(pick.id);
                const auto faces = surface.facesOfEdge(pick.id);
                text = tr("<b>Edge %1</b> from vertex %2 to vertex %3<br>")
                           .arg(pick.id)
                           .arg(edge.from)
                           .arg(edge.to);
                if (edge.isSpline()) {
                    text += tr("Spline curve (S), %1, %n control point(s).<br>", nullptr,
                               static_cast<int>(edge.controlPoints.size()))
                                .arg(spaceText(edge.space));
                    if (faces.size() == 2) {
                        text += creaseText(surface, pick.id, m_crease);
                    } else {
                        text += tr("A boundary curve of patch %1.")
                                    .arg(faces.empty() ? 0u : faces.front());
                    }
                } else {
                    text += tr("Ruling (R), a straight segment of length %1 mm.")
                                .arg(model::distance(surface.position(edge.from),
                                                     surface.position(edge.to)),
                                     0, 'f', 3);
                    if (faces.size() == 2) {
                        text +=
                            QStringLiteral("<br>") +
                            (edge.smooth ? tr("Smooth between patches %1 and %2: the surface stays "
                                              "smooth across it.")
                                         : tr("Sharp between patches %1 and %2: the surface may "
                                              "fold along it."))
                                .arg(faces[0])
                                .arg(faces[1]);
                    }
                }
            }
            break;
        case document::Pick::Kind::Face:
            if (surface.hasFace(pick.id)) {
                text = tr("<b>Patch %1</b>: %2<br>Edge labels along the patch: %3<br>%n "
                          "corner(s).",
                          nullptr, static_cast<int>(surface.faceLoop(pick.id).size()))
                           .arg(pick.id)
                           .arg(faceTypeText(surface.faceType(pick.id)))
                           .arg(QString::fromStdString(surface.labelString(pick.id)));
            }
            break;
        }
    }
    if (text.isEmpty()) {
        m_described.reset(); // no such entity
    }
    m_summary->setText(text);
    m_refreshing = false;
}

void PropertiesPanel::coordinateEdited() {
    if (m_refreshing || m_selection->picks().size() != 1) {
        return;
    }
    const document::Pick pick = *m_selection->picks().begin();
    const auto& surfaces = m_document->project().surfaces;
    if (pick.kind != document::Pick::Kind::Vertex || pick.surface < 0 ||
        pick.surface >= static_cast<int>(surfaces.size()) ||
        !surfaces[static_cast<std::size_t>(pick.surface)].hasVertex(pick.id)) {
        return;
    }
    const model::Vec3 current = surfaces[static_cast<std::size_t>(pick.surface)].position(pick.id);
    const model::Vec3 wanted(m_coordinates[0]->value(), m_coordinates[1]->value(),
                             m_coordinates[2]->value());
    const model::Vec3 delta = wanted - current;
    if (delta.norm() == 0.0) {
        return;
    }
    const QString refusal =
        pushOrExplain(*m_document, document::MoveVerticesCommand::createTranslation(
                                       *m_document, pick.surface, {pick.id}, delta));
    if (!refusal.isEmpty()) {
        QMessageBox::warning(this, tr("Cannot move"), refusal);
        refresh();
    }
}

} // namespace devsurf::app
