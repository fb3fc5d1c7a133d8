// Test data for the workbench's time steps: the demo over three steps, 6 hours apart, written as
// one NetCDF file, opened by a Workbench with step 0's surfaces shown as the window shows them.
#pragma once

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <string>

#include "data/demo_ensemble.h"
#include "data/netcdf_writer.h"
#include "workbench/isovalue_session.h"
#include "workbench/workbench.h"

namespace ensil::test {

inline constexpr int kStepWaitMs = 60000;  // an upper bound for a loaded CI machine, not a pace
inline constexpr std::size_t kDemoSteps = 3;

// Writes the steps to `path`, opens them and waits for step 0's surfaces.
inline void openDemoSteps(workbench::Workbench& bench, const std::string& path) {
    const data::DemoEnsembleParams demo{.members = 6, .nx = 32, .ny = 16, .nz = 6, .seed = 9};
    data::writeNetcdfSteps(
        [&demo](std::size_t step) {
            return data::makeDemoEnsembleAt(demo, step, kDemoSteps).ensemble;
        },
        {data::kDemoTimeUnits, {0.0, 6.0, 12.0}}, path);
    QSignalSpy arrived(&bench, &workbench::Workbench::dataArrived);
    data::DataSelection selection;
    selection.paths = {path};
    bench.openFiles(selection);
    ASSERT_TRUE(arrived.wait(kStepWaitMs));
    bench.startSessionOfNewData(bench.overview()->defaultIsovalue);
    QSignalSpy built(bench.isovalue(), &workbench::IsovalueSession::finished);
    bench.buildFirstSurfaces();
    ASSERT_TRUE(built.wait(kStepWaitMs));
    bench.surfacesShown();
}

}  // namespace ensil::test
