#include "crease_reactions.h"
#include "edit_refusal.h"

#include "../workspace.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/commands/crease_condition_command.h"
#include "model/document/commands/smooth_rulings_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"

#include <QAction>
#include <QMenu>

#include <set>

namespace devsurf::app {

namespace {

// The selected edges, when they all belong to one surface, sorted by what they can take.
struct SelectedEdges {
    int surface = -1; // -1: no edge selected, or edges of several surfaces
    bool severalSurfaces = false;
    std::set<model::EdgeId> edges;
    int creases = 0;       // curves between two patches
    int innerRulings = 0;  // rulings between two patches
    int withCondition = 0; // creases with the asked condition
    int withFlag = 0;      // inner rulings with the asked smooth flag
};

SelectedEdges selectedEdges(Workspace* workspace, model::CreaseCondition condition, bool smooth) {
    SelectedEdges result;
    for (const document::Pick& pick : workspace->selection()->picks()) {
        if (pick.kind != document::Pick::Kind::Edge) {
            continue;
        }
        if (result.surface >= 0 && result.surface != pick.surface) {
            result.severalSurfaces = true;
        }
        result.surface = pick.surface;
        result.edges.insert(pick.id);
    }
    const auto& surfaces = workspace->document()->project().surfaces;
    if (result.severalSurfaces || result.surface < 0 ||
        result.surface >= static_cast<int>(surfaces.size())) {
        result.surface = -1;
        result.edges.clear();
        return result;
    }
    const model::CompositeSurface& surface = surfaces[static_cast<std::size_t>(result.surface)];
    for (model::EdgeId id : result.edges) {
        if (!surface.hasEdge(id) || surface.facesOfEdge(id).size() != 2) {
            continue;
        }
        const model::EdgeRecord& edge = surface.edge(id);
        if (edge.isSpline()) {
            ++result.creases;
            result.withCondition += edge.condition == condition ? 1 : 0;
        } else {
            ++result.innerRulings;
            result.withFlag += edge.smooth == smooth ? 1 : 0;
        }
    }
    return result;
}

QString purpose(model::CreaseCondition condition) {
    switch (condition) {
    case model::CreaseCondition::CurvedFold:
        return CreaseConditionReaction::tr(
            "Curved fold: the solver keeps the crease's osculating plane halfway between the two "
            "patches, so that the design folds from one flat sheet.");
    case model::CreaseCondition::Geodesic:
        return CreaseConditionReaction::tr(
            "Geodesic: the solver keeps the crease a geodesic of both patches.");
    case model::CreaseCondition::Straight:
        return CreaseConditionReaction::tr(
            "Straight when unfolded: the solver keeps the crease a straight line in the "
            "development.");
    case model::CreaseCondition::None:
        break;
    }
    return CreaseConditionReaction::tr("No condition: the solver treats the crease freely.");
}

void setTip(QAction* action, const QString& tip) {
    action->setToolTip(tip);
    action->setStatusTip(tip);
}

} // namespace

CreaseConditionReaction::CreaseConditionReaction(QAction* action, Workspace* workspace,
                                                 model::CreaseCondition condition)
    : Reaction(action, workspace), m_condition(condition) {
    action->setCheckable(true);
    followDocumentAndSelection();
}

void CreaseConditionReaction::updateEnableState() {
    const SelectedEdges selected = selectedEdges(workspace(), m_condition, false);
    QString tip = purpose(m_condition);
    if (selected.creases == 0) {
        tip += QLatin1Char(' ') + tr("Select creases (curves between two patches) of one "
                                     "surface first.");
    }
    action()->setEnabled(selected.creases > 0);
    action()->setChecked(selected.creases > 0 &&
                         selected.withCondition == static_cast<int>(selected.edges.size()));
    setTip(action(), tip);
}

void CreaseConditionReaction::onTriggered() {
    const SelectedEdges selected = selectedEdges(workspace(), m_condition, false);
    if (selected.surface >= 0) {
        document::CommandOrError edit = document::CreaseConditionCommand::create(
            *workspace()->document(), selected.surface, selected.edges, m_condition);
        const QString refusal = pushOrExplain(*workspace()->document(), std::move(edit));
        if (!refusal.isEmpty()) {
            emit workspace()->statusMessage(refusal);
        }
    }
    // Triggering toggled the check mark; it shows the selection's condition again.
    updateEnableState();
}

SmoothRulingsReaction::SmoothRulingsReaction(QAction* action, Workspace* workspace, bool smooth)
    : Reaction(action, workspace), m_smooth(smooth) {
    action->setCheckable(true);
    followDocumentAndSelection();
}

void SmoothRulingsReaction::updateEnableState() {
    const SelectedEdges selected =
        selectedEdges(workspace(), model::CreaseCondition::None, m_smooth);
    QString tip = m_smooth ? tr("Smooth: the solver keeps the surface smooth across the selected "
                                "rulings (both patches share the tangent plane).")
                           : tr("Sharp: the surface may fold along the selected rulings.");
    if (selected.innerRulings == 0) {
        tip += QLatin1Char(' ') + tr("Select rulings between two patches of one surface first.");
    }
    action()->setEnabled(selected.innerRulings > 0);
    action()->setChecked(selected.innerRulings > 0 &&
                         selected.withFlag == static_cast<int>(selected.edges.size()));
    setTip(action(), tip);
}

void SmoothRulingsReaction::onTriggered() {
    const SelectedEdges selected =
        selectedEdges(workspace(), model::CreaseCondition::None, m_smooth);
    if (selected.surface >= 0) {
        document::CommandOrError edit = document::SmoothRulingsCommand::create(
            *workspace()->document(), selected.surface, selected.edges, m_smooth);
        const QString refusal = pushOrExplain(*workspace()->document(), std::move(edit));
        if (!refusal.isEmpty()) {
            emit workspace()->statusMessage(refusal);
        }
    }
    updateEnableState();
}

QMenu* createCreaseMenu(QWidget* parent, Workspace* workspace) {
    auto* menu = new QMenu(CreaseConditionReaction::tr("Cr&ease"), parent);
    menu->setObjectName(QStringLiteral("menuCrease"));
    menu->setToolTipsVisible(true);
    const std::pair<const char*, model::CreaseCondition> conditions[] = {
        {"actionCurvedFold", model::CreaseCondition::CurvedFold},
        {"actionGeodesic", model::CreaseCondition::Geodesic},
        {"actionStraightWhenUnfolded", model::CreaseCondition::Straight},
        {"actionNoCondition", model::CreaseCondition::None}};
    for (const auto& [name, condition] : conditions) {
        QAction* action =
            menu->addAction(document::CreaseConditionCommand::conditionText(condition));
        action->setObjectName(QString::fromLatin1(name));
        new CreaseConditionReaction(action, workspace, condition);
    }
    menu->addSeparator();
    QAction* smooth = menu->addAction(SmoothRulingsReaction::tr("&Smooth Rulings"));
    smooth->setObjectName(QStringLiteral("actionSmoothRulings"));
    new SmoothRulingsReaction(smooth, workspace, true);
    QAction* sharp = menu->addAction(SmoothRulingsReaction::tr("S&harp Rulings"));
    sharp->setObjectName(QStringLiteral("actionSharpRulings"));
    new SmoothRulingsReaction(sharp, workspace, false);
    return menu;
}

} // namespace devsurf::app
