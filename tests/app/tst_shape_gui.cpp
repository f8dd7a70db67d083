#include "io/project_file.h"
#include "main_window.h"
#include "model/examples.h"
#include "model/project.h"
#include "shape_export_dialog.h"
#include "test_registry.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

// File ▸ Export 3D Shape…: the action, the dialog's options, writing and refusing.
class TstShapeGui : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void actionFollowsTheDesign() {
        app::MainWindow window;
        QAction* action = window.action(QStringLiteral("actionExportShape"));
        QVERIFY(action != nullptr);
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        QVERIFY(action->isEnabled());
    }

    void everyFormat() {
        const model::Project project = model::makeExample("fig8");
        app::ShapeExportDialog dialog(project, QStringLiteral("fig8"), m_dir.path());
        for (int format = app::ShapeExportDialog::StepAP242; format <= app::ShapeExportDialog::Ply;
             ++format) {
            dialog.formatBox()->setCurrentIndex(format);
            const bool mesh = format >= app::ShapeExportDialog::Obj;
            QCOMPARE(dialog.toleranceBox()->isEnabled(), mesh);
            QCOMPARE(dialog.thicknessBox()->isEnabled(), mesh);
            const QString path =
                m_dir.filePath(QStringLiteral("fig8-%1.").arg(format) +
                               app::ShapeExportDialog::extensionFor(
                                   static_cast<app::ShapeExportDialog::Format>(format)));
            QVERIFY(dialog.exportTo(path));
            QVERIFY(QFileInfo(path).size() > 1000);
            QVERIFY(!dialog.summary().isEmpty());
        }
    }

    // The design's own project file is never overwritten: one message, the file unchanged.
    void refusesTheProjectFile() {
        const model::Project project = model::makeExample("cylinder");
        const QString file = m_dir.filePath(QStringLiteral("cylinder.devsurf"));
        io::saveProjectFile(project, file, io::Backup::None);
        QFile in(file);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray before = in.readAll();
        in.close();
        app::ShapeExportDialog dialog(project, QStringLiteral("cylinder"), m_dir.path());
        dialog.setProjectFile(file);
        dialog.formatBox()->setCurrentIndex(app::ShapeExportDialog::Stl);
        bool answered = false;
        test::acceptNextMessageBox(answered);
        QVERIFY(!dialog.exportTo(file));
        QVERIFY(answered);
        QVERIFY(in.open(QIODevice::ReadOnly));
        QCOMPARE(in.readAll(), before);
    }
};

DEVSURF_REGISTER_TEST(TstShapeGui);

#include "tst_shape_gui.moc"
