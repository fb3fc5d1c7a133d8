// A dock panel that states what is loaded: source, variable, units, members, grid, axes, value
// range and missing points, in plain words. Fed a plain struct so it knows nothing of readers
// or preprocessing. Where the files hold other variables, the variable is a choice: picking one
// asks the window to open it in place of this one. GUI thread only.
#pragma once

#include <QWidget>

#include "engine/ensemble_facts.h"

class QComboBox;
class QFormLayout;
class QLabel;

namespace ensil::ui {

class EnsembleInfoPanel : public QWidget {
    Q_OBJECT
public:
    explicit EnsembleInfoPanel(QWidget* parent = nullptr);

    void showFacts(const engine::EnsembleFacts& facts);
    void showMessage(const QString& message);  // e.g. while loading, or an error
    // The variables the files hold that can be opened, by name: with two or more, among them the
    // one shown, the Variable row is a list (Alt+V). Empty: a plain line. Kept until set again.
    void setVariableChoices(const QStringList& names);
    [[nodiscard]] QComboBox* variableChoice() const { return m_variableChoice; }
    // The panel's text as shown, line by line (for tests and copying).
    [[nodiscard]] QString text() const;

signals:
    // The user picked another variable of the files.
    void variableChosen(const QString& name);

private:
    void showRows();

    QLabel* m_message;
    QFormLayout* m_form;
    QComboBox* m_variableChoice = nullptr;  // a row of m_form while facts are shown
    engine::EnsembleFacts m_facts;
    bool m_showingFacts = false;
    QStringList m_variables;
};

}  // namespace ensil::ui
