#include "widgets/render_panel.h"

#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QSignalSpy>
#include <QSpinBox>

using namespace ensil;

namespace {
gl::RenderSettings unusual() {
    gl::RenderSettings s;
    s.mode = gl::RenderMode::Surfaces;
    s.thickness = 0.017F;
    s.surfaceAlpha = 0.35F;
    s.showMean = false;
    s.removal = true;
    s.removalMin = 2.5F;
    s.removalMax = 40.0F;
    s.groupSize = 7;
    s.showAxes = false;
    s.showLegend = false;
    return s;
}
}  // namespace

TEST(RenderPanel, ShowsSettingsWithoutSignallingAndWritesThemBack) {
    ui::RenderPanel panel;
    QSignalSpy edited(&panel, &ui::RenderPanel::settingsEdited);
    panel.setSettings(unusual());
    EXPECT_EQ(edited.count(), 0);
    gl::RenderSettings fresh;
    fresh.plane.enabled = true;  // not the panel's business: kept as it is
    const gl::RenderSettings back = panel.applyTo(fresh);
    EXPECT_EQ(back.mode, gl::RenderMode::Surfaces);
    EXPECT_FLOAT_EQ(back.thickness, 0.017F);
    EXPECT_FLOAT_EQ(back.surfaceAlpha, 0.35F);
    EXPECT_FALSE(back.showMean);
    EXPECT_TRUE(back.removal);
    EXPECT_FLOAT_EQ(back.removalMin, 2.5F);
    EXPECT_FLOAT_EQ(back.removalMax, 40.0F);
    EXPECT_EQ(back.groupSize, 7);
    EXPECT_FALSE(back.showAxes);
    EXPECT_FALSE(back.showLegend);
    EXPECT_TRUE(back.plane.enabled);
}

TEST(RenderPanel, UserEditsSignalOnceAndKeepTheRemovalBandOrdered) {
    ui::RenderPanel panel;
    panel.setOutlyingnessRange(100.0, QStringLiteral("K\u00b2"));
    panel.setSettings(unusual());
    QSignalSpy edited(&panel, &ui::RenderPanel::settingsEdited);
    auto* minimum = panel.findChild<QDoubleSpinBox*>(QStringLiteral("removalMin"));
    ASSERT_NE(minimum, nullptr);
    ASSERT_EQ(minimum->suffix(), QStringLiteral(" K\u00b2"));
    minimum->setValue(60.0);  // above o*max: o*max moves above it
    EXPECT_EQ(edited.count(), 1);
    const gl::RenderSettings s = panel.applyTo({});
    EXPECT_FLOAT_EQ(s.removalMin, 60.0F);
    EXPECT_GT(s.removalMax, s.removalMin);
    panel.setMode(gl::RenderMode::OpaqueSurfaces);
    EXPECT_EQ(edited.count(), 2);
    EXPECT_EQ(panel.applyTo({}).mode, gl::RenderMode::OpaqueSurfaces);
    EXPECT_FALSE(panel.findChild<QGroupBox*>("removal")->isEnabled())
        << "opaque surfaces draw no silhouettes to remove";
}

TEST(RenderPanel, AFirstOutlyingnessRangeProposesTheLowerHalf) {
    ui::RenderPanel panel;
    EXPECT_TRUE(panel.setOutlyingnessRange(12.0, {})) << "the first range proposes a band";
    const gl::RenderSettings s = panel.applyTo({});
    EXPECT_FLOAT_EQ(s.removalMin, 0.0F);
    EXPECT_FLOAT_EQ(s.removalMax, 6.0F);
    // A later range (another isovalue) keeps what the user chose.
    EXPECT_FALSE(panel.setOutlyingnessRange(30.0, {}));
    EXPECT_FLOAT_EQ(panel.applyTo({}).removalMax, 6.0F);
}

TEST(RenderPanel, ASmallerRangeNeverClampsThresholdsAProjectHolds) {
    // Clamping them would draw the project otherwise than `ensil render PROJECT` does.
    ui::RenderPanel panel;
    gl::RenderSettings saved;
    saved.removalMin = 5.0F;
    saved.removalMax = 40.0F;
    panel.setSettings(saved);
    EXPECT_FALSE(panel.setOutlyingnessRange(12.0, {}));
    EXPECT_FLOAT_EQ(panel.applyTo({}).removalMin, 5.0F);
    EXPECT_FLOAT_EQ(panel.applyTo({}).removalMax, 40.0F);
}
