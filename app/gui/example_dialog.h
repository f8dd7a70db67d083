#pragma once

#include <QDialog>

class QComboBox;
class QLabel;
class QSpinBox;

namespace devsurf::app {

// Chooses a built-in example and its size for File ▸ New from Example.
class ExampleDialog : public QDialog {
    Q_OBJECT
public:
    explicit ExampleDialog(QWidget* parent = nullptr);

    QString exampleName() const;
    int exampleSize() const;

private:
    void exampleChanged(int index);

    QComboBox* m_examples;
    QSpinBox* m_size;
    QLabel* m_description;
};

} // namespace devsurf::app
