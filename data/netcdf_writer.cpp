#include "data/netcdf_writer.h"

#include <netcdf.h>

#include <array>
#include <cmath>
#include <limits>

#include "data/error.h"
#include "data/netcdf_cf.h"

namespace ensil::data {
namespace {

// With `time`, the variable gains a leading time dimension and `stepAt` gives each step after
// the first (`ensemble`).
void writeFile(const Ensemble& ensemble, const NetcdfOutput& nc, const WriteProgress& progress,
               const TimeCoordinate* time = nullptr, const EnsembleAtStep& stepAt = {}) {
    const Grid& grid = ensemble.grid;
    const std::string memberDim =
        ensemble.memberDimension.empty() ? "number" : ensemble.memberDimension;
    int memberDimId = 0;
    std::array<int, 3> axisDimIds{};
    std::array<int, 3> axisVarIds{};
    int memberVarId = 0;
    nc.check(nc_def_dim(nc.id(), memberDim.c_str(), ensemble.memberCount(), &memberDimId),
             "define dimension " + memberDim);
    nc.check(nc_def_var(nc.id(), memberDim.c_str(), NC_INT, 1, &memberDimId, &memberVarId),
             "define variable " + memberDim);
    nc.text(memberVarId, "long_name", "ensemble member numerical id");
    nc.text(memberVarId, "standard_name", "realization");
    nc.text(memberVarId, "units", "1");
    for (int a = 2; a >= 0; --a) {  // z, y, x: the CF order of dimensions
        const Axis& axis = grid.axis(a);
        const auto ai = static_cast<std::size_t>(a);
        const CfCoordinate c = defineCfCoordinate(nc, axis, a, axis.name, axis.size());
        axisDimIds[ai] = c.dimension;
        axisVarIds[ai] = c.variable;
    }
    std::vector<int> dims{memberDimId, axisDimIds[2], axisDimIds[1], axisDimIds[0]};
    int timeVarId = 0;
    if (time != nullptr) {
        int timeDimId = 0;
        nc.check(nc_def_dim(nc.id(), "time", time->values.size(), &timeDimId),
                 "define dimension time");
        nc.check(nc_def_var(nc.id(), "time", NC_DOUBLE, 1, &timeDimId, &timeVarId),
                 "define variable time");
        nc.text(timeVarId, "standard_name", "time");
        nc.text(timeVarId, "long_name", "time");
        nc.text(timeVarId, "units", time->units);
        nc.text(timeVarId, "calendar", "standard");
        nc.text(timeVarId, "axis", "T");
        dims.insert(dims.begin(), timeDimId);
    }
    int var = 0;
    nc.check(nc_def_var(nc.id(), ensemble.variable.c_str(), NC_FLOAT, static_cast<int>(dims.size()),
                        dims.data(), &var),
             "define variable " + ensemble.variable);
    nc.text(var, "units", ensemble.units);
    nc.text(var, "long_name", ensemble.longName);
    if (ensemble.variable == "wind_speed") nc.text(var, "standard_name", "wind_speed");
    nc.floatAttribute(var, "_FillValue", std::numeric_limits<float>::quiet_NaN());
    nc.text(NC_GLOBAL, "Conventions", "CF-1.8");
    nc.text(NC_GLOBAL, "title", ensemble.longName.empty() ? ensemble.variable : ensemble.longName);
    nc.text(NC_GLOBAL, "source", "ensil " + ensemble.source);
    nc.check(nc_enddef(nc.id()), "finish the header");

    std::vector<int> numbers(ensemble.memberCount());
    for (std::size_t m = 0; m < numbers.size(); ++m) numbers[m] = static_cast<int>(m + 1);
    nc.check(nc_put_var_int(nc.id(), memberVarId, numbers.data()), "write " + memberDim);
    for (int a = 0; a < 3; ++a) {
        nc.check(nc_put_var_double(nc.id(), axisVarIds[static_cast<std::size_t>(a)],
                                   grid.axis(a).values.data()),
                 "write coordinate " + grid.axis(a).name);
    }
    if (time == nullptr) {
        for (std::size_t m = 0; m < ensemble.memberCount(); ++m) {
            const std::array<std::size_t, 4> start{m, 0, 0, 0};
            const std::array<std::size_t, 4> count{1, grid.nz(), grid.ny(), grid.nx()};
            nc.check(nc_put_vara_float(nc.id(), var, start.data(), count.data(),
                                       ensemble.members[m].values.data()),
                     "write member " + std::to_string(m + 1));
            if (progress) progress(m + 1, ensemble.memberCount());
        }
        return;
    }
    nc.check(nc_put_var_double(nc.id(), timeVarId, time->values.data()), "write time");
    const std::size_t steps = time->values.size(), members = ensemble.memberCount();
    for (std::size_t t = 0; t < steps; ++t) {
        const Ensemble later = t == 0 ? Ensemble{} : stepAt(t);
        const Ensemble& e = t == 0 ? ensemble : later;
        if (e.memberCount() != members || e.grid.nx() != grid.nx() || e.grid.ny() != grid.ny() ||
            e.grid.nz() != grid.nz()) {
            throw Error(ErrorKind::InvalidArgument, "step " + std::to_string(t) +
                                                        " has other members or another grid "
                                                        "than the first step");
        }
        for (std::size_t m = 0; m < members; ++m) {
            const std::array<std::size_t, 5> start{t, m, 0, 0, 0};
            const std::array<std::size_t, 5> count{1, 1, grid.nz(), grid.ny(), grid.nx()};
            nc.check(nc_put_vara_float(nc.id(), var, start.data(), count.data(),
                                       e.members[m].values.data()),
                     "write member " + std::to_string(m + 1) + " of step " + std::to_string(t));
            if (progress) progress(t * members + m + 1, steps * members);
        }
    }
}

}  // namespace

void writeNetcdf(const Ensemble& ensemble, const std::string& path, const WriteProgress& progress) {
    if (ensemble.members.empty()) {
        throw Error(ErrorKind::InvalidArgument, "cannot write '" + path + "': no members");
    }
    for (const Member& member : ensemble.members) {
        if (member.values.size() != ensemble.grid.pointCount()) {
            throw Error(ErrorKind::InvalidArgument,
                        "cannot write '" + path + "': " + member.name + " has " +
                            std::to_string(member.values.size()) + " values, the grid " +
                            std::to_string(ensemble.grid.pointCount()));
        }
    }
    writeCfFile(path, [&](const NetcdfOutput& nc) { writeFile(ensemble, nc, progress); });
}

void writeNetcdfSteps(const EnsembleAtStep& stepAt, const TimeCoordinate& time,
                      const std::string& path, const WriteProgress& progress) {
    if (time.values.empty()) {
        throw Error(ErrorKind::InvalidArgument, "cannot write '" + path + "': no time steps");
    }
    const Ensemble first = stepAt(0);
    if (first.members.empty()) {
        throw Error(ErrorKind::InvalidArgument, "cannot write '" + path + "': no members");
    }
    writeCfFile(path,
                [&](const NetcdfOutput& nc) { writeFile(first, nc, progress, &time, stepAt); });
}

}  // namespace ensil::data
