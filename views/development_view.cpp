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

void DevelopmentView::setShowSheet(bool show) {
    m_showSheet = show;
    setShowSheetImpl(show);
}

} // namespace devsurf::views
