// A dock panel that states what is loaded: source, variable, units, members, grid, axes, value
// range and missing points, in plain words. Fed a plain struct so it knows nothing of readers
// or preprocessing. GUI thread only.
#pragma once

#include <QWidget>

class QFormLayout;
class QLabel;

namespace ensil::ui {

struct EnsembleFacts {
    QString source;
    QString variable;  // "wind_speed (Wind speed)"
    QString units;
    QString memberDimension;
    int members = 0;
    QString gridSize;  // "256 x 128 x 16"
    QStringList axes;  // one line per axis: "lon: -80 .. 40 degrees_east, uniform"
    QString valueRange;
    qulonglong missing = 0;
    double megabytes = 0.0;
    // What the data cannot show well (few levels, members left out), a line each; empty when
    // nothing.
    QString warning;
};

class EnsembleInfoPanel : public QWidget {
    Q_OBJECT
public:
    explicit EnsembleInfoPanel(QWidget* parent = nullptr);

    void showFacts(const EnsembleFacts& facts);
    void showMessage(const QString& message);  // e.g. while loading, or an error
    // The panel's text as shown, line by line (for tests and copying).
    [[nodiscard]] QString text() const;

private:
    QLabel* m_message;
    QFormLayout* m_form;
};

}  // namespace ensil::ui
