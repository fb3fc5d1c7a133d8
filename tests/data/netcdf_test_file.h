// Writes small NetCDF files for reader tests with the netCDF-C API: dimensions with optional
// coordinate variables, variables with attributes, values from a function of the indices.
#pragma once

#include <gtest/gtest.h>
#include <netcdf.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ensil::test {

class NcTestFile {
public:
    explicit NcTestFile(const std::string& path, int mode = NC_CLOBBER | NC_NETCDF4) {
        EXPECT_EQ(nc_create(path.c_str(), mode, &m_id), NC_NOERR) << path;
    }
    ~NcTestFile() { close(); }
    NcTestFile(const NcTestFile&) = delete;
    NcTestFile& operator=(const NcTestFile&) = delete;

    // A dimension; with coordinate values, also its coordinate variable.
    int dim(const std::string& name, std::size_t size, std::vector<double> coords = {},
            std::vector<std::pair<std::string, std::string>> attributes = {}) {
        int id = -1;
        EXPECT_EQ(nc_def_dim(m_id, name.c_str(), size, &id), NC_NOERR);
        if (!coords.empty()) {
            const int var = variable(name, NC_DOUBLE, {id});
            for (const auto& [key, value] : attributes) text(var, key, value);
            m_coords.emplace_back(var, std::move(coords));
        }
        return id;
    }
    int variable(const std::string& name, nc_type type, const std::vector<int>& dims) {
        int id = -1;
        EXPECT_EQ(
            nc_def_var(m_id, name.c_str(), type, static_cast<int>(dims.size()), dims.data(), &id),
            NC_NOERR)
            << name;
        return id;
    }
    void text(int var, const std::string& name, const std::string& value) {
        EXPECT_EQ(nc_put_att_text(m_id, var, name.c_str(), value.size(), value.c_str()), NC_NOERR);
    }
    void number(int var, const std::string& name, nc_type type, std::vector<double> values) {
        EXPECT_EQ(nc_put_att_double(m_id, var, name.c_str(), type, values.size(), values.data()),
                  NC_NOERR)
            << name;
    }
    // Ends definitions, writes coordinates, then each variable's values from fill(flat index).
    void write(int var, std::size_t count, const std::function<double(std::size_t)>& fill) {
        endDefinitions();
        std::vector<double> values(count);
        for (std::size_t i = 0; i < count; ++i) values[i] = fill(i);
        EXPECT_EQ(nc_put_var_double(m_id, var, values.data()), NC_NOERR);
    }
    // Ends definitions and writes a character variable's rows, each padded to its length.
    void writeRows(int var, const std::vector<std::string>& rows, std::size_t length) {
        endDefinitions();
        std::string all;
        for (const std::string& row : rows) all += row + std::string(length - row.size(), ' ');
        EXPECT_EQ(nc_put_var_text(m_id, var, all.data()), NC_NOERR);
    }
    void endDefinitions() {
        if (m_defining) {
            EXPECT_EQ(nc_enddef(m_id), NC_NOERR);
            m_defining = false;
            for (const auto& [var, values] : m_coords) {
                EXPECT_EQ(nc_put_var_double(m_id, var, values.data()), NC_NOERR);
            }
        }
    }
    void close() {
        if (m_id >= 0) {
            endDefinitions();
            nc_close(m_id);
            m_id = -1;
        }
    }

private:
    int m_id = -1;
    bool m_defining = true;
    std::vector<std::pair<int, std::vector<double>>> m_coords;
};

inline std::vector<double> range(std::size_t n, double first = 0.0, double step = 1.0) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = first + step * static_cast<double>(i);
    return v;
}

}  // namespace ensil::test
