#pragma once

#include <QDialog>

#include <vector>

class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace devsurf::app {

// Asks where along or across a strip an edit goes, in per cent, with a slider and a number,
// and announces every change so that the caller can preview the edit in the 3D view before OK.
// Either any percentage in a range (a crease) or one of given positions (a ruling through a
// spline breakpoint).
class PositionDialog : public QDialog {
    Q_OBJECT
public:
    PositionDialog(const QString& title, const QString& question, QWidget* parent);

    void setRange(double minPercent, double maxPercent, double percent);
    void setChoices(std::vector<double> fractions, int current);

    // The chosen position in 0..1; with choices, the index of the chosen one.
    double fraction() const;
    int choice() const;

    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* percentBox() const { return m_percent; }

signals:
    void fractionChanged(double fraction);

private:
    void onSlider(int value);
    void onPercent(double percent);

    QSlider* m_slider;
    QDoubleSpinBox* m_percent;
    std::vector<double> m_choices; // empty: any value in the range
    bool m_updating = false;
};

} // namespace devsurf::app
