// Readers turn files into an Ensemble. An ensemble arrives in one of three shapes:
//   - one file with a member dimension, e.g. t(number, time, plev, lat, lon);
//   - one file per member (run_01.nc ... run_56.nc, member_*.vti), same grid in each;
//   - one file where another dimension stands in for members (forecast times, months): the user
//     names it in DataSelection::memberDimension.
// Each format implements EnsembleReader; openEnsemble()/describeEnsemble() pick the reader by the
// files' first bytes, not their names. Readers are stateless and callable from any thread.
// Every failure is a data::Error whose message names the file, variable and dimension at fault
// and says what would work.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "data/ensemble.h"
#include "data/job.h"
#include "data/level_range.h"
#include "data/region.h"

namespace ensil::data {

// What the user asked for. Empty fields mean "choose automatically".
struct DataSelection {
    std::vector<std::string> paths{};  // one file with members, or one file per member
    std::string variable{};            // variable / dataset / point-data array name
    std::string memberDimension{};     // override of the detected member dimension (NetCDF)
    std::size_t timeIndex = 0;         // index for every other non-spatial dimension
    // The vertical levels kept (data/level_range.h); none: all of them.
    std::optional<LevelRange> levels{};
    // The region kept (data/region.h); none: the whole grid.
    std::optional<Region> region{};

    bool operator==(const DataSelection&) const = default;
};

// A variable the file holds, and whether ensil can make an ensemble of it.
struct VariableInfo {
    std::string name;
    std::string longName;
    std::string standardName;  // CF's, where the file gives one
    std::string units;
    std::vector<std::string>
        dimensions;  // as stored, e.g. {"number", "time", "plev", "lat", "lon"}
    std::vector<std::size_t> shape;
    bool usable = false;
    std::size_t levels = 0;    // points along the vertical axis, when usable
    bool derived = false;      // computed by ensil (wind_speed from u and v)
    std::string whyNotUsable;  // set when !usable: what is missing, in plain words
};

// What a selection resolves to, read from headers only (cheap): everything `ensil info` prints
// except the value statistics.
struct EnsembleDescription {
    std::string format;  // "NetCDF-4", "NetCDF classic", "HDF5", "VTK legacy", "VTK XML image",
                         // "GRIB 1", "GRIB 2", "GRIB 1 and 2"
    std::vector<VariableInfo> variables;
    std::string variable;  // the chosen one
    std::string longName;
    std::string units;
    std::string memberDimension;        // empty for one file per member
    std::string memberDimensionReason;  // how it was found, e.g. "standard_name = realization"
    std::size_t members = 0;
    std::vector<std::string> memberNames;
    std::vector<std::string> fixedDimensions;  // e.g. "time = 0 of 4 (2017-01-01T00:00)"
    TimeSteps timeSteps;                       // what timeIndex may be, with dates
    Grid grid;
    GridMapping gridMapping;            // see data/grid_mapping.h
    std::vector<std::string> warnings;  // as Ensemble::warnings, from the headers alone
    // Set when the selection keeps only some levels (DataSelection::levels): `grid` is cut to
    // the file's layers [first, first + grid.nz()) along `fileZ`, all of the file's levels.
    struct KeptLevels {
        std::size_t first = 0;
        Axis fileZ;
    };
    std::optional<KeptLevels> keptLevels;
    // Set when the selection keeps `region` (DataSelection::region): `grid` is cut to the
    // file's columns and rows in `window` (gridWindow), along `fileX` and `fileY`, the file's.
    struct KeptRegion {
        Region region;
        HorizontalWindow window;
        Axis fileX;
        Axis fileY;
    };
    std::optional<KeptRegion> keptRegion;
    [[nodiscard]] std::size_t bytes() const { return members * grid.pointCount() * sizeof(float); }
};

// A part of an ensemble, for reading it in slabs: the members [firstMember, firstMember +
// memberCount) and the grid's layers along z [firstLayer, firstLayer + layerCount) (a hyperslab).
struct EnsemblePart {
    std::size_t firstMember = 0;
    std::size_t memberCount = 0;
    std::size_t firstLayer = 0;
    std::size_t layerCount = 0;
    // The grid's columns and rows read (data/region.h); none: all of them. Set for the reader
    // from the region a selection keeps (filePart); a part asked for leaves it empty.
    std::optional<HorizontalWindow> window{};

    bool operator==(const EnsemblePart&) const = default;
};

class EnsembleReader {
public:
    virtual ~EnsembleReader() = default;

    [[nodiscard]] virtual std::string name() const = 0;  // "NetCDF", "HDF5", "VTK"
    // True when the file's first bytes say it is in this reader's format.
    [[nodiscard]] virtual bool recognizes(const std::string& path) const = 0;
    // Resolves the selection from the headers. Throws Error.
    [[nodiscard]] virtual EnsembleDescription describe(const DataSelection& selection) const = 0;
    // Reads the values. Throws Error, Cancelled. Values are float, NaN where missing.
    [[nodiscard]] virtual Ensemble read(const DataSelection& selection, const std::stop_token& stop,
                                        const Progress& progress) const = 0;
    // True when readPart() reads a part without the rest (data/ensemble_part.h).
    [[nodiscard]] virtual bool readsParts() const { return false; }
    // Reads only `part` of the ensemble `description` says (describe()'s for this selection):
    // its members, on the grid cut to its layers. Call it through openEnsemblePart(), which
    // checks the part first. Throws Error, Cancelled; Error(UnsupportedFormat) where
    // readsParts() is false (defined in data/ensemble_part.cpp).
    [[nodiscard]] virtual Ensemble readPart(const DataSelection& selection,
                                            const EnsembleDescription& description,
                                            const EnsemblePart& part, const std::stop_token& stop,
                                            const Progress& progress) const;
};

// The reader for the selection's files, chosen by their first bytes. Throws Error(FileNotFound)
// or Error(UnsupportedFormat) listing the formats ensil reads.
const EnsembleReader& readerFor(const DataSelection& selection);

// What the headers say of the selection, its grid cut to the levels and the region it keeps.
EnsembleDescription describeEnsemble(const DataSelection& selection);
// The description the selection's reader gave, cut to the levels the selection keeps (a
// description of the file's every level when it keeps them all). Throws Error(InvalidArgument)
// when the levels cannot be kept (layersWithin).
EnsembleDescription keepLevels(EnsembleDescription description, const DataSelection& selection);
// The description, cut to the region the selection keeps (unchanged when it keeps the whole
// grid). Throws Error(InvalidArgument) when the grid is not a regular longitude-latitude grid,
// RegionOutsideGrid when the region holds fewer than 2 of its columns or rows (regionWithin).
EnsembleDescription keepRegion(EnsembleDescription description, const DataSelection& selection);
// The reader's own description of what `description` keeps: its grid with all of the file's
// levels, columns and rows again (what EnsembleReader::readPart expects).
EnsembleDescription fileDescription(const EnsembleDescription& description);
// `part` of what `description` keeps as a part of the file: its layers further up by the
// levels left out below, and the window of the region kept.
EnsemblePart filePart(const EnsembleDescription& description, const EnsemblePart& part);

// Checks the memory the ensemble needs against what the machine has (Error(OutOfMemory) with
// both figures), then reads it. Infinite values become NaN (missing), counted in
// Ensemble::infiniteValues; Error(AllValuesMissing) when no value is left.
// `description`, when given, receives what the headers said (read once, not twice).
Ensemble openEnsemble(const DataSelection& selection, const std::stop_token& stop = {},
                      const Progress& progress = {}, EnsembleDescription* description = nullptr);

// Makes every +inf or -inf value NaN (missing: no isosurface, range or distance can use it),
// counting them in Ensemble::infiniteValues. What openEnsemble and openEnsemblePart do.
void makeInfinitiesMissing(Ensemble& ensemble);

// "2 values of 't' are infinite (+inf or -inf); ensil treats them as missing values", when
// openEnsemble() found any.
std::optional<std::string> infiniteValuesWarning(const Ensemble& ensemble);

// The members with no valid (non-NaN) value, by index in member order. Such a member has no
// isosurface and no distance to any other member.
std::vector<std::size_t> membersWithoutData(const Ensemble& ensemble);

// Takes the members membersWithoutData() finds out of `ensemble` and returns their names
// ("member 3", by position, where the file names none), in member order. Their distances, the
// linkage heights and their figures would all be NaN or infinite: the command line and the
// workbench both leave them out of the clustering and of every per-member result this way.
std::vector<std::string> leaveOutMembersWithoutData(Ensemble& ensemble);

// "'member 2' of 't' has no valid value (every value is missing); it is left out of the
// clustering and of every per-member result", for one name leaveOutMembersWithoutData() gave.
std::string memberWithoutDataWarning(const Ensemble& ensemble, const std::string& name);

// What cache keys append for the members left out (" without=member 2"; empty when none), so
// that meshes of fewer members than the file holds are not taken for the file's.
std::string membersWithoutDataKey(const std::vector<std::string>& names);

// What identifies the data a selection reads, for cache keys: every file's absolute path,
// size and modification time, and the variable, member dimension, time index, levels and
// region. A file that changes changes the identity.
std::string sourceIdentity(const DataSelection& selection);

// Throws Error(OutOfMemory) when `bytes` will not fit in the memory available now.
void checkMemoryFor(std::size_t bytes, const std::string& what);

}  // namespace ensil::data
