#pragma once

#include "distance_legend.h"
#include "model/composite_surface.h"
#include "model/creases.h"

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <optional>
#include <vector>

class QPainter;

namespace devsurf::views {

// What a view paints over its rendering with QPainter: a scale bar in the lower right corner
// and, optionally, the patch numbers at their patches. It ignores the mouse, so picking and
// the camera work through it.
class ViewOverlay : public QWidget {
    Q_OBJECT
public:
    struct Label {
        QPointF position; // widget coordinates
        QString text;
    };

    // A crease's condition, written in a small coloured box at the crease's midpoint.
    struct Badge {
        QPointF position; // widget coordinates
        model::CreaseCondition condition = model::CreaseCondition::None;
        int surface = 0;
        model::EdgeId edge = model::kInvalidId;
    };

    explicit ViewOverlay(QWidget* parent);

    // The badge's text ("CF", "G", "SU") and colour for a condition.
    static QString badgeText(model::CreaseCondition condition);
    static QColor badgeColour(model::CreaseCondition condition);
    // How the views draw creases: mountain red, valley blue, not folded dark crimson (with the
    // dashes of foldDashes).
    static QColor foldColour(model::FoldAssignment fold);
    // How the views draw rulings between two patches: smooth ones light, sharp ones dark.
    static QColor smoothRulingColour();
    static QColor sharpRulingColour();
    // The sheet a held development is confined to (development view).
    static QColor sheetColour();

    // Scale bar of the given length on screen (logical pixels) and its text, e.g. "50 mm";
    // none when pixels is not positive.
    void setScaleBar(double pixels, const QString& text);
    void setLabels(std::vector<Label> labels);
    // The fold legend in the upper left corner, drawn as the views draw the lines: "Mountain
    // fold", "Valley fold" and "Crease, not folded", for those present.
    void setFoldLegend(bool mountains, bool valleys, bool flat = false);
    // The rest of the legend, below the folds: a badge with its condition for every condition
    // among conditions, and, when smooth rulings are drawn, a light line "Smooth ruling" and
    // (if any) a dark line "Sharp ruling".
    void setMarkLegend(std::vector<model::CreaseCondition> conditions, bool smoothRulings,
                       bool sharpRulings);
    // A last entry "Sheet" (a wide line in sheetColour()) when a held sheet is drawn.
    void setSheetLegend(bool sheet);
    void setBadges(std::vector<Badge> badges);
    const std::vector<Badge>& badges() const { return m_badges; }
    // The legend's entries as written, top to bottom.
    QStringList legendEntries() const;
    // What the legend shows, as state: the fold lines, the conditions' badges and the rulings.
    struct LegendContents {
        bool mountainFolds = false;
        bool valleyFolds = false;
        bool flatCreases = false;
        std::vector<model::CreaseCondition> conditions;
        bool smoothRulings = false;
        bool sharpRulings = false;
    };
    LegendContents legendContents() const {
        return {m_mountains,  m_valleys,       m_flatCreases,
                m_conditions, m_smoothRulings, m_sharpRulings};
    }
    bool showsMountainLegend() const { return m_mountains; }
    bool showsValleyLegend() const { return m_valleys; }

    // The legend of a quality colouring, drawn at the right (QualityColouring::legendBox):
    // the colours from low to high on a logarithmic scale, a label every second decade, and
    // the tolerance marked, the colours below it labelled `toleranceLabel`.
    struct QualityLegend {
        QString title;
        std::vector<QColor> colours;
        double low = 1e-12;
        double high = 1e-2;
        double tolerance = 1e-8;
        QString toleranceLabel;
    };
    void setQualityLegend(std::optional<QualityLegend> legend);
    // Where it is drawn (widget coordinates); empty without one.
    QRectF qualityLegendRect() const;

    // The legend of the reference shapes' colour map by distance, at the right, left of the
    // quality legend when both are shown.
    void setDistanceLegend(std::optional<DistanceLegend> legend);
    const std::optional<DistanceLegend>& distanceLegend() const { return m_distance; }
    // Where it is drawn (widget coordinates); empty without one.
    QRectF distanceLegendRect() const;

    // A measurement: a line through the points (widget coordinates) with the text at the last.
    void setMeasurement(std::vector<QPointF> points, const QString& text);

    // A lasso being drawn (Tools ▸ Mark Region of Reference Shape): a closed line through the
    // points (widget coordinates); none when empty.
    void setLasso(std::vector<QPointF> points);
    const std::vector<QPointF>& lasso() const { return m_lasso; }

    // A solve's verdict written in the upper right corner in `colour` (empty: none).
    void setVerdict(const QString& text, const QColor& colour);
    QString verdict() const { return m_verdict; }
    // Where the verdict is drawn (widget coordinates); empty without one.
    QRectF verdictRect() const;

    double scaleBarPixels() const { return m_barPixels; }
    QString scaleBarText() const { return m_barText; }
    const std::vector<Label>& labels() const { return m_labels; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    double m_barPixels = 0.0;
    QString m_barText;
    std::vector<Label> m_labels;
    struct LegendEntry {
        QColor colour;
        QString badge; // a badge swatch; a line swatch when empty
        QString text;
        std::vector<double> dashes; // the line's (foldDashes); empty: solid
    };
    std::vector<LegendEntry> legend() const;

    bool m_mountains = false;
    bool m_valleys = false;
    bool m_flatCreases = false;
    bool m_sheet = false;
    std::vector<model::CreaseCondition> m_conditions;
    bool m_smoothRulings = false;
    bool m_sharpRulings = false;
    std::vector<Badge> m_badges;
    QString m_verdict;
    QColor m_verdictColour;
    std::optional<QualityLegend> m_quality;
    std::optional<DistanceLegend> m_distance;
    std::vector<QPointF> m_measured;
    std::vector<QPointF> m_lasso;
    QString m_measuredText;
    void paintQualityLegend(QPainter& painter, const QFont& font) const;
};

} // namespace devsurf::views
