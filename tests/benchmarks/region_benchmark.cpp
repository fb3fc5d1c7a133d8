// Reading a region (--bbox) of a global 0.25-degree ensemble against reading all of it (issue
// 42): writes 10 members x 1440 x 721 x 5 levels of float (longitudes 0 .. 359.75 E, latitudes
// 90 N .. 90 S; NetCDF-4, 198 MiB) to a temporary file unless given one, warms the page cache,
// then times data::openEnsemble of the whole grid, of Europe across the 0/360 seam
// (-10,40,35,72: two hyperslabs a member) and of a box as large east of the seam (0,50,35,72:
// one hyperslab). Prints medians.
//
//   ensil_region_benchmark [--runs N] [--members M] [--levels L] [FILE.nc [--var V]]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "data/ensemble_reader.h"
#include "data/netcdf_writer.h"
#include "data/region.h"
#include "data/working_memory.h"
#include "timing.h"

using namespace ensil;

namespace {

// A smooth field with some structure in every member: what a global forecast's temperature
// might hold, without the cost of anything realistic.
data::Ensemble globalEnsemble(std::size_t members, std::size_t levels) {
    data::Ensemble e;
    e.variable = "t";
    e.units = "K";
    e.memberDimension = "number";
    data::Axis lon = data::makeUniformAxis("lon", "degrees_east", 0.0, 359.75, 1440);
    lon.standardName = "longitude";
    data::Axis lat = data::makeUniformAxis("lat", "degrees_north", 90.0, -90.0, 721);
    lat.standardName = "latitude";
    data::Axis plev = data::makeUniformAxis("plev", "hPa", 1000.0, 200.0, levels);
    plev.positiveUp = false;
    e.grid = data::Grid(std::move(lon), std::move(lat), std::move(plev));
    for (std::size_t m = 0; m < members; ++m) {
        data::Member member{"member " + std::to_string(m + 1), {}};
        member.values.resize(e.grid.pointCount());
        for (std::size_t k = 0; k < e.grid.nz(); ++k) {
            for (std::size_t j = 0; j < e.grid.ny(); ++j) {
                const double phi = e.grid.y().values[j] * std::numbers::pi / 180.0;
                for (std::size_t i = 0; i < e.grid.nx(); ++i) {
                    const double lambda = e.grid.x().values[i] * std::numbers::pi / 180.0;
                    member.values[e.grid.index(i, j, k)] = static_cast<float>(
                        250.0 + 40.0 * std::cos(phi) - 5.0 * static_cast<double>(k) +
                        3.0 * std::sin(3.0 * lambda + 0.3 * static_cast<double>(m)));
                }
            }
        }
        e.members.push_back(std::move(member));
    }
    return e;
}

void readAllBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> buffer(1 << 20);
    while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0) {
    }
}

}  // namespace

int main(int argc, char** argv) {
    data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    int runs = 7;
    std::size_t members = 10;
    std::size_t levels = 5;
    data::DataSelection whole;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--runs" && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else if (arg == "--members" && i + 1 < argc) {
            members = static_cast<std::size_t>(std::max(1, std::atoi(argv[++i])));
        } else if (arg == "--levels" && i + 1 < argc) {
            levels = static_cast<std::size_t>(std::max(2, std::atoi(argv[++i])));
        } else if (arg == "--var" && i + 1 < argc) {
            whole.variable = argv[++i];
        } else {
            whole.paths.push_back(arg);
        }
    }
    std::string temporary;
    if (whole.paths.empty()) {
        temporary = (std::filesystem::temp_directory_path() / "ensil-region-benchmark.nc").string();
        data::writeNetcdf(globalEnsemble(members, levels), temporary);
        whole.paths.push_back(temporary);
    }
    const std::string& path = whole.paths.front();
    readAllBytes(path);  // warm the page cache

    struct Case {
        const char* name;
        std::optional<data::Region> region;
    };
    const std::vector<Case> cases{
        {"whole grid", std::nullopt},
        {"--bbox -10,40,35,72 (Europe, across the seam)", data::Region{-10, 40, 35, 72}},
        {"--bbox 0,50,35,72 (as large, one hyperslab)", data::Region{0, 50, 35, 72}}};
    std::printf("file: %s (%.1f MiB), %d runs (medians below)\n", path.c_str(),
                static_cast<double>(std::filesystem::file_size(path)) / (1024.0 * 1024.0), runs);
    double wholeMs = 0.0;
    for (const Case& c : cases) {
        data::DataSelection selection = whole;
        selection.region = c.region;
        data::EnsembleDescription d;
        const double ms = bench::medianMs(runs, [&] {
            const data::Ensemble e = data::openEnsemble(selection, {}, {}, &d);
            if (e.members.empty()) std::fprintf(stderr, "no members read\n");
        });
        if (!c.region) wholeMs = ms;
        std::printf(
            "%-48s %4zu x %3zu x %zu x %2zu members, %7.1f MiB: %8.1f ms (%.3f of the whole "
            "grid's time)\n",
            c.name, d.grid.nx(), d.grid.ny(), d.grid.nz(), d.members,
            static_cast<double>(d.bytes()) / (1024.0 * 1024.0), ms, ms / wholeMs);
    }
    if (!temporary.empty()) std::filesystem::remove(temporary);
    return 0;
}
