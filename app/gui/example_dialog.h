#pragma once

#include "model/examples.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;

namespace devsurf::app {

// Chooses a built-in example, its size and whether it holds its sheet for File ▸ New from
// Example. Holding the sheet is on by default for an example that starts flat (remembered
// when the designer turns it off); examples that hold theirs as built, or cannot hold a flat
// one, show it checked or cleared and disabled, with a tooltip that says why.
class ExampleDialog : public QDialog {
    Q_OBJECT
public:
    explicit ExampleDialog(QWidget* parent = nullptr);

    QString exampleName() const;
    int exampleSize() const;
    model::ExampleSheet exampleSheet() const;
    // Whether new designs hold their sheet, as the designer last chose (held by default): the
    // example the application starts on follows it too.
    static model::ExampleSheet rememberedSheet();

private:
    void exampleChanged(int index);
    void describe(); // the example's description, as it holds its sheet or not

    QComboBox* m_examples;
    QSpinBox* m_size;
    QCheckBox* m_holdSheet;
    QLabel* m_description;
};

} // namespace devsurf::app
