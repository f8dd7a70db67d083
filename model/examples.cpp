#include "examples.h"

#include "development.h"
#include "example_shapes.h"
#include "held_by_pins.h"
#include "model_error.h"
#include "sampled_mesh.h"
#include "sheet_creases.h"
#include "sheet_domain.h"

#include <algorithm>

namespace devsurf::model {

namespace {

// `s`, holding no sheet, holding the sheet it starts as (ExampleSheet::Held).
void holdStartingSheet(CompositeSurface& s, SheetShape shape) {
    for (auto taut = findTautPinLines(s); !taut.empty(); taut = findTautPinLines(s)) {
        s.setPinned(taut.front().second, false);
    }
    if (const auto problem = keepDevelopment(s)) {
        throw ModelError(*problem);
    }
    if (s.sheetDomain().shape == SheetShape::Cylinder) {
        return; // it closes around: held on the cylinder keepDevelopment found
    }
    const SampledMesh mesh = sampleSurface(s, kDevelopmentSamplesPerInterval);
    SheetDomain domain = fittingDomain(shape, mesh, s.development());
    const bool curvedFolds = std::any_of(s.edges().begin(), s.edges().end(), [](const auto& e) {
        return e.second.condition == CreaseCondition::CurvedFold;
    });
    if (!domain.isFree() && curvedFolds) {
        // The crease pattern is scored where it is drawn: its creases stay on their curves in
        // the sheet while the rulings move.
        domain.creaseCurves = sheetFrameCurves(domain, creaseCurvesAsTheyLie(s, s.development()));
        domain.creaseCurveOf = assignCreasesToCurves(domain, s, mesh, s.development());
    }
    s.setSheetDomain(domain);
}

} // namespace

const std::vector<ExampleInfo>& builtInExamples() {
    static const std::vector<ExampleInfo> examples{
        {"sheet", 3, 1, 60, true, false},     {"annulus", 6, 1, 60, true, false},
        {"cylinder", 6, 3, 120, true, false}, {"mixed", 2, 1, 50, true, false},
        {"fig8", 3, 2, 30, true, false},      {"fig6", 4, 1, 40, true, false},
        {"fig13", 6, 3, 40, false, true},     {"torus", 6, 3, 40, false, false},
        {"column", 12, 6, 48, false, true},   {"fig12", 6, 3, 12, false, true},
    };
    return examples;
}

Project makeExample(const std::string& name, int size, ExampleSheet sheet) {
    for (const ExampleInfo& info : builtInExamples()) {
        if (info.name != name) {
            continue;
        }
        if (size == 0) {
            size = info.defaultSize;
        }
        if (size < info.minSize || size > info.maxSize) {
            Problem problem = problemOf(ProblemCode::ExampleSize);
            problem.name = name;
            problem.count = size;
            problem.expected = info.minSize;
            problem.limit = info.maxSize;
            throw ModelError(problem);
        }
        Project project;
        if (name == "sheet") {
            project.addSurface(example_shapes::makeSheet(size));
        } else if (name == "annulus") {
            project.addSurface(example_shapes::makeAnnulus(size, sheet == ExampleSheet::Held));
        } else if (name == "cylinder") {
            project.addSurface(example_shapes::makeCylinder(size));
        } else if (name == "mixed") {
            project.addSurface(example_shapes::makeMixed(size));
        } else if (name == "fig8") {
            project.addSurface(example_shapes::makeFig8(size));
        } else if (name == "fig13") {
            project.addSurface(example_shapes::makeFig13(size));
        } else if (name == "torus") {
            project.addSurface(example_shapes::makeTorus(size));
        } else if (name == "fig12") {
            project.addSurface(example_shapes::makeFig12(size));
        } else if (name == "column") {
            project.addSurface(example_shapes::makeColumn(size));
        } else {
            project.addSurface(example_shapes::makeFig6(size));
        }
        if (sheet == ExampleSheet::Held && info.canHoldItsSheet) {
            // (The cylinder holds the cylinder its unfolding rolls onto.)
            const SheetShape shape = name == "annulus" ? SheetShape::Annulus
                                     : name == "mixed" || name == "cylinder"
                                         ? SheetShape::Free
                                         : SheetShape::Rectangle;
            holdStartingSheet(project.surfaces.front(), shape);
        }
        return project;
    }
    Problem problem = problemOf(ProblemCode::UnknownExample);
    problem.name = name;
    throw ModelError(problem);
}

} // namespace devsurf::model
