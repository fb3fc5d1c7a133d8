// Turns an ensemble overview into the plain facts the info panel shows.
#pragma once

#include "app/ensemble_overview.h"
#include "data/ensemble_reader.h"
#include "widgets/ensemble_info_panel.h"

namespace ensil::app {

ui::EnsembleFacts ensembleFacts(const EnsembleOverview& overview);
// "lon: -80 .. 40 degrees_east, 256 points, uniform"
QString describeAxis(const data::Axis& axis);
// A variable's dimensions with their lengths where known: "number=10, plev=7, lat=61, lon=120"
QString describeDimensions(const data::VariableInfo& variable);

}  // namespace ensil::app
