#include "data/eccodes_library.h"

#include <eccodes.h>

#include <cstdlib>

namespace ensil::data {
namespace {

std::mutex& eccodesMutex() {
    static std::mutex mutex;
    return mutex;
}

// ecCodes prints its complaints to stderr; ensil's messages say what went wrong instead, with
// the library's last words appended. Written only under eccodesMutex().
std::string& lastLibraryMessage() {
    static std::string message;
    return message;
}

void keepLibraryMessage(const codes_context* /*context*/, int /*level*/, const char* text) {
    lastLibraryMessage() = text != nullptr ? text : "";
}

[[noreturn]] void throwLibraryAssertion(const char* message) {
    throw LibraryAssertion(message != nullptr ? message : "an internal check failed");
}

void refuseOversizedRequest(std::size_t bytes) {
    if (bytes <= kMostEccodesAllocatesAtOnce) return;
    throw LibraryAssertion("a damaged header made it ask for " + std::to_string(bytes >> 20) +
                           " MiB at once, more than any field ensil reads needs (" +
                           std::to_string(kMostEccodesAllocatesAtOnce >> 20) + " MiB)");
}

// ecCodes's allocators (its context's three kinds: work, long-lasting and message buffers)
// with that limit. Below it they are the C library's, as ecCodes's defaults are, so a block
// allocated before these were installed is freed alike. A failure throws, as ecCodes's own
// allocators assert.
void* allocateForEccodes(const codes_context* /*context*/, std::size_t bytes) {
    refuseOversizedRequest(bytes);
    void* block = std::malloc(bytes);
    if (block == nullptr) throw LibraryAssertion("the system had no memory left for it");
    return block;
}

void* reallocateForEccodes(const codes_context* /*context*/, void* block, std::size_t bytes) {
    refuseOversizedRequest(bytes);
    void* moved = std::realloc(block, bytes);
    if (moved == nullptr && bytes > 0) {
        throw LibraryAssertion("the system had no memory left for it");
    }
    return moved;
}

void freeForEccodes(const codes_context* /*context*/, void* block) { std::free(block); }

}  // namespace

std::unique_lock<std::mutex> lockEccodes() {
    std::unique_lock lock(eccodesMutex());
    static const bool hooked = [] {
        codes_context* context = codes_context_get_default();
        codes_context_set_logging_proc(context, keepLibraryMessage);
        codes_set_codes_assertion_failed_proc(throwLibraryAssertion);
        codes_context_set_memory_proc(context, allocateForEccodes, freeForEccodes,
                                      reallocateForEccodes);
        codes_context_set_persistent_memory_proc(context, allocateForEccodes, freeForEccodes);
        codes_context_set_buffer_memory_proc(context, allocateForEccodes, freeForEccodes,
                                             reallocateForEccodes);
        return true;
    }();
    (void)hooked;
    lastLibraryMessage().clear();
    return lock;
}

std::string libraryWords(int code) {
    std::string words = codes_get_error_message(code);
    if (!lastLibraryMessage().empty()) words += " (ecCodes: " + lastLibraryMessage() + ")";
    return words;
}

}  // namespace ensil::data
