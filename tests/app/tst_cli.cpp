#include "cli_run.h"
#include "helical_band.h"
#include "io/project_file.h"
#include "model/examples.h"
#include "test_registry.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <set>

using namespace devsurf;

namespace {

using Run = test::CliRun;
using test::runCli;

} // namespace

class TstCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const char* name) const { return m_dir.filePath(QString::fromUtf8(name)); }

private slots:
    void helpAndVersion() {
        Run run = runCli({"--help"});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("export-json"));
        run = runCli({"info", "--help"});
        QCOMPARE(run.exitCode, 0);
        run = runCli({"--version"});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.startsWith("devsurf-cli "));
    }

    void pinAndListVertices() {
        const QString file = path("pin.devsurf");
        QCOMPARE(runCli({"example", "sheet", "--as-built", "-o", file}).exitCode, 0);
        const QString pinned = path("pinned.devsurf");
        Run run = runCli({"pin", file, "--vertices", "0,3,12", "-o", pinned});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(io::loadProjectFile(pinned).surfaces[0].pinnedVertices(),
                 (std::set<model::VertexId>{0, 3, 12}));
        run = runCli({"pin", pinned, "--vertices", "3", "--unpin", "-o", pinned});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(io::loadProjectFile(pinned).surfaces[0].pinnedVertices(),
                 (std::set<model::VertexId>{0, 12}));

        // The listing as JSON: every vertex with its position, pin and boundary flag.
        run = runCli({"info", pinned, "--vertices", "--edges", "--json"});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject surface =
            QJsonDocument::fromJson(run.out.toUtf8()).object()["surfaces"].toArray()[0].toObject();
        const QJsonArray vertices = surface["vertices"].toArray();
        QCOMPARE(vertices.size(), 16);
        int pins = 0;
        int interior = 0;
        for (const QJsonValue& v : vertices) {
            pins += v["pinned"].toBool() ? 1 : 0;
            interior += v["boundary"].toBool() ? 0 : 1;
        }
        QCOMPARE(pins, 2);
        QCOMPARE(interior, 4); // the 3 × 3 sheet has a 2 × 2 block of interior vertices
        QCOMPARE(vertices[15]["position"].toArray()[0].toDouble(), 300.0);
        const QJsonArray edges = surface["edges"].toArray();
        QCOMPARE(edges.size(), 24);
        int creases = 0;
        for (const QJsonValue& e : edges) {
            creases += e["kind"].toString() == "crease" ? 1 : 0;
            // The flat sheet's creases are unfolded; rulings and boundaries have no fold.
            QCOMPARE(e["assignment"].toString(), QString(e["kind"] == "crease" ? "F" : ""));
            QVERIFY(std::abs(e["foldAngle"].toDouble()) < 0.1);
        }
        QCOMPARE(creases, 6); // two interior curves of three S-edges each
        run = runCli({"info", pinned, "--vertices"});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("    0 0 0 0 pinned boundary\n"));
        QVERIFY(run.out.contains("    5 100 100 0 free interior\n"));

        // Bad ids: one sentence naming them, the output untouched.
        run = runCli({"pin", file, "--vertices", "0,99", "-o", path("never.devsurf")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("99"));
        QCOMPARE(run.err.count('\n'), 1);
        QVERIFY(!QFile::exists(path("never.devsurf")));
        run = runCli({"pin", file, "--vertices", "a,b", "-o", path("never.devsurf")});
        QCOMPARE(run.exitCode, 1);
        QCOMPARE(runCli({"pin", file, "-o", path("never.devsurf")}).exitCode, 1);
        QCOMPARE(runCli({"info", file, "--json"}).exitCode, 1);
    }

    void badUsageExitsWithOne() {
        for (const QStringList& args :
             QList<QStringList>{{},
                                {"frobnicate"},
                                {"example", "annulus"},
                                {"example", "klein-bottle", "-o", path("t.devsurf")},
                                {"example", "sheet", "--size", "abc", "-o", path("t.devsurf")},
                                {"example", "sheet", "--size", "0", "-o", path("t.devsurf")},
                                {"info"},
                                {"info", "a", "b"},
                                {"export-json", path("x.devsurf")},
                                {"validate", "--bogus", "x"}}) {
            const Run run = runCli(args);
            QVERIFY2(run.exitCode == 1, qPrintable(args.join(' ')));
            QVERIFY(run.err.startsWith("devsurf-cli: "));
            QCOMPARE(run.err.count('\n'), 1);
        }
    }

    void exampleInfoValidateExport() {
        const QString file = path("a.devsurf");
        Run run = runCli({"example", "annulus", "-o", file});
        QCOMPARE(run.exitCode, 0);
        // Held by default, as File ▸ New from Example makes it; --as-built as it comes.
        QVERIFY(io::loadProjectFile(file) ==
                model::makeExample("annulus", 0, model::ExampleSheet::Held));
        QVERIFY(run.out.contains("holding its sheet"));
        const QString asBuilt = path("as-built.devsurf");
        QCOMPARE(runCli({"example", "annulus", "--as-built", "-o", asBuilt}).exitCode, 0);
        QVERIFY(io::loadProjectFile(asBuilt) == model::makeExample("annulus"));

        run = runCli({"info", file});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains(
            "Faces: 48 (48 SRSR strips, 0 SRS strips, 0 SRR cones, 0 planar faces)"));
        QVERIFY(run.out.contains("Spline spaces: degree 3, C2, 3 intervals (56 S-edges)"));
        QVERIFY(run.out.contains("Control points: 280"));
        QVERIFY(run.out.contains("Vertices: 56"));
        QVERIFY(run.out.contains("Edges: 56 S, 48 R"));

        run = runCli({"validate", file});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("valid"));

        const QString json = path("a.json");
        run = runCli({"export-json", file, "-o", json, "--samples", "3"});
        QCOMPARE(run.exitCode, 0);
        QFile jsonFile(json);
        QVERIFY(jsonFile.open(QIODevice::ReadOnly));
        const QJsonDocument doc = QJsonDocument::fromJson(jsonFile.readAll());
        QCOMPARE(doc.object()["format"].toString(), QString("devsurf-interchange"));

        run = runCli({"example", "mixed", "--as-built", "--size", "3", "-o", path("m.devsurf")});
        QCOMPARE(run.exitCode, 0);
        run = runCli({"info", path("m.devsurf")});
        QVERIFY(run.out.contains("1 SRSR strip, 1 SRS strip, 1 SRR cone, 1 planar face"));
    }

    void damagedInputExitsWithTwo() {
        const QString file = path("d.devsurf");
        QCOMPARE(runCli({"example", "sheet", "--as-built", "-o", file}).exitCode, 0);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QByteArray bytes = f.readAll();
        bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x10);
        f.seek(0);
        f.write(bytes);
        f.close();
        for (const char* command : {"info", "validate", "export-json"}) {
            QStringList args{command, file};
            if (QString(command) == "export-json") {
                args << "-o" << path("d.json");
            }
            const Run run = runCli(args);
            QCOMPARE(run.exitCode, 2);
            QVERIFY(run.err.contains("d.devsurf"));
            QVERIFY(run.err.contains("checksum"));
            QCOMPARE(run.err.count('\n'), 1);
        }
        QVERIFY(!QFile::exists(path("d.json")));
        const Run missing = runCli({"info", path("nothing-here.devsurf")});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY(missing.err.contains("nothing-here.devsurf"));
    }

    void invalidSurfaceListsEveryProblem() {
        // Written by the encoder (which does not validate), refused by every reader.
        model::Project project = model::makeExample("sheet", 2);
        model::CompositeSurface& surface = project.surfaces[0];
        surface.setRuling(surface.faceEdges(0)[0]); // SRSR → RRSR
        surface.setRuling(surface.faceEdges(3)[2]); // another face broken
        const QString file = path("invalid.devsurf");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        const std::string bytes = io::encodeProject(project);
        f.write(bytes.data(), static_cast<qint64>(bytes.size()));
        f.close();
        const Run run = runCli({"validate", file});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("Patch 0 is labelled RRSR"));
        QVERIFY(run.err.contains("Patch 3 is labelled"));
        QCOMPARE(runCli({"info", file}).exitCode, 2);
    }

    void allZeroCoordinatesAreRefusedEverywhere() {
        // A sound archive and checksum around a design whose every coordinate is zero.
        model::Project project = model::makeExample("sheet", 2);
        model::CompositeSurface& surface = project.surfaces[0];
        const model::CompositeSurface original = surface;
        for (const auto& [id, p] : original.vertices()) {
            surface.moveVertex(id, {0, 0, 0});
        }
        for (const auto& [id, record] : original.edges()) {
            if (record.isSpline()) {
                surface.setControlPoints(
                    id, std::vector<model::Vec3>(record.controlPoints.size(), model::Vec3{}));
            }
        }
        const QString file = path("zero.devsurf");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        const std::string bytes = io::encodeProject(project);
        f.write(bytes.data(), static_cast<qint64>(bytes.size()));
        f.close();
        const Run run = runCli({"validate", file});
        QCOMPARE(run.exitCode, 2);
        const QString first = run.err.section('\n', 0, 0);
        QVERIFY2(first.contains("zero.devsurf"), qPrintable(first));
        QVERIFY(run.err.contains("Patch 0 has zero area."));
        QVERIFY(run.err.contains("has zero length."));
        const Run solve = runCli({"solve", file, "-o", path("zero-solved.devsurf")});
        QCOMPARE(solve.exitCode, 2);
        QVERIFY(solve.err.contains("zero.devsurf"));
        QVERIFY(!QFile::exists(path("zero-solved.devsurf")));
    }

    void solvePrintsOneLinePerIteration() {
        const QString file = path("solve.devsurf");
        QCOMPARE(runCli({"example", "annulus", "--as-built", "-o", file}).exitCode, 0);
        const QString out = path("solved.devsurf");
        const Run run =
            runCli({"solve", file, "--perturb", "0.001", "--iterations", "3", "-o", out});
        QCOMPARE(run.exitCode, 0);
        const QStringList lines = run.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 10);
        QVERIFY2(QRegularExpression("^Surface 1 \\(annulus\\): \\d+ variables, \\d+ rows$")
                     .match(lines[0])
                     .hasMatch(),
                 qPrintable(lines[0]));
        for (int i = 1; i <= 3; ++i) {
            const QRegularExpression line(
                QStringLiteral("^iteration +%1  residual \\S+  assembly \\S+ ms  factorisation "
                               "\\S+ ms  solve \\S+ ms  flatness mean \\S+ max \\S+, \\|K\\| mean "
                               "\\S+ max \\S+, det mean \\S+ max \\S+$")
                    .arg(i));
            QVERIFY2(line.match(lines[i]).hasMatch(), qPrintable(lines[i]));
        }
        QVERIFY2(lines[4].startsWith("Reached the tolerance") ||
                     lines[4].startsWith("Did not reach the tolerance"),
                 qPrintable(lines[4]));
        QVERIFY2(lines[5] == "No face folds over onto itself." ||
                     lines[5].startsWith("Folded over onto itself: face "),
                 qPrintable(lines[5]));
        // (A rough start's development may overlap itself; this line says either way.)
        QVERIFY2(lines[6] == "The development does not overlap itself." ||
                     lines[6].startsWith("The development overlaps itself at patch"),
                 qPrintable(lines[6]));
        // The verdict (solver::verdictOf, worded as the Solver panel words it) and its numbers.
        QVERIFY2(lines[7].startsWith("Verdict: Developable") ||
                     lines[7].startsWith("Verdict: Not developable"),
                 qPrintable(lines[7]));
        QVERIFY2(lines[8].startsWith("  Largest constraint residual "), qPrintable(lines[8]));
        QCOMPARE(lines[9], "Wrote " + out);
    }

    void solveAndDragSayWhereTheDevelopmentOverlapsItself() {
        // A band winding one and a half times round the z-axis: whatever the solver makes of
        // its strips, its development turns by more than a full turn and overlaps itself.
        model::Project project;
        project.surfaces.push_back(test::helicalBand());
        const QString file = path("band.devsurf");
        io::saveProjectFile(project, file);
        auto namedPatches = [](const QString& out) {
            const QRegularExpressionMatch match =
                QRegularExpression(
                    QStringLiteral("^The development overlaps itself at patch(es)? "
                                   "([0-9, ]+?)(, …)? and cannot be cut from one sheet\\.$"),
                    QRegularExpression::MultilineOption)
                    .match(out);
            std::set<int> patches;
            for (const QString& id : match.captured(2).split(QStringLiteral(", "))) {
                patches.insert(id.toInt());
            }
            return match.hasMatch() ? patches : std::set<int>{};
        };
        Run run = runCli({"solve", file, "--iterations", "2", "-o", path("band-solved.devsurf")});
        QCOMPARE(run.exitCode, 0);
        std::set<int> patches = namedPatches(run.out);
        QVERIFY2(!patches.empty(), qPrintable(run.out));
        for (int face : patches) {
            QVERIFY(project.surfaces.front().hasFace(static_cast<model::FaceId>(face)));
        }
        run = runCli({"drag", file, "--vertices", "0", "--by", "0,0,5", "--steps", "2", "--after",
                      "2", "-o", path("band-dragged.devsurf")});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(!namedPatches(run.out).empty(), qPrintable(run.out));
    }

    void creaseConditionsAreSetListedAndSolved() {
        const QString file = path("annulus-crease.devsurf");
        QCOMPARE(runCli({"example", "annulus", "--as-built", "-o", file}).exitCode, 0);
        const model::CompositeSurface surface = io::loadProjectFile(file).surfaces[0];
        model::EdgeId crease = model::kInvalidId;
        model::EdgeId boundary = model::kInvalidId;
        for (const auto& [id, record] : surface.edges()) {
            if (record.isSpline()) {
                (surface.facesOfEdge(id).size() == 2 ? crease : boundary) = id;
            }
        }
        const QString out = path("creased.devsurf");
        Run run = runCli({"crease", file, "--edges", QString::number(crease), "--condition",
                          "curved-fold", "-o", out});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(io::loadProjectFile(out).surfaces[0].edge(crease).condition,
                 model::CreaseCondition::CurvedFold);
        run = runCli({"info", out, "--edges"});
        QVERIFY(run.out.contains(QString("    %1 S ").arg(crease)));
        QVERIFY(run.out.contains("crease curved-fold F "));
        // The flat annulus satisfies the condition: solving keeps it as it is.
        QCOMPARE(runCli({"solve", out, "-o", path("creased-solved.devsurf")}).exitCode, 0);
        // A boundary curve is no crease (input error, exit 2); a bad or unsolved condition and
        // missing options are usage errors (exit 1); nothing is written.
        const QString never = path("never-creased.devsurf");
        run = runCli({"crease", file, "--edges", QString::number(boundary), "--condition",
                      "geodesic", "-o", never});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains(QString::number(boundary)));
        QCOMPARE(run.err.count('\n'), 1);
        QCOMPARE(runCli({"crease", file, "--edges", QString::number(crease), "--condition",
                         "folded", "-o", never})
                     .exitCode,
                 1);
        QCOMPARE(runCli({"crease", file, "--condition", "none", "-o", never}).exitCode, 1);
        QVERIFY(!QFile::exists(never));
    }

    void straightConditionAndSmoothRulingsAreSetAndListed() {
        const QString file = path("sheet-smooth.devsurf");
        QCOMPARE(runCli({"example", "sheet", "--as-built", "-o", file}).exitCode, 0);
        const model::CompositeSurface surface = io::loadProjectFile(file).surfaces[0];
        model::EdgeId crease = model::kInvalidId;
        model::EdgeId inner = model::kInvalidId;
        model::EdgeId outer = model::kInvalidId;
        for (const auto& [id, record] : surface.edges()) {
            const bool shared = surface.facesOfEdge(id).size() == 2;
            if (record.isSpline()) {
                crease = shared ? id : crease;
            } else {
                (shared ? inner : outer) = id;
            }
        }
        const QString straight = path("sheet-straight.devsurf");
        QCOMPARE(runCli({"crease", file, "--edges", QString::number(crease), "--condition",
                         "straight", "-o", straight})
                     .exitCode,
                 0);
        QCOMPARE(io::loadProjectFile(straight).surfaces[0].edge(crease).condition,
                 model::CreaseCondition::Straight);
        const QString smooth = path("sheet-smooth-on.devsurf");
        Run run = runCli({"smooth", straight, "--edges", QString::number(inner), "-o", smooth});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(io::loadProjectFile(smooth).surfaces[0].edge(inner).smooth);
        run = runCli({"info", smooth, "--edges"});
        QVERIFY2(run.out.contains(QString("    %1 R ").arg(inner)), qPrintable(run.out));
        QVERIFY(run.out.contains(" smooth\n"));
        run = runCli({"info", smooth, "--edges", "--json"});
        QVERIFY(run.out.contains("\"smooth\": true"));
        const QString sharp = path("sheet-smooth-off.devsurf");
        QCOMPARE(runCli({"smooth", smooth, "--edges", QString::number(inner), "--off", "-o", sharp})
                     .exitCode,
                 0);
        QVERIFY(io::loadProjectFile(sharp).surfaces[0] ==
                io::loadProjectFile(straight).surfaces[0]);
        // A boundary ruling and a curve are refused (input error, exit 2), nothing written.
        const QString never = path("never-smooth.devsurf");
        for (model::EdgeId edge : {outer, crease}) {
            run = runCli({"smooth", file, "--edges", QString::number(edge), "-o", never});
            QCOMPARE(run.exitCode, 2);
            QVERIFY(run.err.contains(QString::number(edge)));
        }
        QCOMPARE(runCli({"smooth", file, "-o", never}).exitCode, 1);
        QVERIFY(!QFile::exists(never));
    }

    void benchIsTheSeparateProgram() {
        const Run run = runCli({"bench"});
        QCOMPARE(run.exitCode, 1);
        QVERIFY(run.err.contains("devsurf-bench"));
    }
};

DEVSURF_REGISTER_TEST(TstCli);
#include "tst_cli.moc"
