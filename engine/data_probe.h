// What the open-data dialog shows about a set of files: the variables they hold, the member
// dimension found (or the candidates when none is), the time steps to choose from, and any
// reader error in plain words. Read from the headers only (data::describeEnsemble), never the
// values. Pure function of the files; call it on a worker thread (it may wait for the netCDF
// library while a load holds it). Never throws.
#pragma once

#include <QString>
#include <QStringList>
#include <vector>

#include "data/ensemble_reader.h"

namespace ensil::engine {

struct ProbedVariable {
    QString name;
    QString dimensions;  // "number=10, time=4, plev=2, lat=61, lon=120"
    QString units;
    QString longName;
    bool usable = false;
    QString whyNotUsable;  // set when !usable
};

// What the files hold under the current choices, as the headers say.
struct DataProbe {
    QString format;  // "NetCDF-4", "VTK legacy", ...
    std::vector<ProbedVariable> variables;
    QString variable;                    // the variable the choices resolve to
    QStringList memberDimensionChoices;  // dimensions that could hold the members
    QString memberDimension;             // the one in use; empty: one member per file
    QString memberDimensionReason;       // "standard_name = realization", "chosen by you"
    int members = 0;
    int timeSteps = 0;            // indices along the fixed dimensions; 0 when none
    QStringList fixedDimensions;  // "time = 0 of 4 (2017-01-01T00:00)"
    QString grid;                 // "120 x 61 x 2"
    // The vertical axis kept, as ensil info says it: "plev: 1000 .. 100 hPa, 7 points, uneven
    // spacing" (what a level range is typed against).
    QString levels;
    // The horizontal axes kept, as ensil info says them, "lon: -9 .. 39 degrees_east, 17 points,
    // uniform; lat: 72 .. 36 degrees_north, 13 points, uniform" (what a region is typed
    // against), and how much of the file's they are when a region is kept.
    QString region;
    QString size;   // "21 MiB of values", and how they open; empty: not said
    QString error;  // plain words; non-empty: the files cannot be read so
};

// With a memoryLimit (the workbench's), the probe also says how the data would open within it
// (DataProbe::size, engine::howItOpens).
DataProbe probeData(const data::DataSelection& selection, std::size_t memoryLimit = 0);

}  // namespace ensil::engine
