// STEP and IGES curves through OpenCASCADE: every edge of what the file transfers (free curves
// and the edges of surfaces and solids alike), sampled within the chord tolerance.

#include "curve_import.h"
#include "io/occt_support.h"
#include "step_guard.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <OSD.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <QFile>

#include <cmath>
#include <csignal>
#include <exception>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <vector>

namespace devsurf::io {

namespace {

// OpenCASCADE's readers take their settings from one global table and report on standard
// output: one reader at a time, and only failures reported.
std::mutex& readerMutex() {
    static std::mutex mutex;
    return mutex;
}

// While OpenCASCADE reads, signals become its exceptions (a damaged file can make its
// translators dereference null; OCC_CATCH_SIGNALS then throws Standard_Failure); the previous
// handlers come back afterwards.
class SignalsAsExceptions {
public:
    SignalsAsExceptions() {
        for (int s = 1; s < kSignals; ++s) {
            sigaction(s, nullptr, &m_previous[s]);
        }
        OSD::SetSignal(OSD_SignalMode_Set, Standard_False);
        // OpenCASCADE leaves its handler by a long jump that does not restore the signal mask:
        // unblocked during the handler, a second fault in the same read is caught too. A cyclic
        // file makes its translators recurse until the stack overflows: the handler runs on a
        // stack of its own.
        m_stack.resize(kStackSize);
        stack_t stack = {};
        stack.ss_sp = m_stack.data();
        stack.ss_size = m_stack.size();
        m_hasStack = sigaltstack(&stack, &m_previousStack) == 0;
        for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) {
            struct sigaction action = {};
            if (sigaction(s, nullptr, &action) == 0) {
                action.sa_flags |= SA_NODEFER | (m_hasStack ? SA_ONSTACK : 0);
                sigaction(s, &action, nullptr);
            }
        }
    }
    ~SignalsAsExceptions() {
        for (int s = 1; s < kSignals; ++s) {
            if (s != SIGKILL && s != SIGSTOP) {
                sigaction(s, &m_previous[s], nullptr);
            }
        }
        if (m_hasStack) {
            sigaltstack(&m_previousStack, nullptr);
        }
    }
    SignalsAsExceptions(const SignalsAsExceptions&) = delete;
    SignalsAsExceptions& operator=(const SignalsAsExceptions&) = delete;

private:
    static constexpr int kSignals = 32;
    static constexpr std::size_t kStackSize = 256 * 1024;
    struct sigaction m_previous[kSignals] = {};
    std::vector<char> m_stack;
    stack_t m_previousStack = {};
    bool m_hasStack = false;
};
bool finite(const gp_Pnt& p) {
    return std::isfinite(p.X()) && std::isfinite(p.Y()) && std::isfinite(p.Z());
}

CurveImportResult readLocked(const QString& path, CurveFormat format,
                             const CurveImportOptions& options) {
    using Code = CurveImportError::Code;
    auto proceed = [&options](double fraction) {
        return !options.progress || options.progress(fraction);
    };
    if (!proceed(0.0)) {
        return curveImportFailure(Code::Cancelled);
    }
    std::unique_ptr<XSControl_Reader> reader;
    if (format == CurveFormat::Step) {
        STEPControl_Controller::Init();
        reader = std::make_unique<STEPControl_Reader>();
    } else {
        IGESControl_Controller::Init();
        reader = std::make_unique<IGESControl_Reader>();
    }
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    const QByteArray name = QFile::encodeName(path);
    if (reader->ReadFile(name.constData()) != IFSelect_RetDone) {
        return curveImportFailure(Code::Damaged, "OpenCASCADE could not read it");
    }
    if (!proceed(0.3)) {
        return curveImportFailure(Code::Cancelled);
    }
    Handle(OcctProgress) progress = new OcctProgress(options.progress, 0.3, 0.4);
    reader->TransferRoots(progress->Start());
    if (progress->cancelled()) {
        return curveImportFailure(Code::Cancelled);
    }
    const TopoDS_Shape shape = reader->OneShape();
    TopTools_IndexedMapOfShape edges;
    if (!shape.IsNull()) {
        TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    }
    CurveImportResult result;
    const double tolerance = options.tolerance > 0.0 ? options.tolerance : 0.05;
    for (int i = 1; i <= edges.Extent(); ++i) {
        if (!proceed(0.7 + 0.3 * (i - 1) / edges.Extent())) {
            return curveImportFailure(Code::Cancelled);
        }
        const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
        if (BRep_Tool::Degenerated(edge) || !BRep_Tool::IsGeometric(edge)) {
            ++result.skipped;
            continue;
        }
        try {
            OCC_CATCH_SIGNALS
            BRepAdaptor_Curve curve(edge);
            GCPnts_QuasiUniformDeflection sampling(curve, tolerance);
            if (!sampling.IsDone() || sampling.NbPoints() < 2 ||
                static_cast<std::size_t>(sampling.NbPoints()) > kMaxCurvePoints) {
                ++result.skipped;
                continue;
            }
            model::ReferenceCurve reference;
            reference.name = "Edge " + std::to_string(result.curves.size() + 1);
            bool ok = true;
            for (int k = 1; k <= sampling.NbPoints(); ++k) {
                const gp_Pnt p = sampling.Value(k);
                ok = ok && finite(p);
                reference.points.push_back({p.X(), p.Y(), p.Z()});
            }
            if (ok) {
                result.curves.push_back(std::move(reference));
            } else {
                ++result.skipped;
            }
        } catch (const Standard_Failure&) {
            ++result.skipped; // one bad edge does not spoil the others
        }
    }
    if (result.curves.empty()) {
        return curveImportFailure(Code::NoCurves);
    }
    if (!proceed(1.0)) {
        return curveImportFailure(Code::Cancelled);
    }
    return result;
}

} // namespace

CurveImportResult readCadCurves(const QString& path, CurveFormat format,
                                const CurveImportOptions& options) {
    if (format != CurveFormat::Step && format != CurveFormat::Iges) {
        return curveImportFailure(CurveImportError::Code::UnknownFormat);
    }
    if (format == CurveFormat::Step) {
        QFile file(path);
        if (file.open(QIODevice::ReadOnly)) {
            const QByteArray bytes = file.readAll();
            if (const std::optional<std::string> unsafe =
                    unsafeStepContent(std::string(bytes.constData(), bytes.size()))) {
                return curveImportFailure(CurveImportError::Code::Damaged, *unsafe);
            }
        }
    }
    const std::lock_guard<std::mutex> lock(readerMutex());
    quietOpenCascade();
    const SignalsAsExceptions signalGuard;
    try {
        OCC_CATCH_SIGNALS
        return readLocked(path, format, options);
    } catch (const Standard_Failure& error) {
        return curveImportFailure(CurveImportError::Code::Damaged,
                                  error.GetMessageString() ? error.GetMessageString() : "");
    } catch (const std::bad_alloc&) {
        return curveImportFailure(CurveImportError::Code::TooLarge, "not enough memory");
    } catch (const std::exception& error) {
        return curveImportFailure(CurveImportError::Code::Damaged, error.what());
    } catch (...) {
        return curveImportFailure(CurveImportError::Code::Damaged);
    }
}

} // namespace devsurf::io
