#pragma once

#include "scene_view.h"

namespace devsurf::views {

// The development view: the cutting pattern's pieces (model::buildCuttingPattern, without
// sheets) side by side in the plane, each oriented as the 3D view shows its surface, seen from
// above with a parallel projection; the outline (both sides of a cut-open seam, with their
// vertices), creases and rulings drawn over pale patch colours, pieces that overlap outlined
// in red. Pan (left or middle drag) and zoom (right drag, wheel) only. The
// selection is the same as the 3D view's: picking here selects the same document::Pick.
class DevelopmentView : public SceneView {
    Q_OBJECT
public:
    DevelopmentView(document::Document* document, document::Selection* selection,
                    QWidget* parent = nullptr);
    ~DevelopmentView() override;

    bool showVertices() const { return m_showVertices; }
    // The sheet a held development is confined to, drawn behind it (View ▸ Sheet).
    bool showsSheet() const { return m_showSheet; }

public slots:
    void setShowVertices(bool show);
    void setShowSheet(bool show);

private:
    bool m_showVertices = true;
    bool m_showSheet = true;
};

} // namespace devsurf::views
