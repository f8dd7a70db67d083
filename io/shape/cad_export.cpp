#include "cad_export.h"

#include "patch_surfaces.h"

#include "io/occt_support.h"
#include "io/output_file.h"
#include "model/derived_geometry.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <IGESControl_Controller.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Pln.hxx>

#include <QFile>
#include <QTemporaryDir>

#include <algorithm>
#include <map>
#include <mutex>
#include <sstream>

namespace devsurf::io {

namespace {

using model::Vec3;

gp_Pnt toPnt(const Vec3& p) {
    return gp_Pnt(p.x, p.y, p.z);
}

Vec3 toVec(const gp_Pnt& p) {
    return {p.X(), p.Y(), p.Z()};
}

// The patch's exact B-spline: the poles of a in the row v = 0, of b in v = 1; the knot vector as
// OpenCASCADE keeps it, distinct values with their multiplicities.
TopoDS_Face ruledFace(const PatchSurface& patch) {
    const std::vector<double>& knots = patch.a.knots();
    std::vector<double> values;
    std::vector<int> multiplicities;
    for (double k : knots) {
        if (!values.empty() && k - values.back() <= 1e-14) {
            ++multiplicities.back();
        } else {
            values.push_back(k);
            multiplicities.push_back(1);
        }
    }
    TColStd_Array1OfReal uKnots(1, static_cast<int>(values.size()));
    TColStd_Array1OfInteger uMults(1, static_cast<int>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) {
        uKnots(static_cast<int>(i) + 1) = values[i];
        uMults(static_cast<int>(i) + 1) = multiplicities[i];
    }
    TColStd_Array1OfReal vKnots(1, 2);
    vKnots(1) = 0.0;
    vKnots(2) = 1.0;
    TColStd_Array1OfInteger vMults(1, 2);
    vMults.Init(2);
    const std::vector<Vec3>& a = patch.a.controlPoints();
    const std::vector<Vec3>& b = patch.b.controlPoints();
    TColgp_Array2OfPnt poles(1, static_cast<int>(a.size()), 1, 2);
    for (std::size_t i = 0; i < a.size(); ++i) {
        poles(static_cast<int>(i) + 1, 1) = toPnt(a[i]);
        poles(static_cast<int>(i) + 1, 2) = toPnt(b[i]);
    }
    Handle(Geom_BSplineSurface) surface =
        new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, patch.a.degree(), 1);
    BRepBuilderAPI_MakeFace face(surface, 0.0, 1.0, 0.0, 1.0, Precision::Confusion());
    if (!face.IsDone()) {
        throw ShapeExportError(ShapeExportError::Code::BadSurface, patch.surface, patch.face);
    }
    TopoDS_Face result = face.Face();
    if (patch.flipped) {
        result.Reverse();
    }
    return result;
}

// A planar patch: its plane, oriented by the loop (Newell's normal), bounded by the polygon.
TopoDS_Face planarFace(const PatchSurface& patch) {
    Vec3 normal;
    const std::size_t n = patch.corners.size();
    BRepBuilderAPI_MakePolygon polygon;
    for (std::size_t i = 0; i < n; ++i) {
        normal += model::cross(patch.corners[i], patch.corners[(i + 1) % n]);
        polygon.Add(toPnt(patch.corners[i]));
    }
    polygon.Close();
    if (!polygon.IsDone() || normal.norm() == 0.0) {
        throw ShapeExportError(ShapeExportError::Code::BadSurface, patch.surface, patch.face);
    }
    const gp_Pln plane(toPnt(patch.corners.front()), gp_Dir(normal.x, normal.y, normal.z));
    BRepBuilderAPI_MakeFace face(plane, polygon.Wire(), Standard_True);
    if (!face.IsDone()) {
        throw ShapeExportError(ShapeExportError::Code::BadSurface, patch.surface, patch.face);
    }
    return face.Face();
}
// The design's vertices sorted by x, to find the vertex at a point of the sewn shape.
class VertexFinder {
public:
    VertexFinder(const model::CompositeSurface& surface, double tolerance)
        : m_tolerance(tolerance) {
        for (const auto& [id, position] : surface.vertices()) {
            m_sorted.push_back({position, id});
        }
        std::sort(m_sorted.begin(), m_sorted.end(),
                  [](const Entry& l, const Entry& r) { return l.position.x < r.position.x; });
    }
    model::VertexId at(const Vec3& p) const {
        auto it = std::lower_bound(m_sorted.begin(), m_sorted.end(), p.x - m_tolerance,
                                   [](const Entry& e, double x) { return e.position.x < x; });
        model::VertexId best = model::kInvalidId;
        double bestDistance = m_tolerance;
        for (; it != m_sorted.end() && it->position.x <= p.x + m_tolerance; ++it) {
            const double d = (it->position - p).norm();
            if (d <= bestDistance) {
                bestDistance = d;
                best = it->id;
            }
        }
        return best;
    }

private:
    struct Entry {
        Vec3 position;
        model::VertexId id;
    };
    double m_tolerance;
    std::vector<Entry> m_sorted;
};

Vec3 edgeMidpoint(const TopoDS_Edge& edge) {
    BRepAdaptor_Curve curve(edge);
    return toVec(curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter())));
}

// The edges of the sewn shape by the design's edge they lie on (found by their end vertices).
std::map<model::EdgeId, std::vector<TopoDS_Edge>>
edgesByDesignEdge(const TopoDS_Shape& sewn, const model::CompositeSurface& surface,
                  double tolerance, TopTools_IndexedDataMapOfShapeListOfShape& facesOfEdge) {
    TopExp::MapShapesAndAncestors(sewn, TopAbs_EDGE, TopAbs_FACE, facesOfEdge);
    const VertexFinder finder(surface, tolerance);
    std::map<model::EdgeId, std::vector<TopoDS_Edge>> result;
    for (int i = 1; i <= facesOfEdge.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(facesOfEdge.FindKey(i));
        if (BRep_Tool::Degenerated(edge)) {
            continue;
        }
        TopoDS_Vertex first;
        TopoDS_Vertex last;
        TopExp::Vertices(edge, first, last);
        if (first.IsNull() || last.IsNull()) {
            continue;
        }
        const model::VertexId from = finder.at(toVec(BRep_Tool::Pnt(first)));
        const model::VertexId to = finder.at(toVec(BRep_Tool::Pnt(last)));
        if (from == model::kInvalidId || to == model::kInvalidId) {
            continue;
        }
        const model::EdgeId id = surface.edgeBetween(from, to);
        if (id != model::kInvalidId) {
            result[id].push_back(edge);
        }
    }
    return result;
}

struct SewnSurface {
    TopoDS_Shape shape;
    std::vector<std::pair<TopoDS_Face, std::string>> faceNames;
    std::vector<std::pair<TopoDS_Edge, std::string>> edgeNames;
    CadExportSurface report;
};

SewnSurface sewSurface(const model::CompositeSurface& surface, bool severalSurfaces,
                       double tolerance, const CadExportOptions& options, double done,
                       double share) {
    SewnSurface result;
    result.report.surface = surface.id();
    const std::vector<PatchSurface> patches = patchSurfaces(surface);
    std::vector<TopoDS_Face> faces;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        const PatchSurface& patch = patches[i];
        try {
            faces.push_back(patch.isPlanar() ? planarFace(patch) : ruledFace(patch));
        } catch (const Standard_Failure&) {
            throw ShapeExportError(ShapeExportError::Code::BadSurface, patch.surface, patch.face);
        }
        if (options.progress && !options.progress(done + 0.3 * share * static_cast<double>(i + 1) /
                                                             static_cast<double>(patches.size()))) {
            throw ShapeExportError(ShapeExportError::Code::Cancelled);
        }
    }
    result.report.faces = faces.size();

    BRepBuilderAPI_Sewing sewing(tolerance);
    for (const TopoDS_Face& face : faces) {
        sewing.Add(face);
    }
    Handle(OcctProgress) progress =
        new OcctProgress(options.progress, done + 0.3 * share, 0.7 * share);
    sewing.Perform(progress->Start());
    if (progress->cancelled()) {
        throw ShapeExportError(ShapeExportError::Code::Cancelled);
    }
    result.shape = sewing.SewedShape();
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const TopoDS_Shape sewnFace =
            sewing.IsModified(faces[i]) ? sewing.Modified(faces[i]) : faces[i];
        if (!sewnFace.IsNull() && sewnFace.ShapeType() == TopAbs_FACE) {
            result.faceNames.emplace_back(TopoDS::Face(sewnFace),
                                          patchName(patches[i], severalSurfaces));
        }
    }
    for (TopExp_Explorer shells(result.shape, TopAbs_SHELL); shells.More(); shells.Next()) {
        ++result.report.shells;
        result.report.closedShell = BRep_Tool::IsClosed(shells.Current());
    }
    TopExp_Explorer looseFaces(result.shape, TopAbs_FACE, TopAbs_SHELL);
    if (result.report.shells != 1 || looseFaces.More()) {
        result.report.closedShell = false;
    }

    // The seams: every design edge of two patches should be one edge of two faces.
    TopTools_IndexedDataMapOfShapeListOfShape facesOfEdge;
    const auto edges = edgesByDesignEdge(result.shape, surface, tolerance * 10.0, facesOfEdge);
    result.report.closedDesign = true;
    for (const auto& [id, record] : surface.edges()) {
        const std::size_t designFaces = surface.facesOfEdge(id).size();
        if (designFaces < 2) {
            result.report.closedDesign = false;
            continue;
        }
        const auto found = edges.find(id);
        bool sewn = found != edges.end() && found->second.size() == 1 &&
                    facesOfEdge.FindFromKey(found->second.front()).Extent() == 2;
        if (!sewn) {
            UnsewnEdge unsewn{surface.id(), id, 0.0};
            if (found != edges.end() && found->second.size() >= 2) {
                unsewn.gap =
                    (edgeMidpoint(found->second[0]) - edgeMidpoint(found->second[1])).norm();
            }
            result.report.unsewn.push_back(unsewn);
        }
    }
    // Mountain and valley creases by name (the crease table of the derived geometry).
    const auto derived = model::DerivedGeometry::of(surface, 8);
    for (const model::Crease& crease : derived->creases()) {
        if (crease.assignment == model::FoldAssignment::Flat) {
            continue;
        }
        const auto found = edges.find(crease.edge);
        if (found == edges.end() || found->second.size() != 1) {
            continue;
        }
        std::string name =
            "crease " + std::to_string(crease.edge) +
            (crease.assignment == model::FoldAssignment::Mountain ? " mountain" : " valley");
        if (severalSurfaces) {
            name = "surface " + std::to_string(surface.id()) + " " + name;
        }
        result.edgeNames.emplace_back(found->second.front(), name);
        ++result.report.namedCreases;
    }
    return result;
}

TCollection_ExtendedString extended(const std::string& text) {
    return TCollection_ExtendedString(text.c_str(), Standard_True);
}

// The XCAF document: one top-level shape per surface with its name, its faces and named creases
// as named sub-shapes.
Handle(TDocStd_Document)
    cadDocument(const model::Project& project, const std::vector<SewnSurface>& sewn) {
    Handle(TDocStd_Document) document;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
    for (std::size_t i = 0; i < sewn.size(); ++i) {
        const TDF_Label label = shapes->AddShape(sewn[i].shape, Standard_False);
        const std::string& name = project.surfaces[i].name();
        TDataStd_Name::Set(
            label,
            extended(name.empty() ? "surface " + std::to_string(project.surfaces[i].id()) : name));
        for (const auto& [face, faceName] : sewn[i].faceNames) {
            const TDF_Label sub = shapes->AddSubShape(label, face);
            if (!sub.IsNull()) {
                TDataStd_Name::Set(sub, extended(faceName));
            }
        }
        for (const auto& [edge, edgeName] : sewn[i].edgeNames) {
            const TDF_Label sub = shapes->AddSubShape(label, edge);
            if (!sub.IsNull()) {
                TDataStd_Name::Set(sub, extended(edgeName));
            }
        }
    }
    return document;
}

// The application keeps every document it made until it is closed, also when writing fails.
struct OpenDocument {
    explicit OpenDocument(Handle(TDocStd_Document) document) : handle(std::move(document)) {}
    ~OpenDocument() { XCAFApp_Application::GetApplication()->Close(handle); }
    OpenDocument(const OpenDocument&) = delete;
    OpenDocument& operator=(const OpenDocument&) = delete;
    Handle(TDocStd_Document) handle;
};

// OpenCASCADE's writers take their settings from one global table.
std::mutex& writerSettingsMutex() {
    static std::mutex mutex;
    return mutex;
}

QByteArray stepBytes(const Handle(TDocStd_Document) & document, CadFormat format) {
    STEPCAFControl_Controller::Init();
    Interface_Static::SetCVal("write.step.schema",
                              format == CadFormat::StepAP214 ? "AP214IS" : "AP242DIS");
    Interface_Static::SetCVal("write.step.unit", "MM");
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    Interface_Static::SetIVal("write.stepcaf.subshapes.name", 1);
    STEPCAFControl_Writer writer;
    writer.SetNameMode(Standard_True);
    if (!writer.Transfer(document, STEPControl_AsIs)) {
        throw ShapeExportError(ShapeExportError::Code::Translate);
    }
    // The STEP writer of OpenCASCADE 7.6 writes to a path only: a private temporary file.
    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("shape.step"));
    if (!folder.isValid() || writer.Write(path.toLocal8Bit().constData()) != IFSelect_RetDone) {
        throw ShapeExportError(ShapeExportError::Code::Translate);
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        throw ShapeExportError(ShapeExportError::Code::Translate);
    }
    return file.readAll();
}

QByteArray igesBytes(const Handle(TDocStd_Document) & document) {
    IGESControl_Controller::Init();
    Interface_Static::SetCVal("write.iges.unit", "MM");
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    // Faces in shells (type 514) rather than loose trimmed surfaces: readers get the sewing.
    Interface_Static::SetIVal("write.iges.brep.mode", 1);
    IGESCAFControl_Writer writer;
    writer.SetNameMode(Standard_True);
    if (!writer.Transfer(document)) {
        throw ShapeExportError(ShapeExportError::Code::Translate);
    }
    std::ostringstream stream;
    if (!writer.Write(stream)) {
        throw ShapeExportError(ShapeExportError::Code::Translate);
    }
    const std::string text = stream.str();
    return QByteArray(text.data(), static_cast<int>(text.size()));
}

} // namespace

std::size_t CadExportResult::faces() const {
    std::size_t count = 0;
    for (const CadExportSurface& s : surfaces) {
        count += s.faces;
    }
    return count;
}

bool CadExportResult::sewn() const {
    return std::all_of(surfaces.begin(), surfaces.end(),
                       [](const CadExportSurface& s) { return s.unsewn.empty(); });
}

CadExportResult saveCadFile(const model::Project& project, const QString& path,
                            const CadExportOptions& options) {
    if (project.surfaces.empty()) {
        throw ShapeExportError(ShapeExportError::Code::NoSurface);
    }
    CadExportResult result;
    result.sewingTolerance = options.sewingTolerance > 0.0
                                 ? options.sewingTolerance
                                 : std::max(1e-6 * projectDiameter(project), 1e-7);
    std::vector<SewnSurface> sewn;
    const double share = 0.9 / static_cast<double>(project.surfaces.size());
    for (std::size_t i = 0; i < project.surfaces.size(); ++i) {
        sewn.push_back(sewSurface(project.surfaces[i], project.surfaces.size() > 1,
                                  result.sewingTolerance, options, share * static_cast<double>(i),
                                  share));
        result.surfaces.push_back(sewn.back().report);
    }
    QByteArray bytes;
    {
        const std::lock_guard<std::mutex> lock(writerSettingsMutex());
        quietOpenCascade();
        try {
            const OpenDocument document(cadDocument(project, sewn));
            bytes = options.format == CadFormat::Iges ? igesBytes(document.handle)
                                                      : stepBytes(document.handle, options.format);
        } catch (const Standard_Failure&) {
            throw ShapeExportError(ShapeExportError::Code::Translate);
        }
    }
    if (options.progress && !options.progress(1.0)) {
        throw ShapeExportError(ShapeExportError::Code::Cancelled);
    }
    writeFileAtomically(path, bytes);
    return result;
}

bool cadFormatFromName(const std::string& name, CadFormat& format) {
    if (name == "step" || name == "stp" || name == "step242") {
        format = CadFormat::StepAP242;
    } else if (name == "step214") {
        format = CadFormat::StepAP214;
    } else if (name == "iges" || name == "igs") {
        format = CadFormat::Iges;
    } else {
        return false;
    }
    return true;
}

} // namespace devsurf::io
