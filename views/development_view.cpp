#include "development_view.h"

namespace devsurf::views {

DevelopmentView::DevelopmentView(document::Document* document, document::Selection* selection,
                                 QWidget* parent)
    : SceneView(Kind::Development, document, selection, parent) {
    setShowVerticesImpl(m_showVertices);
}

DevelopmentView::~DevelopmentView() = default;

void DevelopmentView::setShowVertices(bool show) {
    m_showVertices = show;
    setShowVerticesImpl(show);
}

} // namespace devsurf::views
