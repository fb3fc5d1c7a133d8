// What the workbench shows as soon as an ensemble is loaded, before any isovalue is chosen:
// value statistics, the ensemble moments (mean member, variance), and the column maximum of the
// mean for the floor map.
// Computed off the GUI thread by a pure function. Immutable once built.
#pragma once

#include <functional>
#include <memory>
#include <stop_token>
#include <string>
#include <vector>

#include "data/ensemble.h"
#include "data/job.h"
#include "engine/floor_map.h"
#include "engine/workbench_reading.h"
#include "geo/map_lines.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/field_statistics.h"

namespace ensil::engine {

struct EnsembleOverview {
    std::shared_ptr<const data::Ensemble> ensemble;
    prep::FieldStatistics statistics;
    float defaultIsovalue = 0.0F;  // where the isovalue starts (preprocessing/default_isovalue.h)
    std::shared_ptr<const prep::EnsembleMoments> moments;  // mean member and variance
    ColumnMaxima columnMaxima;  // of the mean and of the spread, for the floor
    // Coastlines, borders and graticule in the grid's coordinates (none without geography).
    std::shared_ptr<const std::vector<geo::MapLine>> mapLines;
    std::string sourceKey;  // identity of the data (with a content hash), for the mesh cache
    // Members with no valid value, left out of `ensemble` (data::leaveOutMembersWithoutData).
    std::vector<std::string> membersWithoutData;
    // The files' variables that can be opened (engine::WorkbenchEnsemble::variables); empty
    // for the demo.
    std::vector<std::string> variables;
    // Set when the data are larger than the workbench's memory budget: `ensemble` is then a
    // thinned copy, and the surfaces come from the whole data read in slabs.
    std::shared_ptr<const StreamedSource> streamed;
};

// What another time step of the data shown shares with the step on screen, so that reading a
// step does not compute it again: the isovalue the data opened at (a step keeps the session's
// isovalue; this is only its fallback), and the map lines (tens of milliseconds through PROJ
// for the 1:50m coastlines) when the grid and its mapping are the same.
struct SameDataParts {
    float defaultIsovalue = 0.0F;
    std::shared_ptr<const std::vector<geo::MapLine>> mapLines;
    data::Grid grid;
    data::GridMapping gridMapping;
};
SameDataParts sameDataParts(const EnsembleOverview& overview);

// How the workbench reads data it opens (engine::readForWorkbench, or the demo generated).
using WorkbenchRead =
    std::function<WorkbenchEnsemble(const std::stop_token&, const data::Progress&)>;

// What the workbench shows of data it opens, on a worker: the ensemble `read` gives (the first
// 60 % of the progress), its members without any valid value left out as the command line
// leaves them out (no NaN distance of theirs may reach the clustering), and its overview built.
// `identify` gives the data's identity for the mesh cache; it reads the files (a content hash),
// so it runs here too. `sameData` as for buildEnsembleOverview. Throws as `read` and
// buildEnsembleOverview do.
EnsembleOverview readEnsembleOverview(const WorkbenchRead& read,
                                      const std::function<std::string()>& identify,
                                      const std::stop_token& stop, const data::Progress& progress,
                                      const SameDataParts* sameData = nullptr);

// Throws data::Cancelled, data::Error. With `sameData` from another time step of the same data
// on the same grid and mapping, its isovalue and map lines are taken instead of computed.
EnsembleOverview buildEnsembleOverview(std::shared_ptr<const data::Ensemble> ensemble,
                                       const std::stop_token& stop, const data::Progress& progress,
                                       const SameDataParts* sameData = nullptr);

}  // namespace ensil::engine
