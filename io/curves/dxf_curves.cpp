// DXF curves through dxflib: LINE, POLYLINE (2D and 3D), LWPOLYLINE (with elevation and
// bulges), SPLINE, ARC and CIRCLE, each entity one curve, in the file's units scaled to mm.

#include "curve_import.h"
#include "curve_sampling.h"
#include "dxf_guard.h"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <cmath>
#include <exception>
#include <istream>
#include <new>
#include <streambuf>

namespace devsurf::io {

using model::ReferenceCurve;
using model::Vec3;

namespace {

Vec3 unit(const Vec3& v) {
    const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return n > 0.0 ? v / n : Vec3(0, 0, 1);
}

// A planar entity's object coordinate system: DXF's arbitrary axis algorithm.
struct Ocs {
    Vec3 x{1, 0, 0};
    Vec3 y{0, 1, 0};
    Vec3 z{0, 0, 1};
    explicit Ocs(const Vec3& normal) {
        z = unit(normal);
        const bool nearPole = std::abs(z.x) < 1.0 / 64 && std::abs(z.y) < 1.0 / 64;
        x = unit(cross(nearPole ? Vec3(0, 1, 0) : Vec3(0, 0, 1), z));
        y = unit(cross(z, x));
    }
    Vec3 toWorld(const Vec3& p) const { return x * p.x + y * p.y + z * p.z; }
};

// The file's $INSUNITS in mm (unitless and unknown units: 1).
double millimetresPer(int insunits) {
    switch (insunits) {
    case 1:
        return 25.4;
    case 2:
        return 304.8;
    case 4:
        return 1.0;
    case 5:
        return 10.0;
    case 6:
        return 1000.0;
    case 8:
        return 25.4e-6;
    case 9:
        return 0.0254;
    case 10:
        return 914.4;
    case 14:
        return 100.0;
    default:
        return 1.0;
    }
}

// Serves the bytes to dxflib in chunks, reporting progress per chunk; a cancel ends the
// stream, so dxflib stops at the next read.
class ProgressBuffer : public std::streambuf {
public:
    ProgressBuffer(const std::string& bytes, const std::function<bool(double)>& progress)
        : m_bytes(bytes), m_progress(progress) {}
    bool cancelled() const { return m_cancelled; }

protected:
    int_type underflow() override {
        if (m_position >= m_bytes.size() || m_cancelled) {
            return traits_type::eof();
        }
        if (m_progress && !m_progress(0.9 * static_cast<double>(m_position) /
                                      static_cast<double>(m_bytes.size()))) {
            m_cancelled = true;
            return traits_type::eof();
        }
        const std::size_t size = std::min<std::size_t>(kChunk, m_bytes.size() - m_position);
        char* begin = const_cast<char*>(m_bytes.data()) + m_position;
        setg(begin, begin, begin + size);
        m_position += size;
        return traits_type::to_int_type(*gptr());
    }

private:
    static constexpr std::size_t kChunk = 64 * 1024;
    const std::string& m_bytes;
    const std::function<bool(double)>& m_progress;
    std::size_t m_position = 0;
    bool m_cancelled = false;
};

// Collects the curves dxflib reports. A polyline's vertices and a spline's points arrive after
// the entity itself, so each is finished when the next entity (or the end) comes.
class CurveCollector : public DL_CreationAdapter {
public:
    explicit CurveCollector(double tolerance) : m_tolerance(tolerance) {}

    void setVariableInt(const std::string& key, int value, int) override {
        if (key == "$INSUNITS") {
            m_scale = millimetresPer(value);
        }
    }
    void addBlock(const DL_BlockData&) override {
        finish();
        m_inBlock = true; // block definitions are drawn only where inserted
    }
    void endBlock() override {
        finish();
        m_inBlock = false;
    }
    void endEntity() override { finish(); }
    void endSequence() override { finish(); }

    void addLine(const DL_LineData& d) override {
        if (begin()) {
            add("LINE", {{d.x1, d.y1, d.z1}, {d.x2, d.y2, d.z2}});
        }
    }
    void addArc(const DL_ArcData& d) override {
        if (begin()) {
            double a0 = d.angle1 * M_PI / 180.0;
            double a1 = d.angle2 * M_PI / 180.0;
            while (std::isfinite(a1) && std::isfinite(a0) && a1 <= a0 && a0 - a1 < 1e6) {
                a1 += 2 * M_PI;
            }
            circle("ARC", {d.cx, d.cy, d.cz}, d.radius, a0, a1);
        }
    }
    void addCircle(const DL_CircleData& d) override {
        if (begin()) {
            circle("CIRCLE", {d.cx, d.cy, d.cz}, d.radius, 0.0, 2 * M_PI);
        }
    }
    // An ellipse (or an arc of one) in world coordinates: centre, major axis as a vector, the
    // minor axis ratio times as long, turned by 90° about the extrusion; angles are parameters.
    void addEllipse(const DL_EllipseData& d) override {
        if (!begin()) {
            return;
        }
        const Vec3 centre{d.cx, d.cy, d.cz};
        const Vec3 major{d.mx, d.my, d.mz};
        const double a = major.norm();
        double t0 = d.angle1, t1 = d.angle2;
        while (std::isfinite(t0) && std::isfinite(t1) && t1 <= t0 && t0 - t1 < 1e6) {
            t1 += 2 * M_PI;
        }
        if (!centre.isFinite() || !(a > 0.0) || !std::isfinite(a) || !(d.ratio > 0.0) ||
            !(d.ratio <= 1.0) || !std::isfinite(t0) || !(t1 > t0) || t1 - t0 > 2 * M_PI + 1e-9) {
            ++m_skipped;
            return;
        }
        const Vec3 minor = cross(Ocs(extrusion()).z, major) * d.ratio;
        // Chords of the circle of radius a (the largest radius of curvature's bound on the
        // second derivative) stray no farther than the tolerance.
        const std::vector<Vec3> circle =
            sampleArc(Vec3(0, 0, 0), 1.0, Vec3(1, 0, 0), Vec3(0, 1, 0), t0, t1,
                      std::min(m_tolerance / m_scale / a, 1.0));
        std::vector<Vec3> points;
        points.reserve(circle.size());
        for (const Vec3& c : circle) {
            points.push_back(centre + major * c.x + minor * c.y);
        }
        add("ELLIPSE", std::move(points));
    }
    void addPolyline(const DL_PolylineData& d) override {
        if (!begin()) {
            return;
        }
        m_polyline = Polyline{};
        m_polyline->layer = getAttributes().getLayer();
        m_polyline->flags = d.flags;
        m_polyline->elevation = d.elevation;
        m_polyline->ocs = Ocs(extrusion());
    }
    void addVertex(const DL_VertexData& d) override {
        if (m_polyline) {
            m_polyline->vertices.push_back({d.x, d.y, d.z});
            m_polyline->bulges.push_back(d.bulge);
        }
    }
    void addSpline(const DL_SplineData& d) override {
        if (!begin()) {
            return;
        }
        m_spline = Spline{};
        m_spline->layer = getAttributes().getLayer();
        m_spline->nurbs.degree = static_cast<int>(std::min(d.degree, 100u));
    }
    void addControlPoint(const DL_ControlPointData& d) override {
        if (m_spline) {
            m_spline->nurbs.controlPoints.push_back({d.x, d.y, d.z});
            m_spline->nurbs.weights.push_back(d.w);
        }
    }
    void addKnot(const DL_KnotData& d) override {
        if (m_spline) {
            m_spline->nurbs.knots.push_back(d.k);
        }
    }
    void addFitPoint(const DL_FitPointData& d) override {
        if (m_spline) {
            m_spline->fitPoints.push_back({d.x, d.y, d.z});
        }
    }
    // Everything else that is an entity ends the pending one and is not a curve.
    void addPoint(const DL_PointData&) override { other(); }
    void addInsert(const DL_InsertData&) override { other(); }
    void addText(const DL_TextData&) override { other(); }
    void addMText(const DL_MTextData&) override { other(); }
    void addSolid(const DL_SolidData&) override { other(); }
    void add3dFace(const DL_3dFaceData&) override { other(); }
    void addHatch(const DL_HatchData&) override { other(); }
    void addXLine(const DL_XLineData&) override { other(); }
    void addRay(const DL_RayData&) override { other(); }

    // Ends the last entity and scales everything to mm.
    std::vector<ReferenceCurve> takeCurves() {
        finish();
        for (ReferenceCurve& curve : m_curves) {
            for (Vec3& p : curve.points) {
                p *= m_scale;
            }
        }
        return std::move(m_curves);
    }
    int skipped() const { return m_skipped; }

private:
    struct Polyline {
        std::string layer;
        int flags = 0;
        double elevation = 0.0;
        Ocs ocs{Vec3(0, 0, 1)};
        std::vector<Vec3> vertices;
        std::vector<double> bulges;
    };
    struct Spline {
        std::string layer;
        Nurbs nurbs;
        std::vector<Vec3> fitPoints;
    };

    // Finishes the pending entity; false inside a block definition (the entity is ignored).
    bool begin() {
        finish();
        return !m_inBlock;
    }
    void other() {
        if (begin()) {
            ++m_skipped;
        }
    }
    Vec3 extrusion() {
        const DL_Extrusion* e = getExtrusion();
        if (e == nullptr || e->getDirection() == nullptr) {
            return {0, 0, 1};
        }
        const double* d = e->getDirection();
        const Vec3 n(d[0], d[1], d[2]);
        return n.isFinite() && (n.x != 0 || n.y != 0 || n.z != 0) ? n : Vec3(0, 0, 1);
    }

    void add(const char* type, std::vector<Vec3> points, std::string layer = {}) {
        bool ok = points.size() >= 2;
        for (const Vec3& p : points) {
            ok = ok && p.isFinite();
        }
        if (!ok) {
            ++m_skipped;
            return;
        }
        ReferenceCurve curve;
        curve.name = std::string(type) + " " + std::to_string(m_curves.size() + 1);
        curve.source = layer.empty() ? getAttributes().getLayer() : std::move(layer);
        curve.points = std::move(points);
        m_curves.push_back(std::move(curve));
    }

    void circle(const char* type, const Vec3& centre, double radius, double a0, double a1) {
        if (!(radius > 0.0) || !std::isfinite(radius) || !centre.isFinite() || !std::isfinite(a0) ||
            !std::isfinite(a1) || !(a1 > a0)) {
            ++m_skipped;
            return;
        }
        const Ocs ocs(extrusion());
        add(type,
            sampleArc(ocs.toWorld(centre), radius, ocs.x, ocs.y, a0, a1, m_tolerance / m_scale));
    }

    void finish() {
        if (m_polyline) {
            finishPolyline(*m_polyline);
            m_polyline.reset();
        }
        if (m_spline) {
            finishSpline(*m_spline);
            m_spline.reset();
        }
    }

    void finishPolyline(const Polyline& p) {
        if ((p.flags & (16 | 64)) != 0) { // polygon and polyface meshes are not curves
            ++m_skipped;
            return;
        }
        const bool is3d = (p.flags & 8) != 0;
        const bool closed = (p.flags & 1) != 0;
        const std::size_t n = p.vertices.size();
        std::vector<Vec3> points;
        const std::size_t segments = closed ? n : (n == 0 ? 0 : n - 1);
        auto ocsPoint = [&](std::size_t i) {
            const Vec3& v = p.vertices[i % n];
            return Vec3(v.x, v.y, v.z + p.elevation);
        };
        if (n > 0) {
            points.push_back(is3d ? p.vertices[0] : ocsPoint(0));
        }
        for (std::size_t i = 0; i < segments; ++i) {
            const double bulge = is3d ? 0.0 : p.bulges[i];
            if (is3d) {
                points.push_back(p.vertices[(i + 1) % n]);
            } else if (bulge != 0.0 && std::isfinite(bulge)) {
                const std::vector<Vec3> arc = bulgeArc(ocsPoint(i), ocsPoint(i + 1), bulge);
                points.insert(points.end(), arc.begin() + 1, arc.end());
            } else {
                points.push_back(ocsPoint(i + 1));
            }
        }
        if (!is3d) {
            for (Vec3& q : points) {
                q = p.ocs.toWorld(q);
            }
        }
        add("POLYLINE", std::move(points), p.layer);
    }

    // The arc from a to b (same z) whose included angle is 4·atan(bulge), counter-clockwise
    // for a positive bulge.
    std::vector<Vec3> bulgeArc(const Vec3& a, const Vec3& b, double bulge) const {
        const double theta = 4.0 * std::atan(bulge);
        const Vec3 d = b - a;
        const double chord = std::sqrt(d.x * d.x + d.y * d.y);
        if (!(chord > 0.0)) {
            return {a, b};
        }
        const Vec3 left(-d.y / chord, d.x / chord, 0.0);
        const Vec3 middle = (a + b) * 0.5;
        const Vec3 centre = middle + left * (0.5 * chord / std::tan(0.5 * theta));
        const double radius =
            std::sqrt((a.x - centre.x) * (a.x - centre.x) + (a.y - centre.y) * (a.y - centre.y));
        const double start = std::atan2(a.y - centre.y, a.x - centre.x);
        const Vec3 x(1, 0, 0);
        const Vec3 y = theta > 0 ? Vec3(0, 1, 0) : Vec3(0, -1, 0);
        const double a0 = theta > 0 ? start : -start;
        std::vector<Vec3> arc = sampleArc(Vec3(centre.x, centre.y, a.z), radius, x, y, a0,
                                          a0 + std::abs(theta), m_tolerance / m_scale);
        arc.front() = a; // exact ends
        arc.back() = b;
        return arc;
    }

    void finishSpline(Spline& s) {
        if (s.nurbs.controlPoints.empty() && s.fitPoints.size() >= 2) {
            add("SPLINE", std::move(s.fitPoints), s.layer);
            return;
        }
        bool rational = false;
        for (double w : s.nurbs.weights) {
            rational = rational || w != 1.0;
        }
        if (!rational) {
            s.nurbs.weights.clear();
        }
        std::optional<std::vector<Vec3>> points =
            sampleNurbs(s.nurbs, m_tolerance / m_scale, kMaxCurvePoints);
        if (!points) {
            ++m_skipped;
            return;
        }
        add("SPLINE", std::move(*points), s.layer);
    }

    double m_tolerance;
    double m_scale = 1.0;
    bool m_inBlock = false;
    std::optional<Polyline> m_polyline;
    std::optional<Spline> m_spline;
    std::vector<ReferenceCurve> m_curves;
    int m_skipped = 0;
};

} // namespace

CurveImportResult readDxfCurves(const std::string& bytes, const CurveImportOptions& options) {
    using Code = CurveImportError::Code;
    if (bytes.size() > kMaxCurveFileSize) {
        return curveImportFailure(Code::TooLarge);
    }
    if (const std::optional<std::string> unsafe = unsafeDxfContent(bytes)) {
        return curveImportFailure(Code::Damaged, *unsafe);
    }
    try {
        CurveCollector collector(options.tolerance > 0.0 ? options.tolerance : 0.05);
        ProgressBuffer buffer(bytes, options.progress);
        std::istream stream(&buffer);
        DL_Dxf dxf;
        const bool read = dxf.in(stream, &collector);
        if (buffer.cancelled()) {
            return curveImportFailure(Code::Cancelled);
        }
        if (!read) {
            return curveImportFailure(Code::Damaged, "dxflib could not read it");
        }
        CurveImportResult result;
        result.curves = collector.takeCurves();
        result.skipped = collector.skipped();
        if (result.curves.empty()) {
            return curveImportFailure(Code::NoCurves);
        }
        if (options.progress && !options.progress(1.0)) {
            return curveImportFailure(Code::Cancelled);
        }
        return result;
    } catch (const std::bad_alloc&) {
        return curveImportFailure(Code::TooLarge, "not enough memory");
    } catch (const std::exception& error) {
        return curveImportFailure(Code::Damaged, error.what());
    } catch (...) {
        return curveImportFailure(Code::Damaged);
    }
}

} // namespace devsurf::io
