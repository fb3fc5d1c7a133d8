#include "widgets/cutting_plane_panel.h"

#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <cmath>

using namespace ensil;

namespace {
// A box 1 x 0.5 x 0.2 whose vertical axis is pressure, 1000 hPa at the bottom (position -1)
// to 100 hPa at the top, its levels not evenly spaced across the box (as log-pressure is).
std::array<ui::PlaneAxis, 3> axes() {
    ui::PlaneAxis x{"lon", "degrees_east", {-1.0, 1.0}, {-80.0, 40.0}};
    ui::PlaneAxis y{"lat", "degrees_north", {-1.0, 1.0}, {25.0, 75.0}};
    ui::PlaneAxis z{"plev", "hPa", {-1.0, -0.4, 0.2, 1.0}, {1000.0, 700.0, 500.0, 100.0}};
    return {x, y, z};
}
constexpr glm::vec3 kMin{0.0F}, kMax{1.0F, 0.5F, 0.2F};
}  // namespace

TEST(CuttingPlanePanel, AxisLookupsInterpolateBothWaysEvenOnDecreasingValues) {
    const ui::PlaneAxis z = axes()[2];
    EXPECT_DOUBLE_EQ(ui::axisValueAt(z, 0.2), 500.0);
    EXPECT_DOUBLE_EQ(ui::axisValueAt(z, -0.1), 600.0);
    EXPECT_DOUBLE_EQ(ui::axisPositionOf(z, 600.0), -0.1);
    EXPECT_DOUBLE_EQ(ui::axisValueAt(z, 5.0), 100.0) << "clamped at the ends";
}

TEST(CuttingPlanePanel, APressureLevelTypedInHectopascalsPlacesTheHorizontalPlaneThere) {
    ui::CuttingPlanePanel panel;
    panel.setBox(kMin, kMax, axes());
    panel.setCutting(true);
    panel.setOrientation(ui::CuttingPlanePanel::AlongZ);
    QSignalSpy changed(&panel, &ui::CuttingPlanePanel::planeChanged);
    auto* value = panel.findChild<QDoubleSpinBox*>(QStringLiteral("dataValue"));
    ASSERT_NE(value, nullptr);
    ASSERT_EQ(value->suffix(), QStringLiteral(" hPa"));
    value->setValue(500.0);
    EXPECT_GE(changed.count(), 1);
    const gl::CuttingPlane p = panel.plane();
    EXPECT_TRUE(p.enabled);
    EXPECT_FLOAT_EQ(p.normal.z, 1.0F);
    // Position 0.2 across a box 0.2 high: 0.1 + 0.2 * 0.1 above the floor.
    EXPECT_NEAR(p.offset, 0.12F, 1e-3F);
    EXPECT_NEAR(panel.dataPosition(), 500.0, 1.0);
}

TEST(CuttingPlanePanel, TheSliderMovesTheFreePlaneAcrossTheWholeBox) {
    ui::CuttingPlanePanel panel;
    panel.setBox(kMin, kMax, axes());
    panel.setOrientation(ui::CuttingPlanePanel::Free);
    panel.findChild<QDoubleSpinBox*>(QStringLiteral("normalX"))->setValue(1.0);
    panel.findChild<QDoubleSpinBox*>(QStringLiteral("normalY"))->setValue(1.0);
    panel.findChild<QDoubleSpinBox*>(QStringLiteral("normalZ"))->setValue(0.0);
    EXPECT_TRUE(std::isnan(panel.dataPosition()));
    const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
    panel.setPosition(1.0);  // touches the corner furthest along n
    EXPECT_NEAR(panel.plane().offset, glm::dot(n, kMax), 1e-3F);
    panel.setPosition(-1.0);
    EXPECT_NEAR(panel.plane().offset, glm::dot(n, kMin), 1e-3F);
    panel.setPosition(0.0);
    EXPECT_NEAR(panel.plane().offset, glm::dot(n, 0.5F * kMax), 1e-3F);
}

TEST(CuttingPlanePanel, ARestoredPlaneShowsAsItWasWithoutSignalling) {
    ui::CuttingPlanePanel panel;
    panel.setBox(kMin, kMax, axes());
    gl::CuttingPlane saved = gl::CuttingPlane::acrossBox({0, 1, 0}, -0.5F, kMin, kMax);
    saved.thickness = 0.01F;
    QSignalSpy changed(&panel, &ui::CuttingPlanePanel::planeChanged);
    panel.setPlane(saved);
    EXPECT_EQ(changed.count(), 0);
    const gl::CuttingPlane shown = panel.plane();
    EXPECT_TRUE(shown.enabled);
    EXPECT_FLOAT_EQ(shown.normal.y, 1.0F);
    EXPECT_NEAR(shown.offset, saved.offset, 1e-3F);
    EXPECT_FLOAT_EQ(shown.thickness, 0.01F);
    EXPECT_NEAR(panel.dataPosition(), 37.5, 0.1) << "a quarter of the way from 25 N to 75 N";
}
