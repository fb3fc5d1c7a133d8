// main() for test suites that need a QApplication (OpenGL, widgets, the workbench). They run
// under a display: `xvfb-run -a ctest ...` on machines without one. Listing tests (CTest's
// discovery) needs no display, so no QApplication is made for it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <QApplication>
#include <QSurfaceFormat>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "data/platform.h"
#include "gl/surface_format.h"
#include "tests/support/private_user_folders.h"

namespace {
bool listingOnly(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--gtest_list_tests") == 0) return true;
    }
    return false;
}

// Tests point XDG_CACHE_HOME at temporary folders (the mesh cache); Mesa would put its shader
// cache there too, remember the folder for the whole process and complain once it is gone.
void ensureShaderCacheDir() {
    if (std::getenv("MESA_SHADER_CACHE_DIR") != nullptr) return;
    const auto dir = std::filesystem::temp_directory_path() /
                     ("ensil-test-shader-cache-" + std::to_string(::getuid()));
    std::filesystem::create_directories(dir);
    ::setenv("MESA_SHADER_CACHE_DIR", dir.c_str(), 1);
}
}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (listingOnly(argc, argv)) return RUN_ALL_TESTS();
    const char* display = std::getenv("DISPLAY");
    const char* platform = std::getenv("QT_QPA_PLATFORM");
    if ((display == nullptr || *display == '\0') && platform == nullptr) {
        std::fprintf(stderr,
                     "These tests draw with OpenGL and need a display. Run them under a "
                     "virtual one: xvfb-run -a ctest --preset ci\n");
        return 1;
    }
    ensil::data::ensurePrivateRuntimeDirectory();  // as ensil does: Qt would warn at every start
    ensureShaderCacheDir();
    const ensil::test::PrivateUserFolders userFolders;
    QSurfaceFormat::setDefaultFormat(ensil::gl::preferredSurfaceFormat());
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("ensil-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("ensil-tests"));
    return RUN_ALL_TESTS();
}
