// Reading NetCDF-4 files on a worker thread (as the workbench does) prints nothing: netCDF reads
// them through HDF5, whose error printing is per thread and was left on for threads other than
// the first, filling the terminal with HDF5-DIAG pages for attributes netCDF only probes for.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "data/ensemble_reader.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

TEST(NetcdfThreads, ReadingOnAWorkerThreadPrintsNoHdf5Diagnostics) {
    const test::TempDir dir;
    const std::string log = dir.file("stderr.txt");
    // Standard error into a file while the file is read (a real NetCDF-4 file).
    std::fflush(stderr);
    const int saved = ::dup(STDERR_FILENO);
    std::FILE* capture = std::fopen(log.c_str(), "w");
    ASSERT_NE(capture, nullptr);
    ::dup2(::fileno(capture), STDERR_FILENO);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc"};
    selection.variable = "t";
    // The library is first used here, on this thread (netCDF silences HDF5 on this one only) ...
    (void)data::describeEnsemble(selection);
    std::size_t members = 0;
    // ... then on another.
    std::thread worker([&members, &selection] {
        (void)data::describeEnsemble(selection);
        members = data::openEnsemble(selection).memberCount();
    });
    worker.join();
    std::fflush(stderr);
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::fclose(capture);
    EXPECT_EQ(members, 10u);
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str().find("HDF5-DIAG"), std::string::npos) << text.str().substr(0, 600);
}
