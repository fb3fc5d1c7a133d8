// Fuzzes the whole reading path behind EnsembleReader (data/ensemble_reader.h): the reader is
// chosen by the file's first bytes (NetCDF classic/64-bit/CDF-5 and NetCDF-4, plain HDF5,
// legacy VTK and VTK XML, GRIB 1 and 2 through ecCodes), describe() runs the header planning
// (CF conventions, member dimension detection, grids from coordinate variables, attributes;
// GRIB messages grouped into variables, levels, members and times), and read() then reads
// the values, as openEnsemble() would. The documented failure is data::Error; any other
// exception type, a crash, a hang, an allocation beyond what the header check allows, or a
// file left open afterwards is a finding (not for HDF5 files: netCDF-C 4.9 itself keeps one
// open when nc_open fails on a damaged NetCDF-4 file). read() runs only when the description
// asks for at most 64 MiB, standing in for openEnsemble()'s check against the machine's
// memory (which would let a small file ask for gigabytes here and drown real findings in
// out-of-memory reports).
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "data/ensemble_reader.h"
#include "data/error.h"
#include "tests/fuzz/fuzz_support.h"

namespace {
constexpr std::size_t kMaxReadBytes = std::size_t{64} << 20;
}

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ensil::data;
    static const ensil::fuzz::TemporaryFile file;
    file.write(data, size);
    const int openBefore = ensil::fuzz::openFileCount();
    DataSelection selection;
    selection.paths = {file.path()};
    try {
        const EnsembleReader& reader = readerFor(selection);
        const EnsembleDescription description = reader.describe(selection);
        if (description.bytes() <= kMaxReadBytes) {
            const Ensemble ensemble = reader.read(selection, {}, {});
            // What preprocessing relies on without checking again.
            if (ensemble.members.size() != description.members) {
                ensil::fuzz::unexpected("read() returned another member count than describe()");
            }
            for (const Member& m : ensemble.members) {
                if (m.values.size() != ensemble.grid.pointCount()) {
                    ensil::fuzz::unexpected("a member holds another value count than its grid");
                }
            }
        }
    } catch (const Error& e) {
        ensil::fuzz::refused(e);
    } catch (const std::exception& e) {
        ensil::fuzz::unexpected(e);
    }
    const bool hdf5 = size >= 4 && std::memcmp(data, "\x89HDF", 4) == 0;
    if (!hdf5 && ensil::fuzz::openFileCount() != openBefore) {
        ensil::fuzz::unexpected("the reader left a file open");
    }
    return 0;
}
