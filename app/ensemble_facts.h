// Turns an ensemble overview into the plain facts the info panel shows.
#pragma once

#include "app/ensemble_overview.h"
#include "widgets/ensemble_info_panel.h"

namespace ensil::app {

ui::EnsembleFacts describeEnsemble(const EnsembleOverview& overview);
// "lon: -80 .. 40 degrees_east, 256 points, uniform"
QString describeAxis(const data::Axis& axis);

}  // namespace ensil::app
