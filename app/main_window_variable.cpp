// Another variable of the files, chosen in the Ensemble panel (issue: change the variable without
// opening the files again): once data from files are on screen, their headers are read in the
// background for the variables that can be opened (data::describeEnsemble: headers only), which
// the panel offers as a list; a pick opens the same files, member dimension and time step with
// that variable, as File > Open would, and the session's settings stay.
#include "app/main_window.h"
#include "data/ensemble_reader.h"
#include "session/session_model.h"
#include "widgets/ensemble_info_panel.h"

namespace ensil::app {

void MainWindow::createVariableChoice() {
    connect(m_info, &ui::EnsembleInfoPanel::variableChosen, this, [this](const QString& name) {
        if (!m_requested) return;
        data::DataSelection selection = *m_requested;
        selection.variable = name.toStdString();
        openFiles(selection);
    });
}

void MainWindow::offerVariables() {
    m_variableProbe.cancel();
    if (!m_requested) return;  // the demo has one
    const data::DataSelection selection = *m_requested;
    m_variableProbe.start(
        [selection](const std::stop_token&, const data::Progress&) {
            const data::EnsembleDescription description = data::describeEnsemble(selection);
            VariableChoices choices;
            for (const data::VariableInfo& v : description.variables) {
                if (v.usable) choices.names << QString::fromStdString(v.name);
            }
            choices.current = QString::fromStdString(description.variable);
            return choices;
        },
        [this](const VariableChoices& choices) {
            m_info->setVariableChoices(choices.names, choices.current);
        },
        // Headers that cannot be read now leave the variable as a plain line.
        [](const std::exception_ptr&, bool) {});
}

}  // namespace ensil::app
