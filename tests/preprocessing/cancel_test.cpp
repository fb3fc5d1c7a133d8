// Cancelling at random moments, many times: every step either finishes or throws Cancelled,
// nothing else, and (under the asan preset, which runs this label) nothing leaks.
#include <gtest/gtest.h>

#include <chrono>
#include <glm/geometric.hpp>
#include <random>
#include <thread>

#include "fixtures.h"
#include "preprocessing/clustering.h"
#include "preprocessing/isosurface_pipeline.h"
#include "preprocessing/similarity.h"

using namespace ensil;

TEST(Cancel, AtRandomMomentsEveryStepStopsCleanly) {
    const auto e = test::analyticEnsemble(8, 36, 36, 36, [](auto m, auto i, auto j, auto k) {
        return glm::length(glm::vec3(i, j, k) - glm::vec3(17.5F + static_cast<float>(m) * 0.3F)) -
               static_cast<float>(m) * 0.5F;
    });
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
    const data::DisplayFrame frame(e.grid, 1.0F);
    prep::PipelineOptions options;
    options.isovalue = 10.0F;
    std::mt19937 rng(42);
    std::uniform_int_distribution<int> delayUs(0, 40000);
    int cancelled = 0, finished = 0;
    for (int trial = 0; trial < 40; ++trial) {
        std::stop_source stop;
        std::jthread canceller([&stop, delay = delayUs(rng)] {
            std::this_thread::sleep_for(std::chrono::microseconds(delay));
            stop.request_stop();
        });
        try {
            const auto meshes =
                prep::buildIsovalueMeshes(e, moments, frame, options, stop.get_token());
            const auto d = prep::computeDistanceMatrix(e, options.isovalue, stop.get_token());
            (void)prep::clusterMembers(d, prep::Linkage::Ward, stop.get_token());
            ++finished;
            EXPECT_EQ(meshes.members.size(), 8u);
        } catch (const data::Cancelled&) {
            ++cancelled;
        }
    }
    EXPECT_GT(cancelled, 0) << "some runs must have been stopped";
    RecordProperty("finished", finished);
}
