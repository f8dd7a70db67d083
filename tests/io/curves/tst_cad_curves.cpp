// STEP and IGES curves written by OpenCASCADE in the test (a B-spline and a circle as free
// edges) read back through the import; damaged files give an error, never a crash.

#include "curve_test_util.h"
#include "test_registry.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax2.hxx>

#include <QTemporaryDir>
#include <QTest>

#include <chrono>
#include <regex>

using namespace devsurf;
using devsurf::model::distance;
using model::Vec3;

namespace {

constexpr double kCadTolerance = 0.05;

// C(t) = (30t, 30t², 30t³), t in [0, 1], as a cubic Bezier (a B-spline of one span).
Vec3 cubic(double t) {
    return {30 * t, 30 * t * t, 30 * t * t * t};
}

TopoDS_Compound curves() {
    TColgp_Array1OfPnt poles(1, 4);
    poles(1) = gp_Pnt(0, 0, 0);
    poles(2) = gp_Pnt(10, 0, 0);
    poles(3) = gp_Pnt(20, 10, 0);
    poles(4) = gp_Pnt(30, 30, 30);
    TColStd_Array1OfReal knots(1, 2);
    knots(1) = 0;
    knots(2) = 1;
    TColStd_Array1OfInteger multiplicities(1, 2);
    multiplicities(1) = 4;
    multiplicities(2) = 4;
    Handle(Geom_BSplineCurve) spline = new Geom_BSplineCurve(poles, knots, multiplicities, 3);
    // A circle of radius 25 about (100, 100, 10) in a plane tilted about x.
    Handle(Geom_Circle) circle =
        new Geom_Circle(gp_Ax2(gp_Pnt(100, 100, 10), gp_Dir(0, 1, 1)), 25.0);
    BRep_Builder builder;
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    builder.Add(compound, BRepBuilderAPI_MakeEdge(spline).Edge());
    builder.Add(compound, BRepBuilderAPI_MakeEdge(circle).Edge());
    return compound;
}

bool writeStep(const QString& path) {
    STEPControl_Controller::Init();
    Interface_Static::SetCVal("write.step.unit", "MM");
    STEPControl_Writer writer;
    if (writer.Transfer(curves(), STEPControl_AsIs) != IFSelect_RetDone) {
        return false;
    }
    return writer.Write(path.toLocal8Bit().constData()) == IFSelect_RetDone;
}

bool writeIges(const QString& path) {
    IGESControl_Controller::Init();
    IGESControl_Writer writer("MM", 0);
    writer.AddShape(curves());
    writer.ComputeModel();
    return writer.Write(path.toLocal8Bit().constData());
}

} // namespace

class TstCadCurves : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    void checkCurves(const QString& path) {
        const io::CurveImportResult result = io::importCurveFile(path, {kCadTolerance, {}});
        QVERIFY2(!result.error, result.error ? result.error->detail.c_str() : "");
        QCOMPARE(result.curves.size(), std::size_t(2));
        const model::ReferenceCurve* spline = nullptr;
        const model::ReferenceCurve* circle = nullptr;
        for (const model::ReferenceCurve& curve : result.curves) {
            (distance(curve.points.front(), curve.points.back()) < 1e-6 ? circle : spline) = &curve;
        }
        QVERIFY(spline != nullptr && circle != nullptr);
        QVERIFY(spline->points.size() >= 3);
        for (const Vec3& p : spline->points) {
            QVERIFY2(distance(p, cubic(p.x / 30.0)) < 1e-6, qPrintable(QString::number(p.x)));
        }
        // Chords within the tolerance (of the closest point of a fine search).
        for (std::size_t i = 0; i + 1 < spline->points.size(); ++i) {
            const Vec3 middle = (spline->points[i] + spline->points[i + 1]) * 0.5;
            double best = 1e300;
            for (int k = 0; k <= 20000; ++k) {
                best = std::min(best, distance(middle, cubic(k / 20000.0)));
            }
            QVERIFY2(best <= kCadTolerance * 1.01, qPrintable(QString::number(best)));
        }
        const Vec3 centre(100, 100, 10);
        const Vec3 normal(0, std::sqrt(0.5), std::sqrt(0.5));
        QVERIFY(circle->points.size() >= 8);
        for (const Vec3& p : circle->points) {
            QVERIFY(std::abs(distance(p, centre) - 25.0) < 1e-6);
            const Vec3 d = p - centre;
            QVERIFY(std::abs(d.x * normal.x + d.y * normal.y + d.z * normal.z) < 1e-6);
        }
    }

    void fuzz(const QString& good, const QString& suffix, int total) {
        // The writer stamps the time into a STEP file's header: fixed here, so that every run
        // damages the same bytes the same way.
        const std::string bytes = std::regex_replace(
            test::readBytes(good), std::regex("'[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9:]{8}'"),
            "'2026-01-01T00:00:00'");
        QVERIFY(!bytes.empty());
        std::mt19937 rng(4242);
        int failed = 0;
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < total; ++i) {
            const QString path = m_dir.filePath(QStringLiteral("damaged%1.%2").arg(i).arg(suffix));
            QVERIFY(test::writeBytes(path, test::mutated(bytes, rng, i)));
            const io::CurveImportResult r = io::importCurveFile(path, {kCadTolerance, {}});
            if (r.error) {
                QVERIFY(r.curves.empty());
                ++failed;
            }
            for (const model::ReferenceCurve& curve : r.curves) {
                QVERIFY(curve.points.size() >= 2);
            }
            QFile::remove(path);
        }
        QVERIFY(failed > 0);
        qInfo("%d damaged %s files: %d refused (%lld ms)", total, qPrintable(suffix), failed,
              static_cast<long long>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                         std::chrono::steady_clock::now() - start)
                                         .count()));
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        // The writers' statistics are not part of the test's output.
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
        QVERIFY(writeStep(m_dir.filePath(QStringLiteral("curves.step"))));
        QVERIFY(writeIges(m_dir.filePath(QStringLiteral("curves.igs"))));
    }

    void stepCurvesLieOnTheirCurves() {
        checkCurves(m_dir.filePath(QStringLiteral("curves.step")));
    }

    void igesCurvesLieOnTheirCurves() { checkCurves(m_dir.filePath(QStringLiteral("curves.igs"))); }

    void progressAndCancel() {
        std::vector<double> fractions;
        io::CurveImportOptions options;
        options.progress = [&fractions](double f) {
            fractions.push_back(f);
            return true;
        };
        QVERIFY(!io::importCurveFile(m_dir.filePath(QStringLiteral("curves.step")), options).error);
        QVERIFY(fractions.size() >= 3);
        QCOMPARE(fractions.back(), 1.0);
        for (double stopAt : {0.0, 0.3, 0.8}) {
            options.progress = [stopAt](double f) { return f < stopAt; };
            const io::CurveImportResult r =
                io::importCurveFile(m_dir.filePath(QStringLiteral("curves.igs")), options);
            QVERIFY(r.error && r.error->code == io::CurveImportError::Code::Cancelled);
        }
    }

    void notCadFilesAreRefused() {
        const QString path = m_dir.filePath(QStringLiteral("text.stp"));
        QVERIFY(test::writeBytes(path, "this is not a STEP file\n"));
        const io::CurveImportResult r = io::importCurveFile(path);
        QVERIFY(r.error && r.curves.empty());
    }

    void stepEntityDefinedTwiceIsRefused() {
        // A DATA section numbering two instances alike (#76 renumbered #70, as one damaged
        // file of the fuzzing below had it) made OpenCASCADE loop forever: refused at once.
        std::string bytes = test::readBytes(m_dir.filePath(QStringLiteral("curves.step")));
        const std::size_t second = bytes.find("\n#2 =");
        QVERIFY(second != std::string::npos);
        bytes.replace(second, 5, "\n#1 =");
        const QString path = m_dir.filePath(QStringLiteral("twice.step"));
        QVERIFY(test::writeBytes(path, bytes));
        const auto start = std::chrono::steady_clock::now();
        const io::CurveImportResult r = io::importCurveFile(path);
        QVERIFY(r.error && r.error->code == io::CurveImportError::Code::Damaged);
        QVERIFY2(r.error->detail.find("#1 is defined twice") != std::string::npos,
                 r.error->detail.c_str());
        QVERIFY(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
        // Strings and comments may hold anything: a file whose only '#1 =' besides the
        // instance is inside a string and a comment is read.
        std::string quoted = test::readBytes(m_dir.filePath(QStringLiteral("curves.step")));
        const std::size_t data = quoted.find("DATA;");
        QVERIFY(data != std::string::npos);
        quoted.insert(data + 5, "\n/* ;#1 = x; */");
        const QString commented = m_dir.filePath(QStringLiteral("commented.step"));
        QVERIFY(test::writeBytes(commented, quoted));
        const io::CurveImportResult ok = io::importCurveFile(commented);
        QVERIFY2(!ok.error, ok.error ? ok.error->detail.c_str() : "");
    }

    void damagedStepNeverCrashes() {
        fuzz(m_dir.filePath(QStringLiteral("curves.step")), QStringLiteral("step"), 150);
    }

    void damagedIgesNeverCrashes() {
        fuzz(m_dir.filePath(QStringLiteral("curves.igs")), QStringLiteral("igs"), 150);
    }
};

DEVSURF_REGISTER_TEST(TstCadCurves);
#include "tst_cad_curves.moc"
