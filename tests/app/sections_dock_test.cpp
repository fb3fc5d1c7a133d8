// The Sections dock in the workbench (widgets/sections_panel.h): the map and cross-section of
// the data on screen appear where the members' contours are, follow the isovalue and the
// clusters, and a click on a contour selects its member everywhere. Screenshots are kept in
// test-output/ to be looked at.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QMenu>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

#include "app/main_window.h"
#include "data/display_frame.h"
#include "engine/section_painter.h"
#include "session/session_history.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "widgets/render_panel.h"
#include "widgets/section_canvas.h"
#include "widgets/section_colours_button.h"
#include "widgets/sections_panel.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {

// Until every section asked for has reached the screen.
bool settled(const ui::SectionsPanel& panel) {
    return QTest::qWaitFor([&] { return !panel.isBuilding(); }, 60000);
}

// Shows the Sections dock and waits until both sections are on screen.
bool showSections(app::MainWindow& window) {
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("sectionsDock"));
    if (dock == nullptr) return false;
    dock->show();
    dock->raise();
    ui::SectionsPanel* panel = window.sectionsPanel();
    return QTest::qWaitFor([&] { return panel->mapCanvas()->view() != nullptr; }, 60000) &&
           settled(*panel) && panel->crossCanvas()->view() != nullptr;
}

// A widget position on member m's first contour in the canvas.
std::optional<QPoint> pointOnContour(const ui::SectionCanvas& canvas, std::size_t m) {
    const engine::SectionView& view = *canvas.view();
    const QRectF plot = engine::sectionPlotRect(view, QRectF(canvas.rect()), canvas.sectionStyle());
    for (const engine::SectionLine& line : view.members.at(m).lines) {
        for (const glm::dvec2& p : line.points) {
            const QPoint at(static_cast<int>(std::lround(plot.left() + p.x * plot.width())),
                            static_cast<int>(std::lround(plot.bottom() - p.y * plot.height())));
            if (canvas.memberAt(at) == m) return at;
        }
    }
    return std::nullopt;
}

}  // namespace

TEST(SectionsDock, ShowsTheDemosJetsWhereTheContoursAreAndSelectsByClick) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1600, 1000}));
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 20, .nx = 96, .ny = 48, .nz = 12, .seed = 3}));
    ASSERT_TRUE(showSections(window));
    ui::SectionsPanel* panel = window.sectionsPanel();
    // The default places are where the members' contours are: both sections have them.
    const engine::SectionView& map = *panel->mapCanvas()->view();
    const engine::SectionView& cross = *panel->crossCanvas()->view();
    EXPECT_TRUE(panel->levelEdit()->text().endsWith(QStringLiteral("hPa")))
        << panel->levelEdit()->text().toStdString();
    int mapLines = 0, crossLines = 0;
    for (const auto& c : map.members) mapLines += static_cast<int>(c.lines.size());
    for (const auto& c : cross.members) crossLines += static_cast<int>(c.lines.size());
    EXPECT_GT(mapLines, 20);
    EXPECT_GT(crossLines, 20);
    // The contours are in the clusters' colours the view shows.
    workbench::MemberSelection* selection = window.memberSelection();
    ASSERT_TRUE(selection->isClustered());
    for (const auto& c : map.members) {
        const QColor shown = selection->memberColor(static_cast<int>(c.member));
        EXPECT_NEAR(c.colour.r, shown.redF(), 1e-3);
        EXPECT_NEAR(c.colour.g, shown.greenF(), 1e-3);
    }
    // A click on a member's contour selects it everywhere; Ctrl adds another.
    const std::size_t member = 5;
    const auto at = pointOnContour(*panel->mapCanvas(), member);
    ASSERT_TRUE(at);
    QTest::mouseClick(panel->mapCanvas(), Qt::LeftButton, Qt::NoModifier, *at);
    EXPECT_EQ(selection->selectedMembers(), QList<int>{static_cast<int>(member)});
    // The tooltip names it and its value on its contour: the isovalue.
    const QString said = panel->mapCanvas()->describe(*at);
    EXPECT_TRUE(said.contains(QStringLiteral("(#6)"))) << said.toStdString();
    // Hidden members are neither drawn nor picked.
    selection->setMemberVisible(static_cast<int>(member), false);
    EXPECT_NE(panel->mapCanvas()->memberAt(*at), std::optional<std::size_t>(member));
    selection->setMemberVisible(static_cast<int>(member), true);
    // Each section shows where the other lies: the map the cross-section's path, the
    // cross-section the map's level.
    ASSERT_EQ(panel->mapCanvas()->overlay().size(), 1U);
    ASSERT_EQ(panel->crossCanvas()->overlay().size(), 1U);
    const double level = panel->crossCanvas()->overlay().front().points.front().y;
    EXPECT_GT(level, 0.0);
    EXPECT_LT(level, 1.0);
    // And the 3D view shows both: the map's outline at its level, the cross-section's curtain.
    const auto& guides = window.view()->renderer().sectionGuides();
    ASSERT_EQ(guides.size(), 5U);
    EXPECT_DOUBLE_EQ(guides.front().front().z, level);
    window.grab().save(test::testOutputDir() + "/sections_dock_demo.png");

    // A drag with the right button across the map draws the cross-section's path, as the
    // session's (an undo step).
    ui::SectionCanvas* canvas = panel->mapCanvas();
    const QRectF plot =
        engine::sectionPlotRect(*canvas->view(), QRectF(canvas->rect()), canvas->sectionStyle());
    const QPoint from = plot.topLeft().toPoint() + QPoint(20, 20);
    const QPoint to = plot.bottomRight().toPoint() - QPoint(20, 20);
    QTest::mousePress(canvas, Qt::RightButton, Qt::NoModifier, from);
    QMouseEvent move(QEvent::MouseMove, QPointF(to), canvas->mapToGlobal(QPointF(to)), Qt::NoButton,
                     Qt::RightButton, Qt::NoModifier);
    QApplication::sendEvent(canvas, &move);
    QTest::mouseRelease(canvas, Qt::RightButton, Qt::NoModifier, to);
    ASSERT_TRUE(settled(*panel));
    EXPECT_EQ(window.captureSession().sections.crossKind, session::SectionPlaces::Cross::Path);
    EXPECT_EQ(panel->crossKindBox()->currentIndex(), 2);
    ASSERT_NE(panel->crossCanvas()->view(), nullptr)
        << panel->crossCanvas()->message().toStdString();
    EXPECT_EQ(panel->crossCanvas()->view()->title.rfind("wind_speed from ", 0), 0U)
        << panel->crossCanvas()->view()->title;
    // Its path on the map runs from the top left to the bottom right of the plot.
    const auto& path = panel->mapCanvas()->overlay().front().points;
    EXPECT_LT(path.front().x, 0.2);
    EXPECT_GT(path.front().y, 0.8);
    EXPECT_GT(path.back().x, 0.8);
    EXPECT_LT(path.back().y, 0.2);
    // The cross-section's pressure axis goes up as the 3D view's does: Rendering > Vertical
    // axis, linear in pressure, puts each level where that display frame puts it.
    auto* vertical = window.renderPanel()->findChild<QComboBox*>("vertical_axis");
    ASSERT_NE(vertical, nullptr);
    const std::vector<double> throughLogPressure = panel->crossCanvas()->view()->rowPositions;
    vertical->setCurrentIndex(static_cast<int>(data::VerticalAxis::Pressure));
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    {
        const data::Grid& grid = window.overview()->ensemble->grid;
        const data::DisplayFrame linear(grid, 1.0F, data::VerticalAxis::Pressure);
        std::vector<double> expected;
        for (const double p : grid.z().values) {
            expected.push_back(linear.toDisplay({grid.x().front(), grid.y().front(), p}).z /
                               linear.boxMax().z);
        }
        std::vector<double> rows = panel->crossCanvas()->view()->rowPositions;
        std::sort(rows.begin(), rows.end());
        std::sort(expected.begin(), expected.end());
        ASSERT_EQ(rows.size(), expected.size());
        for (std::size_t k = 0; k < rows.size(); ++k) EXPECT_NEAR(rows[k], expected[k], 1e-5);
        EXPECT_NE(panel->crossCanvas()->view()->rowPositions, throughLogPressure);
    }
    // A hidden dock leaves the 3D view as it was.
    window.findChild<QDockWidget*>(QStringLiteral("sectionsDock"))->hide();
    EXPECT_TRUE(window.view()->renderer().sectionGuides().empty());
}

TEST(SectionsDock, FollowsTheIsovalueAndTakesPlacesAsTyped) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1400, 900}));
    QSignalSpy finished(window.isovalueSession(), &workbench::IsovalueSession::finished);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc"};
    selection.variable = "t";
    window.openFiles(selection);
    ASSERT_TRUE(finished.wait(120000));
    ASSERT_TRUE(showSections(window));
    ui::SectionsPanel* panel = window.sectionsPanel();
    const QString defaultLevel = panel->levelEdit()->text();
    EXPECT_TRUE(defaultLevel.endsWith(QStringLiteral(" hPa"))) << defaultLevel.toStdString();
    // A level typed in hPa on an axis in Pa; a latitude as people write it.
    panel->levelEdit()->setText(QStringLiteral("500hPa"));
    emit panel->levelEdit()->editingFinished();
    ASSERT_TRUE(settled(*panel));
    EXPECT_EQ(panel->mapCanvas()->view()->title, "t at 500 hPa");
    // The place is the session's: undo takes it back to where the contours are, redo again.
    EXPECT_EQ(window.history()->stack()->undoText(), QStringLiteral("Map Level default -> 500hPa"));
    window.history()->stack()->undo();
    EXPECT_TRUE(window.captureSession().sections.level.empty());
    EXPECT_EQ(panel->levelEdit()->text(), defaultLevel);  // where the contours are, shown
    window.history()->stack()->redo();
    EXPECT_EQ(panel->levelEdit()->text(), QStringLiteral("500hPa"));
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    // A place outside the data is said in the canvas, the edit marked.
    panel->levelEdit()->setText(QStringLiteral("1000 hPa"));
    emit panel->levelEdit()->editingFinished();
    ASSERT_TRUE(settled(*panel));
    EXPECT_EQ(panel->mapCanvas()->view(), nullptr);
    EXPECT_TRUE(panel->mapCanvas()->message().contains(QStringLiteral("outside the data")))
        << panel->mapCanvas()->message().toStdString();
    panel->levelEdit()->setText(QStringLiteral("850hPa"));
    emit panel->levelEdit()->editingFinished();
    ASSERT_TRUE(settled(*panel));
    // A new isovalue: the contours follow it.
    const float before = window.isovalueSession()->result()->meshes->isovalue;
    window.isovalueSession()->setIsovalue(before + 5.0F, 1.0F);
    ASSERT_TRUE(finished.wait(120000));
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    EXPECT_NE(panel->mapCanvas()->view()->subtitle.find("isovalue"), std::string::npos);
    const engine::SectionView& map = *panel->mapCanvas()->view();
    // Every contour point lies where the member's value is the new isovalue.
    for (const auto& c : map.members) {
        for (const auto& line : c.lines) {
            for (const glm::dvec2& p : line.points) {
                EXPECT_NEAR(engine::sectionValueAt(map, map.memberValues[c.member], p),
                            before + 5.0F, 0.5);
            }
        }
    }
    // Rendering > Contour boxplot draws it on the sections: the median is the workbench's, the
    // band the samples between the deepest half's union and intersection.
    auto* band = window.renderPanel()->findChild<QCheckBox*>("band");
    ASSERT_NE(band, nullptr);
    band->setChecked(true);
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    const engine::SectionView& boxplot = *panel->mapCanvas()->view();
    EXPECT_EQ(boxplot.medianMember, window.memberSelection()->medianMember());
    EXPECT_GT(engine::bandSampleCount(boxplot), 0U);
    band->setChecked(false);
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    EXPECT_EQ(panel->mapCanvas()->view()->medianMember, -1);
    // Exported as a figure a journal takes.
    test::TempDir dir;
    QString error;
    const QString svg = QString::fromStdString(dir.file("map.svg"));
    ASSERT_TRUE(panel->exportSection(true, svg, &error)) << error.toStdString();
    EXPECT_GT(QFileInfo(svg).size(), 1000);
    EXPECT_FALSE(panel->exportSection(true, QString::fromStdString(dir.file("map.gif")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral(".svg"))) << error.toStdString();
    window.grab().save(test::testOutputDir() + "/sections_dock_era5.png");

    // A project keeps the places, the fill and its colours; reopened, the dock shows them.
    window.memberSelection()->setSelection({3});
    window.sectionsPanel()->fillBox()->setCurrentIndex(4);  // the selected member less the mean
    emit window.sectionsPanel()->fillBox()->activated(4);
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    EXPECT_EQ(panel->mapCanvas()->view()->colourMap, engine::SectionColourMap::RdBu);
    // Greys from the Colours menu, then a fixed range: each an undoable step.
    QAction* greys = nullptr;
    for (QAction* a : panel->coloursButton()->menu()->actions()) {
        if (a->text() == QStringLiteral("Greys")) greys = a;
    }
    ASSERT_NE(greys, nullptr);
    greys->trigger();
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    EXPECT_EQ(panel->mapCanvas()->view()->colourMap, engine::SectionColourMap::Greys);
    EXPECT_TRUE(greys->isChecked());
    panel->coloursButton()->setFixedRange(std::pair{-3.0, 3.0});
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    EXPECT_FLOAT_EQ(panel->mapCanvas()->view()->fillMinimum, -3.0F);
    window.history()->stack()->undo();
    while (panel->isBuilding()) ASSERT_TRUE(settled(*panel));
    EXPECT_NE(panel->mapCanvas()->view()->fillMinimum, -3.0F) << "the section's own range again";
    window.history()->stack()->redo();
    const QString project = QString::fromStdString(dir.file("sections.ensil"));
    ASSERT_TRUE(window.saveProjectTo(project));
    app::MainWindow reopened;
    ASSERT_TRUE(test::showWorkbench(reopened, {1400, 900}));
    ASSERT_TRUE(test::openProjectAndWait(reopened, project));
    ASSERT_TRUE(showSections(reopened));
    EXPECT_EQ(reopened.sectionsPanel()->levelEdit()->text(), QStringLiteral("850hPa"));
    EXPECT_EQ(reopened.sectionsPanel()->fillBox()->currentIndex(), 4);
    const engine::SectionView& again = *reopened.sectionsPanel()->mapCanvas()->view();
    EXPECT_EQ(again.colourMap, engine::SectionColourMap::Greys);
    EXPECT_FLOAT_EQ(again.fillMinimum, -3.0F);
    EXPECT_FLOAT_EQ(again.fillMaximum, 3.0F);
    EXPECT_NE(again.fillCaption.find("minus the mean"), std::string::npos) << again.fillCaption;
}

TEST(SectionsDock, IsATabBehindTheDendrogramAtFirstAndCostsNothingThere) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1200, 800}));
    ASSERT_TRUE(
        test::loadDemoAndWait(window, {.members = 8, .nx = 32, .ny = 16, .nz = 6, .seed = 2}));
    // Not shown: no section is made, and the 3D view shows no guides.
    EXPECT_EQ(window.sectionsPanel()->mapCanvas()->view(), nullptr);
    EXPECT_TRUE(window.view()->renderer().sectionGuides().empty());
}
