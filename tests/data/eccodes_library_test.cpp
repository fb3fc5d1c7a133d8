// How ensil runs ecCodes (data/eccodes_library.h): under its lock, ecCodes's own allocation
// entry points refuse a request larger than any field ensil reads needs, with a LibraryAssertion
// that names the size, instead of ecCodes aborting the program when the system cannot give it
// (the fuzzer's damaged GRIB message asked for 496 GiB).
#include "data/eccodes_library.h"

#include <eccodes.h>
#include <gtest/gtest.h>

#include <string>

// ecCodes's allocation entry points, which every allocation inside the library goes through:
// exported by libeccodes but declared only in its internal header.
extern "C" {
void* grib_context_malloc(const codes_context* c, std::size_t size);
void* grib_context_buffer_malloc(const codes_context* c, std::size_t size);
void* grib_context_malloc_persistent(const codes_context* c, std::size_t size);
void* grib_context_realloc(const codes_context* c, void* p, std::size_t size);
void grib_context_free(const codes_context* c, void* p);
}

using namespace ensil;

namespace {

// The LibraryAssertion's words when `allocate` throws one; empty when it allocated.
template <typename Allocate>
std::string refusal(Allocate allocate) {
    try {
        void* block = allocate();
        grib_context_free(codes_context_get_default(), block);
        return {};
    } catch (const data::LibraryAssertion& e) {
        return e.what();
    }
}

}  // namespace

TEST(EccodesLibrary, RefusesAnAllocationLargerThanAnyFieldNeedsAndGrantsOthers) {
    const auto lock = data::lockEccodes();
    codes_context* context = codes_context_get_default();
    const std::size_t tooMuch = std::size_t{496} << 30;  // what the damaged message asked for

    const std::string work = refusal([&] { return grib_context_malloc(context, tooMuch); });
    EXPECT_NE(work.find("ask for 507904 MiB at once"), std::string::npos) << work;
    EXPECT_NE(work.find("(512 MiB)"), std::string::npos) << work;
    EXPECT_FALSE(refusal([&] { return grib_context_buffer_malloc(context, tooMuch); }).empty());
    EXPECT_FALSE(refusal([&] { return grib_context_malloc_persistent(context, tooMuch); }).empty());
    EXPECT_FALSE(refusal([&] {
                     void* small = grib_context_malloc(context, 64);
                     try {
                         return grib_context_realloc(context, small, tooMuch);
                     } catch (...) {
                         grib_context_free(context, small);
                         throw;
                     }
                 }).empty());

    // Up to the limit, ecCodes gets its memory: a field of a 0.1-degree global grid as doubles.
    const std::size_t field = std::size_t{3600} * 1801 * sizeof(double);
    EXPECT_EQ(refusal([&] { return grib_context_malloc(context, field); }), "");
    EXPECT_EQ(refusal([&] { return grib_context_buffer_malloc(context, field); }), "");
    EXPECT_EQ(
        refusal([&] { return grib_context_malloc(context, data::kMostEccodesAllocatesAtOnce); }),
        "");
}
