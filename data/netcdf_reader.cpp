#include "data/netcdf_reader.h"

#include <netcdf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "data/cf_conventions.h"
#include "data/ensemble_part.h"
#include "data/error.h"
#include "data/netcdf_file.h"
#include "data/netcdf_plan.h"
#include "data/reader_support.h"

namespace ensil::data {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// How to turn stored numbers into physical values: masks first (on the stored numbers, as CF
// says for packed data), then scale and offset.
struct Unpacking {
    std::vector<double> missing;  // _FillValue and missing_value
    double validMin = -std::numeric_limits<double>::infinity();
    double validMax = std::numeric_limits<double>::infinity();
    double scale = 1.0, offset = 0.0;
    bool packed = false;
};

Unpacking unpackingFor(const NetcdfFile& file, const NcVariable& var) {
    Unpacking u;
    for (const char* name : {"_FillValue", "missing_value"}) {
        for (double v : file.numericAttribute(var.id, name)) u.missing.push_back(v);
    }
    if (file.numericAttribute(var.id, "_FillValue").empty()) {
        // netCDF's default fill marks never-written values in float and double variables.
        if (var.type == NC_FLOAT) u.missing.push_back(NC_FILL_FLOAT);
        if (var.type == NC_DOUBLE) u.missing.push_back(NC_FILL_DOUBLE);
    }
    const auto range = file.numericAttribute(var.id, "valid_range");
    if (range.size() == 2) {
        u.validMin = range[0];
        u.validMax = range[1];
    }
    if (const auto lo = file.numericAttribute(var.id, "valid_min"); !lo.empty()) u.validMin = lo[0];
    if (const auto hi = file.numericAttribute(var.id, "valid_max"); !hi.empty()) u.validMax = hi[0];
    if (const auto s = file.numericAttribute(var.id, "scale_factor"); !s.empty()) u.scale = s[0];
    if (const auto o = file.numericAttribute(var.id, "add_offset"); !o.empty()) u.offset = o[0];
    u.packed = u.scale != 1.0 || u.offset != 0.0;
    return u;
}

template <typename T>
void unpackInto(const T* raw, std::size_t n, const Unpacking& u, float* out) {
    for (std::size_t i = 0; i < n; ++i) {
        const auto v = static_cast<double>(raw[i]);
        bool masked = std::isnan(v) || v < u.validMin || v > u.validMax;
        for (double m : u.missing) masked = masked || v == m || (std::isnan(m) && std::isnan(v));
        out[i] = masked ? kNaN : static_cast<float>(v * u.scale + u.offset);
    }
}

// Reads one member of one component into `out` (sizes[0] * sizes[1] * sizes[2] values, x fastest),
// from the point `first` (along x, y, z) on.
void readComponent(const NetcdfFile& file, const NcPlan& plan, const NcComponent& c,
                   std::size_t member, FieldValues& out, std::vector<double>& scratch,
                   const std::array<std::size_t, 3>& first) {
    const NcVariable& var = *c.variable;
    const std::size_t rank = var.dimIds.size();
    std::vector<std::size_t> start(rank, 0), count(rank, 1);
    std::vector<std::ptrdiff_t> stride(rank, 1), imap(rank, 0);
    const std::array<std::ptrdiff_t, 3> strides{
        1, static_cast<std::ptrdiff_t>(c.sizes[0]),
        static_cast<std::ptrdiff_t>(c.sizes[0] * c.sizes[1])};
    std::vector<int> order;  // slots of spatial dimensions in storage order
    for (std::size_t d = 0; d < rank; ++d) {
        const int id = var.dimIds[d];
        const auto slot = std::find(c.spatialDims.begin(), c.spatialDims.end(), id);
        if (slot != c.spatialDims.end()) {
            const auto s = static_cast<std::size_t>(slot - c.spatialDims.begin());
            count[d] = c.sizes[s];
            start[d] = first.at(s);
            imap[d] = strides[s];
            order.push_back(static_cast<int>(s));
        } else {
            start[d] = id == plan.memberDim ? member : plan.timeIndex;
        }
    }
    const bool canonical = order == std::vector<int>{2, 1, 0};  // (z, y, x): straight copy
    const std::size_t n = c.sizes[0] * c.sizes[1] * c.sizes[2];
    out.resize(n);
    const Unpacking u = unpackingFor(file, var);
    const std::string what = "read '" + var.name + "' member " + std::to_string(member);
    if (var.type == NC_FLOAT && !u.packed && u.missing.size() <= 1 && std::isinf(u.validMin) &&
        std::isinf(u.validMax)) {
        // The common case: floats with at most one fill value. A tight loop the compiler
        // vectorises; NaN never equals the fill, so it stays NaN.
        file.check(
            canonical ? nc_get_vara_float(file.id(), var.id, start.data(), count.data(), out.data())
                      : nc_get_varm_float(file.id(), var.id, start.data(), count.data(),
                                          stride.data(), imap.data(), out.data()),
            what);
        const float fill = u.missing.empty() ? kNaN : static_cast<float>(u.missing.front());
        if (std::isnan(fill)) return;  // a NaN fill is already what ensil uses for missing
        float* values = out.data();
        for (std::size_t i = 0; i < n; ++i) values[i] = values[i] == fill ? kNaN : values[i];
        return;
    }
    if (var.type == NC_FLOAT && !u.packed) {
        file.check(
            canonical ? nc_get_vara_float(file.id(), var.id, start.data(), count.data(), out.data())
                      : nc_get_varm_float(file.id(), var.id, start.data(), count.data(),
                                          stride.data(), imap.data(), out.data()),
            what);
        unpackInto(out.data(), n, u, out.data());
        return;
    }
    scratch.resize(n);
    file.check(canonical ? nc_get_vara_double(file.id(), var.id, start.data(), count.data(),
                                              scratch.data())
                         : nc_get_varm_double(file.id(), var.id, start.data(), count.data(),
                                              stride.data(), imap.data(), scratch.data()),
               what);
    unpackInto(scratch.data(), n, u, out.data());
}

// Averages neighbours along every axis where the component has one more point than `target`.
void destagger(const NcComponent& c, const std::array<std::size_t, 3>& target,
               FieldValues& values) {
    std::array<std::size_t, 3> size = c.sizes;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        if (size[axis] == target[axis]) continue;
        std::array<std::size_t, 3> next = size;
        next[axis] = target[axis];
        FieldValues result(next[0] * next[1] * next[2]);
        const std::array<std::size_t, 3> step{1, size[0], size[0] * size[1]};
        for (std::size_t k = 0; k < next[2]; ++k) {
            for (std::size_t j = 0; j < next[1]; ++j) {
                for (std::size_t i = 0; i < next[0]; ++i) {
                    const std::size_t src = i + size[0] * (j + size[1] * k);
                    result[i + next[0] * (j + next[1] * k)] =
                        0.5F * (values[src] + values[src + step[axis]]);
                }
            }
        }
        values = std::move(result);
        size = next;
    }
}

// A box of the plan's grid: the points [first[s], first[s] + count[s]) along x, y and z.
struct Block {
    std::array<std::size_t, 3> first{};
    std::array<std::size_t, 3> count{};
};

// The component as read over `block`: as many points along each axis, one more where it is
// staggered.
NcComponent componentBlock(const NcPlan& plan, const NcComponent& c, const Block& block) {
    NcComponent part = c;
    const std::array<std::size_t, 3> grid{plan.grid.nx(), plan.grid.ny(), plan.grid.nz()};
    for (std::size_t s = 0; s < 3; ++s)
        part.sizes.at(s) = block.count.at(s) + (c.sizes.at(s) - grid.at(s));
    return part;
}

// One member over `block` into `out` (its points, x fastest): one hyperslab per component.
void readBlock(const NetcdfFile& file, const NcPlan& plan, std::size_t member, const Block& block,
               FieldValues& out) {
    FieldValues part;
    std::vector<double> scratch;
    const NcComponent first = componentBlock(plan, plan.components.front(), block);
    readComponent(file, plan, first, member, out, scratch, block.first);
    destagger(first, block.count, out);
    if (plan.offset != 0.0) {
        const auto offset = static_cast<float>(plan.offset);
        for (float& v : out) v += offset;  // NaN stays NaN
    }
    if (plan.components.size() < 2) return;
    const NcComponent second = componentBlock(plan, plan.components.at(1), block);
    readComponent(file, plan, second, member, part, scratch, block.first);
    destagger(second, block.count, part);
    toWindSpeed(out.data(), part.data(), out.size());
}

// One member over the grid's layers [firstLayer, firstLayer + grid.nz()), `grid` being the plan's
// grid cut to them (the whole grid for the whole member), and to `window`'s columns and rows
// where one is given (a region kept): a hyperslab per run of columns, two across the seam.
void readMember(const NetcdfFile& file, const NcPlan& plan, std::size_t member, FieldValues& out,
                const Grid& grid, std::size_t firstLayer, const HorizontalWindow* window) {
    if (window == nullptr) {
        readBlock(file, plan, member, {{0, 0, firstLayer}, {grid.nx(), grid.ny(), grid.nz()}}, out);
        return;
    }
    const auto blockOf = [&](const ColumnRun& run) {
        return Block{{run.first, window->firstRow, firstLayer},
                     {run.count, window->rowCount, grid.nz()}};
    };
    if (window->columns.size() == 1) {
        readBlock(file, plan, member, blockOf(window->columns.front()), out);
        return;
    }
    out.resize(grid.pointCount());
    FieldValues block;
    std::size_t column = 0;  // where the run's first column goes
    for (const ColumnRun& run : window->columns) {
        readBlock(file, plan, member, blockOf(run), block);
        for (std::size_t row = 0; row < window->rowCount * grid.nz(); ++row) {
            std::copy_n(block.data() + run.count * row, run.count,
                        out.data() + column + grid.nx() * row);
        }
        column += run.count;
    }
}

std::size_t membersIn(const NetcdfFile& file, const NcPlan& plan) {
    return plan.memberDim < 0 ? 1 : file.dimension(plan.memberDim).size;
}

}  // namespace

bool NetcdfReader::recognizes(const std::string& path) const {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 8> magic{};
    if (!in.read(magic.data(), magic.size())) return false;
    if (magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F' &&
        (magic[3] == 1 || magic[3] == 2 || magic[3] == 5)) {
        return true;
    }
    if (std::string(magic.data(), 4) != "\x89HDF") return false;
    // NetCDF-4 is HDF5 inside. netCDF-C also opens plain HDF5 files: those without netCDF-4's
    // marks (h5py's, with the members in a group at any depth, where netCDF-C sees only the
    // root group and says it holds no variable) are left to the HDF5 reader, and so are files
    // where netCDF-C has to invent "phony_dim_N" dimensions.
    const std::lock_guard lock(netcdfLibraryMutex());
    if (!hasNetcdf4Marks(path)) return false;
    try {
        const NetcdfFile file(path);
        if (std::any_of(file.dimensions().begin(), file.dimensions().end(),
                        [](const NcDimension& d) { return d.name.starts_with("phony_dim"); })) {
            return false;
        }
        // netCDF-C reads only the root group here: a file with dimension scales whose data sit
        // in a subgroup (h5py with dimension scales, netCDF-4 groups) has no field there, and
        // the HDF5 reader, which finds member groups at any depth, is the one to read it.
        return std::any_of(file.variables().begin(), file.variables().end(),
                           [](const NcVariable& v) { return v.dimIds.size() >= 3; });
    } catch (const Error&) {
        return false;
    }
}

EnsembleDescription NetcdfReader::describe(const DataSelection& selection) const {
    const std::lock_guard lock(netcdfLibraryMutex());
    const bool oneFile = selection.paths.size() == 1;
    const std::vector<std::string> stems = memberNamesFromPaths(selection.paths);
    EnsembleDescription d;
    std::string firstLabel;  // the first file's step at the time index
    for (std::size_t f = 0; f < selection.paths.size(); ++f) {
        const NetcdfFile file(selection.paths[f]);
        const NcPlan plan = planVariable(file, selection, oneFile);
        if (f == 0) {
            d.format = file.formatName();
            d.variables = listVariables(file, selection.memberDimension);
            d.variable = plan.name;
            d.longName = plan.longName;
            d.units = plan.units;
            d.grid = plan.grid;
            d.gridMapping = plan.gridMapping;
            d.fixedDimensions = describeFixedDimensions(file, plan);
            d.timeSteps = describeTimeSteps(file, plan);
            if (selection.timeIndex < d.timeSteps.count()) {
                firstLabel = d.timeSteps.labels[selection.timeIndex];
            }
            if (plan.memberDim >= 0) {
                d.memberDimension = file.dimension(plan.memberDim).name;
                d.memberDimensionReason = plan.memberReason;
            } else {
                d.memberDimensionReason = "one file per member";
            }
        } else {
            // Without a named variable each file picks its own first 3D one: files that hold
            // different variables must not be mixed into one ensemble under the first's name.
            if (plan.name != d.variable) {
                throw Error(ErrorKind::InvalidArgument,
                            "'" + file.path() + "' holds '" + plan.name + "' where '" +
                                selection.paths.front() + "' holds '" + d.variable +
                                "': every member file must hold the same variable; name it "
                                "with --var (the Variable box of the Open dialog)");
            }
            checkSameGrid(selection.paths.front(), d.grid, file.path(), plan.grid);
            noteTimesThatDiffer(d, selection.timeIndex, firstLabel, selection.paths.front(),
                                describeTimeSteps(file, plan), file.path());
        }
        std::vector<std::string> names = memberNames(file, plan);
        if (names.empty()) names.push_back(stems[f]);
        if (!oneFile && plan.memberDim >= 0) {
            for (std::string& n : names) n.insert(0, stems[f] + " ");
        }
        d.members += names.size();
        d.memberNames.insert(d.memberNames.end(), names.begin(), names.end());
    }
    return d;
}

Ensemble NetcdfReader::read(const DataSelection& selection, const std::stop_token& stop,
                            const Progress& progress) const {
    const EnsembleDescription description = describe(selection);
    Ensemble e = ensembleDescribedBy(description, selection.paths);
    std::size_t next = 0;
    for (const std::string& path : selection.paths) {
        const std::lock_guard lock(netcdfLibraryMutex());
        const NetcdfFile file(path);
        const NcPlan plan = planVariable(file, selection, selection.paths.size() == 1);
        for (std::size_t m = 0; m < membersIn(file, plan); ++m, ++next) {
            throwIfStopped(stop);
            Member& member = e.members.at(next);
            member.name = description.memberNames.at(next);
            readMember(file, plan, m, member.values, plan.grid, 0, nullptr);
            report(progress, static_cast<double>(next + 1) / static_cast<double>(e.members.size()));
        }
    }
    return e;
}

Ensemble NetcdfReader::readPart(const DataSelection& selection,
                                const EnsembleDescription& description, const EnsemblePart& part,
                                const std::stop_token& stop, const Progress& progress) const {
    Ensemble e = ensembleDescribedBy(description, selection.paths);
    e.grid = gridLayers(description.grid, part.firstLayer, part.layerCount);
    if (part.window) e.grid = gridWindow(e.grid, *part.window);
    e.members.resize(part.memberCount);
    const std::size_t end = part.firstMember + part.memberCount;
    std::size_t next = 0;  // the ensemble's index of the file's first member
    for (std::size_t f = 0; f < selection.paths.size() && next < end; ++f) {
        const std::lock_guard lock(netcdfLibraryMutex());
        const NetcdfFile file(selection.paths[f]);
        const NcPlan plan = planVariable(file, selection, selection.paths.size() == 1);
        const std::size_t inFile = membersIn(file, plan);
        for (std::size_t m = std::max(part.firstMember, next); m < std::min(end, next + inFile);
             ++m) {
            throwIfStopped(stop);
            Member& member = e.members.at(m - part.firstMember);
            member.name = description.memberNames.at(m);
            readMember(file, plan, m - next, member.values, e.grid, part.firstLayer,
                       part.window ? &*part.window : nullptr);
            report(progress, static_cast<double>(m + 1 - part.firstMember) /
                                 static_cast<double>(part.memberCount));
        }
        next += inFile;
    }
    return e;
}

}  // namespace ensil::data
