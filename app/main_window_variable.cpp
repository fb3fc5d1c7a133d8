// Another variable of the files, chosen in the Ensemble panel (issue: change the variable without
// opening the files again): the variables that can be opened come with the data (the headers
// read to open it, engine::WorkbenchEnsemble::variables), and the panel offers them as a list; a
// pick opens the same files, member dimension and time step with that variable, as File > Open
// would, and the session's settings stay.
#include "app/main_window.h"
#include "widgets/ensemble_info_panel.h"
#include "workbench/workbench.h"

namespace ensil::app {

void MainWindow::createVariableChoice() {
    connect(m_info, &ui::EnsembleInfoPanel::variableChosen, this, [this](const QString& name) {
        if (!m_workbench->files()) return;
        data::DataSelection selection = *m_workbench->files();
        selection.variable = name.toStdString();
        openFiles(selection);
    });
}

void MainWindow::offerVariables() {
    QStringList names;
    for (const std::string& name : overview()->variables) names << QString::fromStdString(name);
    m_info->setVariableChoices(names);
}

}  // namespace ensil::app
