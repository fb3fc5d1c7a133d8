#include "widgets/ensemble_info_panel.h"

#include <gtest/gtest.h>

using namespace ensil::ui;

TEST(EnsembleInfoPanel, ShowsEveryFactAndAMessageReplacesThem) {
    EnsembleInfoPanel panel;
    engine::EnsembleFacts facts;
    facts.source = "demo";
    facts.variable = "wind_speed";
    facts.units = "m s-1";
    facts.memberDimension = "number";
    facts.members = 50;
    facts.gridSize = "256 x 128 x 16";
    facts.axes = {"lon: -80 .. 40", "lat: 25 .. 75", "plev: 1000 .. 100"};
    facts.valueRange = "0 .. 83 m s-1";
    facts.missing = 12;
    facts.megabytes = 100.0;
    panel.showFacts(facts);
    const QString text = panel.text();
    EXPECT_TRUE(text.contains("Members: 50 (dimension 'number')")) << text.toStdString();
    EXPECT_TRUE(text.contains("Grid: 256 x 128 x 16"));
    EXPECT_TRUE(text.contains("Axis: plev: 1000 .. 100"));
    EXPECT_TRUE(text.contains("Missing: 12"));
    EXPECT_TRUE(text.contains("Memory: 100.0 MiB"));

    panel.showMessage("Loading...");
    EXPECT_EQ(panel.text(), QString("Loading..."));
}
