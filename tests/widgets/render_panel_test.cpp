// The Rendering panel, made from the setting table: it shows a session's values without a
// signal, writes every one back, names each control by its setting, and keeps its own rules
// (the removal band ordered, a first band from the outlyingness, a project's thresholds kept).
#include "widgets/render_panel.h"

#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QSignalSpy>
#include <QSpinBox>

#include "session/setting_table.h"
#include "tests/support/image_compare.h"

using namespace ensil;

namespace {
session::SessionState unusual() {
    session::SessionState s;
    s.render.mode = gl::RenderMode::Surfaces;
    s.render.thickness = 0.017F;
    s.render.surfaceAlpha = 0.35F;
    s.render.showMean = false;
    s.render.removal = true;
    s.render.removalMin = 2.5F;
    s.render.removalMax = 40.0F;
    s.render.groupSize = 7;
    s.render.showAxes = false;
    s.render.showLegend = false;
    s.render.showTitle = false;
    s.render.floor = gl::FloorContent::MeanAtLevel;
    s.render.floorLevel = 3;
    s.verticalExaggeration = 2.5F;
    s.render.verticalAxis = data::VerticalAxis::StandardHeight;
    s.camera.orthographic = true;
    s.background = {1.0F, 1.0F, 1.0F};
    return s;
}
}  // namespace

TEST(RenderPanel, ShowsTheSessionWithoutSignallingAndWritesEverySettingBack) {
    ui::RenderPanel panel;
    QSignalSpy edited(&panel, &ui::RenderPanel::edited);
    const session::SessionState shown = unusual();
    panel.showSession(shown);
    EXPECT_EQ(edited.count(), 0);
    session::SessionState back;
    back.render.plane.enabled = true;  // not the panel's business: kept as it is
    panel.applyTo(back);
    // Every setting the panel shows comes back as it was shown, through the table.
    int shownSettings = 0;
    for (const session::Setting& s : session::settingTable()) {
        if (panel.control(s.id) == nullptr) continue;
        ++shownSettings;
        EXPECT_NEAR(s.get(back), s.get(shown), 1e-6) << s.id;
        // Named as projects and the command line name it.
        EXPECT_EQ(panel.control(s.id)->widget()->objectName().toStdString(), s.id);
    }
    EXPECT_EQ(shownSettings, 25);
    EXPECT_TRUE(back.render.plane.enabled);
    EXPECT_FALSE(panel.findChild<QDoubleSpinBox*>("thickness")->isEnabled())
        << "surfaces draw no silhouettes";
    EXPECT_TRUE(panel.findChild<QSpinBox*>("floor_level")->isEnabled()) << "the mean at a level";
    panel.resize(panel.sizeHint());
    panel.grab().save(test::testOutputDir() + "/render_panel.png");  // to look at
}

TEST(RenderPanel, UserEditsSignalOnceAndKeepTheRemovalBandOrdered) {
    ui::RenderPanel panel;
    panel.setOutlyingnessRange(100.0, QStringLiteral("K\u00b2"));
    panel.showSession(unusual());
    QSignalSpy edited(&panel, &ui::RenderPanel::edited);
    auto* minimum = panel.findChild<QDoubleSpinBox*>(QStringLiteral("removal_min"));
    ASSERT_NE(minimum, nullptr);
    ASSERT_EQ(minimum->suffix(), QStringLiteral(" K\u00b2"));
    minimum->setValue(60.0);  // above o*max: o*max moves above it
    EXPECT_EQ(edited.count(), 1);
    session::SessionState s;
    panel.applyTo(s);
    EXPECT_FLOAT_EQ(s.render.removalMin, 60.0F);
    EXPECT_GT(s.render.removalMax, s.render.removalMin);
    panel.setMode(gl::RenderMode::OpaqueSurfaces);
    EXPECT_EQ(edited.count(), 2);
    panel.applyTo(s);
    EXPECT_EQ(s.render.mode, gl::RenderMode::OpaqueSurfaces);
    EXPECT_FALSE(panel.findChild<QGroupBox*>("removal")->isEnabled())
        << "opaque surfaces draw no silhouettes to remove";
    // A flag, a choice and a number each signal once and reach the session.
    panel.findChild<QCheckBox*>("title")->setChecked(true);
    panel.findChild<QComboBox*>("projection")->setCurrentIndex(0);
    panel.findChild<QDoubleSpinBox*>("vertical_exaggeration")->setValue(4.0);
    EXPECT_EQ(edited.count(), 5);
    panel.applyTo(s);
    EXPECT_TRUE(s.render.showTitle);
    EXPECT_FALSE(s.camera.orthographic);
    EXPECT_FLOAT_EQ(s.verticalExaggeration, 4.0F);
}

TEST(RenderPanel, AFirstOutlyingnessRangeProposesTheLowerHalf) {
    ui::RenderPanel panel;
    EXPECT_TRUE(panel.setOutlyingnessRange(12.0, {})) << "the first range proposes a band";
    session::SessionState s;
    panel.applyTo(s);
    EXPECT_FLOAT_EQ(s.render.removalMin, 0.0F);
    EXPECT_FLOAT_EQ(s.render.removalMax, 6.0F);
    // A later range (another isovalue) keeps what the user chose.
    EXPECT_FALSE(panel.setOutlyingnessRange(30.0, {}));
    panel.applyTo(s);
    EXPECT_FLOAT_EQ(s.render.removalMax, 6.0F);
}

TEST(RenderPanel, ASmallerRangeNeverClampsThresholdsAProjectHolds) {
    // Clamping them would draw the project otherwise than `ensil render PROJECT` does.
    ui::RenderPanel panel;
    session::SessionState saved;
    saved.render.removalMin = 5.0F;
    saved.render.removalMax = 40.0F;
    panel.showSession(saved);
    EXPECT_FALSE(panel.setOutlyingnessRange(12.0, {}));
    session::SessionState s;
    panel.applyTo(s);
    EXPECT_FLOAT_EQ(s.render.removalMin, 5.0F);
    EXPECT_FLOAT_EQ(s.render.removalMax, 40.0F);
}
