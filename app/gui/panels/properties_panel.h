#pragma once

#include <QWidget>

class QDoubleSpinBox;
class QFormLayout;
class QLabel;

namespace devsurf::document {
class Document;
class Selection;
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

private:
    void refresh();
    void coordinateEdited();

    document::Document* m_document;
    document::Selection* m_selection;
    QLabel* m_summary;
    QWidget* m_positionBox;
    QDoubleSpinBox* m_coordinates[3];
    bool m_refreshing = false;
};

} // namespace devsurf::app
