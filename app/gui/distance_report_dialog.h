#pragma once

#include <QDialog>
#include <QPointer>

#include <memory>
#include <vector>

class QLabel;
class QProgressBar;
class QTableWidget;
class QVBoxLayout;

namespace devsurf::document {
class Document;
} // namespace devsurf::document

namespace devsurf::views {
class ReferenceDistances;
struct ReferenceDistanceResult;
} // namespace devsurf::views

namespace devsurf::app {

// Tools ▸ Distance to Reference…: how far the design is from each reference shape, both ways
// (mean, 95th percentile, largest; in mm and in % of the shape's bounding-box diagonal), and
// how much of the shape lies within the coverage tolerance. The measurement runs in the
// background (views::ReferenceDistances) behind a busy bar; the window stays usable, Close
// stops waiting. While it is open it follows the design: a change measures again, and the
// figures shown meanwhile are marked as out of date.
class DistanceReportDialog : public QDialog {
    Q_OBJECT
public:
    DistanceReportDialog(document::Document* document, QWidget* parent);
    ~DistanceReportDialog() override;

    // The measurement shown (null while the first one runs) and whether it is the design's
    // current state.
    std::shared_ptr<const views::ReferenceDistanceResult> shownResult() const { return m_shown; }
    bool showsCurrent() const;
    // The table of a shape: rows target → surface and surface → target, columns mean, 95th
    // percentile, largest; each cell holds its value in mm as Qt::UserRole and in % of the
    // diagonal as Qt::UserRole + 1.
    QTableWidget* table(int shape) const;
    bool isMeasuring() const;
    // How the report words a length ("1.234 mm": four significant digits, whole millimetres
    // from a metre on) and a percentage; the approximation's sentences word theirs alike.
    static QString millimetres(double value);
    static QString percent(double value);

signals:
    // The figures shown changed (a measurement arrived or the design changed).
    void updated();

private:
    void refresh();
    void clearReports();
    void rebuildReports(const views::ReferenceDistanceResult& result);

    document::Document* m_document;
    // Owned by the document, which may go first when the window closes.
    QPointer<views::ReferenceDistances> m_source;
    std::shared_ptr<const views::ReferenceDistanceResult> m_shown;
    QLabel* m_status = nullptr;
    QProgressBar* m_busy = nullptr;
    QWidget* m_reports = nullptr;
    QVBoxLayout* m_reportsLayout = nullptr;
    std::vector<QTableWidget*> m_tables;
};

} // namespace devsurf::app
