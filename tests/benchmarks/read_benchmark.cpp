// Reading speed of the NetCDF reader against the speed of reading the file's bytes.
// Writes the paper-sized demo ensemble (50 members, 256 x 128 x 16, about 105 MB) to a
// temporary NetCDF file unless a file is given, warms the page cache, then times, over
// several runs: `cat FILE > /dev/null` (as a subprocess, like a user would measure it), a
// plain read of all bytes in this process (into a reused buffer, as cat does), a read of all
// bytes into fresh memory of the file's size (what any loader that keeps the data must do),
// and data::openEnsemble. Prints medians.
//
//   ensil_read_benchmark [--runs N] [FILE.nc [--var V] [--member-dim D]]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "data/bulk_allocator.h"
#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "data/netcdf_writer.h"
#include "data/working_memory.h"
#include "timing.h"

using ensil::bench::median;
using ensil::bench::medianMs;

namespace {
using Clock = std::chrono::steady_clock;

std::size_t readAllBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> buffer(1 << 20);
    std::size_t total = 0;
    while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0) {
        total += static_cast<std::size_t>(in.gcount());
    }
    return total;
}
}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    int runs = 7;
    ensil::data::DataSelection selection;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else if (arg == "--var" && i + 1 < argc)
            selection.variable = argv[++i];
        else if (arg == "--member-dim" && i + 1 < argc)
            selection.memberDimension = argv[++i];
        else
            selection.paths.push_back(arg);
    }
    std::string temporary;
    if (selection.paths.empty()) {
        temporary = (std::filesystem::temp_directory_path() / "ensil-read-benchmark.nc").string();
        const auto demo = ensil::data::makeDemoEnsemble({});
        ensil::data::writeNetcdf(demo.ensemble, temporary);
        selection.paths.push_back(temporary);
    }
    const std::string& path = selection.paths.front();
    const double mib = static_cast<double>(std::filesystem::file_size(path)) / (1024.0 * 1024.0);
    readAllBytes(path);  // warm the page cache

    const std::string cat = "cat '" + path + "' > /dev/null";
    const double catMs = medianMs(runs, [&] {
        if (std::system(cat.c_str()) != 0) std::fprintf(stderr, "cat failed\n");
    });
    const double bytesMs = medianMs(runs, [&] { readAllBytes(path); });
    // The floor for any loader: the same bytes into fresh memory that it keeps.
    const auto fileBytes = static_cast<std::size_t>(std::filesystem::file_size(path));
    const double freshMs = medianMs(runs, [&] {
        ensil::data::FieldValues block(fileBytes / sizeof(float) + 1);
        std::ifstream in(path, std::ios::binary);
        in.read(reinterpret_cast<char*>(block.data()), static_cast<std::streamsize>(fileBytes));
    });
    std::size_t members = 0, points = 0;
    const double readMs = medianMs(runs, [&] {
        const auto e = ensil::data::openEnsemble(selection);
        members = e.memberCount();
        points = e.grid.pointCount();
    });

    std::printf("file:                 %s (%.1f MiB)\n", path.c_str(), mib);
    std::printf("ensemble:             %zu members x %zu points\n", members, points);
    std::printf("runs:                 %d (medians below)\n", runs);
    std::printf("cat FILE > /dev/null: %8.1f ms  (%.0f MiB/s)\n", catMs, mib / catMs * 1000.0);
    std::printf("read bytes in-process:%8.1f ms  (%.0f MiB/s)\n", bytesMs, mib / bytesMs * 1000.0);
    std::printf("bytes into fresh block:%7.1f ms  (%.0f MiB/s, the floor for any loader)\n",
                freshMs, mib / freshMs * 1000.0);
    std::printf("openEnsemble:         %8.1f ms  (%.0f MiB/s)\n", readMs, mib / readMs * 1000.0);
    std::printf("ratio openEnsemble / cat: %.2f (goal <= 2); / fresh-block floor: %.2f\n",
                readMs / catMs, readMs / freshMs);
    if (!temporary.empty()) std::filesystem::remove(temporary);
    return 0;
}
