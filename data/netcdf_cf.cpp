#include "data/netcdf_cf.h"

#include <netcdf.h>

#include <array>
#include <cstdio>
#include <mutex>
#include <utility>

#include "data/error.h"
#include "data/netcdf_file.h"

namespace ensil::data {

NetcdfOutput::NetcdfOutput(std::string path) : m_path(std::move(path)) {
    int id = -1;
    check(nc_create(m_path.c_str(), NC_CLOBBER | NC_NETCDF4, &id), "create the file");
    m_id = id;
}

NetcdfOutput::~NetcdfOutput() {
    if (m_id >= 0) nc_close(m_id);
}

void NetcdfOutput::close() {
    const int id = m_id;
    m_id = -1;
    check(nc_close(id), "finish writing");
}

void NetcdfOutput::abort() {
    if (m_id >= 0) nc_abort(m_id);
    m_id = -1;
}

void NetcdfOutput::check(int status, const std::string& what) const {
    if (status != NC_NOERR) {
        throw Error(ErrorKind::WriteFailed,
                    "cannot " + what + " in '" + m_path + "': " + nc_strerror(status));
    }
}

void NetcdfOutput::text(int var, const char* name, const std::string& value) const {
    if (value.empty()) return;
    check(nc_put_att_text(m_id, var, name, value.size(), value.c_str()),
          std::string("write attribute ") + name);
}

void NetcdfOutput::floatAttribute(int var, const char* name, float value) const {
    check(nc_put_att_float(m_id, var, name, NC_FLOAT, 1, &value),
          std::string("write attribute ") + name);
}

void NetcdfOutput::doubleAttribute(int var, const char* name,
                                   std::span<const double> values) const {
    check(nc_put_att_double(m_id, var, name, NC_DOUBLE, values.size(), values.data()),
          std::string("write attribute ") + name);
}

const char* cfAxisLetter(int axis) {
    static constexpr std::array<const char*, 3> kLetters{"X", "Y", "Z"};
    return kLetters.at(static_cast<std::size_t>(axis));
}

CfCoordinate defineCfCoordinate(const NetcdfOutput& nc, const Axis& axis, int axisIndex,
                                const std::string& name, std::size_t size,
                                const std::string& longName) {
    CfCoordinate c;
    nc.check(nc_def_dim(nc.id(), name.c_str(), size, &c.dimension), "define dimension " + name);
    nc.check(nc_def_var(nc.id(), name.c_str(), NC_DOUBLE, 1, &c.dimension, &c.variable),
             "define variable " + name);
    nc.text(c.variable, "units", axis.units);
    nc.text(c.variable, "standard_name", axis.standardName);
    nc.text(c.variable, "long_name",
            !longName.empty()           ? longName
            : axis.standardName.empty() ? axis.name
                                        : axis.standardName);
    nc.text(c.variable, "axis", cfAxisLetter(axisIndex));
    if (axisIndex == 2) nc.text(c.variable, "positive", axis.positiveUp ? "up" : "down");
    return c;
}

void writeCfFile(const std::string& path, const std::function<void(const NetcdfOutput&)>& body) {
    const std::lock_guard lock(netcdfLibraryMutex());
    NetcdfOutput nc(path);
    try {
        body(nc);
        nc.close();
    } catch (...) {
        nc.abort();
        std::remove(path.c_str());
        throw;
    }
}

}  // namespace ensil::data
