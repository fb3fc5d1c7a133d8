#include "gl/runtime_directory.h"

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#if defined(__linux__)
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace ensil::gl {

std::optional<std::string> ensureRuntimeDirectory() {
#if defined(__linux__)
    const char* given = std::getenv("XDG_RUNTIME_DIR");
    if (given != nullptr && *given != '\0') return std::nullopt;
    std::error_code error;
    const std::filesystem::path temp = std::filesystem::temp_directory_path(error);
    if (error) return std::nullopt;
    const std::filesystem::path dir = temp / ("ensil-runtime-" + std::to_string(::getuid()));
    // mkdir with 0700 where it is missing; where it exists, it must be ours and closed to others
    // (a folder another user made in /tmp under this name must not receive our sockets).
    if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) return std::nullopt;
    struct stat info {};
    if (::lstat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != ::getuid() ||
        (info.st_mode & 077) != 0) {
        return std::nullopt;
    }
    ::setenv("XDG_RUNTIME_DIR", dir.c_str(), 1);
    return dir.string();
#else
    return std::nullopt;  // Qt uses no XDG_RUNTIME_DIR on macOS and Windows
#endif
}

}  // namespace ensil::gl
