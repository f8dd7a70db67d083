#pragma once

// The 3D and development views of one document side by side in a window, as the tests of the
// views show them.

#include "model/document/document.h"
#include "model/document/selection.h"
#include "views/development_view.h"
#include "views/surface_view.h"

#include <QHBoxLayout>
#include <QTest>
#include <QWidget>

namespace devsurf::test {

struct SideBySideViews {
    document::Document document;
    document::Selection selection;
    QWidget window;
    views::SurfaceView* spatial = nullptr;
    views::DevelopmentView* development = nullptr;

    SideBySideViews(model::Project project, int width, int height) {
        document.resetProject(std::move(project));
        auto* layout = new QHBoxLayout(&window);
        spatial = new views::SurfaceView(&document, &selection);
        development = new views::DevelopmentView(&document, &selection);
        layout->addWidget(spatial);
        layout->addWidget(development);
        window.resize(width, height);
    }

    // Shows the window and renders both views; false if the window never became exposed.
    bool show() {
        window.show();
        if (!QTest::qWaitForWindowExposed(&window)) {
            return false;
        }
        // The first grab initialises the GL widgets (context, VTK window size).
        spatial->grabImage();
        development->grabImage();
        return true;
    }

    const model::CompositeSurface& surface() const { return document.project().surfaces.at(0); }
};

} // namespace devsurf::test
