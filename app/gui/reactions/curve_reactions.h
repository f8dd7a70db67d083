#pragma once

#include "reaction.h"

#include <QString>

#include <functional>
#include <memory>

namespace devsurf::app {

class BackgroundRead;

// File ▸ Import Curves…: the curves of a DXF, SVG, STEP or IGES file become reference curves, one
// undo step. The file is read on a worker thread behind a progress dialog that can cancel; a
// file that cannot be read is one message and changes nothing.
class ImportCurvesReaction : public Reaction {
    Q_OBJECT
public:
    ImportCurvesReaction(QAction* action, Workspace* workspace);
    ~ImportCurvesReaction() override;

    // Replaces the file dialog (tests): returns the file to import, or empty for none.
    void setFileChooser(std::function<QString()> chooser) { m_chooser = std::move(chooser); }
    // Starts reading the file; finished() follows when it is read and applied, refused or
    // cancelled.
    void importFile(const QString& path);
    bool isBusy() const { return m_read != nullptr; }

signals:
    void finished(bool imported);

protected:
    void onTriggered() override;

private:
    struct Job;
    void onRead();

    std::function<QString()> m_chooser;
    std::shared_ptr<Job> m_job;
    BackgroundRead* m_read = nullptr;
};

// Edit ▸ Remove Reference Curves: every reference curve, one undo step.
class RemoveReferenceCurvesReaction : public Reaction {
    Q_OBJECT
public:
    RemoveReferenceCurvesReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

// Tools ▸ Fit Edge to Reference Curve: the one selected spline edge (a crease or a strip's
// boundary) laid onto the reference curve nearest it (model::fitEdgeToCurve), one undo step;
// the status bar says how close it lies, and that Solve makes the surface developable again.
class FitEdgeToCurveReaction : public Reaction {
    Q_OBJECT
public:
    FitEdgeToCurveReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

} // namespace devsurf::app
