#include "data/ensemble_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <string>

#include "data/content_hash.h"
#include "data/ensemble_part.h"
#include "data/error.h"
#include "data/grib_reader.h"
#include "data/hdf5_reader.h"
#include "data/netcdf_reader.h"
#include "data/platform.h"
#include "data/reader_support.h"
#include "data/vtk_reader.h"

namespace ensil::data {
namespace {

// Cuts every member of an ensemble read whole to the file's part `part` (its layers, and its
// window's columns and rows), and gives it `grid`, the grid of that part. A member's values run
// x fastest and z slowest, so each row of a run of columns is one contiguous block.
void keepPart(Ensemble& ensemble, const EnsemblePart& part, const Grid& grid) {
    const std::size_t nx = ensemble.grid.nx();
    const std::size_t ny = ensemble.grid.ny();
    const HorizontalWindow window =
        part.window ? *part.window : HorizontalWindow{{{0, nx, 0.0}}, 0, ny};
    for (Member& member : ensemble.members) {
        FieldValues kept(grid.pointCount());
        float* to = kept.data();
        for (std::size_t k = part.firstLayer; k < part.firstLayer + part.layerCount; ++k) {
            for (std::size_t j = window.firstRow; j < window.firstRow + window.rowCount; ++j) {
                for (const ColumnRun& run : window.columns) {
                    to = std::copy_n(member.values.data() + run.first + nx * (j + ny * k),
                                     run.count, to);
                }
            }
        }
        member.values = std::move(kept);
    }
    ensemble.grid = grid;
}

// Asked in this order: NetCDF-4 files are HDF5 files too, so NetCDF goes first.
const std::vector<std::unique_ptr<EnsembleReader>>& readers() {
    static const auto list = [] {
        std::vector<std::unique_ptr<EnsembleReader>> r;
        r.push_back(std::make_unique<NetcdfReader>());
        r.push_back(std::make_unique<Hdf5Reader>());
        r.push_back(std::make_unique<VtkReader>());
        r.push_back(std::make_unique<GribReader>());
        return r;
    }();
    return list;
}

}  // namespace

const EnsembleReader& readerFor(const DataSelection& selection) {
    if (selection.paths.empty()) {
        throw Error(ErrorKind::InvalidArgument, "no file given: name one or more files to open");
    }
    const std::string& path = selection.paths.front();
    for (const std::string& p : selection.paths) {
        if (!std::filesystem::exists(p))
            throw Error(ErrorKind::FileNotFound, "no such file: '" + p + "'");
        if (std::filesystem::is_directory(p)) {
            std::string message = "'" + p + "' is a folder; name the files in it (e.g. '";
            message += p;
            message += "/*.nc')";
            throw Error(ErrorKind::InvalidArgument, message);
        }
        // Opening a named pipe (or a device) to look at its first bytes would wait forever.
        if (!std::filesystem::is_regular_file(p)) {
            throw Error(ErrorKind::InvalidArgument,
                        "'" + p +
                            "' is not a regular file (a named pipe, a device or a socket); "
                            "name a file that holds the data");
        }
    }
    // One file, one member: a file named twice (perhaps through another path or a link) would
    // become two identical members, and every cluster and statistic would count it twice.
    std::map<std::filesystem::path, const std::string*> seen;
    for (const std::string& p : selection.paths) {
        std::error_code error;
        const std::filesystem::path canonical = std::filesystem::canonical(p, error);
        if (error) continue;  // read by the reader, which names what is wrong
        const auto [it, added] = seen.emplace(canonical, &p);
        if (!added) {
            throw Error(ErrorKind::InvalidArgument,
                        "'" + *it->second + "' is given twice" +
                            (*it->second == p ? std::string() : " (also as '" + p + "')") +
                            ": each file is read as its own member(s), so the same data would "
                            "count twice in every cluster and statistic. Name each file once");
        }
    }
    std::string names;
    for (const auto& reader : readers()) {
        if (reader->recognizes(path)) return *reader;
        names += (names.empty() ? "" : ", ") + reader->name();
    }
    throw Error(ErrorKind::UnsupportedFormat, "'" + path + "' is not in a format ensil reads (" +
                                                  names + "), or it is truncated");
}

EnsembleDescription describeEnsemble(const DataSelection& selection) {
    return keepRegion(keepLevels(readerFor(selection).describe(selection), selection), selection);
}

EnsembleDescription keepLevels(EnsembleDescription description, const DataSelection& selection) {
    if (!selection.levels) return description;
    const LayerSpan span =
        layersWithin(description.grid.z(), *selection.levels,
                     "'" + description.variable + "' in " + sourceOf(selection.paths));
    description.keptLevels = EnsembleDescription::KeptLevels{span.first, description.grid.z()};
    description.grid = gridLayers(description.grid, span.first, span.count);
    return description;
}

EnsembleDescription keepRegion(EnsembleDescription description, const DataSelection& selection) {
    if (!selection.region) return description;
    const HorizontalWindow window =
        regionWithin(description.grid, description.gridMapping, *selection.region,
                     "'" + description.variable + "' in " + sourceOf(selection.paths));
    description.keptRegion = EnsembleDescription::KeptRegion{
        *selection.region, window, description.grid.x(), description.grid.y()};
    description.grid = gridWindow(description.grid, window);
    return description;
}

EnsembleDescription fileDescription(const EnsembleDescription& description) {
    EnsembleDescription file = description;
    if (description.keptLevels || description.keptRegion) {
        const auto& region = description.keptRegion;
        file.grid =
            Grid(region ? region->fileX : description.grid.x(),
                 region ? region->fileY : description.grid.y(),
                 description.keptLevels ? description.keptLevels->fileZ : description.grid.z());
        file.keptLevels.reset();
        file.keptRegion.reset();
    }
    return file;
}

EnsemblePart filePart(const EnsembleDescription& description, const EnsemblePart& part) {
    EnsemblePart file = part;
    if (description.keptLevels) file.firstLayer += description.keptLevels->first;
    if (description.keptRegion) file.window = description.keptRegion->window;
    return file;
}

std::string sourceIdentity(const DataSelection& selection) {
    std::string id;
    for (const std::string& p : selection.paths) {
        std::error_code error;
        const auto absolute = std::filesystem::absolute(p, error).lexically_normal();
        const auto size = std::filesystem::file_size(p, error);
        const auto time = std::filesystem::last_write_time(p, error).time_since_epoch().count();
        // The contents too: a file rewritten with its size and time kept is other data.
        char hash[17] = "unreadable";
        try {
            std::snprintf(hash, sizeof hash, "%016llx",
                          static_cast<unsigned long long>(contentHash(p)));
        } catch (const Error&) {
            // Reading it will say what is wrong; the key only has to differ.
        }
        id += "file=" + absolute.string() + " size=" + std::to_string(size) +
              " mtime=" + std::to_string(time) + " xxh3=" + hash + "; ";
    }
    return id + "var=" + selection.variable + " member-dim=" + selection.memberDimension +
           " time-index=" + std::to_string(selection.timeIndex) +
           (selection.levels ? " levels=" + levelRangeText(*selection.levels) : "") +
           (selection.region ? " region=" + regionText(*selection.region) : "");
}

void checkMemoryFor(std::size_t bytes, const std::string& what) {
    const std::size_t available = availableMemoryBytes();
    // Keep a quarter of what is free for meshes, the cache and everything else.
    if (available > 0 && static_cast<double>(bytes) > 0.75 * static_cast<double>(available)) {
        throw Error(ErrorKind::OutOfMemory,
                    what + " needs " + sizeText(static_cast<double>(bytes)) +
                        " of memory; ensil takes at most three quarters of the " +
                        sizeText(static_cast<double>(available)) +
                        " available now, keeping the rest for meshes and other programs. "
                        "Choose fewer members, files or points, or close other programs");
    }
}

void makeInfinitiesMissing(Ensemble& ensemble) {
    // An infinity is no value an isosurface can pass through; left in, it made the range
    // [min, inf] (null in JSON) and the histogram's bins undefined. Each member is first only
    // read (a count without branches, which vectorises) and written only if it has any: most
    // have none, and writing every value back doubled the memory traffic of this pass, about a
    // tenth of reading a time step.
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    for (Member& m : ensemble.members) {
        std::size_t infinite = 0;
        for (const float v : m.values) infinite += std::abs(v) == kInfinity ? 1 : 0;
        if (infinite == 0) continue;
        for (float& v : m.values) v = std::abs(v) == kInfinity ? kNaN : v;
        ensemble.infiniteValues += infinite;
    }
}

Ensemble openEnsemble(const DataSelection& selection, const std::stop_token& stop,
                      const Progress& progress, EnsembleDescription* describedAs) {
    const EnsembleReader& reader = readerFor(selection);
    EnsembleDescription description =
        keepRegion(keepLevels(reader.describe(selection), selection), selection);
    const auto checkMemory = [](const EnsembleDescription& d) {
        checkMemoryFor(d.bytes(), "'" + d.variable + "' (" + std::to_string(d.members) +
                                      " members of " + std::to_string(d.grid.nx()) + " x " +
                                      std::to_string(d.grid.ny()) + " x " +
                                      std::to_string(d.grid.nz()) + " points)");
    };
    checkMemory(description);
    Ensemble ensemble;
    if (!description.keptLevels && !description.keptRegion) {
        ensemble = reader.read(selection, stop, progress);
    } else {
        const EnsemblePart part =
            filePart(description, {0, description.members, 0, description.grid.nz()});
        if (reader.readsParts()) {
            // Only the levels, columns and rows kept are read.
            ensemble =
                reader.readPart(selection, fileDescription(description), part, stop, progress);
        } else {
            // A format read whole (GRIB, VTK, HDF5): read, then what is kept copied out.
            checkMemory(fileDescription(description));
            ensemble = reader.read(selection, stop, progress);
            keepPart(ensemble, part, description.grid);
        }
    }
    if (describedAs != nullptr) *describedAs = std::move(description);
    makeInfinitiesMissing(ensemble);
    if (membersWithoutData(ensemble).size() == ensemble.members.size()) {
        throw Error(
            ErrorKind::AllValuesMissing,
            "every value of '" + ensemble.variable + "' in " + ensemble.source +
                " is missing (fill value or outside valid_range): there is nothing to draw");
    }
    return ensemble;
}

std::optional<std::string> infiniteValuesWarning(const Ensemble& ensemble) {
    const std::size_t n = ensemble.infiniteValues;
    if (n == 0) return std::nullopt;
    return std::to_string(n) + (n == 1 ? " value of '" : " values of '") + ensemble.variable +
           (n == 1 ? "' is" : "' are") +
           " infinite (+inf or -inf); ensil treats them as missing values";
}

std::vector<std::size_t> membersWithoutData(const Ensemble& ensemble) {
    std::vector<std::size_t> empty;
    for (std::size_t m = 0; m < ensemble.members.size(); ++m) {
        const FieldValues& values = ensemble.members[m].values;
        if (std::none_of(values.begin(), values.end(), [](float v) { return v == v; })) {
            empty.push_back(m);
        }
    }
    return empty;
}

std::vector<std::string> leaveOutMembersWithoutData(Ensemble& ensemble) {
    const std::vector<std::size_t> empty = membersWithoutData(ensemble);
    if (empty.empty()) return {};
    std::vector<std::string> names;
    std::vector<Member> kept;
    kept.reserve(ensemble.members.size() - empty.size());
    for (std::size_t m = 0, next = 0; m < ensemble.members.size(); ++m) {
        if (next < empty.size() && empty[next] == m) {
            const std::string& name = ensemble.members[m].name;
            names.push_back(name.empty() ? "member " + std::to_string(m + 1) : name);
            ++next;
        } else {
            kept.push_back(std::move(ensemble.members[m]));
        }
    }
    ensemble.members = std::move(kept);
    return names;
}

std::string memberWithoutDataWarning(const Ensemble& ensemble, const std::string& name) {
    return "'" + name + "' of '" + ensemble.variable +
           "' has no valid value (every value is missing); it is left out of the clustering and "
           "of every per-member result";
}

std::string membersWithoutDataKey(const std::vector<std::string>& names) {
    std::string key;
    for (const std::string& name : names) key += (key.empty() ? " without=" : ",") + name;
    return key;
}

}  // namespace ensil::data
