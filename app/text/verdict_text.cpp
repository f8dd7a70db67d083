#include "verdict_text.h"

#include <QStringList>

#include <map>
#include <vector>

namespace devsurf::app {

namespace {

// "patch 3", "patches 3, 4" or, with several surfaces, "surface 1 patches 3, 4; surface 2 …".
QString places(const solver::Verdict& verdict) {
    std::map<int, QStringList> bySurface;
    for (const auto& [surface, face] : verdict.patches) {
        QStringList& ids = bySurface[surface];
        if (ids.size() < 8) {
            ids << QString::number(face);
        } else if (ids.size() == 8) {
            ids << QStringLiteral("…");
        }
    }
    QStringList parts;
    for (const auto& [surface, ids] : bySurface) {
        const QString patches =
            ids.size() == 1 ? VerdictText::tr("patch %1").arg(ids.front())
                            : VerdictText::tr("patches %1").arg(ids.join(QStringLiteral(", ")));
        parts << (bySurface.size() > 1
                      ? VerdictText::tr("surface %1 %2").arg(surface + 1).arg(patches)
                      : patches);
    }
    return parts.join(QStringLiteral("; "));
}

QString advice(const solver::Verdict& verdict) {
    QStringList tries;
    if (verdict.undoLastStep) {
        tries << VerdictText::tr("undo the last step and make a smaller change");
    }
    if (verdict.solveMore) {
        tries << VerdictText::tr("solve with more iterations");
    }
    if (verdict.releasePins) {
        tries << VerdictText::tr("release pins that hold the sheet");
    }
    if (tries.isEmpty()) {
        tries << VerdictText::tr("solve again");
    }
    return tries.join(VerdictText::tr("; or "));
}

} // namespace

QString VerdictText::millimetres(double value) {
    if (value < 1e-4) {
        return tr("< 0.0001");
    }
    return QString::number(value, 'g', 2);
}

QString VerdictText::of(const solver::Verdict& verdict) {
    switch (verdict.kind) {
    case solver::VerdictKind::None:
        break;
    case solver::VerdictKind::ReadyToCut:
        return tr("Developable to the tolerance — ready to cut.");
    case solver::VerdictKind::WithinIsometry: {
        const QString mm = millimetres(verdict.isometryMm);
        return tr("Developable to within %1 mm of isometry over the sheet: the cut pattern is "
                  "off by at most %1 mm.")
            .arg(mm);
    }
    case solver::VerdictKind::NotDevelopable: {
        const QString where = places(verdict);
        if (verdict.overlapsOnly) {
            return tr("Developable patch by patch, but the development overlaps itself at %1: "
                      "it cannot be cut from one piece. Try: %2.")
                .arg(where, advice(verdict));
        }
        const QString what =
            verdict.foldsOver ? tr("Not developable: the surface folds over or its "
                                   "development overlaps itself")
            : verdict.sheetStretched
                ? tr("Not developable from its sheet: it lies %1 mm from the sheet it keeps")
                      .arg(millimetres(verdict.sheetStretchMm))
                : tr("Not developable");
        return where.isEmpty() ? tr("%1. Try: %2.").arg(what, advice(verdict))
                               : tr("%1 at %2. Try: %3.").arg(what, where, advice(verdict));
    }
    }
    return QString();
}

QString VerdictText::brief(const solver::Verdict& verdict) {
    switch (verdict.kind) {
    case solver::VerdictKind::None:
        break;
    case solver::VerdictKind::ReadyToCut:
        return tr("Developable — ready to cut");
    case solver::VerdictKind::WithinIsometry:
        return tr("Developable within %1 mm").arg(millimetres(verdict.isometryMm));
    case solver::VerdictKind::NotDevelopable: {
        const QString where = places(verdict);
        if (verdict.overlapsOnly) {
            return tr("Development overlaps itself: %1").arg(where);
        }
        return where.isEmpty() ? tr("Not developable") : tr("Not developable: %1").arg(where);
    }
    }
    return QString();
}

QString VerdictText::details(const solver::Verdict& verdict) {
    if (verdict.kind == solver::VerdictKind::None) {
        return QString();
    }
    QString text = tr("Largest constraint residual %1 (tolerance %2).")
                       .arg(QString::number(verdict.residual, 'e', 1),
                            QString::number(verdict.tolerance, 'e', 1));
    if (verdict.sheetExtent > 0.0) {
        text += QLatin1Char(' ') +
                tr("Development: largest relative edge-length error %1 over a sheet of %2 mm, "
                   "%3 mm from isometric.")
                    .arg(QString::number(verdict.edgeLengthError, 'e', 1))
                    .arg(verdict.sheetExtent, 0, 'f', 0)
                    .arg(millimetres(verdict.isometryMm));
    }
    if (verdict.sheetStretchMm >= 0.0) {
        text +=
            QLatin1Char(' ') +
            tr("Distance from the sheet it keeps: %1 mm.").arg(millimetres(verdict.sheetStretchMm));
    }
    return text;
}

} // namespace devsurf::app
