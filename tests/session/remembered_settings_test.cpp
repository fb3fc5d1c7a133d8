// Remembered settings round-trip through the table, and a hand-edited file cannot put a value
// out of range into the session. Uses an INI file in a temporary folder, never the user's.
#include "session/remembered_settings.h"

#include <gtest/gtest.h>

#include "session/setting_table.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

TEST(RememberedSettings, WhatIsRememberedComesBack) {
    const test::TempDir dir;
    QSettings settings(QString::fromStdString(dir.file("ensil.ini")), QSettings::IniFormat);
    session::SessionState drawn;
    drawn.render.mode = gl::RenderMode::Surfaces;
    drawn.render.thickness = 0.3F;
    drawn.render.showLegend = false;
    drawn.render.groupSize = 7;
    drawn.background = session::unpackColour(0x336699);
    drawn.camera.orthographic = true;
    drawn.clusters = 9;  // belongs to the data: not remembered
    session::remember(settings, drawn);
    session::SessionState restored;
    session::restoreRemembered(settings, restored);
    EXPECT_EQ(restored.render.mode, gl::RenderMode::Surfaces);
    EXPECT_FLOAT_EQ(restored.render.thickness, 0.3F);
    EXPECT_FALSE(restored.render.showLegend);
    EXPECT_EQ(restored.render.groupSize, 7);
    EXPECT_DOUBLE_EQ(session::packColour(restored.background), 0x336699);
    EXPECT_TRUE(restored.camera.orthographic);
    EXPECT_EQ(restored.clusters, 5);
}

TEST(RememberedSettings, AHandEditedValueOutOfRangeKeepsTheSessionsValue) {
    const test::TempDir dir;
    QSettings settings(QString::fromStdString(dir.file("ensil.ini")), QSettings::IniFormat);
    settings.setValue("rendering/thickness", -5);
    settings.setValue("rendering/groupSize", "many");
    settings.setValue("rendering/mode", 2);  // an earlier version's index
    settings.setValue("rendering/mean", "perhaps");
    session::SessionState state;
    session::restoreRemembered(settings, state);
    EXPECT_FLOAT_EQ(state.render.thickness, session::SessionState{}.render.thickness);
    EXPECT_EQ(state.render.groupSize, session::SessionState{}.render.groupSize);
    EXPECT_EQ(state.render.mode, gl::RenderMode::Surfaces);
    EXPECT_TRUE(state.render.showMean);
}
