// What the fuzz targets share: one private temporary file per process (mkstemp under $TMPDIR),
// rewritten with each input, because the readers take paths, not bytes; the count of files the
// process holds open; and two ways to report: a documented refusal (printed only with
// ENSIL_FUZZ_VERBOSE) and a report-and-abort for exceptions the API does not document and
// broken promises, so libFuzzer records them as findings with the input.
#pragma once

#include <dirent.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

namespace ensil::fuzz {

inline std::string temporaryFolder() {
    const char* dir = std::getenv("TMPDIR");
    return dir != nullptr && *dir != '\0' ? dir : "/tmp";
}

class TemporaryFile {
public:
    explicit TemporaryFile(const std::string& suffix = "") {
        std::string pattern = temporaryFolder() + "/ensil-fuzz-XXXXXX" + suffix;
        m_fd = mkstemps(pattern.data(), static_cast<int>(suffix.size()));
        if (m_fd < 0) {
            std::perror("ensil fuzz: mkstemps");
            std::abort();
        }
        m_path = pattern;
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    ~TemporaryFile() {
        close(m_fd);
        unlink(m_path.c_str());
    }

    // Replaces the file's contents with `size` bytes.
    void write(const std::uint8_t* data, std::size_t size) const {
        if (ftruncate(m_fd, 0) != 0 || pwrite(m_fd, data, size, 0) != static_cast<ssize_t>(size)) {
            std::perror("ensil fuzz: writing the input");
            std::abort();
        }
    }
    [[nodiscard]] const std::string& path() const { return m_path; }

private:
    int m_fd = -1;
    std::string m_path;
};

// How many files this process holds open: a reader that returns (or throws) holding one more
// leaks a descriptor on every file it opens, which LeakSanitizer cannot see when the library
// keeps its own list of open files.
inline int openFileCount() {
    int count = 0;
    if (DIR* dir = opendir("/proc/self/fd")) {
        while (readdir(dir) != nullptr) ++count;
        closedir(dir);
    }
    return count;
}

// A documented refusal: silent while fuzzing; printed when ENSIL_FUZZ_VERBOSE is set, to see
// why a seed or a reproducer is refused (ENSIL_FUZZ_VERBOSE=1 ensil_fuzz_NAME FILE...).
inline void note(const char* what) {
    static const bool verbose = std::getenv("ENSIL_FUZZ_VERBOSE") != nullptr;
    if (verbose) std::fprintf(stderr, "ensil fuzz: %s\n", what);
}
inline void refused(const std::exception& e) {
    note((std::string("refused: ") + e.what()).c_str());
}

[[noreturn]] inline void unexpected(const std::exception& e) {
    std::fprintf(stderr, "ensil fuzz: undocumented exception %s: %s\n", typeid(e).name(), e.what());
    std::abort();
}

[[noreturn]] inline void unexpected(const char* what) {
    std::fprintf(stderr, "ensil fuzz: %s\n", what);
    std::abort();
}

}  // namespace ensil::fuzz
