#include "data/content_hash.h"

#include <xxhash.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "data/error.h"

namespace ensil::data {

std::uint64_t contentHash(const std::string& path) {
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
    return XXH3_64bits_digest(state.get());
}

}  // namespace ensil::data
