#include "workbench/recent_selections.h"

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
data::DataSelection selectionOf(std::vector<std::string> paths, std::string variable = {},
                                std::string memberDimension = {}, std::size_t timeIndex = 0) {
    data::DataSelection s;
    s.paths = std::move(paths);
    s.variable = std::move(variable);
    s.memberDimension = std::move(memberDimension);
    s.timeIndex = timeIndex;
    return s;
}
}  // namespace

TEST(RecentSelections, KeepTheChoicesNewestFirstAndWithoutDuplicates) {
    test::TempDir dir;
    QSettings settings(QString::fromStdString(dir.file("recent.ini")), QSettings::IniFormat);
    workbench::rememberSelection(settings, selectionOf({"/data/a.nc"}, "t", "", 2));
    workbench::rememberSelection(settings, selectionOf({"/data/runs/1.vti", "/data/runs/2.vti"}));
    workbench::rememberSelection(settings, selectionOf({"/data/c.cdf"}, "T", "frtime", 0));
    workbench::rememberSelection(settings, selectionOf({"/data/a.nc"}, "z", "time", 1));

    const auto recent = workbench::recentSelections(settings);
    ASSERT_EQ(recent.size(), 3u);
    EXPECT_EQ(recent[0].label, "/data/a.nc");
    EXPECT_EQ(recent[0].selection.variable, "z") << "the latest choices for a.nc";
    EXPECT_EQ(recent[0].selection.memberDimension, "time");
    EXPECT_EQ(recent[0].selection.timeIndex, 1u);
    EXPECT_EQ(recent[1].selection.memberDimension, "frtime");
    EXPECT_EQ(recent[2].label, "2 files in /data/runs");
    EXPECT_EQ(recent[2].selection.paths.size(), 2u);
    EXPECT_TRUE(recent[2].selection.variable.empty());
}

// File > Open Recent opens the same part of the files: the levels and the region kept too.
TEST(RecentSelections, KeepTheLevelsAndTheRegion) {
    test::TempDir dir;
    QSettings settings(QString::fromStdString(dir.file("recent.ini")), QSettings::IniFormat);
    data::DataSelection part = selectionOf({"/data/gfs.nc"}, "t", "", 3);
    part.levels = data::parseLevelRange("850:200hPa");
    part.region = data::parseRegion("-10,40,35,72");
    workbench::rememberSelection(settings, part);
    workbench::rememberSelection(settings, selectionOf({"/data/whole.nc"}, "u"));
    const auto recent = workbench::recentSelections(settings);
    ASSERT_EQ(recent.size(), 2u);
    EXPECT_EQ(recent[1].selection, part);
    EXPECT_FALSE(recent[0].selection.levels.has_value());
    EXPECT_FALSE(recent[0].selection.region.has_value());

    // Edited by hand into nonsense: the whole file, not a failure.
    QVariantMap choices = settings.value("recentChoices").toMap();
    choices["/data/gfs.nc"] = QStringList{"t", "", "3", "ten to twenty", "-10,40,35,72"};
    settings.setValue("recentChoices", choices);
    const auto edited = workbench::recentSelections(settings);
    EXPECT_EQ(edited[1].selection.variable, "t");
    EXPECT_FALSE(edited[1].selection.levels.has_value());
}

TEST(RecentSelections, DropOldEntriesAndReadEntriesWithoutChoices) {
    test::TempDir dir;
    QSettings settings(QString::fromStdString(dir.file("recent.ini")), QSettings::IniFormat);
    // As written before choices were kept: files only.
    settings.setValue("recentFiles", QStringList{"/data/old.nc"});
    auto recent = workbench::recentSelections(settings);
    ASSERT_EQ(recent.size(), 1u);
    EXPECT_EQ(recent[0].selection.paths, std::vector<std::string>{"/data/old.nc"});
    EXPECT_TRUE(recent[0].selection.variable.empty());

    for (int i = 0; i < 5; ++i) {
        workbench::rememberSelection(settings,
                                     selectionOf({"/data/" + std::to_string(i) + ".nc"}, "v"), 3);
    }
    recent = workbench::recentSelections(settings);
    ASSERT_EQ(recent.size(), 3u);
    EXPECT_EQ(recent[0].label, "/data/4.nc");
    EXPECT_EQ(recent[2].label, "/data/2.nc");
    EXPECT_EQ(settings.value("recentChoices").toMap().size(), 3) << "dropped entries' choices go";
}
