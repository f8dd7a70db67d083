// Tools ▸ Join Surfaces (Ctrl+J): strips whose boundary curves or rulings face each other become
// one composite surface with shared edges, developable (sampled here, independently of the
// solver), as one undo step that undo and redo take back and re-apply byte for byte; the
// selection chooses the surfaces; surfaces that face nothing are left as they are, and say so.
// Tools ▸ Remove Ruling (Ctrl+Alt+R) then merges two strips joined along a ruling into one.
#include "main_window.h"
#include "model/document/commands/join_surfaces_command.h"
#include "model/document/commands/merge_strips_command.h"
#include "model/document/commands/reference_shapes_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/reference/initial_strip.h"
#include "model/strip_joining.h"
#include "reactions/join_reaction.h"
#include "sampled_developability.h"
#include "test_registry.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace devsurf;
using model::Vec3;

namespace {

// A flat strip of the plane z = 0: curves along x (x0 … x0 + 100), rulings along y (y0 … y0 + 40).
model::CompositeSurface flatStrip(double x0, double y0, const std::string& name) {
    std::vector<Vec3> points;
    for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 4; ++j) {
            points.emplace_back(x0 + 10.0 * i, y0 + 10.0 * j, 0.0);
        }
    }
    model::CompositeSurface strip = model::reference::initialStrip(points, {3, 2, 3}, 0.0);
    strip.setName(name);
    return strip;
}

// Strips a and b 2 mm apart across y = 40 … 42, strip c far from both.
void openThreeStrips(app::MainWindow& window) {
    model::Project project;
    project.addSurface(flatStrip(0.0, 0.0, "a"));
    project.addSurface(flatStrip(0.0, 42.0, "b"));
    project.addSurface(flatStrip(0.0, 300.0, "c"));
    window.workspace()->document()->resetProject(project);
}

void selectFaceOf(app::MainWindow& window, std::initializer_list<int> surfaces) {
    const document::Document* doc = window.workspace()->document();
    std::set<document::Pick> picks;
    for (int s : surfaces) {
        picks.insert({document::Pick::Kind::Face, s, doc->surface(s).faces().begin()->first});
    }
    window.workspace()->selection()->set(picks);
}

int sharedEdges(const model::CompositeSurface& surface) {
    int count = 0;
    for (const auto& [id, record] : surface.edges()) {
        count += surface.facesOfEdge(id).size() == 2 ? 1 : 0;
    }
    return count;
}

// Presses Ctrl+J and waits for the join to end; its (applied, sentence).
std::pair<bool, QString> joinByKey(app::MainWindow& window) {
    QAction* action = window.action(QStringLiteral("actionJoinSurfaces"));
    auto* reaction = action->findChild<app::JoinReaction*>();
    QSignalSpy finished(reaction, &app::JoinReaction::finished);
    QTest::keyClick(&window, Qt::Key_J, Qt::ControlModifier);
    if (finished.isEmpty() && !finished.wait(60000)) {
        return {false, QStringLiteral("timeout")};
    }
    return {finished.front().at(0).toBool(), finished.front().at(1).toString()};
}

} // namespace

class TstJoinGui : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void actionNeedsTwoSurfaces() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        QAction* join = window.action(QStringLiteral("actionJoinSurfaces"));
        QVERIFY(join != nullptr);
        QCOMPARE(join->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_J));
        QVERIFY(!join->isEnabled());
        const QString tooFew = join->toolTip();
        QVERIFY(!tooFew.isEmpty());
        openThreeStrips(window);
        QVERIFY(join->isEnabled());
        QVERIFY(join->toolTip() != tooFew);
    }

    void selectedStripsBecomeOneSurface() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openThreeStrips(window);
        document::Document* doc = window.workspace()->document();
        const std::string before = test::bytesOf(window);
        const model::CompositeSurface c = doc->surface(2);

        // a and b selected: they are joined, c stays a surface of its own.
        selectFaceOf(window, {0, 1});
        const auto [applied, sentence] = joinByKey(window);
        QVERIFY2(applied, qPrintable(sentence));
        QVERIFY2(sentence.contains(QStringLiteral("Joined 2 surfaces into one")),
                 qPrintable(sentence));
        QVERIFY2(sentence.contains(QStringLiteral("1 of 1 pair of facing edges welded")),
                 qPrintable(sentence));
        QCOMPARE(doc->surfaceCount(), 2);
        QVERIFY(doc->surface(1) == c);
        const model::CompositeSurface& joined = doc->surface(0);
        QCOMPARE(joined.name(), std::string("a + b"));
        QVERIFY(joined.validate().empty());
        QCOMPARE(joined.faces().size(), std::size_t(2));
        QCOMPARE(sharedEdges(joined), 1);
        QCOMPARE(model::surfaceParts(joined).size(), std::size_t(1));
        QVERIFY(test::sampledDevelopability(joined) <= 1e-8);
        QVERIFY(test::undoCommand<document::JoinSurfacesCommand>(*doc) != nullptr);
        QCOMPARE(doc->undoStack()->undoText(), QStringLiteral("Join Surfaces"));

        // One undo step, byte for byte both ways.
        const std::string after = test::bytesOf(window);
        doc->undoStack()->undo();
        QVERIFY(test::bytesOf(window) == before);
        doc->undoStack()->redo();
        QVERIFY(test::bytesOf(window) == after);
    }

    void surfacesThatFaceNothingAreLeftAlone() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openThreeStrips(window);
        document::Document* doc = window.workspace()->document();
        const std::string before = test::bytesOf(window);
        const int steps = doc->undoStack()->count();
        // a and c: 260 mm apart, more than a fifth of their length.
        selectFaceOf(window, {0, 2});
        const auto [applied, sentence] = joinByKey(window);
        QVERIFY(!applied);
        QVERIFY2(sentence.contains(QStringLiteral("nothing was joined")), qPrintable(sentence));
        QVERIFY(test::bytesOf(window) == before);
        QCOMPARE(doc->undoStack()->count(), steps);
        QVERIFY(!window.solveController()->isSolving());
        QVERIFY(window.action(QStringLiteral("actionJoinSurfaces"))->isEnabled());
    }

    void withAReferenceTheJoinHoldsToIt() {
        // Nothing selected: every surface is offered; a and b meet and are joined, c faces
        // neither and is left as it is. The reference shape (points of the plane z = 0 under a
        // and b) holds them to it meanwhile.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openThreeStrips(window);
        document::Document* doc = window.workspace()->document();
        const model::CompositeSurface c = doc->surface(2);
        model::ReferenceShape plane{"plane", "", {}, {}, {}};
        for (int i = 0; i <= 50; ++i) {
            for (int j = 0; j <= 41; ++j) {
                plane.points.push_back({2.0 * i, 2.0 * j, 0.0});
            }
        }
        document::CommandOrError add = document::ReferenceShapesCommand::createImport(*doc, plane);
        QVERIFY(document::push(*doc, add));
        const auto [applied, sentence] = joinByKey(window);
        QVERIFY2(applied, qPrintable(sentence));
        QVERIFY2(sentence.contains(QStringLiteral("Joined 2 surfaces into one")),
                 qPrintable(sentence));
        QVERIFY2(sentence.contains(QStringLiteral("1 surface facing no other was left as it is")),
                 qPrintable(sentence));
        QVERIFY2(!sentence.contains(QStringLiteral("not connected")), qPrintable(sentence));
        QVERIFY2(sentence.contains(QStringLiteral("held to the reference shape")),
                 qPrintable(sentence));
        QCOMPARE(doc->surfaceCount(), 2);
        QVERIFY(doc->surface(1) == c);
        const model::CompositeSurface& joined = doc->surface(0);
        QCOMPARE(joined.name(), std::string("a + b"));
        QCOMPARE(model::surfaceParts(joined).size(), std::size_t(1));
        QCOMPARE(sharedEdges(joined), 1);
        QVERIFY(test::sampledDevelopability(joined) <= 1e-8);
        // Still in the plane of the reference.
        for (const auto& [id, position] : joined.vertices()) {
            QVERIFY2(std::abs(position.z) < 1e-6, qPrintable(QString::number(position.z)));
        }
    }

    void stripsJoinedAlongARulingMergeIntoOne() {
        // Two strips end to end, 2 mm apart between their end rulings: joined along them, then
        // that ruling removed by Ctrl+Alt+R.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        model::Project project;
        project.addSurface(flatStrip(0.0, 0.0, "a"));
        project.addSurface(flatStrip(102.0, 0.0, "b"));
        document::Document* doc = window.workspace()->document();
        doc->resetProject(project);
        const auto [applied, sentence] = joinByKey(window);
        QVERIFY2(applied, qPrintable(sentence));
        QCOMPARE(doc->surfaceCount(), 1);
        model::EdgeId shared = model::kInvalidId;
        for (const auto& [id, record] : doc->surface(0).edges()) {
            if (!record.isSpline() && doc->surface(0).facesOfEdge(id).size() == 2) {
                shared = id;
            }
        }
        QVERIFY(shared != model::kInvalidId);

        QAction* remove = window.action(QStringLiteral("actionRemoveRuling"));
        QVERIFY(remove != nullptr);
        QVERIFY(!remove->isEnabled()); // nothing selected
        QVERIFY(remove->toolTip().contains(QStringLiteral("Select one ruling")));
        window.workspace()->selection()->set({{document::Pick::Kind::Edge, 0, shared}});
        QVERIFY(remove->isEnabled());

        const std::string joined = test::bytesOf(window);
        QSignalSpy status(window.workspace(), &app::Workspace::statusMessage);
        QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::AltModifier);
        const model::CompositeSurface& merged = doc->surface(0);
        QCOMPARE(merged.faces().size(), std::size_t(1));
        QCOMPARE(merged.vertices().size(), std::size_t(4));
        QVERIFY(merged.validate().empty());
        QVERIFY(test::undoCommand<document::MergeStripsCommand>(*doc) != nullptr);
        QVERIFY(!status.isEmpty());
        const QString said = status.back().front().toString();
        QVERIFY2(said.contains(QStringLiteral("removed")), qPrintable(said));
        // Still the plane z = 0, 0 … 202 mm along the curves.
        double xLow = 1e300, xHigh = -1e300;
        for (const auto& [id, position] : merged.vertices()) {
            QVERIFY(std::abs(position.z) < 1e-9);
            xLow = std::min(xLow, position.x);
            xHigh = std::max(xHigh, position.x);
        }
        QVERIFY(std::abs(xLow) < 1e-9 && std::abs(xHigh - 202.0) < 1e-9);
        QVERIFY(test::sampledDevelopability(merged) <= 1e-8);
        const std::string after = test::bytesOf(window);
        doc->undoStack()->undo();
        QVERIFY(test::bytesOf(window) == joined);
        doc->undoStack()->redo();
        QVERIFY(test::bytesOf(window) == after);
    }

    void aRulingWhoseEndsMeetOtherPatchesIsNotRemoved() {
        // The sheet's inner rulings end on curves that run on through other patches: refused
        // with a message, the design unchanged.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        document::Document* doc = window.workspace()->document();
        const model::CompositeSurface& sheet = doc->surface(0);
        model::EdgeId inner = model::kInvalidId;
        for (const auto& [id, record] : sheet.edges()) {
            if (!record.isSpline() && sheet.facesOfEdge(id).size() == 2) {
                inner = id;
                break;
            }
        }
        QVERIFY(inner != model::kInvalidId);
        window.workspace()->selection()->set({{document::Pick::Kind::Edge, 0, inner}});
        QAction* remove = window.action(QStringLiteral("actionRemoveRuling"));
        QVERIFY(remove->isEnabled());
        const std::string before = test::bytesOf(window);
        bool answered = false;
        test::acceptNextMessageBox(answered);
        remove->trigger();
        QVERIFY(answered);
        QVERIFY(test::bytesOf(window) == before);
    }
};

DEVSURF_REGISTER_TEST(TstJoinGui);
#include "tst_join_gui.moc"
