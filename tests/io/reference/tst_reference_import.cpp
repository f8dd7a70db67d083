#include "io/reference/reference_import.h"
#include "test_registry.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <set>

using namespace devsurf;
using Code = io::ReferenceImportError::Code;

namespace {

// The tetrahedron every mesh format is written with: four corners, four outward triangles.
const std::vector<model::Vec3> kCorners{{0, 0, 0}, {10, 0, 0}, {0, 20, 0}, {0, 0, 30.5}};
const std::vector<std::array<int, 3>> kTriangles{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

std::string num(double v) {
    return QString::number(v, 'g', 17).toStdString();
}

std::string objText() {
    std::string text = "# tetrahedron\no tet\n";
    for (const model::Vec3& p : kCorners) {
        text += "v " + num(p.x) + " " + num(p.y) + " " + num(p.z) + "\n";
    }
    for (const auto& t : kTriangles) {
        text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
                std::to_string(t[2] + 1) + "\n";
    }
    return text;
}

std::string offText() {
    std::string text = "OFF\n# tetrahedron\n4 4 6\n";
    for (const model::Vec3& p : kCorners) {
        text += num(p.x) + " " + num(p.y) + " " + num(p.z) + "\n";
    }
    for (const auto& t : kTriangles) {
        text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " +
                std::to_string(t[2]) + "\n";
    }
    return text;
}

std::string plyHeader(const char* format) {
    return std::string("ply\nformat ") + format +
           " 1.0\ncomment tetrahedron\nelement vertex 4\nproperty float x\nproperty float "
           "y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\n"
           "end_header\n";
}

std::string plyAsciiText() {
    std::string text = plyHeader("ascii");
    for (const model::Vec3& p : kCorners) {
        text += num(p.x) + " " + num(p.y) + " " + num(p.z) + "\n";
    }
    for (const auto& t : kTriangles) {
        text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " +
                std::to_string(t[2]) + "\n";
    }
    return text;
}

template <class T> void put(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T)); // this machine is little endian, as the files are
    out.append(bytes, sizeof(T));
}

std::string plyBinaryText() {
    std::string text = plyHeader("binary_little_endian");
    for (const model::Vec3& p : kCorners) {
        put(text, static_cast<float>(p.x));
        put(text, static_cast<float>(p.y));
        put(text, static_cast<float>(p.z));
    }
    for (const auto& t : kTriangles) {
        put(text, static_cast<unsigned char>(3));
        for (int i : t) {
            put(text, static_cast<std::int32_t>(i));
        }
    }
    return text;
}

model::Vec3 normalOf(const std::array<int, 3>& t) {
    const model::Vec3 a =
        kCorners[static_cast<std::size_t>(t[1])] - kCorners[static_cast<std::size_t>(t[0])];
    const model::Vec3 b =
        kCorners[static_cast<std::size_t>(t[2])] - kCorners[static_cast<std::size_t>(t[0])];
    const model::Vec3 n{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
}

std::string stlAsciiText() {
    std::string text = "solid tet\n";
    for (const auto& t : kTriangles) {
        const model::Vec3 n = normalOf(t);
        text +=
            "  facet normal " + num(n.x) + " " + num(n.y) + " " + num(n.z) + "\n    outer loop\n";
        for (int i : t) {
            const model::Vec3& p = kCorners[static_cast<std::size_t>(i)];
            text += "      vertex " + num(p.x) + " " + num(p.y) + " " + num(p.z) + "\n";
        }
        text += "    endloop\n  endfacet\n";
    }
    return text + "endsolid tet\n";
}

std::string stlBinaryText() {
    std::string text(80, ' ');
    text.replace(0, 13, "binary tet   ");
    put(text, static_cast<std::uint32_t>(kTriangles.size()));
    for (const auto& t : kTriangles) {
        const model::Vec3 n = normalOf(t);
        put(text, static_cast<float>(n.x));
        put(text, static_cast<float>(n.y));
        put(text, static_cast<float>(n.z));
        for (int i : t) {
            const model::Vec3& p = kCorners[static_cast<std::size_t>(i)];
            put(text, static_cast<float>(p.x));
            put(text, static_cast<float>(p.y));
            put(text, static_cast<float>(p.z));
        }
        put(text, static_cast<std::uint16_t>(0));
    }
    return text;
}

// A unit cube of quads with a normal per corner, its faces in "v//n" form.
std::string cubeObjText() {
    std::string obj;
    for (int i = 0; i < 8; ++i) {
        obj += "v " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " +
               std::to_string((i >> 2) & 1) + "\n";
    }
    for (int i = 0; i < 8; ++i) {
        obj += "vn " + num((i & 1) - 0.5) + " " + num(((i >> 1) & 1) - 0.5) + " " +
               num(((i >> 2) & 1) - 0.5) + "\n";
    }
    for (const char* face : {"1 3 4 2", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6"}) {
        obj += "f";
        for (const QString& corner : QString(face).split(' ')) {
            obj += " " + corner.toStdString() + "//" + corner.toStdString();
        }
        obj += "\n";
    }
    return obj;
}

// A square of one quad in a PLY file with a normal per point.
std::string squarePlyText() {
    return "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\n"
           "property double y\nproperty double z\nproperty float nx\n"
           "property float ny\nproperty float nz\nelement face 1\n"
           "property list uchar uint vertex_indices\nend_header\n"
           "0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0.125 0 0 1\n"
           "4 0 1 2 3\n";
}

struct Sample {
    const char* name;
    std::string bytes;
};

std::vector<Sample> meshSamples() {
    return {{"tet.obj", objText()},      {"tet.off", offText()},
            {"tet.ply", plyAsciiText()}, {"tetb.ply", plyBinaryText()},
            {"tet.stl", stlAsciiText()}, {"tetb.stl", stlBinaryText()}};
}

// The triangles as sets of corner positions, turned so that each starts at its smallest
// corner: equal for the same oriented triangles whatever the numbering of the points.
std::set<std::array<double, 9>> orientedTriangles(const model::ReferenceShape& shape) {
    std::set<std::array<double, 9>> result;
    for (const auto& t : shape.triangles) {
        std::array<model::Vec3, 3> corners;
        for (int k = 0; k < 3; ++k) {
            corners[static_cast<std::size_t>(k)] =
                shape.points[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
        }
        const auto less = [](const model::Vec3& a, const model::Vec3& b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        };
        std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end(), less),
                    corners.end());
        result.insert({corners[0].x, corners[0].y, corners[0].z, corners[1].x, corners[1].y,
                       corners[1].z, corners[2].x, corners[2].y, corners[2].z});
    }
    return result;
}

model::ReferenceShape expectedTetrahedron() {
    model::ReferenceShape shape;
    shape.points = kCorners;
    shape.triangles = kTriangles;
    return shape;
}

bool isSound(const model::ReferenceShape& shape) {
    if (shape.points.empty() ||
        (!shape.normals.empty() && shape.normals.size() != shape.points.size())) {
        return false;
    }
    for (const model::Vec3& p : shape.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            return false;
        }
    }
    for (const auto& t : shape.triangles) {
        for (int i : t) {
            if (i < 0 || static_cast<std::size_t>(i) >= shape.points.size()) {
                return false;
            }
        }
    }
    return true;
}

} // namespace

class TstReferenceImport : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    std::string write(const std::string& name, const std::string& bytes) const {
        const QString path = m_dir.filePath(QString::fromStdString(name));
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly)) {
            return {};
        }
        file.write(bytes.data(), static_cast<qint64>(bytes.size()));
        return path.toStdString();
    }

    Code refusal(const std::string& name, const std::string& bytes) const {
        const io::ReferenceImportResult result = io::readReferenceShape(write(name, bytes));
        if (!result.error) {
            return Code::Cancelled; // never expected in these tests: marks "loaded"
        }
        return result.error->code;
    }

private slots:
    void everyMeshFormatReadsTheTetrahedron() {
        const auto expected = orientedTriangles(expectedTetrahedron());
        for (const Sample& sample : meshSamples()) {
            const io::ReferenceImportResult result =
                io::readReferenceShape(write(sample.name, sample.bytes));
            QVERIFY2(!result.error, sample.name);
            const model::ReferenceShape& shape = result.shape;
            QCOMPARE(shape.points.size(), std::size_t(4));
            QCOMPARE(shape.triangles.size(), std::size_t(4));
            QVERIFY2(orientedTriangles(shape) == expected, sample.name);
            QVERIFY(isSound(shape));
            QVERIFY(shape.normals.empty()); // none in these files (STL's are per facet)
            QCOMPARE(shape.source, std::string(sample.name));
            QCOMPARE(shape.name, std::string(sample.name).substr(0, std::strlen(sample.name) - 4));
        }
    }

    void polygonsAreTriangulatedAndNormalsKept() {
        const std::string obj = cubeObjText();
        const io::ReferenceImportResult result = io::readReferenceShape(write("cube.OBJ", obj));
        QVERIFY(!result.error);
        QCOMPARE(result.shape.points.size(), std::size_t(8));
        QCOMPARE(result.shape.triangles.size(), std::size_t(12));
        QCOMPARE(result.shape.normals.size(), std::size_t(8));
        QCOMPARE(result.shape.points[7], model::Vec3(1, 1, 1));
        QCOMPARE(result.shape.normals[7], model::Vec3(0.5, 0.5, 0.5));
        QCOMPARE(result.shape.normals[2], model::Vec3(-0.5, 0.5, -0.5));
        // Without a normal named for every point there are none (OpenMesh would invent some).
        const io::ReferenceImportResult partial =
            io::readReferenceShape(write("partial.obj", cubeObjText() + "v 9 9 9\n"));
        QVERIFY(!partial.error);
        QCOMPARE(partial.shape.points.size(), std::size_t(9));
        QVERIFY(partial.shape.normals.empty());
        const std::string ply = squarePlyText();
        const io::ReferenceImportResult square = io::readReferenceShape(write("square.ply", ply));
        QVERIFY(!square.error);
        QCOMPARE(square.shape.points.size(), std::size_t(4));
        QCOMPARE(square.shape.triangles.size(), std::size_t(2));
        QCOMPARE(square.shape.normals.size(), std::size_t(4));
        QCOMPARE(square.shape.normals[3], model::Vec3(0, 0, 1));
        QCOMPARE(square.shape.points[3], model::Vec3(0, 1, 0.125));
    }

    void pointCloudsWithAndWithoutNormals() {
        io::ReferenceImportResult result = io::readReferenceShape(
            write("plain.xyz", "# scan\n1 2 3\n\n-4.5 5e-3 6\r\n7,8,9.125\n0.1 0.2 0.3"));
        QVERIFY(!result.error);
        QCOMPARE(result.shape.points.size(), std::size_t(4));
        QVERIFY(result.shape.normals.empty());
        QVERIFY(result.shape.triangles.empty());
        QVERIFY(result.shape.isPointCloud());
        QCOMPARE(result.shape.points[1], model::Vec3(-4.5, 5e-3, 6));
        QCOMPARE(result.shape.points[2], model::Vec3(7, 8, 9.125));
        QCOMPARE(result.shape.points[3], model::Vec3(0.1, 0.2, 0.3)); // the same double

        result = io::readReferenceShape(write("normals.xyz", "1 2 3 0 0 1\n4 5 6 1 0 0\n"));
        QVERIFY(!result.error);
        QCOMPARE(result.shape.normals.size(), std::size_t(2));
        QCOMPARE(result.shape.normals[1], model::Vec3(1, 0, 0));

        // PTS: a count, then x y z intensity r g b: the points only.
        result = io::readReferenceShape(
            write("scan.pts", "3\n1 2 3 -1200 255 0 0\n4 5 6 17 0 255 0\n7 8 9 0 0 0 255\n"));
        QVERIFY(!result.error);
        QCOMPARE(result.shape.points.size(), std::size_t(3));
        QVERIFY(result.shape.normals.empty());
        QCOMPARE(result.shape.points[2], model::Vec3(7, 8, 9));
        // PTS with six columns and no count: normals.
        result = io::readReferenceShape(write("n.PTS", "1 2 3 0 1 0\n4 5 6 0 0 -1\n"));
        QVERIFY(!result.error);
        QCOMPARE(result.shape.normals.size(), std::size_t(2));
        QCOMPARE(result.shape.normals[1], model::Vec3(0, 0, -1));
    }

    void unreadableAndUnknownFilesAreRefused() {
        QVERIFY(io::readReferenceShape(m_dir.filePath("missing.obj").toStdString()).error->code ==
                Code::Unreadable);
        QVERIFY(io::readReferenceShape(m_dir.path().toStdString() + "/").error->code ==
                Code::UnknownFormat);
        QVERIFY(refusal("shape.dxf", objText()) == Code::UnknownFormat);
        QVERIFY(refusal("empty.obj", "") == Code::NoPoints);
        QVERIFY(refusal("comments.xyz", "# nothing\n\n") == Code::NoPoints);
        QVERIFY(refusal("faces.obj", "# none\ng group\n") == Code::NoPoints);
    }

    void damagedFilesAreRefused() {
        // Coordinates that are not numbers, infinite or absurd.
        QVERIFY(refusal("nan.xyz", "1 2 3\nnan 2 3\n") == Code::NotANumber);
        QVERIFY(refusal("inf.xyz", "1 2 3\n1 inf 3\n") == Code::NotANumber);
        QVERIFY(refusal("big.xyz", "1 2 3\n1 2 1e400\n") == Code::NotANumber);
        QVERIFY(refusal("far.pts", "1 2 3\n1 2 1e12\n") == Code::NotANumber);
        QVERIFY(refusal("nn.xyz", "1 2 3 0 0 1\n1 2 3 0 nan 1\n") == Code::NotANumber);
        QVERIFY(refusal("word.xyz", "1 2 3\n1 two 3\n") == Code::Damaged);
        QVERIFY(refusal("columns.xyz", "1 2 3\n1 2 3 4\n5 6 7\n") == Code::Damaged);
        std::string nanObj = objText();
        nanObj.replace(nanObj.find("v 10"), 4, "v nan");
        QVERIFY(refusal("nan.obj", nanObj) == Code::NotANumber);
        std::string nanOff = offText();
        nanOff.replace(nanOff.find("10 0 0"), 2, "1e999");
        QVERIFY(refusal("nan.off", nanOff) == Code::NotANumber);

        // Faces that name points the file does not have.
        QVERIFY(refusal("bad.obj", objText() + "f 1 2 5\n") == Code::BadFaces);
        QVERIFY(refusal("zero.obj", objText() + "f 0 1 2\n") == Code::BadFaces);
        QVERIFY(refusal("back.obj", objText() + "f -1 -2 -5\n") == Code::BadFaces);
        QVERIFY(refusal("texture.obj", objText() + "f 1/1 2/1 3/1\n") == Code::BadFaces);
        QVERIFY(refusal("two.obj", objText() + "f 1 2\n") == Code::BadFaces);
        std::string off = offText();
        off.replace(off.rfind("3 0 3 2"), 7, "3 0 4 2");
        QVERIFY(refusal("bad.off", off) == Code::BadFaces);
        std::string ply = plyAsciiText();
        ply.replace(ply.rfind("3 0 3 2"), 7, "3 0 9 2");
        QVERIFY(refusal("bad.ply", ply) == Code::BadFaces);
        std::string plyBinary = plyBinaryText();
        plyBinary[plyBinary.size() - 4] = 4; // the last corner of the last face
        QVERIFY(refusal("badb.ply", plyBinary) == Code::BadFaces);

        // Absurd counts.
        std::string offCount = offText();
        offCount.replace(offCount.find("4 4 6"), 5, "4000000000 4 6");
        QVERIFY(refusal("count.off", offCount) == Code::Damaged);
        std::string plyCount = plyBinaryText();
        plyCount.replace(plyCount.find("vertex 4"), 8, "vertex 4294967295");
        QVERIFY(refusal("count.ply", plyCount) == Code::Damaged);
        QVERIFY(refusal("count.pts", "99999999999\n1 2 3\n") == Code::Damaged);
        QVERIFY(refusal("negative.pts", "-3\n1 2 3\n") == Code::Damaged);
        std::string stlCount = stlBinaryText();
        stlCount[80] = '\xff';
        stlCount[83] = '\x7f';
        QVERIFY(refusal("count.stl", stlCount) == Code::Truncated);

        // Truncated files.
        for (const Sample& sample : meshSamples()) {
            const std::string name = std::string("cut-") + sample.name;
            const std::size_t keep = sample.bytes.size() * 2 / 3;
            QVERIFY2(refusal(name, sample.bytes.substr(0, keep)) != Code::Cancelled, sample.name);
        }
        QVERIFY(refusal("cut.off", offText().substr(0, offText().size() - 10)) == Code::Truncated);
        QVERIFY(refusal("cutb.stl", stlBinaryText().substr(0, 150)) == Code::Truncated);
        QVERIFY(refusal("cut.stl", stlAsciiText().substr(0, 300)) == Code::Truncated);
        QVERIFY(refusal("cutb.ply", plyBinaryText().substr(0, plyBinaryText().size() - 3)) ==
                Code::Truncated);
        QVERIFY(refusal("cut.xyz", "1 2 3 0 0 1\n4 5 6 0 0") == Code::Truncated);
        QVERIFY(refusal("cut.pts", "3\n1 2 3\n4 5 6\n") == Code::Truncated);
        QVERIFY(refusal("more.pts", "1\n1 2 3\n4 5 6\n") == Code::Damaged);
        QVERIFY(refusal("long.xyz", std::string(2u << 20, '1')) == Code::Damaged);
    }

    void progressRisesAndCancelStops() {
        std::string cloud;
        for (int i = 0; i < 300000; ++i) {
            cloud += std::to_string(i) + " " + std::to_string(i % 17) + " 0.25\n";
        }
        const std::string path = write("large.xyz", cloud);
        std::vector<double> seen;
        io::ReferenceImportResult result = io::readReferenceShape(path, [&seen](double f) {
            seen.push_back(f);
            return true;
        });
        QVERIFY(!result.error);
        QCOMPARE(result.shape.points.size(), std::size_t(300000));
        QCOMPARE(result.shape.points[299999], model::Vec3(299999, 299999 % 17, 0.25));
        QVERIFY(seen.size() >= 3);
        QVERIFY(std::is_sorted(seen.begin(), seen.end()));
        QCOMPARE(seen.back(), 1.0);
        // Cancelled halfway: nothing is returned.
        int calls = 0;
        result =
            io::readReferenceShape(path, [&calls](double f) { return ++calls < 2 || f < 0.5; });
        QVERIFY(result.error && result.error->code == Code::Cancelled);
        QVERIFY(result.shape.points.empty());
        // A mesh can be cancelled as well.
        result = io::readReferenceShape(write("c.obj", objText()), [](double) { return false; });
        QVERIFY(result.error && result.error->code == Code::Cancelled);
    }

    void mutatedFilesAreRefusedOrSound() {
        // Thousands of damaged copies of every sample (truncated, bytes flipped, inserted,
        // deleted, digits changed): each is refused with a code or read as a sound shape.
        std::vector<Sample> samples = meshSamples();
        samples.push_back({"cube.obj", cubeObjText()});
        samples.push_back({"square.ply", squarePlyText()});
        samples.push_back({"cloud.xyz", "1 2 3 0 0 1\n4 5 6 1 0 0\n7 8 9 0 1 0\n"});
        samples.push_back({"cloud.pts", "3\n1 2 3 9 255 0 0\n4 5 6 9 0 255 0\n7 8 9 9 0 0 255\n"});
        std::mt19937 rng(20261128);
        int refused = 0;
        int loaded = 0;
        const int total = 12000;
        static const char* const hostile[] = {"-1",    "0",           "4294967295", "nan", "1e999",
                                              "99999", "-2147483649", "3",          "7",   "inf"};
        for (int i = 0; i < total; ++i) {
            const Sample& sample = samples[static_cast<std::size_t>(i) % samples.size()];
            std::string bytes = sample.bytes;
            switch (rng() % 5) {
            case 0:
                bytes.resize(rng() % bytes.size());
                break;
            case 1:
                for (int k = 0; k < 1 + static_cast<int>(rng() % 4); ++k) {
                    bytes[rng() % bytes.size()] ^= static_cast<char>(1 << (rng() % 8));
                }
                break;
            case 2:
                bytes.insert(rng() % bytes.size(), 1, static_cast<char>(rng() % 256));
                break;
            case 3:
                bytes.erase(rng() % bytes.size(), 1 + rng() % 8);
                break;
            default: {
                std::size_t at = rng() % bytes.size();
                while (at < bytes.size() && !std::isdigit(static_cast<unsigned char>(bytes[at]))) {
                    ++at;
                }
                std::size_t end = at;
                while (end < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[end]))) {
                    ++end;
                }
                bytes.replace(at, end - at, hostile[rng() % 10]);
            }
            }
            // A new file each time: rewriting one file makes the file system flush it to disk.
            const std::string path =
                write(std::string("m") + std::to_string(i) + "-" + sample.name, bytes);
            const io::ReferenceImportResult result = io::readReferenceShape(path);
            // Read again, the same: no reader may keep what it did not find in the file.
            const io::ReferenceImportResult again = io::readReferenceShape(path);
            QFile::remove(QString::fromStdString(path));
            QVERIFY2(again.shape == result.shape &&
                         again.error.has_value() == result.error.has_value(),
                     qPrintable(QString::number(i)));
            if (result.error) {
                QVERIFY2(result.error->detail.find('\n') == std::string::npos,
                         qPrintable(QString::number(i)));
                QVERIFY(result.shape.points.empty());
                ++refused;
            } else {
                QVERIFY2(isSound(result.shape), qPrintable(QString::number(i)));
                ++loaded;
            }
        }
        QCOMPARE(refused + loaded, total);
        QVERIFY(refused > total / 4);
        qInfo("%d mutations: %d refused, %d read as sound shapes", total, refused, loaded);
    }
};

DEVSURF_REGISTER_TEST(TstReferenceImport);
#include "tst_reference_import.moc"
