// Remembered settings, recent files, layouts and caches go to folders of this test process
// alone, never the user's (and never another test's: CTest runs each test in its own process).
// The test mains make one before the application object; removed when the process ends.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace ensil::test {

class PrivateUserFolders {
public:
    PrivateUserFolders() {
        m_root = std::filesystem::temp_directory_path() /
                 ("ensil-test-home-" + std::to_string(::getpid()));
        std::filesystem::remove_all(m_root);
        for (const char* variable : {"XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"}) {
            const auto dir = m_root / variable;
            std::filesystem::create_directories(dir);
            ::setenv(variable, dir.c_str(), 1);
        }
    }
    PrivateUserFolders(const PrivateUserFolders&) = delete;
    PrivateUserFolders& operator=(const PrivateUserFolders&) = delete;
    ~PrivateUserFolders() {
        std::error_code ignored;
        std::filesystem::remove_all(m_root, ignored);
    }

private:
    std::filesystem::path m_root;
};

}  // namespace ensil::test
