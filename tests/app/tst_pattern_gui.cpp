#include "../io/dxf_check.h"
#include "far_design.h"
#include "io/pattern/fabrication_report.h"
#include "io/project_file.h"
#include "main_window.h"
#include "model/examples.h"
#include "model/pattern/sampling_bound.h"
#include "model/project.h"
#include "pattern_export_dialog.h"
#include "reactions/pattern_reactions.h"
#include "test_registry.h"
#include "views/scene_geometry.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QPrinter>
#include <QProcess>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

namespace {

int pdfPages(const QString& file) {
    QProcess process;
    process.start(QStringLiteral("pdfinfo"), {file});
    process.waitForFinished(60000);
    const QString out = QString::fromUtf8(process.readAllStandardOutput());
    for (const QString& line : out.split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1String("Pages:"))) {
            return line.mid(6).trimmed().toInt();
        }
    }
    return 0;
}

app::PatternSettings bigSheet() {
    app::PatternSettings settings;
    settings.sheetPreset = int(app::sheetPresets().size()) - 1; // custom
    settings.pattern.sheetSize = {2000.0, 2000.0};
    return settings;
}

long outlinePoints(const model::CuttingPattern& pattern) {
    long points = 0;
    for (const model::PatternPiece& piece : pattern.pieces) {
        points += static_cast<long>(piece.outline.size());
    }
    return points;
}

} // namespace

// The export dialog and the print path, driven without modal dialogs.
class TstPatternGui : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void init() { QSettings().clear(); }

    void dialogExportsEveryFormat() {
        const model::Project project = model::makeExample("cylinder");
        app::PatternExportDialog dialog(project, QStringLiteral("cylinder"), m_dir.path());
        dialog.setSettings(bigSheet());
        dialog.rebuildPattern();
        QCOMPARE(dialog.reportTable()->rowCount(), int(dialog.pattern().pieces.size()));
        QVERIFY(io::fabricationReport(dialog.pattern(), {}).pieces.front().fitsSheet);
        QCOMPARE(dialog.reportTable()->item(0, 5)->text(), app::PatternExportDialog::tr("yes"));
        QVERIFY(dialog.warningLabel()->isHidden());
        for (const char* format : {"dxf", "svg", "pdf", "fold"}) {
            dialog.formatBox()->setCurrentIndex(int(*io::patternFormatFromName(format)));
            const QString file = m_dir.filePath(QStringLiteral("dialog.") + format);
            QVERIFY2(dialog.exportTo(file), format);
            QVERIFY(QFileInfo(file).size() > 500);
        }
        // What the dialog wrote is the pattern it showed, read back by ezdxf.
        test::verifyDxf(test::readBackDxf(m_dir.filePath("dialog.dxf"), dialog.pattern(), 0.01,
                                          [](int) { return 0.0; }),
                        "AC1015", "LWPOLYLINE", 0.01);
        QVERIFY(pdfPages(m_dir.filePath("dialog.pdf")) >= 3);
        // The options are remembered for the next export and for printing.
        QCOMPARE(app::PatternSettings::load().format, io::PatternFormat::Fold);
        QCOMPARE(app::PatternSettings::load().pattern.sheetSize.x, 2000.0);
    }

    void dialogWarnsAboutProblemsBeforeWriting() {
        const model::Project project = model::makeExample("annulus");
        app::PatternExportDialog dialog(project, QStringLiteral("annulus"), m_dir.path());
        dialog.show(); // the warning's visibility is only meaningful on a shown dialog
        app::PatternSettings settings; // the 600 × 400 mm laser bed: the annulus does not fit
        dialog.setSettings(settings);
        dialog.rebuildPattern();
        QVERIFY(dialog.warningLabel()->isVisible());
        QVERIFY(!dialog.warningLabel()->text().isEmpty());
        QVERIFY(!io::fabricationReport(dialog.pattern(), {}).pieces.front().fitsSheet);
        QCOMPARE(dialog.reportTable()->item(0, 5)->text(), app::PatternExportDialog::tr("no"));
    }

    void fileMenuHasExportAndPrint() {
        app::MainWindow window;
        QAction* print = window.action(QStringLiteral("actionPrint"));
        QVERIFY(print != nullptr);
        QCOMPARE(print->shortcut(), QKeySequence(QKeySequence::Print));
        QVERIFY(window.action(QStringLiteral("actionPrintPreview")) != nullptr);
        QVERIFY(window.action(QStringLiteral("actionExportPattern")) != nullptr);
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        QVERIFY(print->isEnabled());
        // Ctrl+P is print only.
        for (QAction* action : window.findChildren<QAction*>()) {
            if (action != print && !action->shortcut().isEmpty()) {
                QVERIFY2(action->shortcut() != print->shortcut(), qPrintable(action->objectName()));
            }
        }
    }

    // Issue 46, 1: the export dialog never writes over the design's project file.
    void dialogRefusesTheProjectFile() {
        const model::Project project = model::makeExample("cylinder");
        const QString file = m_dir.filePath(QStringLiteral("cylinder.devsurf"));
        io::saveProjectFile(project, file, io::Backup::None);
        const QByteArray before = [&] {
            QFile in(file);
            return in.open(QIODevice::ReadOnly) ? in.readAll() : QByteArray();
        }();
        app::PatternExportDialog dialog(project, QStringLiteral("cylinder"), m_dir.path());
        dialog.setProjectFile(file);
        dialog.setSettings(bigSheet());
        dialog.rebuildPattern();
        bool answered = false;
        test::acceptNextMessageBox(answered);
        QVERIFY(!dialog.exportTo(file));
        QVERIFY(answered);
        QFile in(file);
        QVERIFY(in.open(QIODevice::ReadOnly));
        QCOMPARE(in.readAll(), before);
        QVERIFY(dialog.exportTo(m_dir.filePath(QStringLiteral("cylinder-pattern.out"))));
    }

    // Issue 46, 7: a design reaching 1 km away is sampled within the shared bound, to a coarser
    // tolerance the dialog names, instead of taking minutes at the one asked for.
    void farAwayDesignIsSampledWithinTheBound() {
        const model::Project far = test::farAnnulus();
        QVERIFY(far.surfaces.front().validate().empty());
        const auto over = model::pattern::oversampledSurface(far, 0.01);
        QVERIFY(over.has_value());
        QVERIFY(over->coarser > 0.01);
        app::PatternExportDialog dialog(far, QStringLiteral("far"), m_dir.path());
        QVERIFY(!dialog.pattern().pieces.empty());
        QVERIFY(!dialog.warningLabel()->isHidden());
        QVERIFY(!dialog.warningLabel()->text().isEmpty());
        // What was built is bounded: at 0.01 mm the outline alone had over 100,000 points.
        QVERIFY2(outlinePoints(dialog.pattern()) <= model::pattern::kMaxCurveSamples,
                 qPrintable(QString::number(outlinePoints(dialog.pattern()))));
        QCOMPARE(dialog.settings().write.tolerance, 0.01);
        QCOMPARE(dialog.samplingTolerance(), over->coarser);
        const QString svg = m_dir.filePath(QStringLiteral("far.svg"));
        dialog.formatBox()->setCurrentIndex(int(io::PatternFormat::Svg));
        QVERIFY(dialog.exportTo(svg));
        QVERIFY(QFileInfo(svg).size() > 500);
        // The development view samples by parameter, as the 3D view does: bounded as well.
        const views::SurfaceDevelopment shown =
            views::developSurfaceForView(far.surfaces.front(), 0);
        QVERIFY(!shown.pieces.empty());
        long shownPoints = 0;
        for (const model::PatternPiece& piece : shown.pieces) {
            shownPoints += static_cast<long>(piece.outline.size());
        }
        QVERIFY(shownPoints <= model::pattern::kMaxCurveSamples);
        // A design within the bound keeps the tolerance asked for.
        const model::Project near = model::makeExample("annulus");
        app::PatternExportDialog nearDialog(near, QStringLiteral("near"), m_dir.path());
        QCOMPARE(nearDialog.samplingTolerance(), 0.01);
    }

    void printingPaintsThroughQPrinter() {
        const model::CuttingPattern pattern =
            model::buildCuttingPattern(model::makeExample("annulus"), bigSheet().pattern);
        const QString file = m_dir.filePath(QStringLiteral("printed.pdf"));
        QPrinter printer(QPrinter::HighResolution);
        printer.setOutputFormat(QPrinter::PdfFormat);
        printer.setOutputFileName(file);
        printer.setPageSize(QPageSize(QPageSize::A4));
        QVERIFY(app::printCuttingPattern(printer, pattern, nullptr));
        // The 500 mm annulus on A4: report, overview and at least 3 × 3 tiles.
        QVERIFY(pdfPages(file) >= 11);
    }
};

DEVSURF_REGISTER_TEST(TstPatternGui);
#include "tst_pattern_gui.moc"
