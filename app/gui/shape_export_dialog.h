#pragma once

#include <QDialog>
#include <QString>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace devsurf::model {
struct Project;
}

namespace devsurf::app {

// File ▸ Export 3D Shape…: STEP (AP242, AP214) or IGES with the exact surfaces, or a mesh
// (OBJ, STL, PLY) within a chord tolerance, optionally with a thickness. Exports with a
// progress dialog that can cancel; says where patches could not be sewn.
class ShapeExportDialog : public QDialog {
    Q_OBJECT
public:
    enum Format { StepAP242, StepAP214, Iges, Obj, Stl, Ply };

    ShapeExportDialog(const model::Project& project, const QString& baseName,
                      const QString& directory, QWidget* parent = nullptr);

    // The design's project file, which an export never overwrites (empty: not saved yet).
    void setProjectFile(const QString& projectFile) { m_projectFile = projectFile; }

    QComboBox* formatBox() const { return m_format; }
    QDoubleSpinBox* toleranceBox() const { return m_tolerance; }
    QDoubleSpinBox* thicknessBox() const { return m_thickness; }
    // What the last export wrote, for the status bar ("48 faces in 1 shell").
    QString summary() const { return m_summary; }

    // Writes the shape to `path` with the current options. Returns false (after telling the
    // user) on failure or cancellation.
    bool exportTo(const QString& path);

    static QString extensionFor(Format format);

private:
    void chooseFileAndExport();
    void updateEnabled();
    bool exportCad(const QString& path, Format format);
    bool exportMesh(const QString& path, Format format);

    const model::Project& m_project;
    QString m_baseName;
    QString m_directory;
    QString m_projectFile;
    QString m_summary;
    QComboBox* m_format = nullptr;
    QDoubleSpinBox* m_tolerance = nullptr;
    QDoubleSpinBox* m_thickness = nullptr;
    QLabel* m_note = nullptr;
};

} // namespace devsurf::app
