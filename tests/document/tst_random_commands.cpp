#include "document_test_support.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/commands/refine_spline_class_command.h"
#include "model/document/commands/relabel_edge_command.h"
#include "model/document/commands/split_at_ruling_command.h"
#include "model/document/commands/subdivide_strip_command.h"
#include "model/examples.h"
#include "model/strip.h"
#include "model/topology_edits.h"
#include "solver/session/solve_session.h"
#include "test_registry.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <random>

using namespace devsurf::document;
using namespace devsurf::model;
using devsurf::test::bytesOf;
using devsurf::test::firstProblem;
using devsurf::test::pushOrExplain;

namespace {

// Pinned vertices never move, bit for bit.
bool pinsKept(const CompositeSurface& before, const CompositeSurface& after) {
    for (VertexId v : before.pinnedVertices()) {
        if (!after.isPinned(v) || !(after.position(v) == before.position(v))) {
            return false;
        }
    }
    return true;
}

template <class Map> auto randomKey(const Map& map, std::mt19937& rng) {
    std::uniform_int_distribution<std::size_t> pick(0, map.size() - 1);
    auto it = map.begin();
    std::advance(it, static_cast<std::ptrdiff_t>(pick(rng)));
    return it->first;
}

} // namespace

class TstRandomCommands : public QObject {
    Q_OBJECT
private slots:
    void thousandRandomCommandsUndoAndRedoExactly() {
        // Four small surfaces in one project, so commands also address different surfaces.
        Project project;
        for (const auto& [name, size] : std::vector<std::pair<std::string, int>>{
                 {"sheet", 2}, {"annulus", 1}, {"cylinder", 3}, {"mixed", 1}}) {
            project.surfaces.push_back(makeExample(name, size).surfaces.front());
        }
        Document doc;
        doc.resetProject(project);
        QSignalSpy spy(&doc, &Document::changed);
        const std::string original = bytesOf(doc);

        std::mt19937 rng(20240611);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::uniform_real_distribution<double> symmetric(-1.0, 1.0);
        std::map<std::string, int> pushed;
        int refused = 0;
        int total = 0;
        int lastSurface = -1;
        int dragCount = 0;
        std::set<VertexId> lastVertices;
        const std::size_t maxFaces = 60;

        while (total < 1000) {
            const int index = static_cast<int>(rng() % 4);
            const CompositeSurface& s = doc.surface(index);
            const Project before = doc.project();
            const double kind = unit(rng);
            std::string type;
            CommandOrError result(QString("no command"));
            if (kind < 0.40) {
                std::set<VertexId> vertices;
                if (index == lastSurface && unit(rng) < 0.4) {
                    vertices = lastVertices; // a repeated nudge: merges
                } else {
                    const int count = 1 + static_cast<int>(rng() % 3);
                    for (int i = 0; i < count; ++i) {
                        vertices.insert(randomKey(s.vertices(), rng));
                    }
                }
                if (unit(rng) < 0.5) {
                    type = "translate";
                    result = MoveVerticesCommand::createTranslation(
                        doc, index, vertices,
                        Vec3(symmetric(rng), symmetric(rng), symmetric(rng)) * 3.0);
                } else {
                    type = "rotate";
                    result = MoveVerticesCommand::createRotation(
                        doc, index, vertices, Vec3(symmetric(rng), symmetric(rng), 0) * 100.0,
                        Vec3(symmetric(rng), symmetric(rng), 1.0), 0.1 * symmetric(rng));
                }
                lastSurface = index;
                lastVertices = vertices;
            } else if (kind < 0.60) {
                type = "relabel";
                const double how = unit(rng);
                std::vector<std::pair<EdgeId, EdgeLabel>> labels;
                auto flip = [&s](EdgeId e) {
                    return std::make_pair(e, s.edge(e).isSpline() ? EdgeLabel::Ruling
                                                                  : EdgeLabel::Spline);
                };
                if (how < 0.5) {
                    labels.push_back(flip(randomKey(s.edges(), rng)));
                } else if (how < 0.85) {
                    // Two opposite sides of a quadrilateral, e.g. planar RRRR ↔ strip SRSR.
                    const FaceId face = randomKey(s.faces(), rng);
                    const auto edges = s.faceEdges(face);
                    if (edges.size() == 4) {
                        const std::size_t first = rng() % 2;
                        labels = {flip(edges[first]), flip(edges[first + 2])};
                    }
                } else {
                    // A whole spline class becomes rulings: its strips and cones turn planar.
                    const auto classes = s.splineClasses();
                    if (!classes.empty()) {
                        for (EdgeId e : classes[rng() % classes.size()]) {
                            labels.emplace_back(e, EdgeLabel::Ruling);
                        }
                    }
                }
                if (!labels.empty()) {
                    result = RelabelEdgeCommand::create(doc, index, labels);
                }
            } else if (kind < 0.70) {
                type = "subdivide";
                if (s.faces().size() < maxFaces) {
                    result = SubdivideStripCommand::create(doc, index, randomKey(s.faces(), rng),
                                                           0.1 + 0.8 * unit(rng));
                }
            } else if (kind < 0.80) {
                type = "split";
                const FaceId face = randomKey(s.faces(), rng);
                const FaceType faceType = s.faceType(face);
                if (s.faces().size() < maxFaces && faceType != FaceType::Planar) {
                    const int n = s.edge(stripOfFace(s, face).aSide.edge).space.intervals;
                    if (n >= 2) {
                        result = SplitAtRulingCommand::create(
                            doc, index, face, 1 + static_cast<int>(rng() % (n - 1)));
                    }
                }
            } else if (kind < 0.90) {
                type = "refine";
                const EdgeId edge = randomKey(s.edges(), rng);
                if (s.edge(edge).isSpline() && s.edge(edge).space.intervals <= 4) {
                    result = RefineSplineClassCommand::create(doc, index, edge);
                }
            } else if (kind < 0.95) {
                type = "pin";
                std::set<VertexId> vertices;
                for (int i = 0; i < 1 + static_cast<int>(rng() % 3); ++i) {
                    vertices.insert(randomKey(s.vertices(), rng));
                }
                result = PinVerticesCommand::create(doc, index, vertices, unit(rng) < 0.7);
            } else if (kind < 0.965) {
                // Solve, as the application's Solve does it: a few iterations on the whole
                // surface, pins kept, applied as one command.
                type = "solve";
                try {
                    devsurf::solver::SolveSession session(s, {});
                    if (session.step(2).succeeded()) {
                        QVERIFY(pinsKept(s, session.surface()));
                        result =
                            ApplySurfaceCommand::create(doc, index, session.surface(), "Solve");
                    }
                } catch (const std::invalid_argument&) {
                    // A random edit can leave a surface the solver refuses: nothing happens.
                }
            } else if (kind < 0.98) {
                // A drag: one vertex pulled along three mouse positions, one iteration each,
                // every result merged into one undo step.
                type = "drag";
                const VertexId v = randomKey(s.vertices(), rng);
                const Vec3 by(symmetric(rng), symmetric(rng), symmetric(rng));
                std::vector<CompositeSurface> moves;
                try {
                    devsurf::solver::SolveSession session(s, {{v, false, s.position(v)}});
                    for (int step = 1; step <= 3; ++step) {
                        session.setHandleTarget(v, s.position(v) + by * (step / 3.0));
                        if (!session.step(1).succeeded()) {
                            break;
                        }
                        QVERIFY(pinsKept(s, session.surface()));
                        moves.push_back(session.surface());
                    }
                } catch (const std::invalid_argument&) {
                }
                // A solver result the model refuses (a random edit can leave the solver a
                // degenerate start) ends the drag before anything is pushed.
                const bool valid =
                    moves.size() == 3 &&
                    std::all_of(moves.begin(), moves.end(),
                                [](const CompositeSurface& m) { return firstProblem(m).empty(); });
                if (valid) {
                    const int key = 100 + dragCount++;
                    for (int step = 0; step < 2; ++step) {
                        QVERIFY(pushOrExplain(
                                    doc, ApplySurfaceCommand::create(doc, index, moves[step],
                                                                     "Drag", Change::Geometry, key))
                                    .isEmpty());
                    }
                    result = ApplySurfaceCommand::create(doc, index, moves[2], "Drag",
                                                         Change::Geometry, key);
                }
            } else {
                type = "apply";
                CompositeSurface solved = s;
                const VertexId v = randomKey(s.vertices(), rng);
                solved.moveVertex(v, s.position(v) + Vec3(0, 0, symmetric(rng)));
                result = ApplySurfaceCommand::create(doc, index, solved, "Solve", Change::Geometry,
                                                     unit(rng) < 0.5 ? 1 : -1);
            }
            if (result.isRefused()) {
                ++refused;
                QVERIFY(doc.project() == before);
                continue;
            }
            const int signalCount = spy.count();
            const quint64 revision = doc.revision();
            QVERIFY(pushOrExplain(doc, std::move(result)).isEmpty());
            QCOMPARE(spy.count(), signalCount + 1);
            QVERIFY(doc.revision() > revision);
            const std::string problem = firstProblem(doc.surface(index));
            QVERIFY2(problem.empty(), (type + ": " + problem).c_str());
            ++pushed[type];
            ++total;
        }
        for (const char* type : {"translate", "rotate", "relabel", "subdivide", "split", "refine",
                                 "pin", "solve", "drag", "apply"}) {
            qInfo("%s: %d", type, pushed[type]);
            QVERIFY2(pushed[type] >= 10, type);
        }
        qInfo("pushed %d commands (%d undo steps after merging), %d random edits refused", total,
              doc.undoStack()->count(), refused);
        QVERIFY(doc.undoStack()->count() < total); // some moves merged

        const std::string final = bytesOf(doc);
        QVERIFY(doc.project() == devsurf::io::decodeProject(final));
        while (doc.undoStack()->canUndo()) {
            doc.undoStack()->undo();
            for (const CompositeSurface& s : doc.project().surfaces) {
                QVERIFY2(firstProblem(s).empty(), firstProblem(s).c_str());
            }
        }
        QVERIFY(bytesOf(doc) == original);
        while (doc.undoStack()->canRedo()) {
            doc.undoStack()->redo();
        }
        QVERIFY(bytesOf(doc) == final);
    }
};

DEVSURF_REGISTER_TEST(TstRandomCommands);
#include "tst_random_commands.moc"
