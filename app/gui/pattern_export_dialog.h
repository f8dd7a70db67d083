#pragma once

#include "io/pattern/pattern_writers.h"
#include "model/pattern/cutting_pattern.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QTableWidget;
class QTimer;

namespace devsurf::model {
struct Project;
}

namespace devsurf::app {

// What the last export used (kept in the settings): the pattern's options, the writer's and
// the format. Printing uses the same pattern options.
struct PatternSettings {
    model::PatternOptions pattern;
    io::PatternWriteOptions write;
    io::PatternFormat format = io::PatternFormat::Dxf;
    int sheetPreset = 0; // index into sheetPresets(); the last one is "custom"

    static PatternSettings load();
    void save() const;
};

// File ▸ Export Cutting Pattern…: format, curves (polylines or splines) and tolerance, layers,
// seam allowance, sheet size (laser bed, paper sizes, custom), DXF R12; shows the fabrication
// report of the pattern these options give and warns about overlaps before writing.
class PatternExportDialog : public QDialog {
    Q_OBJECT
public:
    PatternExportDialog(const model::Project& project, const QString& baseName,
                        const QString& directory, QWidget* parent = nullptr);

    PatternSettings settings() const;
    void setSettings(const PatternSettings& settings);
    // The pattern of the current options (rebuilt when they change).
    const model::CuttingPattern& pattern() const { return m_pattern; }
    QTableWidget* reportTable() const { return m_report; }
    QLabel* warningLabel() const { return m_warning; }
    QComboBox* formatBox() const { return m_format; }
    // The tolerance (mm) the pattern was sampled to: the one asked for, or coarser where the
    // design reaches so far that the one asked for would take minutes (the warning says so).
    double samplingTolerance() const { return m_samplingTolerance; }

    // The design's project file, which an export never overwrites (empty: not saved yet).
    void setProjectFile(const QString& projectFile) { m_projectFile = projectFile; }

    // Writes the pattern to `path` with the current options, with a progress dialog for long
    // PDFs. Returns false (after telling the user) on failure or cancellation.
    bool exportTo(const QString& path);

    // The file dialog's filter for a format, e.g. "DXF drawing (*.dxf)".
    static QString filterFor(io::PatternFormat format);

public slots:
    void rebuildPattern();

private:
    void chooseFileAndExport();
    void updateEnabled();
    void showReport();

    const model::Project& m_project;
    QString m_baseName;
    QString m_directory;
    QString m_projectFile;
    model::CuttingPattern m_pattern;
    double m_samplingTolerance = 0.0;
    QString m_samplingNote; // why the tolerance was coarsened or there is no pattern

    QComboBox* m_format;
    QRadioButton* m_polylines;
    QRadioButton* m_splines;
    QDoubleSpinBox* m_tolerance;
    QList<QCheckBox*> m_layers; // one per model::PatternLayer
    QDoubleSpinBox* m_seam;
    QCheckBox* m_glueTabs;
    QComboBox* m_sheet;
    QDoubleSpinBox* m_sheetWidth;
    QDoubleSpinBox* m_sheetHeight;
    QComboBox* m_paper;
    QCheckBox* m_r12;
    QTableWidget* m_report;
    QLabel* m_summary;
    QLabel* m_warning;
    QPushButton* m_export;
    QTimer* m_rebuildTimer = nullptr;
};

// The sheet sizes offered: name and size in mm ({0, 0} for "custom").
struct SheetPreset {
    QString name;
    model::Vec2 size;
};
QList<SheetPreset> sheetPresets();

} // namespace devsurf::app
