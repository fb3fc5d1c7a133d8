// Another time step's overview takes what it shares with the step shown (the isovalue the data
// opened at, the map lines) instead of computing it again, and only on the same grid and mapping.
#include "engine/ensemble_overview.h"

#include <gtest/gtest.h>

#include <memory>

#include "data/demo_ensemble.h"

using namespace ensil;

namespace {
// The demo (on longitude and latitude over the North Atlantic: coastlines on its floor), its
// values times `scale`: another time step with another default isovalue.
std::shared_ptr<const data::Ensemble> demoStep(std::size_t nx, float scale) {
    data::Ensemble e = data::makeDemoEnsemble({.members = 4, .nx = nx, .ny = 16, .nz = 4}).ensemble;
    for (data::Member& m : e.members)
        for (float& v : m.values) v *= scale;
    return std::make_shared<const data::Ensemble>(std::move(e));
}
}  // namespace

TEST(EnsembleOverview, AnotherTimeStepTakesTheOpeningIsovalueAndTheMapLinesOfTheStepShown) {
    const engine::EnsembleOverview first =
        engine::buildEnsembleOverview(demoStep(32, 1.0F), {}, {});
    ASSERT_NE(first.mapLines, nullptr);
    ASSERT_FALSE(first.mapLines->empty()) << "coastlines over the North Atlantic";
    const auto next = demoStep(32, 1.5F);
    const engine::EnsembleOverview alone = engine::buildEnsembleOverview(next, {}, {});
    ASSERT_NE(alone.defaultIsovalue, first.defaultIsovalue) << "else this test shows nothing";

    const engine::SameDataParts shown = engine::sameDataParts(first);
    const engine::EnsembleOverview step = engine::buildEnsembleOverview(next, {}, {}, &shown);
    EXPECT_EQ(step.mapLines, first.mapLines) << "the same lines, not computed again";
    EXPECT_EQ(step.defaultIsovalue, first.defaultIsovalue) << "the isovalue the data opened at";
    // What is the step's own is its own.
    EXPECT_EQ(step.statistics.maximum, alone.statistics.maximum);
    EXPECT_EQ(step.statistics.histogram, alone.statistics.histogram);
    EXPECT_EQ(step.moments->mean.values, alone.moments->mean.values);
}

TEST(EnsembleOverview, OnAnotherGridNothingIsTaken) {
    const engine::EnsembleOverview first =
        engine::buildEnsembleOverview(demoStep(32, 1.0F), {}, {});
    const auto other = demoStep(40, 1.5F);
    const engine::SameDataParts shown = engine::sameDataParts(first);
    const engine::EnsembleOverview step = engine::buildEnsembleOverview(other, {}, {}, &shown);
    const engine::EnsembleOverview alone = engine::buildEnsembleOverview(other, {}, {});
    EXPECT_NE(step.mapLines, first.mapLines);
    EXPECT_EQ(step.mapLines->size(), alone.mapLines->size());
    EXPECT_EQ(step.defaultIsovalue, alone.defaultIsovalue);
}
