#include "data/demo_ensemble.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "data/error.h"

using namespace ensil::data;

namespace {
DemoEnsembleParams smallParams(std::uint64_t seed = 7) {
    return {.members = 30, .nx = 64, .ny = 32, .nz = 8, .seed = seed};
}

double rmsDistance(const Member& a, const Member& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
        const double d = a.values[i] - b.values[i];
        sum += d * d;
    }
    return std::sqrt(sum / static_cast<double>(a.values.size()));
}
}  // namespace

TEST(DemoEnsemble, HasRequestedShapeAndCfMetadata) {
    const DemoEnsemble demo = makeDemoEnsemble(smallParams());
    const Ensemble& e = demo.ensemble;
    EXPECT_EQ(e.memberCount(), 30u);
    EXPECT_EQ(e.grid.nx(), 64u);
    EXPECT_EQ(e.grid.ny(), 32u);
    EXPECT_EQ(e.grid.nz(), 8u);
    EXPECT_EQ(e.variable, "wind_speed");
    EXPECT_EQ(e.units, "m s-1");
    EXPECT_EQ(e.memberDimension, "number");
    ASSERT_EQ(demo.regimes.size(), 30u);
    for (const Member& m : e.members) ASSERT_EQ(m.values.size(), e.grid.pointCount());
    EXPECT_EQ(e.members.front().name, "member 1");
}

TEST(DemoEnsemble, PressureAxisRunsFromSurfaceToTropopauseUnevenly) {
    const Ensemble e = makeDemoEnsemble(smallParams()).ensemble;
    const Axis& z = e.grid.z();
    EXPECT_EQ(z.units, "hPa");
    EXPECT_FALSE(z.positiveUp);
    EXPECT_DOUBLE_EQ(z.front(), 1000.0);
    EXPECT_DOUBLE_EQ(z.back(), 100.0);
    EXPECT_FALSE(z.isUniform());
    EXPECT_TRUE(e.grid.x().isUniform());
}

TEST(DemoEnsemble, SameSeedSameFieldOtherSeedOtherField) {
    const Ensemble a = makeDemoEnsemble(smallParams(3)).ensemble;
    const Ensemble b = makeDemoEnsemble(smallParams(3)).ensemble;
    const Ensemble c = makeDemoEnsemble(smallParams(4)).ensemble;
    for (std::size_t m = 0; m < a.memberCount(); ++m) {
        ASSERT_EQ(a.members[m].values, b.members[m].values) << "member " << m;
    }
    EXPECT_NE(a.members[0].values, c.members[0].values);
}

TEST(DemoEnsemble, WindSpeedsArePhysicallyPlausible) {
    const Ensemble e = makeDemoEnsemble(smallParams()).ensemble;
    float lo = 1e9F, hi = -1e9F;
    for (const Member& m : e.members) {
        for (float v : m.values) {
            ASSERT_TRUE(std::isfinite(v));
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    EXPECT_GE(lo, 0.0F);
    EXPECT_LT(lo, 15.0F) << "calm air should exist near the surface";
    EXPECT_GT(hi, 45.0F) << "jet cores should exceed the paper's 30 m/s isovalue";
    EXPECT_LT(hi, 130.0F);
}

TEST(DemoEnsemble, JetCoreIsAloftNotAtTheSurface) {
    const Ensemble e = makeDemoEnsemble(smallParams()).ensemble;
    const Grid& g = e.grid;
    // Level-wise maximum over all members: it must peak between 400 and 150 hPa.
    std::size_t bestLevel = 0;
    float best = -1.0F;
    for (std::size_t k = 0; k < g.nz(); ++k) {
        for (const Member& m : e.members) {
            for (std::size_t p = 0; p < g.nx() * g.ny(); ++p) {
                const float v = m.values[k * g.nx() * g.ny() + p];
                if (v > best) {
                    best = v;
                    bestLevel = k;
                }
            }
        }
    }
    EXPECT_LE(g.z().values[bestLevel], 400.0);
    EXPECT_GE(g.z().values[bestLevel], 150.0);
}

TEST(DemoEnsemble, RegimesFormClustersAndTheOutlierStandsApart) {
    const DemoEnsemble demo = makeDemoEnsemble(smallParams(11));
    const auto& members = demo.ensemble.members;
    std::map<DemoRegime, int> counts;
    for (DemoRegime r : demo.regimes) ++counts[r];
    EXPECT_EQ(counts[DemoRegime::Outlier], 1);
    EXPECT_GE(counts.size(), 3u) << "at least two ordinary regimes and the outlier";

    double within = 0.0, between = 0.0;
    int nWithin = 0, nBetween = 0;
    std::size_t outlier = 0;
    for (std::size_t i = 0; i < members.size(); ++i) {
        if (demo.regimes[i] == DemoRegime::Outlier) outlier = i;
        for (std::size_t j = i + 1; j < members.size(); ++j) {
            if (demo.regimes[i] == DemoRegime::Outlier || demo.regimes[j] == DemoRegime::Outlier) {
                continue;
            }
            const double d = rmsDistance(members[i], members[j]);
            (demo.regimes[i] == demo.regimes[j] ? within : between) += d;
            (demo.regimes[i] == demo.regimes[j] ? nWithin : nBetween) += 1;
        }
    }
    ASSERT_GT(nWithin, 0);
    ASSERT_GT(nBetween, 0);
    EXPECT_LT(within / nWithin, 0.8 * (between / nBetween))
        << "members of one regime must be closer to each other than to other regimes";

    // The outlier's nearest neighbour is farther than a typical member's nearest neighbour.
    const auto nearest = [&](std::size_t i) {
        double best = 1e300;
        for (std::size_t j = 0; j < members.size(); ++j) {
            if (j != i) best = std::min(best, rmsDistance(members[i], members[j]));
        }
        return best;
    };
    std::vector<double> others;
    for (std::size_t i = 0; i < members.size(); ++i) {
        if (i != outlier) others.push_back(nearest(i));
    }
    std::sort(others.begin(), others.end());
    EXPECT_GT(nearest(outlier), 1.5 * others[others.size() / 2]);
}

TEST(DemoEnsemble, RejectsEmptyAndFlatRequests) {
    EXPECT_THROW(makeDemoEnsemble({.members = 0}), Error);
    EXPECT_THROW(makeDemoEnsemble({.members = 2, .nx = 8, .ny = 8, .nz = 1}), Error);
}

TEST(DemoEnsemble, AskingForMoreThanFitsIsRefusedBeforeAllocating) {
    // 10000 members of 4096 x 4096 x 64 points: 43 TB; once std::bad_alloc after 15 GB.
    const DemoEnsembleParams huge{.members = 10000, .nx = 4096, .ny = 4096, .nz = 64};
    try {
        (void)makeDemoEnsemble(huge);
        FAIL() << "accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::OutOfMemory);
        EXPECT_NE(std::string(e.what()).find("three quarters"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("10000 members of 4096 x 4096 x 64"),
                  std::string::npos)
            << e.what();
    }
}

TEST(DemoEnsemble, MakingItCanBeCancelledAndReportsProgress) {
    const DemoEnsembleParams small{.members = 8, .nx = 16, .ny = 8, .nz = 4};
    std::vector<double> reported;
    (void)makeDemoEnsemble(small, {}, [&](double f) { reported.push_back(f); });
    ASSERT_FALSE(reported.empty());
    EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
    EXPECT_LE(reported.back(), 1.0);
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW((void)makeDemoEnsemble(small, stop.get_token()), Cancelled);
}

TEST(DemoEnsemble, OverTimeStartsAsTheDemoDriftsAndMembersChangeRegime) {
    const DemoEnsembleParams params = smallParams();
    const DemoEnsemble plain = makeDemoEnsemble(params);
    const DemoEnsemble first = makeDemoEnsembleAt(params, 0, 6);
    const DemoEnsemble last = makeDemoEnsembleAt(params, 5, 6);
    for (std::size_t m = 0; m < plain.ensemble.memberCount(); ++m) {
        ASSERT_EQ(rmsDistance(plain.ensemble.members[m], first.ensemble.members[m]), 0.0)
            << "step 0 is the demo itself, member " << m;
    }
    EXPECT_EQ(first.ensemble.timeSteps.dimension, "time");
    ASSERT_EQ(first.ensemble.timeSteps.count(), 6u);
    EXPECT_EQ(first.ensemble.timeSteps.labels[1], "2026-01-01T12:00");
    EXPECT_EQ(last.ensemble.fixedDimensions,
              std::vector<std::string>{"time = 5 of 6 (2026-01-03T12:00)"});
    // Some members change regime, not most; the outlier stays one.
    std::size_t changed = 0;
    for (std::size_t m = 0; m < params.members; ++m) {
        if (first.regimes[m] != last.regimes[m]) ++changed;
        if (first.regimes[m] == DemoRegime::Outlier) {
            EXPECT_EQ(last.regimes[m], DemoRegime::Outlier);
        }
        EXPECT_GT(rmsDistance(first.ensemble.members[m], last.ensemble.members[m]), 0.5)
            << "every jet drifts, member " << m;
    }
    EXPECT_GE(changed, params.members / 6);
    EXPECT_LE(changed, params.members / 2);
    EXPECT_THROW((void)makeDemoEnsembleAt(params, 6, 6), Error);
}
