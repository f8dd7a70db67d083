#include "project_archive.h"

#include "file_error.h"
#include "model/model_error.h"

#include <boost/archive/archive_exception.hpp>
#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/level.hpp>
#include <boost/serialization/split_free.hpp>
#include <boost/serialization/tracking.hpp>
#include <boost/serialization/version.hpp>

#include <cmath>
#include <sstream>

// Class versions of the archive. A reader refuses versions newer than these itself: Boost 1.74
// passes any version through to the load functions.
namespace devsurf::io::versions {
// 2: the reference curves (project file format 5). 3: the reference shapes (format 6).
inline constexpr unsigned kProject = 3;
// 2: pinned vertices (project file format 2). 3: the surface id (project file format 3).
// 4: the kept development (project file format 4). 5: the sheet's shape (format 5).
// 6: the sheet's crease curves (format 7).
inline constexpr unsigned kSurface = 6;
// 2: the smooth flag of rulings (project file format 3, with the surface ids).
inline constexpr unsigned kEdge = 2;
} // namespace devsurf::io::versions

BOOST_SERIALIZATION_SPLIT_FREE(devsurf::model::Project)
BOOST_SERIALIZATION_SPLIT_FREE(devsurf::model::CompositeSurface)
BOOST_SERIALIZATION_SPLIT_FREE(devsurf::model::EdgeRecord)
BOOST_CLASS_VERSION(devsurf::model::Project, devsurf::io::versions::kProject)
BOOST_CLASS_VERSION(devsurf::model::CompositeSurface, devsurf::io::versions::kSurface)
BOOST_CLASS_VERSION(devsurf::model::EdgeRecord, devsurf::io::versions::kEdge)
BOOST_CLASS_TRACKING(devsurf::model::Project, boost::serialization::track_never)
BOOST_CLASS_TRACKING(devsurf::model::CompositeSurface, boost::serialization::track_never)
BOOST_CLASS_TRACKING(devsurf::model::EdgeRecord, boost::serialization::track_never)
BOOST_CLASS_IMPLEMENTATION(devsurf::model::Vec3, boost::serialization::object_serializable)
BOOST_CLASS_TRACKING(devsurf::model::Vec3, boost::serialization::track_never)

namespace devsurf::io {
namespace {

// Bounds every count read from a file before anything is allocated: no count may exceed its
// own limit nor what the rest of the archive could possibly hold (each element takes at
// least two characters in a text archive).
struct ReadContext {
    const std::istream* stream = nullptr;
    std::size_t size = 0;
};
thread_local ReadContext readContext;

std::uint32_t checkedCount(std::uint32_t count, std::uint32_t limit, const char* what,
                           std::uint32_t tokensPerElement = 1) {
    std::size_t remaining = readContext.size;
    if (readContext.stream != nullptr) {
        const auto position = const_cast<std::istream*>(readContext.stream)->tellg();
        if (position >= 0 && static_cast<std::size_t>(position) <= readContext.size) {
            remaining = readContext.size - static_cast<std::size_t>(position);
        }
    }
    if (count > limit || static_cast<std::uint64_t>(count) * tokensPerElement * 2 > remaining + 2) {
        throw FileError(std::string("it announces ") + std::to_string(count) + " " + what +
                        ", more than the file can hold");
    }
    return count;
}

void checkVersion(unsigned version, unsigned supported, const char* what) {
    if (version > supported) {
        throw FileError(std::string("it was written by a newer version of DevSurf (") + what +
                        " version " + std::to_string(version) + "; this version reads up to " +
                        std::to_string(supported) + ")");
    }
    if (version == 0) {
        throw FileError(std::string("it has an unknown ") + what + " version 0");
    }
}

template <class Archive> void saveString(Archive& ar, const std::string& text) {
    const auto size = static_cast<std::uint32_t>(text.size());
    ar << size;
    for (char c : text) {
        const int code = static_cast<unsigned char>(c);
        ar << code;
    }
}

template <class Archive> std::string loadString(Archive& ar, std::uint32_t limit) {
    std::uint32_t size = 0;
    ar >> size;
    checkedCount(size, limit, "characters in a name");
    std::string text;
    text.reserve(size);
    for (std::uint32_t i = 0; i < size; ++i) {
        int code = 0;
        ar >> code;
        if (code < 0 || code > 255) {
            throw FileError("it holds a name with an invalid character");
        }
        text.push_back(static_cast<char>(code));
    }
    return text;
}

// A reference shape: name, source, its points, its normals (none or one per point) and its
// triangles (none for a point cloud) as indices into the points.
template <class Archive> void saveShape(Archive& ar, const model::ReferenceShape& shape) {
    saveString(ar, shape.name);
    saveString(ar, shape.source);
    const auto points = static_cast<std::uint32_t>(shape.points.size());
    ar << points;
    for (const model::Vec3& point : shape.points) {
        ar << point;
    }
    const auto normals = static_cast<std::uint32_t>(shape.normals.size());
    ar << normals;
    for (const model::Vec3& normal : shape.normals) {
        ar << normal;
    }
    const auto triangles = static_cast<std::uint32_t>(shape.triangles.size());
    ar << triangles;
    for (const std::array<int, 3>& t : shape.triangles) {
        ar << t[0] << t[1] << t[2];
    }
}

template <class Archive> model::ReferenceShape loadShape(Archive& ar) {
    model::ReferenceShape shape;
    shape.name = loadString(ar, 4096);
    shape.source = loadString(ar, 4096);
    std::uint32_t points = 0;
    ar >> points;
    checkedCount(points, 100'000'000, "points of a reference shape", 3);
    if (points == 0) {
        throw FileError("it holds a reference shape without points");
    }
    shape.points.resize(points);
    for (model::Vec3& point : shape.points) {
        ar >> point;
        if (!point.isFinite()) {
            throw FileError("it holds a reference shape with a coordinate that is not a number");
        }
    }
    std::uint32_t normals = 0;
    ar >> normals;
    if (normals != 0 && normals != points) {
        throw FileError("it holds a reference shape with " + std::to_string(normals) +
                        " normals for " + std::to_string(points) + " points");
    }
    shape.normals.resize(normals);
    for (model::Vec3& normal : shape.normals) {
        ar >> normal;
        if (!normal.isFinite()) {
            throw FileError("it holds a reference shape with a normal that is not a number");
        }
    }
    std::uint32_t triangles = 0;
    ar >> triangles;
    checkedCount(triangles, 200'000'000, "triangles of a reference shape", 3);
    shape.triangles.resize(triangles);
    for (std::array<int, 3>& t : shape.triangles) {
        ar >> t[0] >> t[1] >> t[2];
        for (int corner : t) {
            if (corner < 0 || static_cast<std::uint32_t>(corner) >= points) {
                throw FileError("it holds a reference shape with a triangle corner " +
                                std::to_string(corner) + " that is not one of its " +
                                std::to_string(points) + " points");
            }
        }
    }
    return shape;
}

} // namespace
} // namespace devsurf::io

namespace boost::serialization {

using namespace devsurf::model;
using devsurf::io::checkedCount;
using devsurf::io::FileError;

template <class Archive> void serialize(Archive& ar, Vec3& p, unsigned /*version*/) {
    ar& p.x;
    ar& p.y;
    ar& p.z;
}

template <class Archive> void save(Archive& ar, const EdgeRecord& e, unsigned /*version*/) {
    const int label = static_cast<int>(e.label);
    ar << e.from << e.to << label;
    if (!e.isSpline()) {
        const int smooth = e.smooth ? 1 : 0;
        ar << smooth;
        return;
    }
    const int condition = static_cast<int>(e.condition);
    ar << e.space.degree << e.space.smoothness << e.space.intervals << condition;
    const auto count = static_cast<std::uint32_t>(e.controlPoints.size());
    ar << count;
    for (const Vec3& p : e.controlPoints) {
        ar << p;
    }
}

template <class Archive> void load(Archive& ar, EdgeRecord& e, unsigned version) {
    devsurf::io::checkVersion(version, devsurf::io::versions::kEdge, "edge");
    int label = 0;
    ar >> e.from >> e.to >> label;
    if (label != 0 && label != 1) {
        throw FileError("it holds an edge with an unknown label");
    }
    e.label = static_cast<EdgeLabel>(label);
    if (!e.isSpline()) {
        if (version >= 2) {
            int smooth = 0;
            ar >> smooth;
            if (smooth != 0 && smooth != 1) {
                throw FileError("it holds a ruling with an invalid smooth flag");
            }
            e.smooth = smooth == 1;
        }
        return;
    }
    int condition = 0;
    ar >> e.space.degree >> e.space.smoothness >> e.space.intervals >> condition;
    if (condition < 0 || condition > 3) {
        throw FileError("it holds a crease with an unknown condition");
    }
    e.condition = static_cast<CreaseCondition>(condition);
    if (!e.space.isValid()) {
        throw FileError("it holds a curve with an invalid spline space");
    }
    std::uint32_t count = 0;
    ar >> count;
    checkedCount(count, 10'000'000, "control points", 3);
    if (count != static_cast<std::uint32_t>(e.space.controlPointCount(false))) {
        throw FileError("it holds a curve whose control points do not fit its spline space");
    }
    e.controlPoints.resize(count);
    for (Vec3& p : e.controlPoints) {
        ar >> p;
    }
}

template <class Archive> void save(Archive& ar, const CompositeSurface& s, unsigned /*version*/) {
    devsurf::io::saveString(ar, s.name());
    ar << s.nextVertexId() << s.nextEdgeId() << s.nextFaceId();
    const auto vertices = static_cast<std::uint32_t>(s.vertices().size());
    ar << vertices;
    for (const auto& [id, p] : s.vertices()) {
        ar << id << p;
    }
    const auto edges = static_cast<std::uint32_t>(s.edges().size());
    ar << edges;
    for (const auto& [id, e] : s.edges()) {
        ar << id << e;
    }
    const auto faces = static_cast<std::uint32_t>(s.faces().size());
    ar << faces;
    for (const auto& [id, loop] : s.faces()) {
        const auto corners = static_cast<std::uint32_t>(loop.size());
        ar << id << corners;
        for (VertexId v : loop) {
            ar << v;
        }
    }
    const auto pinned = static_cast<std::uint32_t>(s.pinnedVertices().size());
    ar << pinned;
    for (VertexId v : s.pinnedVertices()) {
        ar << v;
    }
    const SurfaceId id = s.id();
    ar << id;
    const std::uint8_t keeps = s.keepsDevelopment() ? 1 : 0;
    const auto points = static_cast<std::uint32_t>(s.development().size());
    ar << keeps << points;
    for (const devsurf::model::Vec2& p : s.development()) {
        ar << p.x << p.y;
    }
    const devsurf::model::SheetDomain& d = s.sheetDomain();
    const auto shape = static_cast<std::uint8_t>(d.shape);
    const auto loops = static_cast<std::uint32_t>(d.outline.size());
    ar << shape << d.width << d.height << d.radius << d.innerRadius << d.centre.x << d.centre.y
       << d.angle << loops;
    for (const std::vector<devsurf::model::Vec2>& loop : d.outline) {
        const auto corners = static_cast<std::uint32_t>(loop.size());
        ar << corners;
        for (const devsurf::model::Vec2& p : loop) {
            ar << p.x << p.y;
        }
    }
    const auto curves = static_cast<std::uint32_t>(d.creaseCurves.size());
    ar << curves;
    for (const devsurf::model::SheetDomain::Curve& curve : d.creaseCurves) {
        const std::uint8_t closed = curve.closed ? 1 : 0;
        const auto points = static_cast<std::uint32_t>(curve.points.size());
        ar << closed << points;
        for (const devsurf::model::Vec2& p : curve.points) {
            ar << p.x << p.y;
        }
    }
    const auto creases = static_cast<std::uint32_t>(d.creaseCurveOf.size());
    ar << creases;
    for (const auto& [edge, curve] : d.creaseCurveOf) {
        const auto index = static_cast<std::int32_t>(curve);
        ar << edge << index;
    }
}

template <class Archive> void load(Archive& ar, CompositeSurface& s, unsigned version) {
    devsurf::io::checkVersion(version, devsurf::io::versions::kSurface, "surface");
    s.setName(devsurf::io::loadString(ar, 4096));
    VertexId nextVertex = 0;
    EdgeId nextEdge = 0;
    FaceId nextFace = 0;
    ar >> nextVertex >> nextEdge >> nextFace;
    std::uint32_t vertices = 0;
    ar >> vertices;
    checkedCount(vertices, 10'000'000, "vertices", 4);
    for (std::uint32_t i = 0; i < vertices; ++i) {
        VertexId id = 0;
        Vec3 p;
        ar >> id >> p;
        s.addVertexWithId(id, p);
    }
    std::uint32_t edges = 0;
    ar >> edges;
    checkedCount(edges, 30'000'000, "edges", 4);
    for (std::uint32_t i = 0; i < edges; ++i) {
        EdgeId id = 0;
        EdgeRecord e;
        ar >> id >> e;
        s.addEdgeWithId(id, e);
    }
    std::uint32_t faces = 0;
    ar >> faces;
    checkedCount(faces, 10'000'000, "faces", 5);
    for (std::uint32_t i = 0; i < faces; ++i) {
        FaceId id = 0;
        std::uint32_t corners = 0;
        ar >> id >> corners;
        checkedCount(corners, 100'000, "corners of a face");
        std::vector<VertexId> loop(corners);
        for (VertexId& v : loop) {
            ar >> v;
        }
        s.addFaceWithId(id, loop);
    }
    s.setNextIds(nextVertex, nextEdge, nextFace);
    if (version >= 2) {
        std::uint32_t pinned = 0;
        ar >> pinned;
        checkedCount(pinned, vertices, "pinned vertices");
        for (std::uint32_t i = 0; i < pinned; ++i) {
            VertexId v = 0;
            ar >> v;
            if (!s.hasVertex(v)) {
                throw FileError("it pins vertex " + std::to_string(v) + ", which does not exist");
            }
            s.setPinned(v, true);
        }
    }
    if (version >= 3) {
        SurfaceId id = 0;
        ar >> id;
        s.setId(id);
    }
    if (version >= 4) {
        std::uint8_t keeps = 0;
        std::uint32_t points = 0;
        ar >> keeps >> points;
        if (keeps > 1) {
            throw FileError("it has an invalid development setting " + std::to_string(keeps));
        }
        checkedCount(points, 100'000'000, "development points", 2);
        std::vector<devsurf::model::Vec2> development(points);
        for (devsurf::model::Vec2& p : development) {
            ar >> p.x >> p.y;
        }
        s.setKeepsDevelopment(keeps == 1);
        s.setDevelopment(std::move(development)); // its size is checked by validate()
    }
    if (version >= 5) {
        devsurf::model::SheetDomain d;
        std::uint8_t shape = 0;
        std::uint32_t loops = 0;
        ar >> shape >> d.width >> d.height >> d.radius >> d.innerRadius >> d.centre.x >>
            d.centre.y >> d.angle >> loops;
        if (shape > static_cast<std::uint8_t>(devsurf::model::SheetShape::Cylinder)) {
            throw FileError("it has an unknown sheet shape " + std::to_string(shape));
        }
        d.shape = static_cast<devsurf::model::SheetShape>(shape);
        checkedCount(loops, 100'000, "outline loops", 4);
        d.outline.resize(loops);
        for (std::vector<devsurf::model::Vec2>& loop : d.outline) {
            std::uint32_t corners = 0;
            ar >> corners;
            checkedCount(corners, 10'000'000, "outline points", 2);
            loop.resize(corners);
            for (devsurf::model::Vec2& p : loop) {
                ar >> p.x >> p.y;
            }
        }
        if (version >= 6) {
            std::uint32_t curves = 0;
            ar >> curves;
            checkedCount(curves, 100'000, "crease curves", 5);
            d.creaseCurves.resize(curves);
            for (devsurf::model::SheetDomain::Curve& curve : d.creaseCurves) {
                std::uint8_t closed = 0;
                std::uint32_t points = 0;
                ar >> closed >> points;
                if (closed > 1) {
                    throw FileError("it has an invalid crease curve flag " +
                                    std::to_string(closed));
                }
                checkedCount(points, 10'000'000, "crease curve points", 2);
                curve.closed = closed == 1;
                curve.points.resize(points);
                for (devsurf::model::Vec2& p : curve.points) {
                    ar >> p.x >> p.y;
                }
            }
            std::uint32_t creases = 0;
            ar >> creases;
            checkedCount(creases, 30'000'000, "creases on curves", 2);
            for (std::uint32_t i = 0; i < creases; ++i) {
                EdgeId edge = 0;
                std::int32_t curve = 0;
                ar >> edge >> curve;
                d.creaseCurveOf[edge] = curve; // indices are checked by validate()
            }
        }
        s.setSheetDomain(std::move(d)); // its sizes are checked by validate()
    }
}

template <class Archive> void save(Archive& ar, const Project& p, unsigned /*version*/) {
    devsurf::io::saveString(ar, p.units);
    const auto count = static_cast<std::uint32_t>(p.surfaces.size());
    ar << count;
    for (const CompositeSurface& s : p.surfaces) {
        ar << s;
    }
    const auto curves = static_cast<std::uint32_t>(p.referenceCurves.size());
    ar << curves;
    for (const ReferenceCurve& curve : p.referenceCurves) {
        devsurf::io::saveString(ar, curve.name);
        devsurf::io::saveString(ar, curve.source);
        const auto points = static_cast<std::uint32_t>(curve.points.size());
        ar << points;
        for (const Vec3& point : curve.points) {
            ar << point;
        }
    }
    const auto shapes = static_cast<std::uint32_t>(p.referenceShapes.size());
    ar << shapes;
    for (const ReferenceShape& shape : p.referenceShapes) {
        devsurf::io::saveShape(ar, shape);
    }
}

template <class Archive> void load(Archive& ar, Project& p, unsigned version) {
    devsurf::io::checkVersion(version, devsurf::io::versions::kProject, "project");
    p.units = devsurf::io::loadString(ar, 64);
    std::uint32_t count = 0;
    ar >> count;
    checkedCount(count, 100'000, "surfaces", 8);
    p.surfaces.clear();
    for (std::uint32_t i = 0; i < count; ++i) {
        CompositeSurface s;
        ar >> s;
        p.surfaces.push_back(std::move(s));
    }
    // Files before format 3 hold no surface ids; a damaged file may repeat one.
    p.assignSurfaceIds();
    p.referenceCurves.clear();
    if (version >= 2) {
        std::uint32_t curves = 0;
        ar >> curves;
        checkedCount(curves, 1'000'000, "reference curves", 4);
        for (std::uint32_t i = 0; i < curves; ++i) {
            ReferenceCurve curve;
            curve.name = devsurf::io::loadString(ar, 4096);
            curve.source = devsurf::io::loadString(ar, 4096);
            std::uint32_t points = 0;
            ar >> points;
            checkedCount(points, 100'000'000, "curve points", 3);
            if (points < 2) {
                throw FileError("it holds a reference curve with fewer than two points");
            }
            curve.points.resize(points);
            for (Vec3& point : curve.points) {
                ar >> point;
                if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) {
                    throw FileError("it holds a reference curve with a coordinate that is not a "
                                    "number");
                }
            }
            p.referenceCurves.push_back(std::move(curve));
        }
    }
    p.referenceShapes.clear();
    if (version >= 3) {
        std::uint32_t shapes = 0;
        ar >> shapes;
        checkedCount(shapes, 100'000, "reference shapes", 6);
        for (std::uint32_t i = 0; i < shapes; ++i) {
            p.referenceShapes.push_back(devsurf::io::loadShape(ar));
        }
    }
}

} // namespace boost::serialization

namespace devsurf::io {

std::string writeProjectArchive(const model::Project& project) {
    std::ostringstream out;
    {
        boost::archive::text_oarchive archive(out);
        archive << project;
    }
    return out.str();
}

model::Project readProjectArchive(const std::string& payload) {
    // Boost reads the signature's length from the archive and allocates that much before it
    // compares: check the signature ourselves so a damaged length cannot allocate gigabytes.
    static const std::string signature = "22 serialization::archive ";
    if (payload.compare(0, signature.size(), signature) != 0) {
        throw FileError("its contents are damaged (the archive signature is wrong)");
    }
    std::istringstream in(payload);
    readContext = {&in, payload.size()};
    struct Reset {
        ~Reset() { readContext = {}; }
    } reset;
    model::Project project;
    try {
        boost::archive::text_iarchive archive(in);
        archive >> project;
    } catch (const FileError&) {
        throw;
    } catch (const model::ModelError& error) {
        throw FileError("it describes an impossible surface", {error.problem()});
    } catch (const boost::archive::archive_exception& error) {
        throw FileError(std::string("its contents are damaged (") + error.what() + ")");
    } catch (const std::exception& error) {
        throw FileError(std::string("its contents are damaged (") + error.what() + ")");
    }
    // Anything after the archive means the payload is not what was written.
    in >> std::ws;
    if (!in.eof()) {
        throw FileError("its contents are damaged (unexpected data after the project)");
    }
    const std::vector<std::string> allowedUnits{"mm", "cm", "m", "in", "ft", "pt", "unit"};
    if (std::find(allowedUnits.begin(), allowedUnits.end(), project.units) == allowedUnits.end()) {
        throw FileError("it uses an unknown length unit");
    }
    for (const model::CompositeSurface& surface : project.surfaces) {
        const auto problems = surface.validate();
        if (!problems.empty()) {
            throw FileError("its surface '" + surface.name() + "' is invalid", problems);
        }
    }
    return project;
}

} // namespace devsurf::io
