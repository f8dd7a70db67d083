#include "document_test_support.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/commands/crease_condition_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/commands/reference_curves_command.h"
#include "model/document/commands/reference_shapes_command.h"
#include "model/document/commands/refine_spline_class_command.h"
#include "model/document/commands/relabel_edge_command.h"
#include "model/document/commands/smooth_rulings_command.h"
#include "model/document/commands/split_at_ruling_command.h"
#include "model/document/commands/subdivide_strip_command.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "model/strip.h"
#include "model/topology_edits.h"
#include "test_registry.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <set>

using namespace devsurf::document;
using namespace devsurf::model;
using devsurf::test::bytesOf;
using devsurf::test::firstProblem;
using devsurf::test::pushOrExplain;

namespace {

using devsurf::test::kExamples;

using devsurf::test::firstFaceOfType;

// A relabelling the surface accepts: one edge if any works, else a whole spline class to R
// (which turns the strips along it into planar faces).
CommandOrError someRelabel(Document& doc) {
    const CompositeSurface& s = doc.surface(0);
    for (const auto& [id, record] : s.edges()) {
        const EdgeLabel flipped = record.isSpline() ? EdgeLabel::Ruling : EdgeLabel::Spline;
        CommandOrError result = RelabelEdgeCommand::create(doc, 0, id, flipped);
        if (result) {
            return result;
        }
    }
    std::vector<std::pair<EdgeId, EdgeLabel>> labels;
    const auto classes = s.splineClasses();
    for (EdgeId e : classes.front()) {
        labels.emplace_back(e, EdgeLabel::Ruling);
    }
    return RelabelEdgeCommand::create(doc, 0, labels);
}

} // namespace

class TstCommands : public QObject {
    Q_OBJECT

    // Pushes the command, then undo and redo, comparing the saved bytes each time.
    void redoUndoRedo(Document& doc, CommandOrError result, const char* what) {
        QVERIFY2(result, qPrintable(QString("%1 refused: %2").arg(what, result.error())));
        QVERIFY(!result.command()->text().isEmpty());
        QSignalSpy spy(&doc, &Document::changed);
        const std::string original = bytesOf(doc);
        const quint64 revision0 = doc.revision();
        const int count = doc.undoStack()->count();
        QVERIFY(pushOrExplain(doc, std::move(result)).isEmpty());
        QCOMPARE(doc.undoStack()->count(), count + 1);
        const std::string edited = bytesOf(doc);
        QVERIFY2(edited != original, what);
        QCOMPARE(spy.count(), 1);
        const quint64 revision1 = doc.revision();
        QVERIFY(revision1 > revision0);
        for (const CompositeSurface& s : doc.project().surfaces) {
            QVERIFY2(firstProblem(s).empty(), firstProblem(s).c_str());
        }
        doc.undoStack()->undo();
        QVERIFY2(bytesOf(doc) == original, what);
        QCOMPARE(spy.count(), 2);
        QVERIFY(doc.revision() > revision1);
        const quint64 revision2 = doc.revision();
        doc.undoStack()->redo();
        QVERIFY2(bytesOf(doc) == edited, what);
        QCOMPARE(spy.count(), 3);
        QVERIFY(doc.revision() > revision2);
        QVERIFY(doc.project() == devsurf::io::decodeProject(edited));
    }

private slots:
    void documentBasics() {
        Document doc;
        QSignalSpy changed(&doc, &Document::changed);
        QSignalSpy reset(&doc, &Document::projectReset);
        QSignalSpy modified(&doc, &Document::modifiedChanged);
        doc.resetProject(makeExample("mixed"), "/tmp/x.devsurf");
        QCOMPARE(reset.count(), 1);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.takeFirst().at(0).value<Changes>(), Changes(Change::Everything));
        QCOMPARE(doc.surfaceCount(), 1);
        QCOMPARE(doc.filePath(), QString("/tmp/x.devsurf"));
        QVERIFY(!doc.isModified());
        QVERIFY(pushOrExplain(doc, MoveVerticesCommand::createTranslation(doc, 0, {0}, {1, 0, 0}))
                    .isEmpty());
        QCOMPARE(changed.takeFirst().at(0).value<Changes>(), Changes(Change::Geometry));
        QVERIFY(doc.isModified());
        QVERIFY(modified.count() >= 1);
        QCOMPARE(modified.last().at(0).toBool(), true);
        doc.markSaved();
        QVERIFY(!doc.isModified());
        doc.undoStack()->undo();
        QVERIFY(doc.isModified());
        // Unknown surface: refused.
        const CommandOrError refused =
            MoveVerticesCommand::createTranslation(doc, 3, {0}, {1, 0, 0});
        QVERIFY(refused.isRefused());
        QVERIFY(!refused.error().isEmpty());
    }

    void selectionIsInterfaceState() {
        Selection selection;
        QSignalSpy spy(&selection, &Selection::selectionChanged);
        selection.add({Pick::Kind::Vertex, 0, 3});
        selection.add({Pick::Kind::Vertex, 0, 3});
        QCOMPARE(spy.count(), 1);
        selection.toggle({Pick::Kind::Face, 0, 1});
        QCOMPARE(selection.picks().size(), std::size_t(2));
        selection.prune([](const Pick& p) { return p.kind == Pick::Kind::Face; });
        QCOMPARE(selection.picks().size(), std::size_t(1));
        QVERIFY(selection.contains({Pick::Kind::Face, 0, 1}));
        selection.clear();
        QVERIFY(selection.isEmpty());
        QCOMPARE(spy.count(), 4);
    }

    void everyCommandOnEveryExample() {
        for (const char* name : kExamples) {
            Document doc;
            doc.resetProject(makeExample(name));
            const CompositeSurface& s = doc.surface(0);
            const VertexId first = s.vertices().begin()->first;
            redoUndoRedo(doc, PinVerticesCommand::create(doc, 0, {first, first + 1}, true), "pin");
            redoUndoRedo(doc, PinVerticesCommand::create(doc, 0, {first + 1}, false), "unpin");
            // A curved fold on the first crease, where the example has one, then cleared.
            EdgeId crease = kInvalidId;
            for (const auto& [edge, record] : s.edges()) {
                if (crease == kInvalidId && record.isSpline() && s.facesOfEdge(edge).size() == 2) {
                    crease = edge;
                }
            }
            if (crease != kInvalidId) {
                redoUndoRedo(
                    doc,
                    CreaseConditionCommand::create(doc, 0, {crease}, CreaseCondition::CurvedFold),
                    "curved fold");
                redoUndoRedo(
                    doc, CreaseConditionCommand::create(doc, 0, {crease}, CreaseCondition::None),
                    "clear condition");
            }
            redoUndoRedo(doc, someRelabel(doc), "relabel");
            redoUndoRedo(
                doc,
                SubdivideStripCommand::create(doc, 0, firstFaceOfType(s, FaceType::StripSRSR), 0.3),
                "subdivide");
            for (FaceType type : {FaceType::StripSRSR, FaceType::StripSRS, FaceType::ConeSRR}) {
                const FaceId face = firstFaceOfType(doc.surface(0), type);
                if (face != kInvalidId) {
                    redoUndoRedo(doc, SplitAtRulingCommand::create(doc, 0, face, 1), "split");
                }
            }
            const EdgeId spline = doc.surface(0).splineClasses().back().front();
            redoUndoRedo(doc, RefineSplineClassCommand::create(doc, 0, spline), "refine");
            // Topological edits keep vertex ids, and with them the pins.
            QCOMPARE(doc.surface(0).pinnedVertices(), std::set<VertexId>{first});
            const VertexId v = doc.surface(0).vertices().begin()->first;
            redoUndoRedo(doc, MoveVerticesCommand::createTranslation(doc, 0, {v, v + 1}, {1, 2, 3}),
                         "translate");
            redoUndoRedo(
                doc, MoveVerticesCommand::createRotation(doc, 0, {v}, {0, 0, 0}, {0, 1, 1}, 0.2),
                "rotate");
            CompositeSurface moved =
                moveVertices(doc.surface(0), {v}, RigidMotion::translationBy({0, 0, 5}));
            redoUndoRedo(doc, ApplySurfaceCommand::create(doc, 0, moved, "Solve"), "apply");
            // Undo everything: back to the example.
            while (doc.undoStack()->canUndo()) {
                doc.undoStack()->undo();
            }
            QVERIFY(bytesOf(doc) == devsurf::io::encodeProject(makeExample(name)));
        }
    }

    void splitNeedsBreakpointsAndRefineProvidesThem() {
        Document doc;
        doc.resetProject(makeExample("mixed", 1));
        const FaceId strip = firstFaceOfType(doc.surface(0), FaceType::StripSRSR);
        const CommandOrError refused = SplitAtRulingCommand::create(doc, 0, strip, 1);
        QVERIFY(refused.isRefused());
        QVERIFY(refused.problem() && refused.problem()->code == ProblemCode::SingleInterval);
        QCOMPARE(refused.problem()->face, strip);
        QCOMPARE(SplitAtRulingCommand::nearestBreakpoint(doc.surface(0), strip, 0.4),
                 std::make_pair(0, 1));
        const EdgeId a = stripOfFace(doc.surface(0), strip).aSide.edge;
        QVERIFY(pushOrExplain(doc, RefineSplineClassCommand::create(doc, 0, a)).isEmpty());
        QCOMPARE(doc.undoStack()->text(0), QString("Refine curves"));
        QCOMPARE(SplitAtRulingCommand::nearestBreakpoint(doc.surface(0), strip, 0.4),
                 std::make_pair(1, 2));
        QVERIFY(pushOrExplain(doc, SplitAtRulingCommand::create(doc, 0, strip, 1)).isEmpty());
        QCOMPARE(doc.undoStack()->count(), 2);
    }

    void rotatingARegionMovesItsCurvesRigidly() {
        // Every vertex of the sheet beyond y = 100 turned by 30° about that line: the curves with
        // both ends turned move as a whole, so each control point is exactly the turned one and
        // the part beyond the crease stays flat (a clean fold).
        Document doc;
        doc.resetProject(makeExample("sheet", 3));
        const CompositeSurface before = doc.surface(0);
        std::set<VertexId> beyond;
        for (const auto& [id, p] : before.vertices()) {
            if (p.y > 100.0) {
                beyond.insert(id);
            }
        }
        const double angle = 30.0 * M_PI / 180.0;
        QVERIFY(pushOrExplain(doc, MoveVerticesCommand::createRotation(doc, 0, beyond, {0, 100, 0},
                                                                       {1, 0, 0}, angle))
                    .isEmpty());
        const CompositeSurface& after = doc.surface(0);
        for (const auto& [id, record] : before.edges()) {
            if (!record.isSpline() || record.controlPoints.front().y <= 100.0) {
                continue;
            }
            for (std::size_t i = 0; i < record.controlPoints.size(); ++i) {
                const Vec3& p = record.controlPoints[i];
                const double r = p.y - 100.0;
                const Vec3 turned(p.x, 100.0 + r * std::cos(angle), r * std::sin(angle));
                QVERIFY(distance(after.edge(id).controlPoints[i], turned) < 1e-9);
            }
        }
    }

    void consecutiveMovesMerge() {
        Document doc;
        doc.resetProject(makeExample("annulus", 2));
        const std::string original = bytesOf(doc);
        const std::set<VertexId> vertices{1, 2, 5};
        for (int i = 0; i < 5; ++i) {
            QVERIFY(pushOrExplain(
                        doc, MoveVerticesCommand::createTranslation(doc, 0, vertices, {1, 0, 0.5}))
                        .isEmpty());
        }
        QVERIFY(pushOrExplain(doc, MoveVerticesCommand::createRotation(doc, 0, vertices, {0, 0, 0},
                                                                       {0, 0, 1}, 0.1))
                    .isEmpty());
        QCOMPARE(doc.undoStack()->count(), 1);
        // The merged step ends where the last move ended: x moved 5 times, then the rotation.
        const Vec3 start = makeExample("annulus", 2).surfaces[0].position(1);
        const Vec3 translated = start + Vec3(5, 0, 2.5);
        const Vec3 expected(std::cos(0.1) * translated.x - std::sin(0.1) * translated.y,
                            std::sin(0.1) * translated.x + std::cos(0.1) * translated.y,
                            translated.z);
        QVERIFY(distance(doc.surface(0).position(1), expected) < 1e-9);
        const std::string moved = bytesOf(doc);
        // Another vertex set starts a new step.
        QVERIFY(pushOrExplain(doc, MoveVerticesCommand::createTranslation(doc, 0, {1}, {0, 1, 0}))
                    .isEmpty());
        QCOMPARE(doc.undoStack()->count(), 2);
        doc.undoStack()->undo();
        QVERIFY(bytesOf(doc) == moved);
        doc.undoStack()->undo();
        QVERIFY(bytesOf(doc) == original);
        QVERIFY(!doc.undoStack()->canUndo());
    }

    void solverResultsOfOneDragMerge() {
        Document doc;
        doc.resetProject(makeExample("sheet", 2));
        const std::string original = bytesOf(doc);
        for (int i = 1; i <= 3; ++i) {
            CompositeSurface solved =
                moveVertices(doc.surface(0), {4}, RigidMotion::translationBy({0, 0, 1.0 * i}));
            QVERIFY(pushOrExplain(doc, ApplySurfaceCommand::create(doc, 0, solved, "Drag vertex",
                                                                   Change::Geometry, 7))
                        .isEmpty());
        }
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.surface(0).position(4).z, 6.0);
        // Without a merge key every result is its own step.
        CompositeSurface solved = doc.surface(0);
        solved.moveVertex(0, {0, 0, 1});
        QVERIFY(pushOrExplain(doc, ApplySurfaceCommand::create(doc, 0, solved, "Solve")).isEmpty());
        QCOMPARE(doc.undoStack()->count(), 2);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(bytesOf(doc) == original);
        // An invalid result is refused.
        CompositeSurface broken = doc.surface(0);
        broken.moveVertex(0, {std::nan(""), 0, 0});
        QVERIFY(ApplySurfaceCommand::create(doc, 0, broken, "Solve").isRefused());
    }

    void invalidRelabelIsRefused() {
        for (const char* name : kExamples) {
            Document doc;
            doc.resetProject(makeExample(name));
            QSignalSpy spy(&doc, &Document::changed);
            const std::string original = bytesOf(doc);
            const quint64 revision = doc.revision();
            const CompositeSurface& s = doc.surface(0);
            // An S-edge of an SRSR strip cannot become R: the strip would be labelled RRSR.
            const FaceId strip = firstFaceOfType(s, FaceType::StripSRSR);
            const EdgeId edge = stripOfFace(s, strip).aSide.edge;
            const CommandOrError result =
                RelabelEdgeCommand::create(doc, 0, edge, EdgeLabel::Ruling);
            QVERIFY(result.isRefused());
            QVERIFY(result.problem().has_value());
            QCOMPARE(result.problem()->code, ProblemCode::InvalidFaceLabel);
            QVERIFY(result.problem()->face != kInvalidId);
            QVERIFY(!pushOrExplain(doc, RelabelEdgeCommand::create(doc, 0, edge, EdgeLabel::Ruling))
                         .isEmpty());
            // Relabelling to the label it has is refused too.
            QVERIFY(RelabelEdgeCommand::create(doc, 0, edge, EdgeLabel::Spline).isRefused());
            QVERIFY(bytesOf(doc) == original);
            QCOMPARE(doc.undoStack()->count(), 0);
            QCOMPARE(spy.count(), 0);
            QCOMPARE(doc.revision(), revision);
        }
    }

    void otherRefusalsLeaveTheDocumentUntouched() {
        Document doc;
        doc.resetProject(makeExample("mixed"));
        const std::string original = bytesOf(doc);
        const CompositeSurface& s = doc.surface(0);
        const FaceId cone = firstFaceOfType(s, FaceType::ConeSRR);
        const QString message =
            pushOrExplain(doc, SubdivideStripCommand::create(doc, 0, cone, 0.5));
        QVERIFY2(message.contains(QString("CreaseNeedsStrip face=%1").arg(cone)),
                 qPrintable(message));
        QVERIFY(!pushOrExplain(doc, SplitAtRulingCommand::create(doc, 0, 0, 1)).isEmpty());
        QVERIFY(!pushOrExplain(doc, RefineSplineClassCommand::create(doc, 0, 0)).isEmpty());
        QVERIFY(!pushOrExplain(doc, MoveVerticesCommand::createTranslation(doc, 0, {}, {1, 0, 0}))
                     .isEmpty());
        QVERIFY(!pushOrExplain(
                     doc, MoveVerticesCommand::createRotation(doc, 0, {0}, {0, 0, 0}, {0, 0, 0}, 1))
                     .isEmpty());
        QVERIFY(bytesOf(doc) == original);
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void pinRefusals() {
        Document doc;
        doc.resetProject(makeExample("sheet"));
        const std::string original = bytesOf(doc);
        QVERIFY(PinVerticesCommand::create(doc, 0, {}, true).isRefused());
        const CommandOrError unknown = PinVerticesCommand::create(doc, 0, {0, 9999}, true);
        QVERIFY(unknown.isRefused());
        QVERIFY(unknown.error().contains("9999"));
        QVERIFY(PinVerticesCommand::create(doc, 0, {0}, false).isRefused()); // not pinned
        QVERIFY(PinVerticesCommand::create(doc, 1, {0}, true).isRefused());  // no surface 1
        QVERIFY(pushOrExplain(doc, PinVerticesCommand::create(doc, 0, {0, 3}, true)).isEmpty());
        const CommandOrError again = PinVerticesCommand::create(doc, 0, {0, 3}, true);
        QVERIFY(again.isRefused());
        QCOMPARE(PinVerticesCommand::create(doc, 0, {0, 1}, true).command()->text(),
                 QString("Pin 2 vertices"));
        doc.undoStack()->undo();
        QVERIFY(bytesOf(doc) == original);
    }

    void creaseConditionRefusals() {
        Document doc;
        doc.resetProject(makeExample("sheet"));
        const CompositeSurface& s = doc.surface(0);
        const std::string original = bytesOf(doc);
        EdgeId crease = kInvalidId;
        EdgeId boundary = kInvalidId;
        EdgeId ruling = kInvalidId;
        for (const auto& [edge, record] : s.edges()) {
            const bool shared = s.facesOfEdge(edge).size() == 2;
            (record.isSpline() ? (shared ? crease : boundary) : ruling) = edge;
        }
        QVERIFY(crease != kInvalidId && boundary != kInvalidId && ruling != kInvalidId);
        QVERIFY(
            CreaseConditionCommand::create(doc, 0, {}, CreaseCondition::CurvedFold).isRefused());
        for (const EdgeId edge : {boundary, ruling, EdgeId(9999)}) {
            const CommandOrError refused =
                CreaseConditionCommand::create(doc, 0, {crease, edge}, CreaseCondition::Geodesic);
            QVERIFY(refused.isRefused());
            QVERIFY2(refused.error().contains(QString::number(edge)), qPrintable(refused.error()));
        }
        QVERIFY(CreaseConditionCommand::create(doc, 0, {crease}, CreaseCondition::None)
                    .isRefused()); // already none
        QVERIFY(bytesOf(doc) == original);
        const CommandOrError set =
            CreaseConditionCommand::create(doc, 0, {crease}, CreaseCondition::CurvedFold);
        QVERIFY(set.command()->text().startsWith("Curved fold on 1 "));
        QVERIFY(CreaseConditionCommand::create(doc, 0, {crease}, CreaseCondition::Straight)
                    .command()
                    ->text()
                    .startsWith("Straight when unfolded on 1 "));
    }

    void commandsFollowTheirSurfaceById() {
        // A command keeps acting on its surface when the surfaces' order changes (adding and
        // removing surfaces will shift indices): it addresses the surface by its id.
        Project project = makeExample("sheet");
        project.addSurface(makeExample("mixed").surfaces[0]);
        Document doc;
        doc.resetProject(project);
        const SurfaceId mixed = doc.surface(1).id();
        QVERIFY(pushOrExplain(doc, PinVerticesCommand::create(doc, 1, {0}, true)).isEmpty());
        QVERIFY(doc.surface(1).isPinned(0));
        std::swap(doc.mutableProject().surfaces[0], doc.mutableProject().surfaces[1]);
        QCOMPARE(doc.surface(0).id(), mixed);
        doc.undoStack()->undo();
        QVERIFY(!doc.surface(0).isPinned(0)); // the mixed surface, now first
        QVERIFY(!doc.surface(1).isPinned(0));
        QCOMPARE(doc.surface(0).name(), std::string("mixed"));
        doc.undoStack()->redo();
        QVERIFY(doc.surface(0).isPinned(0));
        QVERIFY(!doc.surface(1).isPinned(0));
    }

    void smoothRulingsUndoRedoAndRefusals() {
        Document doc;
        doc.resetProject(makeExample("sheet"));
        const std::string original = bytesOf(doc);
        std::set<EdgeId> inner;
        EdgeId boundaryRuling = kInvalidId;
        EdgeId curve = kInvalidId;
        for (const auto& [edge, record] : doc.surface(0).edges()) {
            const bool shared = doc.surface(0).facesOfEdge(edge).size() == 2;
            if (record.isSpline()) {
                curve = edge;
            } else if (shared) {
                inner.insert(edge);
            } else {
                boundaryRuling = edge;
            }
        }
        QCOMPARE(inner.size(), std::size_t(6)); // 3 rows of 3 strips: 2 inner rulings per row
        QVERIFY(SmoothRulingsCommand::create(doc, 0, {}, true).isRefused());
        for (const EdgeId edge : {boundaryRuling, curve, EdgeId(9999)}) {
            const CommandOrError refused =
                SmoothRulingsCommand::create(doc, 0, {*inner.begin(), edge}, true);
            QVERIFY(refused.isRefused());
            QVERIFY2(refused.error().contains(QString::number(edge)), qPrintable(refused.error()));
        }
        QVERIFY(SmoothRulingsCommand::create(doc, 0, inner, false).isRefused()); // already sharp
        QVERIFY(bytesOf(doc) == original);

        const CommandOrError smooth = SmoothRulingsCommand::create(doc, 0, inner, true);
        QCOMPARE(smooth.command()->text(), QString("Make 6 rulings smooth"));
        QVERIFY(pushOrExplain(doc, SmoothRulingsCommand::create(doc, 0, inner, true)).isEmpty());
        for (EdgeId edge : inner) {
            QVERIFY(doc.surface(0).edge(edge).smooth);
        }
        const std::string after = bytesOf(doc);
        QVERIFY(after != original);
        doc.undoStack()->undo();
        QVERIFY(bytesOf(doc) == original);
        doc.undoStack()->redo();
        QVERIFY(bytesOf(doc) == after);
        QVERIFY(SmoothRulingsCommand::create(doc, 0, inner, true).isRefused()); // already smooth
        QVERIFY(pushOrExplain(doc, SmoothRulingsCommand::create(doc, 0, {*inner.begin()}, false))
                    .isEmpty());
        QVERIFY(!doc.surface(0).edge(*inner.begin()).smooth);
        doc.undoStack()->undo();
        QVERIFY(bytesOf(doc) == after);
    }

    void referenceCurvesImportAndRemove() {
        Document doc;
        doc.resetProject(makeExample("sheet"));
        const Project original = doc.project();
        const quint64 surfaceRevision = doc.surfaceRevision(0);
        ReferenceCurve line{"LINE 1", "CUT", {{0, 0, 0}, {10, 0, 5}}};
        ReferenceCurve arc{"ARC 2", "", {{1, 0, 0}, {0.5, 0.8660254037844386, 0}, {0, 1, 0.25}}};
        // Refusals change nothing.
        QVERIFY(ReferenceCurvesCommand::createImport(doc, {}).isRefused());
        QVERIFY(ReferenceCurvesCommand::createImport(doc, {ReferenceCurve{"P", "", {{1, 2, 3}}}})
                    .isRefused());
        ReferenceCurve notANumber = line;
        notANumber.points[1].y = std::nan("");
        QVERIFY(ReferenceCurvesCommand::createImport(doc, {line, notANumber}).isRefused());
        QVERIFY(ReferenceCurvesCommand::createRemoveAll(doc).isRefused());
        QVERIFY(doc.project() == original);

        // Saved, the import and its undo are exact to the byte.
        redoUndoRedo(doc, ReferenceCurvesCommand::createImport(doc, {line}), "import curves");
        doc.undoStack()->undo();
        QVERIFY(doc.project() == original);
        QSignalSpy spy(&doc, &Document::changed);
        QVERIFY(
            pushOrExplain(doc, ReferenceCurvesCommand::createImport(doc, {line, arc})).isEmpty());
        QCOMPARE(doc.undoStack()->count(), 1); // one file, one step
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.takeFirst().at(0).value<Changes>(), Changes(Change::ReferenceCurves));
        QCOMPARE(doc.surfaceRevision(0), surfaceRevision); // no surface to resample
        const Project imported = doc.project();
        QCOMPARE(imported.referenceCurves.size(), std::size_t(2));
        QVERIFY(imported.referenceCurves[1] == arc);
        QVERIFY(!(imported == original));

        QVERIFY(ReferenceCurvesCommand::createRemove(doc, {2}).isRefused());
        QVERIFY(ReferenceCurvesCommand::createRemove(doc, {}).isRefused());
        QVERIFY(pushOrExplain(doc, ReferenceCurvesCommand::createRemove(doc, {0})).isEmpty());
        QCOMPARE(doc.project().referenceCurves.size(), std::size_t(1));
        QVERIFY(doc.project().referenceCurves[0] == arc);
        doc.undoStack()->undo();
        QVERIFY(doc.project() == imported);
        doc.undoStack()->undo();
        QVERIFY(doc.project() == original);
        doc.undoStack()->redo();
        QVERIFY(doc.project() == imported);
        doc.undoStack()->redo();
        QCOMPARE(doc.project().referenceCurves.size(), std::size_t(1));
        QVERIFY(pushOrExplain(doc, ReferenceCurvesCommand::createRemoveAll(doc)).isEmpty());
        QVERIFY(doc.project().referenceCurves.empty());
        QVERIFY(doc.project().surfaces == original.surfaces);
    }

    void referenceShapesImportAndRemoveAll() {
        Document doc;
        doc.resetProject(makeExample("sheet"));
        const Project original = doc.project();
        const quint64 surfaceRevision = doc.surfaceRevision(0);
        ReferenceShape tet{"tet",
                           "tet.obj",
                           {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                           {},
                           {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
        ReferenceShape cloud{"scan", "", {{1, 2, 3}, {4, 5, 6}}, {{0, 0, 1}, {0, 1, 0}}, {}};
        // Refusals change nothing.
        QVERIFY(ReferenceShapesCommand::createImport(doc, ReferenceShape{}).isRefused());
        ReferenceShape badFace = tet;
        badFace.triangles[2][1] = 4;
        QVERIFY(ReferenceShapesCommand::createImport(doc, badFace).isRefused());
        ReferenceShape notANumber = cloud;
        notANumber.points[1].z = std::nan("");
        QVERIFY(ReferenceShapesCommand::createImport(doc, notANumber).isRefused());
        QVERIFY(ReferenceShapesCommand::createRemoveAll(doc).isRefused());
        QVERIFY(doc.project() == original);

        // Saved, the import and its undo are exact to the byte.
        redoUndoRedo(doc, ReferenceShapesCommand::createImport(doc, tet), "import shape");
        QSignalSpy spy(&doc, &Document::changed);
        QVERIFY(pushOrExplain(doc, ReferenceShapesCommand::createImport(doc, cloud)).isEmpty());
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.takeFirst().at(0).value<Changes>(), Changes(Change::ReferenceShapes));
        QCOMPARE(doc.surfaceRevision(0), surfaceRevision); // no surface to resample
        const Project both = doc.project();
        QCOMPARE(both.referenceShapes.size(), std::size_t(2));
        QVERIFY(both.referenceShapes[0] == tet && both.referenceShapes[1] == cloud);
        QVERIFY(pushOrExplain(doc, ReferenceShapesCommand::createRemoveAll(doc)).isEmpty());
        QVERIFY(doc.project().referenceShapes.empty());
        QVERIFY(doc.project().surfaces == original.surfaces);
        doc.undoStack()->undo();
        QVERIFY(doc.project() == both);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(doc.project() == original);
        doc.undoStack()->redo();
        doc.undoStack()->redo();
        QVERIFY(doc.project() == both);
        doc.undoStack()->redo();
        QVERIFY(doc.project().referenceShapes.empty());
    }
};

DEVSURF_REGISTER_TEST(TstCommands);
#include "tst_commands.moc"
