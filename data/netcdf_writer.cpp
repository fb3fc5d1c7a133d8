#include "data/netcdf_writer.h"

#include <netcdf.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "data/error.h"

namespace ensil::data {
namespace {

class NetcdfFile {
public:
    explicit NetcdfFile(const std::string& path) : m_path(path) {
        check(nc_create(path.c_str(), NC_CLOBBER | NC_NETCDF4, &m_id), "create the file");
    }
    NetcdfFile(const NetcdfFile&) = delete;
    NetcdfFile& operator=(const NetcdfFile&) = delete;
    ~NetcdfFile() {
        if (m_id >= 0) nc_close(m_id);
    }

    void close() {
        const int id = m_id;
        m_id = -1;
        check(nc_close(id), "finish writing");
    }
    // Gives up on the file without finishing it (used before removing a partial file).
    void abort() {
        if (m_id >= 0) nc_abort(m_id);
        m_id = -1;
    }
    [[nodiscard]] int id() const { return m_id; }

    void check(int status, const std::string& what) const {
        if (status != NC_NOERR) {
            throw Error(ErrorKind::WriteFailed,
                        "cannot " + what + " in '" + m_path + "': " + nc_strerror(status));
        }
    }
    void text(int var, const char* name, const std::string& value) const {
        if (value.empty()) return;
        check(nc_put_att_text(m_id, var, name, value.size(), value.c_str()),
              std::string("write attribute ") + name);
    }

private:
    std::string m_path;
    int m_id = -1;
};

const char* axisLetter(int a) {
    static constexpr std::array<const char*, 3> kLetters{"X", "Y", "Z"};
    return kLetters.at(static_cast<std::size_t>(a));
}

void writeFile(const Ensemble& ensemble, NetcdfFile& nc, const WriteProgress& progress) {
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
        nc.check(nc_def_dim(nc.id(), axis.name.c_str(), axis.size(), &axisDimIds[ai]),
                 "define dimension " + axis.name);
        nc.check(
            nc_def_var(nc.id(), axis.name.c_str(), NC_DOUBLE, 1, &axisDimIds[ai], &axisVarIds[ai]),
            "define variable " + axis.name);
        nc.text(axisVarIds[ai], "units", axis.units);
        nc.text(axisVarIds[ai], "standard_name", axis.standardName);
        nc.text(axisVarIds[ai], "long_name",
                axis.standardName.empty() ? axis.name : axis.standardName);
        nc.text(axisVarIds[ai], "axis", axisLetter(a));
        if (a == 2) nc.text(axisVarIds[ai], "positive", axis.positiveUp ? "up" : "down");
    }
    const std::array<int, 4> dims{memberDimId, axisDimIds[2], axisDimIds[1], axisDimIds[0]};
    int var = 0;
    nc.check(nc_def_var(nc.id(), ensemble.variable.c_str(), NC_FLOAT, 4, dims.data(), &var),
             "define variable " + ensemble.variable);
    nc.text(var, "units", ensemble.units);
    nc.text(var, "long_name", ensemble.longName);
    if (ensemble.variable == "wind_speed") nc.text(var, "standard_name", "wind_speed");
    const float fill = std::numeric_limits<float>::quiet_NaN();
    nc.check(nc_put_att_float(nc.id(), var, "_FillValue", NC_FLOAT, 1, &fill),
             "write attribute _FillValue");
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
    NetcdfFile nc(path);
    try {
        writeFile(ensemble, nc, progress);
        nc.close();
    } catch (...) {
        nc.abort();
        std::remove(path.c_str());
        throw;
    }
}

}  // namespace ensil::data
