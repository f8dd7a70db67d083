#pragma once

#include "model/creases.h"
#include "model/document/selection.h"

#include <QWidget>

#include <optional>

class QDoubleSpinBox;
class QFormLayout;
class QLabel;

namespace devsurf::document {
class Document;
} // namespace devsurf::document

namespace devsurf::app {

// Shows what is selected. A single vertex's position is editable: a change pushes an undoable
// move, exactly like moving it in the view.
class PropertiesPanel : public QWidget {
    Q_OBJECT
public:
    PropertiesPanel(document::Document* document, document::Selection* selection,
                    QWidget* parent = nullptr);

    // The position editors (x, y, z) of a single selected vertex; hidden otherwise.
    QDoubleSpinBox* coordinateEditor(int axis) const { return m_coordinates[axis]; }
    QString summaryText() const;
    // The line that says a single selected vertex is pinned (hidden otherwise).
    QLabel* pinnedLine() const { return m_pinned; }
    // The single selected entity the summary describes (none: nothing or several selected).
    const std::optional<document::Pick>& describedPick() const { return m_described; }
    // The crease the summary describes, with its fold as measured (none: no crease described).
    const std::optional<model::Crease>& describedCrease() const { return m_crease; }

private:
    void refresh();
    void coordinateEdited();

    document::Document* m_document;
    document::Selection* m_selection;
    QLabel* m_summary;
    QLabel* m_pinned;
    QWidget* m_positionBox;
    QDoubleSpinBox* m_coordinates[3];
    bool m_refreshing = false;
    std::optional<document::Pick> m_described;
    std::optional<model::Crease> m_crease;
};

} // namespace devsurf::app
