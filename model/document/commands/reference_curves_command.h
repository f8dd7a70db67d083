#pragma once

#include "command_or_error.h"
#include "model/document/document.h"
#include "model/reference_curve.h"

#include <QCoreApplication>
#include <QUndoCommand>

#include <set>
#include <vector>

namespace devsurf::document {

// Adds or removes reference curves. It holds the whole list before and after (curves are
// polylines, small next to the surfaces), so undo restores it bit for bit and redo never
// re-reads a file.
class ReferenceCurvesCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(ReferenceCurvesCommand)
public:
    // Appends the curves (one undo step for a whole file). Refused when there are none or a
    // curve has fewer than two points or a coordinate that is not finite.
    static CommandOrError createImport(Document& document,
                                       std::vector<model::ReferenceCurve> curves);
    // Removes the curves at these indices; refused when an index does not exist or none is
    // given.
    static CommandOrError createRemove(Document& document, const std::set<int>& indices);
    // Removes every reference curve; refused when there is none.
    static CommandOrError createRemoveAll(Document& document);

    void redo() override;
    void undo() override;

    const std::vector<model::ReferenceCurve>& before() const { return m_before; }
    const std::vector<model::ReferenceCurve>& after() const { return m_after; }

private:
    ReferenceCurvesCommand(Document& document, std::vector<model::ReferenceCurve> before,
                           std::vector<model::ReferenceCurve> after, const QString& text);
    void apply(const std::vector<model::ReferenceCurve>& curves);

    Document& m_document;
    std::vector<model::ReferenceCurve> m_before;
    std::vector<model::ReferenceCurve> m_after;
};

// Whether a curve can be shown and stored: two points or more, every coordinate finite.
bool isUsableReferenceCurve(const model::ReferenceCurve& curve);

} // namespace devsurf::document
