#include "io/crc32.h"
#include "io/file_error.h"
#include "io/project_file.h"
#include "model/examples.h"
#include "test_registry.h"

#include <QTest>

#include <cctype>
#include <cmath>
#include <random>

using namespace devsurf;

namespace {

// Rebuilds a valid envelope around a changed payload, so that the mutation reaches the archive
// parser instead of being caught by the length or checksum test.
std::string withEnvelope(const std::string& original, const std::string& payload) {
    std::string bytes = original.substr(0, 12);
    const std::uint64_t length = payload.size();
    for (int i = 0; i < 8; ++i) {
        bytes.push_back(static_cast<char>((length >> (8 * i)) & 0xFF));
    }
    const std::uint32_t crc = io::crc32(payload.data(), payload.size());
    for (int i = 0; i < 4; ++i) {
        bytes.push_back(static_cast<char>((crc >> (8 * i)) & 0xFF));
    }
    return bytes + payload;
}

// Replaces one number token of the archive with a hostile value.
std::string changeNumber(const std::string& payload, std::mt19937& rng) {
    std::vector<std::pair<std::size_t, std::size_t>> tokens;
    for (std::size_t i = 0; i < payload.size();) {
        if (std::isdigit(static_cast<unsigned char>(payload[i])) || payload[i] == '-') {
            std::size_t j = i + 1;
            while (j < payload.size() && payload[j] != ' ' && payload[j] != '\n') {
                ++j;
            }
            tokens.emplace_back(i, j - i);
            i = j;
        } else {
            ++i;
        }
    }
    const auto [at, length] = tokens[rng() % tokens.size()];
    static const char* const hostile[] = {
        "0", "1", "2",     "-1",  "4294967295", "4294967296", "2147483647", "99999999999",
        "3", "7", "1e308", "nan", "-0",         "65536",      "1000000",    "18446744073709551615"};
    std::string value = hostile[rng() % (sizeof hostile / sizeof *hostile)];
    if (rng() % 4 == 0) {
        value = std::to_string(static_cast<int>(rng() % 200) - 20);
    }
    return payload.substr(0, at) + value + payload.substr(at + length);
}

std::string mutate(const std::string& good, std::mt19937& rng, int kind) {
    const std::string payload = good.substr(io::kProjectHeaderSize);
    std::string bytes = good;
    switch (kind) {
    case 0: // truncation
        return good.substr(0, rng() % good.size());
    case 1: { // bit flips anywhere
        const int flips = 1 + static_cast<int>(rng() % 3);
        for (int i = 0; i < flips; ++i) {
            bytes[rng() % bytes.size()] ^= static_cast<char>(1 << (rng() % 8));
        }
        return bytes;
    }
    case 2: // byte insertion
        bytes.insert(bytes.begin() + static_cast<long>(rng() % bytes.size()),
                     static_cast<char>(rng() % 256));
        return bytes;
    case 3: { // header fields: version and length
        const std::size_t field = rng() % 2 == 0 ? 8 + rng() % 4 : 12 + rng() % 8;
        bytes[field] = static_cast<char>(rng() % 256);
        return bytes;
    }
    case 4: { // bit flips inside the payload with a valid envelope
        std::string changed = payload;
        changed[rng() % changed.size()] ^= static_cast<char>(1 << (rng() % 8));
        return withEnvelope(good, changed);
    }
    case 5: // changed counts, ids, versions and values with a valid envelope
        return withEnvelope(good, changeNumber(payload, rng));
    case 6: { // truncated payload with a valid envelope
        return withEnvelope(good, payload.substr(0, rng() % payload.size()));
    }
    default: { // deleted or duplicated span with a valid envelope
        const std::size_t at = rng() % payload.size();
        const std::size_t length = 1 + rng() % 16;
        std::string changed = payload;
        if (rng() % 2 == 0) {
            changed.erase(at, length);
        } else {
            changed.insert(at, payload.substr(at, length));
        }
        return withEnvelope(good, changed);
    }
    }
}

// The project with two reference curves, so that mutations reach their counts and points.
model::Project withReferenceCurves(model::Project project) {
    project.referenceCurves.push_back({"LINE 1", "0", {{0, 0, 0}, {10, 20, 30}}});
    project.referenceCurves.push_back(
        {"SPLINE 2", "GUIDES", {{1, 2, 3}, {4.5, 5.25, -6}, {7, 8, 9.125}, {10, 11, 12}}});
    return project;
}

// The project with a small mesh (with normals) and a point cloud, so that mutations reach their
// counts, coordinates and triangle corners.
model::Project withSmallReferenceShapes(model::Project project) {
    model::ReferenceShape mesh{"tetrahedron",
                               "tet.off",
                               {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}},
                               {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0.5}},
                               {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
    project.referenceShapes.push_back(mesh);
    project.referenceShapes.push_back({"scan", "", {{1, 2, 3}, {-4.5, 5, 6.25}}, {}, {}});
    return project;
}

// The sheet example holding its sheet on a rectangle with two crease curves, one crease on each.
model::Project withCreaseCurves(model::Project project) {
    model::CompositeSurface& surface = project.surfaces.front();
    surface.setKeepsDevelopment(true);
    model::SheetDomain d;
    d.shape = model::SheetShape::Rectangle;
    d.width = 300.0;
    d.height = 300.0;
    d.creaseCurves = {{{{-150, 0}, {0, 10}, {150, 0}}, false},
                      {{{-20, -20}, {20, -20}, {0, 20}}, true}};
    d.creaseCurveOf = {{surface.edges().begin()->first, 0}, {surface.edges().rbegin()->first, 1}};
    surface.setSheetDomain(d);
    return project;
}

// Whatever loads holds only shapes that the application can draw and measure.
bool shapesAreSound(const model::Project& project) {
    for (const model::ReferenceShape& shape : project.referenceShapes) {
        if (shape.points.empty() ||
            (!shape.normals.empty() && shape.normals.size() != shape.points.size())) {
            return false;
        }
        for (const std::vector<model::Vec3>* list : {&shape.points, &shape.normals}) {
            for (const model::Vec3& p : *list) {
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                    return false;
                }
            }
        }
        for (const std::array<int, 3>& t : shape.triangles) {
            for (int corner : t) {
                if (corner < 0 || static_cast<std::size_t>(corner) >= shape.points.size()) {
                    return false;
                }
            }
        }
    }
    return true;
}

} // namespace

class TstProjectFuzz : public QObject {
    Q_OBJECT
private slots:
    void mutatedFilesAreRejectedOrValid() {
        // Small documents keep each parse cheap so that the sanitizer build runs all of them.
        const std::vector<std::string> originals{
            io::encodeProject(model::makeExample("mixed", 1)),
            io::encodeProject(model::makeExample("sheet", 2)),
            io::encodeProject(model::makeExample("cylinder", 3)),
            io::encodeProject(withReferenceCurves(model::makeExample("sheet", 1))),
            io::encodeProject(withSmallReferenceShapes(model::makeExample("sheet", 1))),
            io::encodeProject(withCreaseCurves(model::makeExample("sheet", 1))),
        };
        std::mt19937 rng(20261121);
        int rejected = 0;
        int loaded = 0;
        const int total = 15000;
        for (int i = 0; i < total; ++i) {
            const std::string& good = originals[static_cast<std::size_t>(i) % originals.size()];
            const std::string bytes = mutate(good, rng, i % 8);
            try {
                const model::Project project = io::decodeProject(bytes);
                for (const auto& surface : project.surfaces) {
                    QVERIFY2(surface.validate().empty(), qPrintable(QString::number(i)));
                }
                for (const auto& curve : project.referenceCurves) {
                    QVERIFY2(curve.points.size() >= 2, qPrintable(QString::number(i)));
                    for (const model::Vec3& p : curve.points) {
                        QVERIFY(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
                    }
                }
                QVERIFY2(shapesAreSound(project), qPrintable(QString::number(i)));
                ++loaded;
            } catch (const io::FileError& error) {
                const std::string message = error.what();
                QVERIFY2(!message.empty() && message.find('\n') == std::string::npos,
                         qPrintable(QString::number(i)));
                ++rejected;
            }
        }
        QCOMPARE(loaded + rejected, total);
        // Most mutations must be caught; some (a changed coordinate) legitimately load.
        QVERIFY(rejected > total / 2);
        qInfo("%d mutations: %d rejected with a message, %d loaded and valid", total, rejected,
              loaded);
    }

    void damagedSignatureLengthIsRejectedBeforeAllocating() {
        // The archive starts with the length of its signature; Boost would allocate whatever
        // a damaged length says (4 GB here) before comparing the signature.
        const std::string good = io::encodeProject(model::makeExample("mixed", 1));
        const std::string payload = good.substr(io::kProjectHeaderSize);
        QVERIFY(payload.compare(0, 3, "22 ") == 0);
        try {
            io::decodeProject(withEnvelope(good, "4000000000" + payload.substr(2)));
            QFAIL("a damaged signature loaded");
        } catch (const io::FileError& error) {
            QVERIFY2(std::string(error.what()).find("archive signature") != std::string::npos,
                     error.what());
        }
    }

    void randomBytesAreRejected() {
        std::mt19937 rng(7);
        for (int i = 0; i < 500; ++i) {
            std::string bytes(rng() % 300, '\0');
            for (char& c : bytes) {
                c = static_cast<char>(rng() % 256);
            }
            if (i % 2 == 0 && bytes.size() >= 8) {
                bytes.replace(0, 8, std::string("DEVSURF\0", 8));
            }
            QVERIFY_THROWS_EXCEPTION(io::FileError, io::decodeProject(bytes));
        }
    }
};

DEVSURF_REGISTER_TEST(TstProjectFuzz);
#include "tst_project_fuzz.moc"
