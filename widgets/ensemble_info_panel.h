// A dock panel that states what is loaded: source, variable, units, members, grid, axes, value
// range and missing points, in plain words. Fed a plain struct so it knows nothing of readers
// or preprocessing. GUI thread only.
#pragma once

#include <QWidget>

#include "engine/ensemble_facts.h"

class QFormLayout;
class QLabel;

namespace ensil::ui {

class EnsembleInfoPanel : public QWidget {
    Q_OBJECT
public:
    explicit EnsembleInfoPanel(QWidget* parent = nullptr);

    void showFacts(const engine::EnsembleFacts& facts);
    void showMessage(const QString& message);  // e.g. while loading, or an error
    // The panel's text as shown, line by line (for tests and copying).
    [[nodiscard]] QString text() const;

private:
    QLabel* m_message;
    QFormLayout* m_form;
};

}  // namespace ensil::ui
