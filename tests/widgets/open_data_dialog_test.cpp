#include "widgets/open_data_dialog.h"

#include <gtest/gtest.h>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTreeWidget>

using namespace ensil;
using namespace ensil::ui;

namespace {
// What a probe of an ERA5-like file says: t and z usable, a 2D variable not.
engine::DataProbe era5Probe() {
    engine::DataProbe p;
    p.format = "NetCDF-4";
    p.variables = {
        {"z", "number=10, time=4, plev=2, lat=61, lon=120", "m**2 s**-2", "Geopotential", true, ""},
        {"t", "number=10, time=4, plev=2, lat=61, lon=120", "K", "Temperature", true, ""},
        {"msl", "number=10, time=4, lat=61, lon=120", "Pa", "Mean sea level pressure", false,
         "has no vertical dimension"},
    };
    p.variable = "t";
    p.memberDimensionChoices = {"number", "time"};
    p.memberDimension = "number";
    p.memberDimensionReason = "named like a member dimension";
    p.members = 10;
    p.timeSteps = 4;
    p.fixedDimensions = {"time = 0 of 4 (2017-01-01T00:00)"};
    p.grid = "120 x 61 x 2";
    return p;
}

QPushButton* okButton(const OpenDataDialog& dialog) {
    return dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
}

// Opens the dialog, answers its first request with `probe`, and returns the request count.
int answerFirstProbe(OpenDataDialog& dialog, const engine::DataProbe& probe) {
    QSignalSpy requested(&dialog, &OpenDataDialog::probeRequested);
    dialog.requestProbe();
    EXPECT_EQ(requested.count(), 1);
    EXPECT_TRUE(dialog.isProbing());
    EXPECT_FALSE(okButton(dialog)->isEnabled()) << "no OK while the headers are being read";
    const int request = requested.front().at(1).toInt();
    dialog.showProbe(probe, request);
    return request;
}
}  // namespace

TEST(OpenDataDialog, ListsTheVariablesAndOffersTheDetectedChoices) {
    OpenDataDialog dialog({"/data/era5.nc"});
    QSignalSpy requested(&dialog, &OpenDataDialog::probeRequested);
    dialog.requestProbe();
    const auto first = requested.front().front().value<data::DataSelection>();
    EXPECT_EQ(first.paths, std::vector<std::string>{"/data/era5.nc"});
    EXPECT_TRUE(first.variable.empty()) << "the readers choose the first usable variable";
    EXPECT_TRUE(first.memberDimension.empty());
    dialog.showProbe(era5Probe(), requested.front().at(1).toInt());

    QTreeWidget* list = dialog.variableList();
    ASSERT_EQ(list->topLevelItemCount(), 3);
    EXPECT_EQ(list->topLevelItem(0)->text(0), "z");
    EXPECT_EQ(list->topLevelItem(0)->text(1), "number=10, time=4, plev=2, lat=61, lon=120");
    EXPECT_EQ(list->topLevelItem(1)->text(2), "K");
    EXPECT_EQ(list->topLevelItem(1)->text(3), "Temperature");
    EXPECT_EQ(list->currentItem()->text(0), "t");
    EXPECT_FALSE(list->topLevelItem(2)->flags() & Qt::ItemIsEnabled) << "msl cannot be chosen";
    EXPECT_TRUE(list->topLevelItem(2)->text(3).contains("has no vertical dimension"));

    QComboBox* members = dialog.memberDimensionBox();
    ASSERT_EQ(members->count(), 2);  // the detected one (automatic) and the other candidate
    EXPECT_TRUE(members->itemText(0).startsWith("number (found: named like"));
    EXPECT_EQ(members->itemData(1).toString(), "time");
    EXPECT_EQ(members->currentIndex(), 0);

    EXPECT_TRUE(dialog.timeIndexBox()->isEnabled());
    EXPECT_EQ(dialog.timeIndexBox()->maximum(), 3);
    const QString details = dialog.findChild<QLabel*>("openDataDetails")->text();
    EXPECT_TRUE(details.contains("10 members of t on a 120 x 61 x 2 grid"))
        << details.toStdString();
    EXPECT_TRUE(details.contains("Fixed: time = 0 of 4 (2017-01-01T00:00)"))
        << details.toStdString();
    EXPECT_FALSE(details.contains("Size:")) << "no size line when the probe says none";
    engine::DataProbe sized = era5Probe();
    sized.size = "0.6 MiB of values";
    dialog.showProbe(sized, requested.front().at(1).toInt());
    EXPECT_TRUE(
        dialog.findChild<QLabel*>("openDataDetails")->text().contains("Size: 0.6 MiB of values"));
    EXPECT_TRUE(okButton(dialog)->isEnabled());
    const data::DataSelection chosen = dialog.selection();
    EXPECT_EQ(chosen.variable, "t");
    EXPECT_TRUE(chosen.memberDimension.empty());
    EXPECT_EQ(chosen.timeIndex, 0u);
}

TEST(OpenDataDialog, EveryChangeOfChoiceAsksForANewProbe) {
    OpenDataDialog dialog({"/data/era5.nc"});
    answerFirstProbe(dialog, era5Probe());
    QSignalSpy requested(&dialog, &OpenDataDialog::probeRequested);

    dialog.variableList()->setCurrentItem(dialog.variableList()->topLevelItem(0));
    ASSERT_EQ(requested.count(), 1);
    EXPECT_EQ(requested.back().front().value<data::DataSelection>().variable, "z");

    dialog.memberDimensionBox()->setCurrentIndex(1);
    ASSERT_EQ(requested.count(), 2);
    EXPECT_EQ(requested.back().front().value<data::DataSelection>().memberDimension, "time");

    dialog.timeIndexBox()->setValue(2);
    ASSERT_EQ(requested.count(), 3);
    const auto last = requested.back().front().value<data::DataSelection>();
    EXPECT_EQ(last.timeIndex, 2u);
    EXPECT_EQ(last.memberDimension, "time");
    EXPECT_EQ(last.variable, "z");
}

TEST(OpenDataDialog, AnAnswerToAnOlderRequestIsIgnored) {
    OpenDataDialog dialog({"/data/era5.nc"});
    QSignalSpy requested(&dialog, &OpenDataDialog::probeRequested);
    dialog.requestProbe();
    dialog.requestProbe();
    engine::DataProbe stale = era5Probe();
    stale.error = "stale";
    dialog.showProbe(stale, requested.front().at(1).toInt());
    EXPECT_TRUE(dialog.isProbing());
    EXPECT_TRUE(dialog.errorText().isEmpty());
    dialog.showProbe(era5Probe(), requested.back().at(1).toInt());
    EXPECT_FALSE(dialog.isProbing());
    EXPECT_TRUE(dialog.canAccept());
}

TEST(OpenDataDialog, AReaderErrorIsShownAndOkStaysDisabled) {
    OpenDataDialog dialog({"/tmp/garbage.nc"});
    engine::DataProbe failed;
    failed.error = "'/tmp/garbage.nc' is not in a format ensil reads (NetCDF, HDF5, VTK)";
    answerFirstProbe(dialog, failed);
    auto* error = dialog.findChild<QLabel*>("openDataError");
    ASSERT_NE(error, nullptr);
    EXPECT_FALSE(error->isHidden());
    EXPECT_EQ(error->text(), failed.error);
    EXPECT_FALSE(okButton(dialog)->isEnabled());
    EXPECT_EQ(dialog.variableList()->topLevelItemCount(), 0);
}

TEST(OpenDataDialog, WithoutAMemberDimensionTheUserMustChooseOne) {
    OpenDataDialog dialog({"/data/contour.cdf"});
    engine::DataProbe probe = era5Probe();
    probe.memberDimension.clear();
    probe.memberDimensionChoices = {"frtime"};
    probe.members = 0;
    probe.error = "no member dimension found\nChoose the dimension that holds the members above.";
    answerFirstProbe(dialog, probe);
    EXPECT_FALSE(okButton(dialog)->isEnabled());
    QComboBox* members = dialog.memberDimensionBox();
    ASSERT_EQ(members->count(), 2);
    EXPECT_TRUE(members->itemText(0).startsWith("Choose"));
    QSignalSpy requested(&dialog, &OpenDataDialog::probeRequested);
    members->setCurrentIndex(1);
    ASSERT_EQ(requested.count(), 1);
    EXPECT_EQ(requested.back().front().value<data::DataSelection>().memberDimension, "frtime");
    engine::DataProbe chosen = era5Probe();
    chosen.memberDimension = "frtime";
    chosen.memberDimensionReason = "chosen by the user";
    chosen.memberDimensionChoices = {"frtime"};
    dialog.showProbe(chosen, requested.back().at(1).toInt());
    EXPECT_TRUE(okButton(dialog)->isEnabled());
    EXPECT_EQ(members->currentData().toString(), "frtime") << "the user's choice stays chosen";
    EXPECT_EQ(dialog.selection().memberDimension, "frtime");
}

TEST(OpenDataDialog, SeveralFilesOfferOneMemberPerFile) {
    OpenDataDialog dialog({"/data/run_01.vti", "/data/run_02.vti"});
    engine::DataProbe probe;
    probe.format = "VTK XML image";
    probe.variables = {{"density", "", "", "", true, ""}};
    probe.variable = "density";
    probe.memberDimensionReason = "one file per member";
    probe.members = 2;
    probe.grid = "8 x 8 x 8";
    answerFirstProbe(dialog, probe);
    EXPECT_EQ(dialog.memberDimensionBox()->count(), 1);
    EXPECT_EQ(dialog.memberDimensionBox()->itemText(0), "One member per file");
    EXPECT_FALSE(dialog.timeIndexBox()->isEnabled()) << "no time dimension to choose along";
    EXPECT_TRUE(okButton(dialog)->isEnabled());
    EXPECT_EQ(dialog.selection().paths.size(), 2u);
}

// The Levels field: a range that parses goes into the selection and is probed (the probe of
// the real ERA-Interim file then says the levels kept); one that does not is said at once,
// without reading the headers, and OK waits until it is mended.
TEST(OpenDataDialog, ALevelRangeIsProbedWithTheChoicesAndAMalformedOneIsSaidAtOnce) {
    const QString file = QStringLiteral(ENSIL_SHARED_DATA_DIR "/eraint_uvz.nc");
    OpenDataDialog dialog({file});
    answerFirstProbe(dialog, era5Probe());
    ASSERT_TRUE(okButton(dialog)->isEnabled());

    QSignalSpy requested(&dialog, &OpenDataDialog::probeRequested);
    dialog.levelsEdit()->setText(QStringLiteral("500-200"));
    dialog.requestProbe();
    EXPECT_EQ(requested.count(), 0) << "nothing to read for a malformed range";
    EXPECT_TRUE(dialog.errorText().contains(QStringLiteral("'500-200'")));
    EXPECT_FALSE(okButton(dialog)->isEnabled());
    EXPECT_FALSE(dialog.selection().levels.has_value());

    dialog.levelsEdit()->setText(QStringLiteral("500:200 hPa"));
    dialog.requestProbe();
    ASSERT_EQ(requested.count(), 1);
    auto selection = requested.front().front().value<data::DataSelection>();
    EXPECT_EQ(selection.levels, (data::LevelRange{500, 200, "hPa"}));
    // The engine's answer for the real file (its wind speed, months standing in for members).
    selection.memberDimension = "month";
    selection.variable = "wind_speed";
    const engine::DataProbe probe = engine::probeData(selection);
    EXPECT_TRUE(probe.error.isEmpty()) << probe.error.toStdString();
    EXPECT_EQ(probe.grid, QStringLiteral("480 x 241 x 2"));
    EXPECT_TRUE(probe.levels.contains(QStringLiteral("level: 200 .. 500 millibars")))
        << probe.levels.toStdString();
    EXPECT_TRUE(probe.levels.contains(QStringLiteral("2 of the file's 3 levels")));
    dialog.showProbe(probe, requested.front().at(1).toInt());
    EXPECT_TRUE(okButton(dialog)->isEnabled());
    EXPECT_TRUE(dialog.findChild<QLabel*>("openDataDetails")->text().contains("Levels: level"));
}

// The Region field: a box that parses goes into the selection and is probed (the probe of the
// real ERA5 file then says the columns and rows kept, across its 0/360 seam); one that does not
// is said at once with the parser's message, without reading the headers, and OK waits until it
// is mended; a box with no grid point is the probe's error, naming the grid's extent; an empty
// field keeps the whole grid.
TEST(OpenDataDialog, ARegionIsProbedWithTheChoicesAndAMalformedOneIsSaidAtOnce) {
    const QString file = QStringLiteral(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc");
    OpenDataDialog dialog({file});
    answerFirstProbe(dialog, era5Probe());
    ASSERT_TRUE(okButton(dialog)->isEnabled());

    QSignalSpy requested(&dialog, &OpenDataDialog::probeRequested);
    dialog.regionEdit()->setText(QStringLiteral("-10,40,95,72"));
    dialog.requestProbe();
    EXPECT_EQ(requested.count(), 0) << "nothing to read for a malformed region";
    EXPECT_TRUE(dialog.errorText().contains(QStringLiteral("the region '-10,40,95,72' has LAT0")))
        << dialog.errorText().toStdString();
    EXPECT_FALSE(okButton(dialog)->isEnabled());
    EXPECT_FALSE(dialog.selection().region.has_value());

    dialog.regionEdit()->setText(QStringLiteral(" -10, 40, 35, 72 "));
    dialog.requestProbe();
    ASSERT_EQ(requested.count(), 1);
    auto selection = requested.back().front().value<data::DataSelection>();
    EXPECT_EQ(selection.region, (data::Region{-10, 40, 35, 72}));
    selection.variable = "t";  // the engine's answer for the real file
    const engine::DataProbe probe = engine::probeData(selection);
    EXPECT_TRUE(probe.error.isEmpty()) << probe.error.toStdString();
    EXPECT_EQ(probe.grid, QStringLiteral("17 x 13 x 2"));
    EXPECT_TRUE(probe.region.contains(QStringLiteral("lon: -9 .. 39 degrees_east, 17 points")))
        << probe.region.toStdString();
    EXPECT_TRUE(probe.region.contains(QStringLiteral("17 x 13 of the file's 120 x 61 columns")))
        << probe.region.toStdString();
    dialog.showProbe(probe, requested.back().at(1).toInt());
    EXPECT_TRUE(okButton(dialog)->isEnabled());
    EXPECT_TRUE(dialog.findChild<QLabel*>("openDataDetails")
                    ->text()
                    .contains("Region: lon: -9 .. 39 degrees_east"));

    dialog.regionEdit()->setText(QStringLiteral("1,2,35,72"));
    dialog.requestProbe();
    ASSERT_EQ(requested.count(), 2);
    selection = requested.back().front().value<data::DataSelection>();
    selection.variable = "t";
    const engine::DataProbe none = engine::probeData(selection);
    dialog.showProbe(none, requested.back().at(1).toInt());
    EXPECT_TRUE(dialog.errorText().contains(
        QStringLiteral("holds no grid point of 't' in %1, whose grid spans longitudes 0 to 357")
            .arg(file)))
        << dialog.errorText().toStdString();
    EXPECT_FALSE(okButton(dialog)->isEnabled());

    dialog.regionEdit()->clear();
    EXPECT_FALSE(dialog.selection().region.has_value());
    EXPECT_TRUE(dialog.regionError().isEmpty());
}
