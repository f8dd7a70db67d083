#include "bounded_pattern.h"

#include "model/pattern/sampling_bound.h"
#include "model/project.h"

#include <QCoreApplication>

#include <optional>

namespace devsurf::app {

BoundedPattern buildBoundedPattern(const model::Project& project,
                                   const model::PatternOptions& options) {
    BoundedPattern result;
    result.tolerance = options.tolerance;
    const std::optional<model::pattern::OversampledSurface> over =
        model::pattern::oversampledSurface(project, options.tolerance);
    if (!over) {
        result.pattern = model::buildCuttingPattern(project, options);
        return result;
    }
    const QString reach = QString::number(over->reach / 1000.0, 'f', 0);
    if (over->coarser <= 0.0) {
        result.refused = true;
        result.note = QCoreApplication::translate(
                          "BoundedPattern",
                          "Surface %1 reaches %2 m from the origin: even at a tolerance of 10 mm "
                          "its pattern would take minutes to build, so there is none. Move its "
                          "far control points closer.")
                          .arg(over->surface + 1)
                          .arg(reach);
        return result;
    }
    model::PatternOptions coarser = options;
    coarser.tolerance = over->coarser;
    result.tolerance = over->coarser;
    result.pattern = model::buildCuttingPattern(project, coarser);
    result.note = QCoreApplication::translate(
                      "BoundedPattern",
                      "Surface %1 reaches %2 m from the origin: its curves are sampled to %3 mm, "
                      "since %4 mm would take minutes.")
                      .arg(over->surface + 1)
                      .arg(reach)
                      .arg(over->coarser)
                      .arg(options.tolerance);
    return result;
}

} // namespace devsurf::app
