#include "sheet_reactions.h"
#include "edit_refusal.h"

#include "../workspace.h"
#include "model/development.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"

#include "../sheet_shape_dialog.h"
#include "model/sampled_mesh.h"
#include "model/sheet_creases.h"

#include <QAction>
#include <QLocale>

namespace devsurf::app {

HoldSheetReaction::HoldSheetReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    action->setCheckable(true);
    followDocumentAndSelection();
}

namespace {

// The surface a sheet setting acts on: the one of the selection, or the only one.
std::optional<int> sheetTarget(const Workspace* workspace) {
    std::optional<int> surface;
    for (const document::Pick& pick : workspace->selection()->picks()) {
        if (surface && *surface != pick.surface) {
            return std::nullopt; // several surfaces selected
        }
        surface = pick.surface;
    }
    if (!surface && workspace->document()->surfaceCount() == 1) {
        surface = 0;
    }
    if (surface && *surface >= workspace->document()->surfaceCount()) {
        return std::nullopt;
    }
    return surface;
}

// `surface` holding its sheet: its kept development, or the one it unfolds to now. Nothing, and
// the reason told under `failure`, if it does not unfold into one flat sheet.
std::optional<model::CompositeSurface>
holdingItsSheet(Workspace* workspace, model::CompositeSurface surface, const QString& failure) {
    if (!surface.keepsDevelopment() || surface.development().empty()) {
        if (const auto problem = model::keepDevelopment(surface)) {
            workspace->apply(document::CommandOrError(failure, *problem), failure);
            return std::nullopt;
        }
    }
    return surface;
}

} // namespace

QString SheetShapeReaction::cylinderText(const model::CompositeSurface& surface) {
    return tr("%1 closes around: it is folded from a cylinder of radius %2 mm, its development "
              "read modulo the cylinder's circumference, and no flat sheet shape applies.")
        .arg(QString::fromStdString(surface.name()),
             QLocale().toString(surface.sheetDomain().radius, 'f', 1));
}

std::optional<int> HoldSheetReaction::targetSurface() const {
    return sheetTarget(workspace());
}

void HoldSheetReaction::updateEnableState() {
    const std::optional<int> surface = targetSurface();
    const document::Document* doc = workspace()->document();
    const bool holds =
        surface && *surface < doc->surfaceCount() && doc->surface(*surface).keepsDevelopment();
    action()->setEnabled(surface.has_value());
    action()->setChecked(holds);
    const QString tip =
        !surface ? tr("Hold the sheet of a surface: select something on one surface first.")
        : holds  ? tr("The surface is folded from its sheet: solves and drags keep it "
                       "isometric to its development, and a dragged vertex stays behind where "
                       "the sheet cannot follow. Uncheck to let the sheet stretch again.")
                 : tr("Fold the surface from its sheet: its development as it unfolds now is "
                       "kept by every solve and drag; a dragged vertex stays behind where the "
                       "sheet cannot follow, instead of the sheet stretching.");
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void HoldSheetReaction::onTriggered() {
    const std::optional<int> surface = targetSurface();
    document::Document* doc = workspace()->document();
    if (!surface || *surface >= doc->surfaceCount()) {
        updateEnableState();
        return;
    }
    model::CompositeSurface changed = doc->surface(*surface);
    const bool hold = !changed.keepsDevelopment();
    const QString title = hold ? tr("Hold the Sheet") : tr("Let the Sheet Stretch");
    if (hold) {
        std::optional<model::CompositeSurface> held =
            holdingItsSheet(workspace(), changed, tr("Cannot hold the sheet"));
        if (!held) {
            updateEnableState();
            return;
        }
        changed = std::move(*held);
    } else {
        changed.setKeepsDevelopment(false);
    }
    workspace()->apply(document::ApplySurfaceCommand::create(*doc, *surface, std::move(changed),
                                                             title, document::Change::Labels),
                       hold ? tr("Cannot hold the sheet") : tr("Cannot let the sheet stretch"));
    updateEnableState();
}

SheetShapeReaction::SheetShapeReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

void SheetShapeReaction::updateEnableState() {
    const bool target = sheetTarget(workspace()).has_value();
    action()->setEnabled(target);
    const QString tip =
        target ? tr("Choose the sheet the surface is folded from: its development as it is, or "
                    "a rectangle, disk or annulus its development stays inside.")
               : tr("Choose the sheet of a surface: select something on one surface first.");
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void SheetShapeReaction::onTriggered() {
    const std::optional<int> surface = sheetTarget(workspace());
    if (!surface) {
        updateEnableState();
        return;
    }
    // The development the sheet is fitted to.
    const std::optional<model::CompositeSurface> held = holdingItsSheet(
        workspace(), workspace()->document()->surface(*surface), tr("Cannot hold the sheet"));
    if (!held) {
        return;
    }
    if (held->sheetDomain().shape == model::SheetShape::Cylinder) {
        if (!workspace()->document()->surface(*surface).keepsDevelopment()) {
            applyShape(*surface, held->sheetDomain()); // now held, around its cylinder
        }
        emit workspace()->statusMessage(cylinderText(*held));
        return;
    }
    const model::SampledMesh mesh =
        model::sampleSurface(*held, model::kDevelopmentSamplesPerInterval);
    SheetShapeDialog dialog(*held, mesh, held->development(), workspace()->window());
    if (dialog.exec() == QDialog::Accepted) {
        applyShape(*surface, dialog.domain());
    }
}

bool SheetShapeReaction::applyShape(int index, const model::SheetDomain& domain) {
    document::Document* doc = workspace()->document();
    if (index < 0 || index >= doc->surfaceCount()) {
        return false;
    }
    std::optional<model::CompositeSurface> held =
        holdingItsSheet(workspace(), doc->surface(index), tr("Cannot hold the sheet"));
    if (!held) {
        return false;
    }
    if (held->sheetDomain().shape == model::SheetShape::Cylinder && domain != held->sheetDomain()) {
        emit workspace()->statusMessage(cylinderText(*held));
        return false;
    }
    model::CompositeSurface changed = std::move(*held);
    changed.setSheetDomain(domain);
    const model::SampledMesh mesh =
        model::sampleSurface(changed, model::kDevelopmentSamplesPerInterval);
    const double gap =
        domain.isFree() ? 0.0 : model::largestDomainGap(domain, mesh, changed.development());
    const double creaseGap = model::largestCreaseCurveGap(domain, mesh, changed.development());
    if (!workspace()->apply(document::ApplySurfaceCommand::create(*doc, index, std::move(changed),
                                                                  tr("Set Sheet Shape"),
                                                                  document::Change::Labels),
                            tr("Cannot set the sheet shape"))) {
        return false;
    }
    if (creaseGap > 1e-6) {
        emit workspace()->statusMessage(
            tr("The development's creases are up to %1 mm from their curves, its boundary up to "
               "%2 mm from the sheet's: Solve moves them there.")
                .arg(QLocale().toString(creaseGap, 'f', 1), QLocale().toString(gap, 'f', 1)));
    } else if (gap > 1e-6) {
        emit workspace()->statusMessage(
            tr("The development's boundary is up to %1 mm from the sheet's: Solve moves it onto "
               "the sheet.")
                .arg(QLocale().toString(gap, 'f', 1)));
    }
    updateEnableState();
    return true;
}

} // namespace devsurf::app
