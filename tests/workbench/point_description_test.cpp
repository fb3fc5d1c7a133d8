// What the status bar and tooltip say of a point under the cursor, on ERA5's real grid and
// uk_hires's rotated one: true longitude and latitude, the level in hPa, and the values the
// data hold there.
#include "workbench/point_description.h"

#include <gtest/gtest.h>

#include "data/ensemble_reader.h"
#include "engine/section_volume.h"
#include "preprocessing/ensemble_moments.h"

using namespace ensil;

namespace {
struct Opened {
    data::Ensemble ensemble;
    prep::EnsembleMoments moments;
    geo::MapProjection projection;
    data::DisplayFrame frame;
    workbench::PointContext context() const {
        return {&ensemble, &moments.mean, &projection, &frame};
    }
};

Opened openWithContext(const char* file, const char* variable, const char* memberDim = "") {
    data::Ensemble e = data::openEnsemble({.paths = {std::string(ENSIL_SHARED_DATA_DIR "/") + file},
                                           .variable = variable,
                                           .memberDimension = memberDim});
    prep::EnsembleMoments moments = prep::computeEnsembleMoments(e);
    geo::MapProjection projection = geo::MapProjection::forGrid(e.grid, e.gridMapping);
    const data::DisplayFrame frame(e.grid, 1.0F);
    return {std::move(e), std::move(moments), std::move(projection), frame};
}
}  // namespace

TEST(PointDescription, ASurfacePointSaysPlaceLevelAndTheMembersAndMeansValues) {
    const Opened era5 = openWithContext("era5_eda_members.nc", "t");
    const data::Grid& g = era5.ensemble.grid;
    // Grid point (lon index 10, lat index 20, level index 0): 30 E, 30 N.
    const std::size_t i = 10, j = 20, k = 0;
    gl::PickResult hit;
    hit.member = 3;
    hit.surface = era5.frame.indexToDisplay(glm::vec3(i, j, k));
    const QString text = workbench::describePoint(era5.context(), hit);
    const float member = era5.ensemble.members[3].values[g.index(i, j, k)];
    const float mean = era5.moments.mean.values[g.index(i, j, k)];
    EXPECT_TRUE(text.startsWith(workbench::formatLonLat(g.x().values[i], g.y().values[j])))
        << text.toStdString();
    EXPECT_TRUE(text.contains(QString::number(g.z().values[k] / 100.0, 'g', 4) + " hPa"))
        << text.toStdString();
    EXPECT_TRUE(text.contains("t " + QString::number(member, 'g', 5) + " K here"))
        << text.toStdString();
    EXPECT_TRUE(text.contains("mean " + QString::number(mean, 'g', 5) + " K"))
        << text.toStdString();
}

TEST(PointDescription, OnAFilledCutFaceItSaysTheSectionsFieldAndValueThere) {
    const Opened era5 = openWithContext("era5_eda_members.nc", "t");
    const data::Grid& g = era5.ensemble.grid;
    engine::SectionSources sources;
    sources.ensemble = &era5.ensemble;
    sources.member = 4;
    sources.valueMinimum = 200.0F;
    sources.valueMaximum = 300.0F;
    const gl::SectionVolume section = engine::sectionVolumeFor(sources, gl::SectionField::Member);
    workbench::PointContext context = era5.context();
    context.section = &section;
    const std::size_t i = 40, j = 30, k = 1;
    gl::PickResult hit;
    hit.section = era5.frame.indexToDisplay(glm::vec3(i, j, k));
    hit.floor = era5.frame.indexToDisplay(glm::vec3(i, j, 0));
    const QString text = workbench::describePoint(context, hit);
    const float value = era5.ensemble.members[4].values[g.index(i, j, k)];
    EXPECT_TRUE(text.startsWith(workbench::formatLonLat(g.x().values[i], g.y().values[j])))
        << text.toStdString();
    EXPECT_TRUE(text.endsWith("member 4: t " + QString::number(value, 'g', 5) + " K"))
        << text.toStdString();
    // Without the face filled the same point is the floor's.
    context.section = nullptr;
    EXPECT_TRUE(workbench::describePoint(context, hit).contains("column maximum"));
}

TEST(PointDescription, LongitudesReadEastAndWestAndRotatedGridsGiveTrueDegrees) {
    EXPECT_EQ(workbench::formatLonLat(357.0, -30.0), QStringLiteral("30.00\u00b0 S, 3.00\u00b0 W"));
    EXPECT_EQ(workbench::formatLonLat(30.0, 30.0), QStringLiteral("30.00\u00b0 N, 30.00\u00b0 E"));
    const Opened uk = openWithContext("uk_hires.nc", "air_potential_temperature", "time");
    gl::PickResult floor;
    floor.floor = uk.frame.indexToDisplay({0.0F, 0.0F, 0.0F});
    const QString text = workbench::describePoint(uk.context(), floor);
    // The grid's first corner, rotated (357.5..., 0.1...), lies near 6.9 W 52.6 N.
    EXPECT_TRUE(text.contains("\u00b0 N")) << text.toStdString();
    EXPECT_TRUE(text.contains("\u00b0 W")) << text.toStdString();
    EXPECT_TRUE(text.contains("column maximum of the mean")) << text.toStdString();
    EXPECT_TRUE(workbench::describePoint(uk.context(), gl::PickResult{}).isEmpty());
}
