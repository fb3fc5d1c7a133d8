#include "app/main_window.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QInputDialog>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <algorithm>
#include <cmath>

#include "data/ensemble_reader.h"
#include "preprocessing/inclusion_depth.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/image_compare.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "widgets/ensemble_info_panel.h"
#include "widgets/member_table_model.h"
#include "widgets/member_table_panel.h"
#include "widgets/render_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

TEST(TestIsolation, RememberedSettingsLiveInAFolderOfThisTestProcessAlone) {
    const QString file = QSettings().fileName();
    EXPECT_TRUE(file.contains(
        QStringLiteral("ensil-test-home-%1/").arg(QCoreApplication::applicationPid())))
        << file.toStdString();
    EXPECT_FALSE(file.startsWith(QDir::homePath() + QStringLiteral("/.config")))
        << file.toStdString();
}

TEST(MainWindow, LoadsTheDemoInTheBackgroundAndShowsIt) {
    app::MainWindow window;
    window.resize(1000, 700);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    window.loadDemo({.members = 5, .nx = 64, .ny = 32, .nz = 8, .seed = 3});
    ASSERT_TRUE(loaded.wait(30000)) << "the demo did not load";
    ASSERT_NE(window.overview(), nullptr);
    EXPECT_EQ(window.overview()->ensemble->memberCount(), 5u);

    const QString info = window.infoPanel()->text();
    EXPECT_TRUE(info.contains("Members: 5")) << info.toStdString();
    EXPECT_TRUE(info.contains("Grid: 64 x 32 x 8")) << info.toStdString();
    EXPECT_TRUE(window.windowTitle().contains("wind_speed"));

    // The screenshot shows the floor map: many pixels that are neither background nor gray.
    ensil::test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("shot.png"));
    // The view has its place in the settled layout before it is drawn.
    QApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QApplication::processEvents();
    ASSERT_TRUE(window.saveScreenshot(path));
    const QImage shot(path);
    ASSERT_FALSE(shot.isNull());
    int coloured = 0;
    for (int y = 0; y < shot.height(); y += 2)
        for (int x = 0; x < shot.width(); x += 2) {
            const QColor c = shot.pixelColor(x, y);
            if (std::max({c.red(), c.green(), c.blue()}) -
                    std::min({c.red(), c.green(), c.blue()}) >
                40)
                ++coloured;
        }
    EXPECT_GT(coloured, shot.width() * shot.height() / 4 / 20) << "floor map missing";
    shot.save(test::testOutputDir() + "/main_window_demo.png");  // kept as a test artifact
}

TEST(MainWindow, CancelledLoadLeavesNothingHalfLoaded) {
    app::MainWindow window;
    QSignalSpy failed(&window, &app::MainWindow::loadingFailed);
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    window.loadDemo({.members = 20, .nx = 128, .ny = 64, .nz = 16, .seed = 1});
    window.cancelLoading();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !window.isLoading(); }, 60000));
    // The job's end arrives through a queued signal: handled, it tells that loading was cancelled.
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return window.infoPanel()->text().contains("loading was cancelled"); }, 60000))
        << window.infoPanel()->text().toStdString();
    EXPECT_EQ(window.overview(), nullptr);
    EXPECT_EQ(loaded.count(), 0);
    EXPECT_EQ(failed.count(), 0) << "a cancel is not a failure";
}

TEST(MainWindow, OpensARealEnsembleFile) {
    app::MainWindow window;
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc"};
    selection.variable = "t";
    window.openFiles(selection);
    ASSERT_TRUE(loaded.wait(30000));
    EXPECT_EQ(window.overview()->ensemble->memberCount(), 10u);
    EXPECT_TRUE(window.infoPanel()->text().contains("Variable: t (Temperature)"))
        << window.infoPanel()->text().toStdString();
    // Two pressure levels: the panel says what that means for its isosurfaces.
    EXPECT_TRUE(window.infoPanel()->text().contains("Note: only 2 levels along plev"))
        << window.infoPanel()->text().toStdString();
}

TEST(MainWindow, LeavesOutAMemberWithoutDataLikeTheCommandLineAndSaysSo) {
    // Member 2 is all _FillValue. `ensil preprocess` leaves it out; the workbench once kept it,
    // and its NaN distances reached the linkage.
    test::ScopedCacheHome cache;
    app::MainWindow window;
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    QSignalSpy failed(window.isovalueSession(), &workbench::IsovalueSession::failed);
    QSignalSpy loadFailed(&window, &app::MainWindow::loadingFailed);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/../bad/member_without_data.nc"};
    window.openFiles(selection);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return built.count() + failed.count() + loadFailed.count() > 0; }, 60000));
    ASSERT_EQ(loadFailed.count(), 0) << loadFailed.front().front().toString().toStdString();
    ASSERT_EQ(failed.count(), 0) << failed.front().front().toString().toStdString();
    ASSERT_NE(window.overview(), nullptr);
    EXPECT_EQ(window.overview()->ensemble->memberCount(), 3u);

    // The clustering and the member table hold the three members with data, as the command
    // line's do.
    const workbench::MemberSelection* members = window.memberSelection();
    ASSERT_EQ(members->memberCount(), 3);
    EXPECT_EQ(members->tree().memberCount, 3);
    QStringList names;
    for (int m = 0; m < members->memberCount(); ++m) names << members->name(m);
    EXPECT_EQ(names, (QStringList{"member 0", "member 1", "member 3"}));
    const workbench::IsovalueResult* result = window.isovalueSession()->result();
    ASSERT_NE(result, nullptr);
    ASSERT_EQ(result->distances.size, 3u);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) EXPECT_TRUE(std::isfinite(result->distances.at(i, j)));
    ASSERT_EQ(result->tree.merges.size(), 2u);
    for (const prep::Merge& merge : result->tree.merges) EXPECT_TRUE(std::isfinite(merge.height));

    // Said once, in the info panel, naming the member.
    const QString info = window.infoPanel()->text();
    EXPECT_TRUE(info.contains("Members: 3")) << info.toStdString();
    EXPECT_EQ(info.count("has no valid value"), 1) << info.toStdString();
    EXPECT_TRUE(
        info.contains("'member 2' of 't' has no valid value (every value is missing); it "
                      "is left out of the clustering"))
        << info.toStdString();
}

TEST(MainWindow, AFailedOpenExplainsAndKeepsWhatIsShown) {
    app::MainWindow window;
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    QSignalSpy failed(&window, &app::MainWindow::loadingFailed);
    window.loadDemo({.members = 5, .nx = 32, .ny = 16, .nz = 4, .seed = 3});
    ASSERT_TRUE(loaded.wait(30000));
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/glosea4_surface_temperature_ensemble.nc"};
    window.openFiles(selection);
    ASSERT_TRUE(failed.wait(30000));
    EXPECT_TRUE(failed.front().front().toString().contains("no vertical"))
        << failed.front().front().toString().toStdString();
    ASSERT_NE(window.overview(), nullptr);
    EXPECT_EQ(window.overview()->ensemble->memberCount(), 5u) << "the demo stays on screen";
}

TEST(MainWindow, AsksWhichDimensionHoldsTheMembersWhenTheFileDoesNotSay) {
    app::MainWindow window;
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/contour.cdf"};
    selection.variable = "T";
    window.openFiles(selection);
    QInputDialog* dialog = nullptr;
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            dialog = window.findChild<QInputDialog*>(QStringLiteral("memberDimensionDialog"));
            return dialog != nullptr;
        },
        60000))
        << "no question about the member dimension";
    EXPECT_EQ(dialog->comboBoxItems(), QStringList{QStringLiteral("frtime")});
    dialog->setTextValue(QStringLiteral("frtime"));
    dialog->accept();
    ASSERT_TRUE(loaded.wait(30000));
    EXPECT_EQ(window.overview()->ensemble->memberCount(), 7u);
    EXPECT_EQ(window.overview()->ensemble->memberDimension, "frtime");
}

TEST(MainWindow, ShowsSilhouettesAtADefaultIsovalueAndRecoloursByClusters) {
    const ensil::test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {900, 600}));
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 8, .nx = 64, .ny = 32, .nz = 8, .seed = 11}))
        << "no isosurfaces were built";
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    const auto& meshes = window.view()->renderer().meshes();
    ASSERT_NE(meshes, nullptr);
    EXPECT_EQ(meshes->members.size(), 8u);
    const auto& stats = window.overview()->statistics;
    const double iso = window.renderToolbar()->isovalue();
    EXPECT_GT(iso, stats.minimum);
    EXPECT_LT(iso, stats.maximum);
    EXPECT_FLOAT_EQ(meshes->isovalue, static_cast<float>(iso));

    // Every member has a cluster colour; one cluster makes them all the same colour.
    EXPECT_EQ(window.isovalueSession()->labels().size(), 8u);
    window.isovalueSession()->setClusterCount(1);
    for (int label : window.isovalueSession()->labels()) EXPECT_EQ(label, 0);
    window.isovalueSession()->setClusterCount(8);
    auto labels = window.isovalueSession()->labels();
    std::sort(labels.begin(), labels.end());
    EXPECT_EQ(std::unique(labels.begin(), labels.end()) - labels.begin(), 8) << "eight singletons";

    // A new isovalue from the toolbar builds new meshes.
    built.clear();
    window.renderToolbar()->isovalueBox()->setValue(stats.minimum +
                                                    0.5 * (stats.maximum - stats.minimum));
    ASSERT_TRUE(built.wait(60000));
    EXPECT_NEAR(window.view()->renderer().meshes()->isovalue,
                stats.minimum + 0.5 * (stats.maximum - stats.minimum), 1e-2);

    // Vertical exaggeration stretches the box and rebuilds the display-space attributes.
    const float height = window.view()->renderer().frame().boxMax().z;
    built.clear();
    auto* exaggeration = window.renderPanel()->findChild<QDoubleSpinBox*>("vertical_exaggeration");
    exaggeration->setValue(3.0);
    EXPECT_FLOAT_EQ(window.view()->renderer().frame().boxMax().z, 3.0F * height);
    ASSERT_TRUE(built.wait(60000)) << "attributes were not rebuilt";
}

TEST(MainWindow, TheMemberTableShowsEachIsovaluesContourBoxplotAndANewEnsembleClearsIt) {
    // ERA5's temperature: the Depth column holds the engine's inclusion depths
    // (preprocessing/inclusion_depth.h) for the file's members at the isovalue shown, and names
    // its median and outliers; at the default isovalue and at 260 K, which has an outlier.
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1200, 800}));
    QSignalSpy built(window.isovalueSession(), &workbench::IsovalueSession::finished);
    const std::string file = ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc";
    data::DataSelection selection;
    selection.paths = {file};
    selection.variable = "t";
    window.openFiles(selection);
    ASSERT_TRUE(built.wait(120000)) << "no isosurfaces were built";
    const data::Ensemble era5 = data::openEnsemble({{file}, "t", {}, 0});
    const ui::MemberTableModel* model = window.memberTable()->model();
    const QString dot = QStringLiteral(" ") + QChar(0x00B7) + QStringLiteral(" ");
    std::size_t outliersSeen = 0;
    const auto checkTable = [&] {
        const float iso = window.view()->renderer().meshes()->isovalue;
        const prep::ContourBoxplot expected = prep::computeContourBoxplot(era5, iso);
        ASSERT_EQ(model->rowCount(), static_cast<int>(era5.memberCount()));
        for (int m = 0; m < model->rowCount(); ++m) {
            const QModelIndex cell = model->index(m, ui::MemberTableModel::Depth);
            const double depth = expected.depth[static_cast<std::size_t>(m)];
            EXPECT_DOUBLE_EQ(cell.data(ui::MemberTableModel::SortRole).toDouble(), depth)
                << "member " << m << " at " << iso;
            const bool median = static_cast<std::size_t>(m) == expected.median;
            const bool outlier = std::find(expected.outliers.begin(), expected.outliers.end(),
                                           static_cast<std::size_t>(m)) != expected.outliers.end();
            const QString text =
                workbench::depthText(depth) + (median    ? dot + QStringLiteral("median")
                                               : outlier ? dot + QStringLiteral("outlier")
                                                         : QString());
            EXPECT_EQ(cell.data().toString().toStdString(), text.toStdString())
                << "member " << m << " at " << iso;
        }
        outliersSeen += expected.outliers.size();
    };
    checkTable();
    EXPECT_FALSE(workbench::depthText(window.memberSelection()->depth(0)).isEmpty());

    // Another isovalue brings its own boxplot: at 260 K member 5 is an outlier.
    built.clear();
    window.renderToolbar()->isovalueBox()->setValue(260.0);
    ASSERT_TRUE(built.wait(120000)) << "no isosurfaces were built at 260 K";
    ASSERT_FLOAT_EQ(window.view()->renderer().meshes()->isovalue, 260.0F);
    checkTable();
    EXPECT_GT(outliersSeen, 0u) << "the outlier word was never checked";

    // A new ensemble: the members are shown at once, without the old ensemble's depths, which
    // come back with the new ensemble's first isovalue.
    std::vector<bool> boxplotOnReset;
    QObject::connect(window.memberSelection(), &workbench::MemberSelection::membersReset, &window,
                     [&] { boxplotOnReset.push_back(window.memberSelection()->hasBoxplot()); });
    built.clear();
    window.loadDemo({.members = 6, .nx = 64, .ny = 32, .nz = 8, .seed = 5});
    ASSERT_TRUE(built.wait(120000));
    ASSERT_EQ(boxplotOnReset.size(), 2u) << "the new members, then their first isovalue's figures";
    EXPECT_FALSE(boxplotOnReset[0]) << "the old ensemble's depths were kept";
    EXPECT_TRUE(boxplotOnReset[1]);
    EXPECT_EQ(model->index(0, ui::MemberTableModel::Depth)
                  .data(ui::MemberTableModel::SortRole)
                  .toDouble(),
              window.isovalueSession()->result()->depth[0]);
}
