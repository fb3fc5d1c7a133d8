#include <gtest/gtest.h>

#include <QApplication>
#include <QFile>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSvgRenderer>
#include <QTest>
#include <QWheelEvent>
#include <cmath>
#include <limits>

#include "panel_fixtures.h"
#include "tests/support/temp_dir.h"
#include "widgets/dendrogram_export.h"
#include "widgets/dendrogram_layout.h"
#include "widgets/dendrogram_painter.h"
#include "widgets/dendrogram_view.h"
#include "workbench/member_selection.h"

using namespace ensil;
using ui::DendrogramLayout;

namespace {
// The merge whose members are exactly these (-1 when none).
int mergeOf(const DendrogramLayout& layout, QList<int> members) {
    std::sort(members.begin(), members.end());
    for (int node = layout.memberCount(); node < layout.nodeCount(); ++node) {
        QList<int> below = layout.membersOf(node);
        std::sort(below.begin(), below.end());
        if (below == members) return node;
    }
    return -1;
}

void showAndWait(QWidget& w) {
    w.resize(600, 300);
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
}

// The two groups' figures with a contour boxplot: member 4 the median, member 5 an outlier.
workbench::MemberFigures twoGroupsWithABoxplot() {
    workbench::MemberFigures f = test::figuresOnALine(test::kTwoGroups);
    f.depth = {0.5, 0.4, 0.6, 0.45, 0.8, 0.05};
    f.median = 4;
    f.outliers = {5};
    return f;
}

// The attributes of the SVG group that holds this text (QSvgGenerator writes the font of each
// run of text on the <g> around it); empty when the text is not there.
QString groupAround(const QString& svg, const QString& text) {
    const qsizetype at = svg.indexOf(QLatin1Char('>') + text + QLatin1Char('<'));
    if (at < 0) return {};
    const qsizetype group = svg.lastIndexOf(QLatin1String("<g "), at);
    return group < 0 ? QString() : svg.mid(group, svg.indexOf(QLatin1Char('>'), group) - group);
}

QColor pixelAt(const QImage& image, QPointF p) {
    return image.pixelColor((p * image.devicePixelRatio()).toPoint());
}

// Whether some pixel in this rectangle (in widget pixels) has this colour.
bool hasColourIn(const QImage& image, const QRectF& rect, const QColor& colour) {
    const qreal ratio = image.devicePixelRatio();
    const QRect pixels = QRectF(rect.topLeft() * ratio, rect.size() * ratio).toAlignedRect();
    for (int y = pixels.top(); y <= pixels.bottom(); ++y) {
        for (int x = pixels.left(); x <= pixels.right(); ++x) {
            if (image.valid(x, y) && image.pixel(x, y) == colour.rgb()) return true;
        }
    }
    return false;
}

// A dendrogram view of the two groups, shown.
class ShownDendrogram : public ::testing::Test {
protected:
    void SetUp() override {
        test::loadTwoGroups(s);
        showAndWait(view);
    }
    workbench::MemberSelection s;
    ui::DendrogramView view{&s};
};
}  // namespace

TEST(DendrogramLayout, PlacesLeavesInTreeOrderAndMergesBetweenTheirChildren) {
    const prep::MergeTree tree = test::treeOnALine(test::kTwoGroups);
    const DendrogramLayout layout(tree);
    ASSERT_EQ(layout.memberCount(), 6);
    ASSERT_EQ(layout.nodeCount(), 11);
    const std::vector<int> order = prep::leafOrder(tree);
    for (int p = 0; p < 6; ++p) {
        EXPECT_DOUBLE_EQ(layout.x(order[static_cast<std::size_t>(p)]), p + 0.5);
        EXPECT_EQ(layout.height(order[static_cast<std::size_t>(p)]), 0.0);
    }
    for (std::size_t k = 0; k < tree.merges.size(); ++k) {
        const int node = 6 + static_cast<int>(k);
        EXPECT_DOUBLE_EQ(layout.height(node), tree.merges[k].height);
        EXPECT_DOUBLE_EQ(layout.x(node),
                         0.5 * (layout.x(tree.merges[k].a) + layout.x(tree.merges[k].b)));
        EXPECT_EQ(layout.parent(tree.merges[k].a), node);
        EXPECT_EQ(layout.memberCountOf(node), tree.merges[k].size);
    }
    EXPECT_EQ(layout.parent(layout.root()), -1);
    QList<int> all = layout.membersOf(layout.root());
    std::sort(all.begin(), all.end());
    EXPECT_EQ(all, (QList<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_GE(mergeOf(layout, {0, 2, 4}), 6) << "each group is one branch";
    EXPECT_GT(layout.topHeight(), layout.height(layout.root()));
}

TEST(DendrogramLayout, TheCutLineForKClustersGivesKClusters) {
    const prep::MergeTree tree = test::treeOnALine(test::kTwoGroups);
    const DendrogramLayout layout(tree);
    for (int k = 1; k <= 6; ++k) {
        const double h = layout.cutHeight(k);
        EXPECT_EQ(layout.clustersAtHeight(h), k) << "k = " << k;
        // Between the last merge kept and the first undone.
        if (k < 6) {
            EXPECT_GT(h, tree.merges[static_cast<std::size_t>(6 - k - 1)].height);
        }
        if (k > 1) {
            EXPECT_LT(h, tree.merges[static_cast<std::size_t>(6 - k)].height);
        }
        // Below the cut: exactly the members and the merges kept.
        int below = 0;
        for (int node = 0; node < layout.nodeCount(); ++node) below += layout.isBelowCut(node, k);
        EXPECT_EQ(below, 6 + (6 - k));
    }
    EXPECT_EQ(layout.clustersAtHeight(-1.0), 6);
    EXPECT_EQ(layout.clustersAtHeight(1e9), 1);
}

TEST(DendrogramLayout, DrawsInfiniteMergesJustAboveTheFiniteOnes) {
    // Two pairs with no valid point in common between them.
    const double inf = std::numeric_limits<double>::infinity();
    prep::DistanceMatrix d{4, {0, 1, inf, inf, 1, 0, inf, inf, inf, inf, 0, 2, inf, inf, 2, 0}, {}};
    const DendrogramLayout layout(prep::clusterMembers(d));
    const int root = layout.root();
    EXPECT_TRUE(std::isinf(layout.mergeHeight(root)));
    EXPECT_TRUE(std::isfinite(layout.height(root)));
    EXPECT_GT(layout.height(root), 2.0);
    EXPECT_LT(layout.height(root), layout.topHeight());
    EXPECT_EQ(layout.clustersAtHeight(layout.cutHeight(2)), 2);
}

TEST(DendrogramLayout, FindsTheBranchUnderAPoint) {
    const DendrogramLayout layout(test::treeOnALine(test::kTwoGroups));
    ui::DendrogramFrame frame;
    frame.plot = QRectF(50, 10, 600, 200);
    frame.leafWidth = 100;
    frame.topHeight = layout.topHeight();
    const int group = mergeOf(layout, {1, 3, 5});
    // On its bar, on its stem, on a member's stem, far from everything.
    const QPointF bar = frame.toPixel(layout.x(layout.childA(group)) + 0.1, layout.height(group));
    EXPECT_EQ(ui::nodeAt(layout, frame, bar + QPointF(0, 2)), group);
    const QPointF stem =
        frame.toPixel(layout.x(group), 0.5 * (layout.height(group) + layout.height(layout.root())));
    EXPECT_EQ(ui::nodeAt(layout, frame, stem + QPointF(3, 0)), group);
    EXPECT_EQ(ui::nodeAt(layout, frame, frame.toPixel(layout.x(5), 0.0) + QPointF(0, -2)), 5);
    EXPECT_EQ(ui::nodeAt(layout, frame, QPointF(5, 5)), -1);
    // Scrolling moves everything left.
    frame.scroll = 100;
    EXPECT_EQ(ui::nodeAt(layout, frame, bar + QPointF(-100, 2)), group);
}

TEST_F(ShownDendrogram, ClickingABranchSelectsItsMembers) {
    const auto& layout = view.layout();
    const ui::DendrogramFrame frame = view.frame();
    const int group = mergeOf(layout, {1, 3, 5});
    const QPoint bar = frame.toPixel(layout.x(group), layout.height(group)).toPoint();
    QTest::mouseClick(view.viewport(), Qt::LeftButton, Qt::NoModifier, bar);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{1, 3, 5}));
    const QPoint leaf = frame.toPixel(layout.x(0), 0.0).toPoint() + QPoint(0, -3);
    QTest::mouseClick(view.viewport(), Qt::LeftButton, Qt::ShiftModifier, leaf);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{0, 1, 3, 5}));
    QTest::mouseClick(view.viewport(), Qt::LeftButton, Qt::ControlModifier, bar);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{0}));
    QTest::mouseClick(view.viewport(), Qt::LeftButton, Qt::NoModifier,
                      frame.plot.topLeft().toPoint() + QPoint(3, 3));
    EXPECT_TRUE(s.selectedMembers().isEmpty()) << "a click on empty space clears";
}

TEST_F(ShownDendrogram, DraggingTheCutLineSetsTheNumberOfClustersLive) {
    const auto& layout = view.layout();
    const ui::DendrogramFrame frame = view.frame();
    const int x = static_cast<int>(frame.plot.right()) - 10;
    const int from = static_cast<int>(std::lround(frame.pixelY(layout.cutHeight(2))));
    QSignalSpy changed(&s, &workbench::MemberSelection::clustersChanged);
    QTest::mousePress(view.viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(x, from));
    QTest::mouseMove(view.viewport(),
                     QPoint(x, static_cast<int>(frame.pixelY(layout.cutHeight(4)))));
    EXPECT_EQ(s.clusterCount(), 4) << "changes while dragging, not only on release";
    const int to = static_cast<int>(frame.pixelY(layout.cutHeight(1)));
    QTest::mouseRelease(view.viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(x, to));
    EXPECT_EQ(s.clusterCount(), 1);
    EXPECT_EQ(changed.count(), 2);
    EXPECT_TRUE(s.selectedMembers().isEmpty()) << "dragging the line selects nothing";
}

TEST_F(ShownDendrogram, TellsTheMergeHeightUnderThePointer) {
    const auto& layout = view.layout();
    const ui::DendrogramFrame frame = view.frame();
    const int pair = mergeOf(layout, {1, 3});
    ASSERT_GE(pair, 0);
    const QString tip = view.toolTipAt(frame.toPixel(layout.x(pair), layout.height(pair)));
    EXPECT_EQ(tip, QStringLiteral("Merge height 0.7: 2 members"));
    EXPECT_EQ(view.toolTipAt(frame.toPixel(layout.x(3), 0.1)),
              QStringLiteral("m3 (cluster %1)").arg(s.clusterOf(3) + 1));
    // Moving over a branch shades its members: what a click there would select.
    const QPointF pairBar = frame.toPixel(layout.x(pair), layout.height(pair));
    test::moveMouse(view.viewport(), pairBar.toPoint());
    ASSERT_EQ(view.hoveredNode(), pair);
    const QImage shaded = view.viewport()->grab().toImage();
    // Inside the band, between the pair's stems and below its bar; outside it, beside the band.
    const QPointF inside = frame.toPixel(layout.x(pair), 0.5 * layout.height(pair));
    const QPointF outside = frame.toPixel(layout.x(layout.root()) - 0.3, 0.5 * layout.height(pair));
    const qreal ratio = shaded.devicePixelRatio();
    EXPECT_NE(shaded.pixelColor((inside * ratio).toPoint()), view.style().background);
    EXPECT_EQ(shaded.pixelColor((outside * ratio).toPoint()), view.style().background);
    // Moving over a member's stem hovers that member.
    const QPoint stem = frame.toPixel(layout.x(3), 0.1).toPoint();
    test::moveMouse(view.viewport(), stem);
    EXPECT_EQ(s.hovered(), 3) << "at " << stem.x() << "," << stem.y();
}

TEST(DendrogramView, TheWheelZoomsAroundThePointer) {
    workbench::MemberSelection s;
    ui::DendrogramView view(&s);
    std::vector<double> positions;
    for (int m = 0; m < 200; ++m) positions.push_back(std::sin(m * 0.37) * 10.0 + m * 0.01);
    s.setMembers(test::figuresOnALine(positions));
    s.setTree(test::treeOnALine(positions));
    showAndWait(view);
    const auto& layout = view.layout();
    const int member = layout.leafOrder()[120];
    const double before = view.frame().pixelX(layout.x(member));
    const QPointF at(before, view.frame().plot.center().y());
    QWheelEvent wheel(at, view.viewport()->mapToGlobal(at), QPoint(), QPoint(0, 360), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view.viewport(), &wheel);
    EXPECT_GT(view.zoom(), 1.5);
    EXPECT_NEAR(view.frame().pixelX(layout.x(member)), before, 1.0) << "the leaf stays put";
    EXPECT_GT(view.frame().leafWidth, 1.5 * view.frame().plot.width() / 200.0);
    EXPECT_GT(view.horizontalScrollBar()->maximum(), 0) << "the zoomed tree scrolls";
}

TEST_F(ShownDendrogram, ShowsSelectedMembersUnderTheirLeaves) {
    s.setSelection({3});
    QApplication::processEvents();  // the repaint the selection asked for
    const QImage image = view.viewport()->grab().toImage();
    const ui::DendrogramFrame frame = view.frame();
    const double radius = std::clamp(frame.leafWidth * 0.3, 2.0, 5.0);
    const QPoint marker =
        QPointF(frame.pixelX(view.layout().x(3)), frame.plot.bottom() + radius + 1.0).toPoint();
    const qreal ratio = image.devicePixelRatio();
    EXPECT_EQ(image.pixelColor(QPoint(marker.x() * ratio, marker.y() * ratio)).rgb(),
              s.memberColor(3).rgb());
    const QPoint unselected =
        QPointF(frame.pixelX(view.layout().x(1)), frame.plot.bottom() + radius + 1.0).toPoint();
    EXPECT_NE(image.pixelColor(unselected).rgb(), s.memberColor(1).rgb());
}

TEST(DendrogramExport, WritesAnSvgWithEveryMemberNameAndRoundMergeHeights) {
    workbench::MemberSelection s;
    test::loadTwoGroups(s);
    test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("tree.svg"));
    QString error;
    ASSERT_TRUE(ui::writeDendrogramSvg(s, path, &error)) << error.toStdString();
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString svg = QString::fromUtf8(file.readAll());
    EXPECT_TRUE(svg.contains("<svg")) << svg.left(200).toStdString();
    for (int m = 0; m < 6; ++m) EXPECT_TRUE(svg.contains(QStringLiteral(">m%1<").arg(m))) << m;
    EXPECT_TRUE(svg.contains(s.memberColor(0).name(), Qt::CaseInsensitive)) << "cluster colours";
    const QSvgRenderer reader(path);
    EXPECT_TRUE(reader.isValid()) << "Qt's own SVG reader cannot read it back";
    EXPECT_GT(reader.defaultSize().width(), 6 * 10) << "one leaf per text line";
    // The two groups merge at the mean of their nine cross distances, 92.1 / 9 = 10.23: the
    // height axis reads 0, 5, 10 (round numbers), not quarters of 10.23.
    for (const char* tick : {">0<", ">5<", ">10<"}) {
        EXPECT_TRUE(svg.contains(QLatin1String(tick))) << tick;
    }
    for (const char* quarter : {">2.56<", ">5.12<", ">7.67<"}) {
        EXPECT_FALSE(svg.contains(QLatin1String(quarter))) << quarter;
    }
}

TEST(DendrogramExport, ExplainsWhatWentWrong) {
    workbench::MemberSelection s;
    QString error;
    EXPECT_FALSE(ui::writeDendrogramSvg(s, "/tmp/never.svg", &error));
    EXPECT_TRUE(error.contains("no dendrogram yet")) << error.toStdString();
    test::loadTwoGroups(s);
    EXPECT_FALSE(ui::writeDendrogramSvg(s, "/nonexistent-folder/tree.svg", &error));
    EXPECT_TRUE(error.contains("/nonexistent-folder/tree.svg")) << error.toStdString();
}

TEST(DendrogramExport, MarksTheMediansAndTheOutliersNames) {
    workbench::MemberSelection s;
    test::loadTwoGroups(s);
    s.setMembers(twoGroupsWithABoxplot());  // the same members: the tree stays
    ASSERT_TRUE(s.isClustered());
    test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("tree.svg"));
    ASSERT_TRUE(ui::writeDendrogramSvg(s, path));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString svg = QString::fromUtf8(file.readAll());
    // The outlier's name in italics, the median's in bold, the others plain.
    const QString outlier = groupAround(svg, QStringLiteral("m5"));
    ASSERT_FALSE(outlier.isEmpty()) << svg.toStdString();
    EXPECT_TRUE(outlier.contains(QLatin1String("font-style=\"italic\""))) << outlier.toStdString();
    const QString median = groupAround(svg, QStringLiteral("m4"));
    ASSERT_FALSE(median.isEmpty()) << svg.toStdString();
    EXPECT_TRUE(median.contains(QLatin1String("font-weight=\"700\""))) << median.toStdString();
    EXPECT_FALSE(median.contains(QLatin1String("italic"))) << median.toStdString();
    for (const int m : {0, 1, 2, 3}) {
        const QString plain = groupAround(svg, QStringLiteral("m%1").arg(m));
        ASSERT_FALSE(plain.isEmpty()) << m;
        EXPECT_FALSE(plain.contains(QLatin1String("italic"))) << plain.toStdString();
        EXPECT_FALSE(plain.contains(QLatin1String("font-weight=\"700\""))) << plain.toStdString();
    }
    // The legend says what the marks are.
    EXPECT_TRUE(svg.contains(QLatin1String(">median<"))) << "legend";
    EXPECT_TRUE(svg.contains(QLatin1String(">outlier<"))) << "legend";
}

TEST_F(ShownDendrogram, MarksTheMedianAndTheOutliersUnderTheirLeaves) {
    const QColor background = view.style().background;
    // Before the boxplot is known there are no marks and no legend.
    ui::DendrogramFrame frame = view.frame();
    QImage image = view.viewport()->grab().toImage();
    EXPECT_EQ(pixelAt(image, ui::boxplotMarkCenter(frame, view.layout().x(4))), background);
    EXPECT_TRUE(
        ui::boxplotLegendRect(s, QRectF(view.viewport()->rect()), frame, view.font()).isEmpty());

    s.setMembers(twoGroupsWithABoxplot());
    QApplication::processEvents();  // the repaint the new figures asked for
    ASSERT_TRUE(s.isClustered());
    frame = view.frame();
    image = view.viewport()->grab().toImage();
    const auto& layout = view.layout();
    EXPECT_EQ(pixelAt(image, ui::boxplotMarkCenter(frame, layout.x(4))).rgb(),
              view.style().median.rgb())
        << "the median's mark";
    EXPECT_EQ(pixelAt(image, ui::boxplotMarkCenter(frame, layout.x(5))).rgb(),
              view.style().outlier.rgb())
        << "the outlier's mark";
    for (const int m : {0, 1, 2, 3}) {
        EXPECT_EQ(pixelAt(image, ui::boxplotMarkCenter(frame, layout.x(m))), background) << m;
    }
    // The marks and the legend say what they mean where the pointer is.
    const QString outlierTip = view.toolTipAt(ui::boxplotMarkCenter(frame, layout.x(5)));
    EXPECT_TRUE(outlierTip.startsWith("m5: inclusion depth 0.0500, an outlier"))
        << outlierTip.toStdString();
    const QString medianTip = view.toolTipAt(frame.toPixel(layout.x(4), 0.1));
    EXPECT_TRUE(medianTip.contains("inclusion depth 0.800, the median of the contour boxplot"))
        << medianTip.toStdString();
    const QRectF legend =
        ui::boxplotLegendRect(s, QRectF(view.viewport()->rect()), frame, view.font());
    ASSERT_FALSE(legend.isEmpty());
    const QString legendTip = view.toolTipAt(legend.center());
    EXPECT_TRUE(legendTip.contains("a diamond marks the median")) << legendTip.toStdString();
    EXPECT_TRUE(legendTip.contains("a triangle each outlier")) << legendTip.toStdString();
    // The legend is drawn (not only placed): the outlier's triangle is in it.
    EXPECT_TRUE(hasColourIn(image, legend, view.style().outlier));
}

TEST(DendrogramView, MarksTheBoxplotReadablyAtFiftyMembers) {
    // 50 members in a 600 pixel view: too narrow for names, so the marks alone tell the median
    // and the outliers, each under its own leaf without touching the next.
    workbench::MemberSelection s;
    ui::DendrogramView view(&s);
    std::vector<double> positions;
    for (int m = 0; m < 50; ++m) positions.push_back(std::sin(m * 0.37) * 10.0 + m * 0.01);
    workbench::MemberFigures figures = test::figuresOnALine(positions);
    for (int m = 0; m < 50; ++m) figures.depth.push_back(0.5 + 0.4 * std::cos(m * 0.37));
    figures.median = 17;
    figures.outliers = {3, 4, 41};
    s.setMembers(figures);
    s.setTree(test::treeOnALine(positions));
    showAndWait(view);
    const ui::DendrogramFrame frame = view.frame();
    ASSERT_LT(frame.leafWidth, QFontMetricsF(view.font()).height()) << "names do not fit";
    EXPECT_LE(2.0 * ui::boxplotMarkRadius(frame), frame.leafWidth - 2.0) << "marks kept apart";
    const QImage image = view.viewport()->grab().toImage();
    const auto& layout = view.layout();
    EXPECT_EQ(pixelAt(image, ui::boxplotMarkCenter(frame, layout.x(17))).rgb(),
              view.style().median.rgb());
    for (const int m : {3, 4, 41}) {
        EXPECT_EQ(pixelAt(image, ui::boxplotMarkCenter(frame, layout.x(m))).rgb(),
                  view.style().outlier.rgb())
            << m;
    }
    EXPECT_EQ(pixelAt(image, ui::boxplotMarkCenter(frame, layout.x(20))), view.style().background);
    // The legend sits in the corner below the height axis: inside the view, covering neither
    // the plot nor the leaves' marks.
    const QRectF legend =
        ui::boxplotLegendRect(s, QRectF(view.viewport()->rect()), frame, view.font());
    EXPECT_TRUE(QRectF(view.viewport()->rect()).contains(legend));
    EXPECT_GE(legend.top(), frame.plot.bottom());
    EXPECT_LE(legend.right(), ui::boxplotMarkCenter(frame, 0.5).x() - ui::boxplotMarkRadius(frame));
    EXPECT_TRUE(hasColourIn(image, legend, view.style().outlier));
}

// One far outlier (issue: a dendrogram 20 px tall): on a linear axis every other merge, and the
// cut lines between them, would lie in the plot's bottom pixels. The axis breaks above the
// second-highest merge: below, most of the plot for the bulk; above, the outlier's merge; and
// each cut line can be grabbed apart from the next, however far the outlier.
TEST(DendrogramLayout, AFarOutlierBreaksTheHeightAxisAndKeepsCutLinesApart) {
    for (const double far : {100.0, 1e6}) {
        const std::vector<double> outlier{0.0, 0.5, 1.1, 1.6, 2.3, 3.0, 3.4, far};
        const ui::DendrogramLayout layout(test::treeOnALine(outlier));
        ASSERT_GT(layout.breakHeight(), 0.0) << far;
        // Just above the bulk's highest merge, below the outlier's.
        EXPECT_GT(layout.breakHeight(), layout.height(layout.root() - 1));
        EXPECT_LT(layout.breakHeight(), layout.height(layout.root()));

        ui::DendrogramFrame frame;
        frame.plot = QRectF(40, 10, 300, 200);
        frame.topHeight = layout.topHeight();
        const auto gap = [&](int k) {
            return std::abs(frame.pixelY(layout.cutHeight(k)) -
                            frame.pixelY(layout.cutHeight(k + 1)));
        };
        EXPECT_LT(gap(3), 4.0) << far << ": on one linear axis the cut lines nearly touch";
        frame.breakHeight = layout.breakHeight();
        for (int k = 1; k <= 4; ++k) EXPECT_GT(gap(k), 10.0) << far << " " << k;  // 2 grabs
        // A drag reads heights back through the same axis, either side of the break.
        for (const double h : {0.0, 0.7, 3.0, 0.5 * far}) {
            EXPECT_NEAR(frame.heightAt(frame.pixelY(h)), h, 1e-9 * layout.topHeight());
        }
        for (int k = 1; k <= 4; ++k) {  // (below 5, merges at equal heights make cuts ambiguous)
            EXPECT_EQ(layout.clustersAtHeight(frame.heightAt(frame.pixelY(layout.cutHeight(k)))),
                      k);
        }
    }
    // Evenly spread members read well on one axis.
    EXPECT_EQ(ui::DendrogramLayout(test::treeOnALine({0, 1, 2, 3, 4, 5})).breakHeight(), 0.0);
}

TEST(DendrogramExport, ABrokenAxisLabelsTheBulksHeightsAndTheOutliers) {
    workbench::MemberSelection s;
    const std::vector<double> outlier{0.0, 0.5, 1.1, 1.6, 2.3, 3.0, 3.4, 100.0};
    s.setMembers(test::figuresOnALine(outlier));
    s.setTree(test::treeOnALine(outlier));
    // Kept in the test output, to look at.
    const QString path = QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/dendrogram_far_outlier.svg");
    QString error;
    ASSERT_TRUE(ui::writeDendrogramSvg(s, path, &error)) << error.toStdString();
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString svg = QString::fromUtf8(file.readAll());
    // Round heights of the bulk (merges up to about 2) and of the outlier's (about 97).
    EXPECT_TRUE(svg.contains(">1<") && svg.contains(">2<")) << "the bulk's heights";
    EXPECT_TRUE(svg.contains(QRegularExpression(">(80|90|100|95)<"))) << "the outlier's height";
}

// In the view: with the axis broken by a far outlier, the default cut line is grabbed and
// dragged across the bulk's merges by the mouse, as on any dendrogram.
TEST(DendrogramView, WithAFarOutlierTheCutLineIsDraggedAcrossTheBulk) {
    workbench::MemberSelection s;
    const std::vector<double> outlier{0.0, 0.5, 1.1, 1.6, 2.3, 3.0, 3.4, 100.0};
    s.setMembers(test::figuresOnALine(outlier));
    s.setTree(test::treeOnALine(outlier));
    s.setClusterCount(4);
    ui::DendrogramView view(&s);
    view.resize(600, 260);
    showAndWait(view);
    view.grab().save(QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/dendrogram_far_outlier.png"));
    const auto& layout = view.layout();
    const ui::DendrogramFrame frame = view.frame();
    ASSERT_GT(frame.breakHeight, 0.0);
    const int x = static_cast<int>(frame.plot.right()) - 10;
    const int from = static_cast<int>(std::lround(frame.pixelY(layout.cutHeight(4))));
    QTest::mousePress(view.viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(x, from));
    const int to = static_cast<int>(std::lround(frame.pixelY(layout.cutHeight(3))));
    QTest::mouseMove(view.viewport(), QPoint(x, to));
    QTest::mouseRelease(view.viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(x, to));
    EXPECT_EQ(s.clusterCount(), 3);
}
