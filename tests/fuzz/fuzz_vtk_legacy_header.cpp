// Fuzzes the legacy VTK header scanner (data/vtk_legacy_header.h) on raw bytes. It is the guard
// in front of VTK's own legacy reader, which trusts counts and keeps going over garbage, so it
// must turn every malformed, truncated or lying header (signs, huge counts, counts beyond the
// file, bad binary sections, odd keywords) into data::Error, never into a crash, a hang or an
// allocation the file's size cannot justify. Any other exception type is a finding. The input
// is written to a private temporary file because the scanner takes a path.
#include <cstddef>
#include <cstdint>

#include "data/error.h"
#include "data/vtk_legacy_header.h"
#include "tests/fuzz/fuzz_support.h"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const ensil::fuzz::TemporaryFile file(".vtk");
    file.write(data, size);
    try {
        const auto structure = ensil::data::vtk::scanLegacyFile(file.path());
        (void)structure;
    } catch (const ensil::data::Error& e) {
        ensil::fuzz::refused(e);
    } catch (const std::exception& e) {
        ensil::fuzz::unexpected(e);
    }
    return 0;
}
