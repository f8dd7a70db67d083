// The command line's words for the solve job's outcome (app/cli/outcome_text).
#include "outcome_text.h"
#include "problem_text.h"
#include "test_registry.h"

#include <QString>
#include <QtTest>

using namespace devsurf;

class TstCliText : public QObject {
    Q_OBJECT
private slots:
    void everyProblemCodeHasItsOwnSentence() {
        // Each code of model/ is worded (not the internal-error fallback), as one sentence
        // naming the ids it carries.
        using devsurf::model::ProblemCode;
        QSet<QString> seen;
        const QString internal =
            devsurf::app::ProblemText::of(devsurf::model::internalProblem("x")).section('(', 0, 0);
        for (int c = 0; c < static_cast<int>(ProblemCode::Internal); ++c) {
            devsurf::model::Problem p = devsurf::model::problemOf(static_cast<ProblemCode>(c));
            p.id = p.vertex = p.edge = p.face = 4321;
            p.otherVertex = p.otherEdge = p.otherFace = 8765;
            const QString text = devsurf::app::ProblemText::of(p);
            QVERIFY2(!text.startsWith(internal), qPrintable(QString::number(c)));
            QVERIFY2(text.endsWith('.') && text.at(0).isUpper(), qPrintable(text));
            QVERIFY2(!seen.contains(text), qPrintable(text));
            seen.insert(text);
        }
        const QString edge = devsurf::app::ProblemText::of(
            devsurf::model::edgeProblem(ProblemCode::CurveZeroLength, 7));
        QVERIFY2(edge.contains(QStringLiteral("7")), qPrintable(edge));
    }

    void patternProblemsNameTheirPieces() {
        devsurf::model::CuttingPattern pattern;
        pattern.pieces.resize(2);
        pattern.pieces[0].name = "A";
        pattern.pieces[1].name = "B";
        devsurf::model::PatternProblem overlap;
        overlap.code = devsurf::model::PatternProblemCode::PiecesOverlap;
        overlap.piece = 0;
        overlap.otherPiece = 1;
        overlap.sheet = 2;
        pattern.problems = {overlap};
        const std::vector<std::string> texts = devsurf::app::patternProblemTexts(pattern);
        QCOMPARE(texts.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(texts.front()),
                 QStringLiteral("Pieces A (patches ) and B (patches ) overlap on sheet 3."));
    }

    void foldOversNameTheFirstFacesAndCountTheRest() {
        QCOMPARE(app::describeFoldOvers({{0, 2}}),
                 std::string("Folded over onto itself: face 0 (2 places)."));
        QCOMPARE(app::describeFoldOvers({}), std::string("No face folds over onto itself."));
        std::vector<std::pair<model::FaceId, int>> many;
        for (int f = 0; f < 14; ++f) {
            many.push_back({model::FaceId(100 + f), f < 12 ? 3 : 1});
        }
        QCOMPARE(app::describeFoldOvers(many),
                 std::string("Folded over onto itself: face 100 (3 places), face 101 (3 places), "
                             "face 102 (3 places), face 103 (3 places), face 104 (3 places), "
                             "face 105 (3 places), face 106 (3 places), face 107 (3 places), "
                             "face 108 (3 places), face 109 (3 places) and 4 more faces (8 "
                             "places)."));
        many.resize(11);
        QVERIFY(QString::fromStdString(app::describeFoldOvers(many))
                    .endsWith("face 109 (3 places) and 1 more face (3 places)."));
    }

    void overlapsNameThePatches() {
        QCOMPARE(app::describeSelfOverlap({4}),
                 std::string("The development overlaps itself at patch 4 and cannot be cut from "
                             "one sheet."));
        QCOMPARE(app::describeSelfOverlap({1, 2, 3, 4, 5, 6, 7, 8, 9}),
                 std::string("The development overlaps itself at patches 1, 2, 3, 4, 5, 6, 7, 8, "
                             "… and cannot be cut from one sheet."));
        QCOMPARE(app::describeSelfOverlap({}),
                 std::string("The development does not overlap itself."));
    }

    void heldVerticesAndFailures() {
        model::HeldVertex triangle;
        triangle.vertex = 5;
        triangle.pins = {0, 3, 12};
        QVERIFY(app::describeHeld(triangle).find(
                    "Vertex 5 lies inside the triangle of the pinned vertices 0, 3 and 12") == 0);
        model::HeldVertex line;
        line.vertex = 1;
        line.pins = {0, 3};
        QVERIFY(app::describeHeld(line).find("between the pinned vertices 0 and 3") !=
                std::string::npos);
        solver::JobFailure failure;
        failure.error = solver::JobError::TargetNotFinite;
        failure.surface = 0;
        failure.vertex = 7;
        QCOMPARE(app::describeFailure(failure),
                 std::string("the target of vertex 7 is not finite"));
        failure = {};
        failure.error = solver::JobError::SolverFailed;
        failure.surface = 1;
        failure.status = solver::Status::FactorizationFailed;
        failure.detail = "not positive definite.";
        QVERIFY(app::describeFailure(failure).find("surface 2 could not be solved: ") == 0);
        QVERIFY(app::describeFailure(failure).find("not positive definite") != std::string::npos);
        solver::DragOutcome outcome;
        QCOMPARE(app::describeOutcome(outcome), std::string("ended without a problem"));
        outcome.foldOverPlaces = 2;
        outcome.residual = 1e-3;
        QCOMPARE(app::describeOutcome(outcome),
                 std::string("did not converge (residual 1.0e-03) and folded over in 2 places"));
    }
};

DEVSURF_REGISTER_TEST(TstCliText);
#include "tst_cli_text.moc"
