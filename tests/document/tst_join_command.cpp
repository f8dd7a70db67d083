// Joining surfaces as one undo step (Tools ▸ Join Surfaces): the joined surface takes the place
// and the id of the first joined one, the others go, and undo and redo restore the project to
// the byte.
#include "document_test_support.h"
#include "model/document/commands/join_surfaces_command.h"
#include "model/examples.h"
#include "model/strip_joining.h"
#include "test_registry.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace devsurf::document;
using namespace devsurf::model;
using devsurf::test::bytesOf;
using devsurf::test::pushOrExplain;

class TstJoinCommand : public QObject {
    Q_OBJECT

private slots:
    void joiningSurfacesReplacesThemByOne() {
        // Three surfaces; the first and the third joined (as the Join job returns them: one
        // surface of their parts side by side), the second stays where it is.
        Document doc;
        Project project;
        for (const char* name : {"sheet", "annulus", "mixed"}) {
            project.addSurface(makeExample(name).surfaces.front());
        }
        doc.resetProject(project);
        const CompositeSurface joined = placeSideBySide(doc.surface(0), doc.surface(2)).surface;
        QVERIFY(joined.validate().empty());
        const SurfaceId firstId = doc.surface(0).id();
        const Project original = doc.project();
        const std::string before = bytesOf(doc);

        // Refusals change nothing: fewer than two, twice the same, out of range, not valid.
        QVERIFY(JoinSurfacesCommand::create(doc, {0}, joined, "join").isRefused());
        QVERIFY(JoinSurfacesCommand::create(doc, {2, 2}, joined, "join").isRefused());
        QVERIFY(JoinSurfacesCommand::create(doc, {0, 3}, joined, "join").isRefused());
        QVERIFY(JoinSurfacesCommand::create(doc, {-1, 0}, joined, "join").isRefused());
        QVERIFY(JoinSurfacesCommand::create(doc, {0, 2}, CompositeSurface(), "join").isRefused());
        QVERIFY(doc.project() == original);

        // The indices in any order; one change signal per step.
        QSignalSpy changed(&doc, &Document::changed);
        QVERIFY(
            pushOrExplain(doc, JoinSurfacesCommand::create(doc, {2, 0}, joined, "join")).isEmpty());
        QCOMPARE(changed.count(), 1);
        QCOMPARE(doc.undoStack()->undoText(), QStringLiteral("join"));
        QCOMPARE(doc.surfaceCount(), 2);
        QCOMPARE(doc.surface(0).name(), joined.name());
        QCOMPARE(doc.surface(0).id(), firstId);
        QCOMPARE(doc.surface(0).faces().size(), joined.faces().size());
        QVERIFY(doc.surface(1) == original.surfaces[1]);
        const std::string after = bytesOf(doc);
        QVERIFY(after != before);

        doc.undoStack()->undo();
        QCOMPARE(changed.count(), 2);
        QVERIFY(bytesOf(doc) == before);
        QVERIFY(doc.project() == original);
        doc.undoStack()->redo();
        QCOMPARE(changed.count(), 3);
        QVERIFY(bytesOf(doc) == after);
    }
};

DEVSURF_REGISTER_TEST(TstJoinCommand);
#include "tst_join_command.moc"
