// The field the cut face shows (engine/section_volume.h), on a grid of eight points whose
// every value is written here: which field, its range and what it is called.
#include "engine/section_volume.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ensil;

namespace {
data::Ensemble fourPoints() {
    data::Ensemble e;
    e.variable = "t";
    e.units = "K";
    e.grid = data::Grid(data::makeUniformAxis("x", "m", 0, 1, 2),
                        data::makeUniformAxis("y", "m", 0, 1, 2),
                        data::makeUniformAxis("z", "m", 0, 1, 2));
    e.members.push_back({"member 0", data::FieldValues{250, 260, 270, 280, 250, 260, 270, 280}});
    e.members.push_back({"member 1", data::FieldValues{255, 265, 275, 285, 255, 265, 275, 285}});
    return e;
}
std::vector<float> asVector(const data::FieldValues& v) { return {v.begin(), v.end()}; }
}  // namespace

TEST(SectionVolume, EachFieldIsItsOwnValuesOnItsOwnScaleUnderItsOwnName) {
    const data::Ensemble e = fourPoints();
    const data::Member mean{
        "mean", data::FieldValues{252.5F, 262.5F, 272.5F, 282.5F, 252.5F, 262.5F, 272.5F, 282.5F}};
    const data::FieldValues stddev{0.0F, 3.5F, std::nanf(""), 7.0F, 0.0F, 3.5F, 3.5F, 3.5F};
    const data::FieldValues exceedance{0.0F, 0.5F, 1.0F, 1.0F, 0.0F, 0.5F, 1.0F, 1.0F};
    engine::SectionSources s;
    s.ensemble = &e;
    s.mean = &mean;
    s.stddev = &stddev;
    s.exceedance = &exceedance;
    s.isovalue = 262.0F;
    s.valueMinimum = 250.0F;
    s.valueMaximum = 285.0F;
    s.member = 1;

    const gl::SectionVolume member = engine::sectionVolumeFor(s, gl::SectionField::Member);
    EXPECT_EQ(member.values, asVector(e.members[1].values));
    EXPECT_EQ(member.minimum, 250.0F) << "members share the ensemble's range";
    EXPECT_EQ(member.maximum, 285.0F);
    EXPECT_EQ(member.caption(), QStringLiteral("section: member 1: t [K]"));

    const gl::SectionVolume meanVolume = engine::sectionVolumeFor(s, gl::SectionField::Mean);
    EXPECT_EQ(meanVolume.values, asVector(mean.values));
    EXPECT_EQ(meanVolume.minimum, 250.0F);
    EXPECT_EQ(meanVolume.caption(), QStringLiteral("section: mean t [K]"));

    const gl::SectionVolume spread =
        engine::sectionVolumeFor(s, gl::SectionField::StandardDeviation);
    EXPECT_EQ(spread.values.size(), 8u);
    EXPECT_TRUE(std::isnan(spread.values[2]));
    EXPECT_EQ(spread.minimum, 0.0F) << "from no spread";
    EXPECT_EQ(spread.maximum, 7.0F) << "to the largest, NaN left out";
    EXPECT_EQ(spread.caption(), QStringLiteral("section: standard deviation of t [K]"));

    const gl::SectionVolume probability =
        engine::sectionVolumeFor(s, gl::SectionField::Probability);
    EXPECT_EQ(probability.values, asVector(exceedance));
    EXPECT_EQ(probability.minimum, 0.0F);
    EXPECT_EQ(probability.maximum, 1.0F);
    EXPECT_EQ(probability.caption(), QStringLiteral("section: P(t > 262 K)"));
    EXPECT_TRUE(probability.units.isEmpty()) << "a probability has no unit";
}

TEST(SectionVolume, AFieldThatIsNotThereLeavesTheFaceUnfilled) {
    const data::Ensemble e = fourPoints();
    engine::SectionSources s;
    s.ensemble = &e;
    s.member = -1;
    EXPECT_TRUE(engine::sectionVolumeFor(s, gl::SectionField::Member).values.empty())
        << "no member hovered or selected";
    s.member = 2;
    EXPECT_TRUE(engine::sectionVolumeFor(s, gl::SectionField::Member).values.empty());
    EXPECT_TRUE(engine::sectionVolumeFor(s, gl::SectionField::Probability).values.empty())
        << "no isovalue yet";
    const data::FieldValues wrongSize{1.0F, 2.0F};
    s.stddev = &wrongSize;
    EXPECT_TRUE(engine::sectionVolumeFor(s, gl::SectionField::StandardDeviation).values.empty());
    s.member = 0;
    EXPECT_TRUE(engine::sectionVolumeFor(s, gl::SectionField::None).values.empty());
}
