#include "reference_curves_command.h"

#include "model/document/change_flags.h"

#include <cmath>

namespace devsurf::document {

bool isUsableReferenceCurve(const model::ReferenceCurve& curve) {
    if (curve.points.size() < 2) {
        return false;
    }
    for (const model::Vec3& p : curve.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            return false;
        }
    }
    return true;
}

ReferenceCurvesCommand::ReferenceCurvesCommand(Document& document,
                                               std::vector<model::ReferenceCurve> before,
                                               std::vector<model::ReferenceCurve> after,
                                               const QString& text)
    : QUndoCommand(text), m_document(document), m_before(std::move(before)),
      m_after(std::move(after)) {}

CommandOrError ReferenceCurvesCommand::createImport(Document& document,
                                                    std::vector<model::ReferenceCurve> curves) {
    if (curves.empty()) {
        return CommandOrError(tr("There are no curves to import."));
    }
    for (const model::ReferenceCurve& curve : curves) {
        if (!isUsableReferenceCurve(curve)) {
            return CommandOrError(tr("A curve to import has fewer than two points or a "
                                     "coordinate that is not a number."));
        }
    }
    std::vector<model::ReferenceCurve> before = document.project().referenceCurves;
    std::vector<model::ReferenceCurve> after = before;
    after.insert(after.end(), std::make_move_iterator(curves.begin()),
                 std::make_move_iterator(curves.end()));
    return CommandOrError(std::unique_ptr<QUndoCommand>(new ReferenceCurvesCommand(
        document, std::move(before), std::move(after), tr("Import Curves"))));
}

CommandOrError ReferenceCurvesCommand::createRemove(Document& document,
                                                    const std::set<int>& indices) {
    const std::vector<model::ReferenceCurve>& before = document.project().referenceCurves;
    if (indices.empty()) {
        return CommandOrError(tr("Select at least one reference curve to remove."));
    }
    for (int index : indices) {
        if (index < 0 || static_cast<std::size_t>(index) >= before.size()) {
            return CommandOrError(tr("Reference curve %1 does not exist.").arg(index + 1));
        }
    }
    std::vector<model::ReferenceCurve> after;
    for (std::size_t i = 0; i < before.size(); ++i) {
        if (indices.count(static_cast<int>(i)) == 0) {
            after.push_back(before[i]);
        }
    }
    return CommandOrError(std::unique_ptr<QUndoCommand>(new ReferenceCurvesCommand(
        document, before, std::move(after), tr("Remove Reference Curves"))));
}

CommandOrError ReferenceCurvesCommand::createRemoveAll(Document& document) {
    const std::size_t count = document.project().referenceCurves.size();
    if (count == 0) {
        return CommandOrError(tr("The design has no reference curves."));
    }
    std::set<int> all;
    for (std::size_t i = 0; i < count; ++i) {
        all.insert(static_cast<int>(i));
    }
    return createRemove(document, all);
}

void ReferenceCurvesCommand::redo() {
    apply(m_after);
}

void ReferenceCurvesCommand::undo() {
    apply(m_before);
}

void ReferenceCurvesCommand::apply(const std::vector<model::ReferenceCurve>& curves) {
    m_document.mutableProject().referenceCurves = curves;
    m_document.notifyChanged(Change::ReferenceCurves);
}

} // namespace devsurf::document
