// What the open-data dialog shows about a set of files: the variables they hold, the member
// dimension found (or the candidates when none is), the time steps to choose from, and any
// reader error in plain words. Read from the headers only (data::describeEnsemble), never the
// values. Pure function of the files; call it on a worker thread (it may wait for the netCDF
// library while a load holds it). Never throws.
#pragma once

#include "data/ensemble_reader.h"
#include "widgets/open_data_dialog.h"

namespace ensil::app {

// With a memoryLimit (the workbench's), the probe also says how the data would open within it
// (DataProbe::size, app::howItOpens).
ui::DataProbe probeData(const data::DataSelection& selection, std::size_t memoryLimit = 0);

}  // namespace ensil::app
