// How ensil runs ecCodes: under one lock (ecCodes keeps state in its one context, and ensil
// switches settings of it, multi-field support among them), with the library's complaints kept
// for ensil's own messages instead of printed, its assertions thrown as LibraryAssertion
// instead of aborting the program, and no single allocation larger than a field ensil could
// read needs. Used by data/grib_messages.cpp only; the data layer's tests check the hooks.
#pragma once

#include <cstddef>
#include <mutex>
#include <stdexcept>
#include <string>

namespace ensil::data {

// An assertion inside ecCodes, or an allocation refused: on some damaged messages (a bitmap
// section where none can be, say) ecCodes 2.28 asserts, and by default aborts the program.
// ensil has it throw this instead (ecCodes takes no lock of its own there and is built with
// unwind tables, so the exception passes through it; what it had allocated is lost), and turns
// it into a skipped message or a data::Error.
class LibraryAssertion : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The most ecCodes may allocate at once. ecCodes sizes some work arrays from what a message's
// header claims before anything checks it (CI's fuzzer found a damaged message that made it ask
// for 496 GiB), and its own allocator then ends the program. 512 MiB holds a field of 67
// million points as doubles: 10 times a 0.1-degree global grid, more than ensil could draw as
// an ensemble.
constexpr std::size_t kMostEccodesAllocatesAtOnce = std::size_t{512} << 20;

// Takes the ecCodes lock; the first call also installs the hooks above in ecCodes's default
// context. Every ecCodes call in ensil runs under it.
[[nodiscard]] std::unique_lock<std::mutex> lockEccodes();

// ecCodes's words for an error code, with the last message it logged under this lock.
[[nodiscard]] std::string libraryWords(int code);

}  // namespace ensil::data
