#include "data/netcdf_writer.h"

#include <netcdf.h>

#include <array>
#include <cmath>
#include <limits>

#include "data/error.h"
#include "data/netcdf_cf.h"

namespace ensil::data {
namespace {

void writeFile(const Ensemble& ensemble, const NetcdfOutput& nc, const WriteProgress& progress) {
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
    const std::array<int, 4> dims{memberDimId, axisDimIds[2], axisDimIds[1], axisDimIds[0]};
    int var = 0;
    nc.check(nc_def_var(nc.id(), ensemble.variable.c_str(), NC_FLOAT, 4, dims.data(), &var),
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
    for (std::size_t m = 0; m < ensemble.memberCount(); ++m) {
        const std::array<std::size_t, 4> start{m, 0, 0, 0};
        const std::array<std::size_t, 4> count{1, grid.nz(), grid.ny(), grid.nx()};
        nc.check(nc_put_vara_float(nc.id(), var, start.data(), count.data(),
                                   ensemble.members[m].values.data()),
                 "write member " + std::to_string(m + 1));
        if (progress) progress(m + 1, ensemble.memberCount());
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

}  // namespace ensil::data
