#pragma once

#include "reaction.h"

#include <QPointer>
#include <QString>

#include <functional>
#include <memory>

namespace devsurf::app {

class BackgroundRead;

class DistanceReportDialog;

// File ▸ Import Reference Shape…: a mesh (OBJ, PLY, STL, OFF) or point cloud (XYZ, PTS) becomes
// a reference shape, one undo step. The file is read on a worker thread behind a progress
// dialog that can cancel; a file that cannot be read is one message and changes nothing.
class ImportReferenceShapeReaction : public Reaction {
    Q_OBJECT
public:
    ImportReferenceShapeReaction(QAction* action, Workspace* workspace);
    ~ImportReferenceShapeReaction() override;

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

// Edit ▸ Remove Reference Shapes: every reference shape, one undo step.
class RemoveReferenceShapesReaction : public Reaction {
    Q_OBJECT
public:
    RemoveReferenceShapesReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

// Tools ▸ Distance to Reference…: the distance report (DistanceReportDialog), one window at a
// time. Disabled, with a tooltip that says why, without a reference shape or a surface.
class DistanceReportReaction : public Reaction {
    Q_OBJECT
public:
    DistanceReportReaction(QAction* action, Workspace* workspace);
    // The window shown, if open.
    DistanceReportDialog* dialog() const;

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    QPointer<DistanceReportDialog> m_dialog;
};

} // namespace devsurf::app
