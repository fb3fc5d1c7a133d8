#include "data/content_hash.h"

#include <xxhash.h>

#include <atomic>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "data/error.h"
#include "data/platform.h"

namespace ensil::data {
namespace {

// Whether the file's change time is old enough that no later write can share it.
bool settled(const FileStamp& stamp) {
    constexpr std::int64_t kSettledNs = 1'000'000'000;
    timespec now{};
    std::timespec_get(&now, TIME_UTC);
    return stamp.changedNs <
           static_cast<std::int64_t>(now.tv_sec) * 1'000'000'000 + now.tv_nsec - kSettledNs;
}

struct Remembered {
    FileStamp state;
    std::uint64_t hash = 0;
};

// Few files are open at once; the memory is dropped whole when it holds more than this.
constexpr std::size_t kMostRemembered = 64;

std::mutex g_mutex;
std::map<std::string, Remembered> g_remembered;  // under g_mutex
std::atomic<std::size_t> g_fileReads{0};

std::uint64_t hashFile(const std::string& path) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                               &std::fclose);
    if (!file) throw Error(ErrorKind::FileNotFound, "cannot read '" + path + "' to identify it");
    const std::unique_ptr<XXH3_state_t, XXH_errorcode (*)(XXH3_state_t*)> state(XXH3_createState(),
                                                                                &XXH3_freeState);
    XXH3_64bits_reset(state.get());
    std::vector<char> buffer(std::size_t{1} << 20);
    while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), file.get())) {
        XXH3_64bits_update(state.get(), buffer.data(), n);
    }
    if (std::ferror(file.get()) != 0) {
        throw Error(ErrorKind::FileNotFound, "cannot read '" + path + "' to identify it");
    }
    ++g_fileReads;
    return XXH3_64bits_digest(state.get());
}

}  // namespace

std::uint64_t contentHash(const std::string& path) {
    const std::optional<FileStamp> before = fileStamp(path);
    if (before) {
        const std::lock_guard lock(g_mutex);
        const auto known = g_remembered.find(path);
        if (known != g_remembered.end() && known->second.state == *before) {
            return known->second.hash;
        }
    }
    const std::uint64_t hash = hashFile(path);
    // Remembered only when nothing moved while it was read.
    if (const std::optional<FileStamp> after = fileStamp(path);
        before && after && *after == *before && settled(*after)) {
        const std::lock_guard lock(g_mutex);
        if (g_remembered.size() >= kMostRemembered) g_remembered.clear();
        g_remembered[path] = {*after, hash};
    }
    return hash;
}

std::size_t contentHashFileReads() { return g_fileReads.load(); }

}  // namespace ensil::data
