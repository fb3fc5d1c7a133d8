#include <gtest/gtest.h>

#include <QApplication>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <QToolButton>
#include <cmath>

#include "gl/palette.h"
#include "panel_fixtures.h"
#include "widgets/csv_export.h"
#include "widgets/member_filter_proxy.h"
#include "widgets/member_table_model.h"
#include "widgets/member_table_panel.h"
#include "workbench/member_selection.h"

using namespace ensil;
using ui::MemberTableModel;

namespace {
QList<int> selectedTableMembers(const ui::MemberTablePanel& panel) {
    QList<int> members;
    for (const QModelIndex& row : panel.table()->selectionModel()->selectedRows()) {
        members << panel.memberAtRow(row.row());
    }
    std::sort(members.begin(), members.end());
    return members;
}

// The member table panel of the two groups, shown.
class ShownMemberTable : public ::testing::Test {
protected:
    void SetUp() override {
        test::loadTwoGroups(s);
        panel.resize(500, 300);
        panel.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    }
    workbench::MemberSelection s;
    ui::MemberTablePanel panel{&s};
};
}  // namespace

// A model that breaks the contract: a table whose cells claim children.
class BrokenModel : public QAbstractTableModel {
public:
    int rowCount(const QModelIndex&) const override { return 2; }
    int columnCount(const QModelIndex&) const override { return 2; }
    QVariant data(const QModelIndex&, int) const override { return {}; }
};

TEST(ModelContractCheck, NoticesABrokenModel) {
    BrokenModel broken;
    test::ModelContractCheck check(&broken);
    EXPECT_FALSE(test::ModelContractCheck::failures().isEmpty())
        << "the checker must be able to fail";
}

TEST(MemberTableModel, KeepsQtsModelContractThroughEveryChange) {
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    ui::MemberFilterProxy proxy;
    proxy.setSourceModel(&model);
    test::ModelContractCheck check(&model);
    test::ModelContractCheck proxyCheck(&proxy);
    test::loadTwoGroups(s);
    s.setClusterCount(3);
    s.setMemberVisible(1, false);
    s.soloCluster(0);
    s.setHovered(2);
    s.setHovered(4);
    proxy.sort(MemberTableModel::DistanceToMean);
    proxy.setFilterText(QStringLiteral("m1"));
    auto figures = test::figuresOnALine({1.0, 2.0});
    s.setMembers(figures);
    s.setMembers({});
    EXPECT_TRUE(test::ModelContractCheck::failures().isEmpty())
        << test::ModelContractCheck::failures().join('\n').toStdString();
}

TEST(MemberTableModel, ShowsEveryColumnAndFollowsTheCut) {
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    test::loadTwoGroups(s);
    ASSERT_EQ(model.rowCount(), 6);
    ASSERT_EQ(model.columnCount(), MemberTableModel::ColumnCount);
    const auto cell = [&](int row, int column, int role = Qt::DisplayRole) {
        return model.index(row, column).data(role);
    };
    EXPECT_EQ(cell(3, MemberTableModel::Index).toInt(), 4);
    EXPECT_EQ(cell(3, MemberTableModel::Name).toString(), QStringLiteral("m3"));
    EXPECT_EQ(cell(3, MemberTableModel::Name, Qt::ToolTipRole).toString(), QStringLiteral("m3"))
        << "the whole name, which the table may elide";
    EXPECT_EQ(cell(3, MemberTableModel::Cluster).toInt(), s.clusterNumber(s.clusterOf(3)))
        << "the stable number the legend shows";
    EXPECT_EQ(cell(3, MemberTableModel::Cluster, Qt::DecorationRole).value<QColor>(),
              s.memberColor(3));
    EXPECT_EQ(cell(3, MemberTableModel::DistanceToMean).toString(), QStringLiteral("10.7"));
    EXPECT_EQ(cell(3, MemberTableModel::MeanOutlyingness).toString(), QStringLiteral("21.4"));
    EXPECT_EQ(cell(2, MemberTableModel::MeanOutlyingness).toString(), QStringLiteral("-"));
    EXPECT_EQ(cell(3, MemberTableModel::Visible, Qt::CheckStateRole).toInt(), Qt::Checked);

    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    s.setClusterCount(6);
    ASSERT_EQ(changed.count(), 1);
    EXPECT_EQ(changed.front().at(0).toModelIndex().column(), MemberTableModel::Cluster);
    EXPECT_EQ(cell(3, MemberTableModel::Cluster).toInt(), s.clusterNumber(s.clusterOf(3)))
        << "the stable number the legend shows";
}

namespace {
// Members whose figures are not known yet, as a new ensemble's.
workbench::MemberFigures namesOnly(const QStringList& names) {
    workbench::MemberFigures f;
    f.names = names;
    return f;
}

// Four members with a contour boxplot: member 1 the median (0.9), member 2 an outlier (0.1).
// Member 3's depth (1e-5) reads "1.00e-05", which sorts above "0.900" as text.
workbench::MemberFigures figuresWithABoxplot() {
    workbench::MemberFigures f = test::figuresOnALine({3.0, 20.0, 100.0, 1.0});
    f.depth = {0.45, 0.9, 0.1, 0.00001};
    f.median = 1;
    f.outliers = {2};
    return f;
}
}  // namespace

TEST(MemberTableModel, ShowsEachMembersDepthAndNamesTheMedianAndTheOutliers) {
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    s.setMembers(figuresWithABoxplot());
    const auto cell = [&](int row, int role = Qt::DisplayRole) {
        return model.index(row, MemberTableModel::Depth).data(role);
    };
    const QString dot = QStringLiteral(" ") + QChar(0x00B7) + QStringLiteral(" ");
    EXPECT_EQ(cell(0).toString(), QStringLiteral("0.450"));
    EXPECT_EQ(cell(1).toString(), QStringLiteral("0.900") + dot + QStringLiteral("median"));
    EXPECT_EQ(cell(2).toString(), QStringLiteral("0.100") + dot + QStringLiteral("outlier"));
    EXPECT_EQ(cell(3).toString(), QStringLiteral("1.00e-05"));
    // Sorting uses the number, not the words.
    EXPECT_DOUBLE_EQ(cell(1, MemberTableModel::SortRole).toDouble(), 0.9);
    EXPECT_DOUBLE_EQ(cell(2, MemberTableModel::SortRole).toDouble(), 0.1);
    // The tips say what the words mean.
    EXPECT_TRUE(cell(1, Qt::ToolTipRole).toString().contains("median of the contour boxplot"))
        << cell(1, Qt::ToolTipRole).toString().toStdString();
    EXPECT_TRUE(cell(1, Qt::ToolTipRole).toString().contains("deepest"));
    EXPECT_TRUE(cell(2, Qt::ToolTipRole).toString().contains("outlier of the contour boxplot"))
        << cell(2, Qt::ToolTipRole).toString().toStdString();
    EXPECT_TRUE(cell(2, Qt::ToolTipRole).toString().contains("lower fence"));
    EXPECT_TRUE(cell(0, Qt::ToolTipRole).toString().startsWith("Inclusion depth of m0"))
        << cell(0, Qt::ToolTipRole).toString().toStdString();
    EXPECT_EQ(model.headerData(MemberTableModel::Depth, Qt::Horizontal, Qt::DisplayRole),
              QStringLiteral("Depth"));
    EXPECT_EQ(model.headerData(MemberTableModel::Depth, Qt::Horizontal, Qt::ToolTipRole),
              QStringLiteral("Inclusion depth of the member's isosurface among the others "
                             "(contour boxplot): 1 = most central, 0 = no surface; the deepest "
                             "is the median"));

    // Members without figures yet (a new ensemble): no depth, no median, no outlier.
    s.setMembers(namesOnly({QStringLiteral("a"), QStringLiteral("b")}));
    EXPECT_EQ(cell(0).toString(), QStringLiteral("-"));
    EXPECT_FALSE(cell(0, MemberTableModel::SortRole).isValid()) << "unknown sorts last";
    EXPECT_FALSE(s.hasBoxplot());
    EXPECT_EQ(s.medianMember(), -1);
}

TEST(MemberTableModel, RefusesABoxplotOfOtherMembers) {
    workbench::MemberSelection s;
    workbench::MemberFigures f = figuresWithABoxplot();
    f.depth.pop_back();
    EXPECT_THROW(s.setMembers(f), std::invalid_argument);
    f = figuresWithABoxplot();
    f.median = 4;
    EXPECT_THROW(s.setMembers(f), std::invalid_argument);
    f = figuresWithABoxplot();
    f.outliers = {-1};
    EXPECT_THROW(s.setMembers(f), std::invalid_argument);
}

TEST(MemberFilterProxy, SortsByDepthAsNumbers) {
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    ui::MemberFilterProxy proxy;
    proxy.setSourceModel(&model);
    s.setMembers(figuresWithABoxplot());
    proxy.sort(MemberTableModel::Depth, Qt::DescendingOrder);
    QList<int> order;
    for (int r = 0; r < proxy.rowCount(); ++r) order << proxy.mapToSource(proxy.index(r, 0)).row();
    // 0.9 above 0.45 above 0.100 above 1e-5; as text "1.00e-05" would come first.
    EXPECT_EQ(order, (QList<int>{1, 0, 2, 3}));
}

TEST(MemberTableModel, TheCsvHasTheDepthAndTheMedianAndOutlierFlags) {
    workbench::MemberSelection s;
    s.setMembers(figuresWithABoxplot());
    const QStringList lines = ui::memberTableCsv(s).split(QStringLiteral("\r\n"));
    ASSERT_GE(lines.size(), 5);
    const QStringList header = lines[0].split(',');
    const qsizetype depth = header.indexOf("depth");
    const qsizetype median = header.indexOf("median");
    const qsizetype outlier = header.indexOf("outlier");
    ASSERT_GE(depth, 0) << lines[0].toStdString();
    ASSERT_GE(median, 0) << lines[0].toStdString();
    ASSERT_GE(outlier, 0) << lines[0].toStdString();
    const std::vector<double> depths{0.45, 0.9, 0.1, 0.00001};
    for (int m = 0; m < 4; ++m) {
        const QStringList fields = lines[m + 1].split(',');
        ASSERT_EQ(fields.size(), header.size()) << lines[m + 1].toStdString();
        EXPECT_EQ(fields[depth].toDouble(), depths[static_cast<std::size_t>(m)])
            << "full precision: " << fields[depth].toStdString();
        EXPECT_EQ(fields[median], m == 1 ? "1" : "0") << m;
        EXPECT_EQ(fields[outlier], m == 2 ? "1" : "0") << m;
    }
}

TEST(MemberTablePanel, NamesAndDepthsStayReadableInASideDock) {
    // ERA5's ten members in a panel as wide as the workbench's side dock (460 pixels): the names
    // and the depth column with its words are shown whole, and every header's text fits.
    workbench::MemberSelection s;
    ui::MemberTablePanel panel(&s);
    panel.resize(450, 400);
    panel.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    workbench::MemberFigures f;
    for (int m = 0; m < 10; ++m) {
        f.names << QStringLiteral("member %1").arg(m);
        f.distanceToMean.push_back(0.006396 + 1e-6 * m);
        f.meanOutlyingness.push_back(0.3467 + 0.01 * m);
        f.depth.push_back(0.95 - 0.001 * m);
    }
    f.median = 0;
    f.outliers = {9};
    s.setMembers(f);
    QApplication::processEvents();
    const QTableView* table = panel.table();
    const QHeaderView* header = table->horizontalHeader();
    const QFontMetrics metrics = table->fontMetrics();
    EXPECT_GE(header->sectionSize(MemberTableModel::Name),
              metrics.horizontalAdvance(QStringLiteral("member 0")))
        << "the names are elided to nothing";
    for (const int m : {0, 9}) {
        const QString depth = panel.model()->index(m, MemberTableModel::Depth).data().toString();
        EXPECT_GE(header->sectionSize(MemberTableModel::Depth), metrics.horizontalAdvance(depth))
            << depth.toStdString();
    }
    for (int c = 0; c < MemberTableModel::ColumnCount; ++c) {
        const QString title =
            panel.model()->headerData(c, Qt::Horizontal, Qt::DisplayRole).toString();
        EXPECT_GE(header->sectionSize(c), header->fontMetrics().horizontalAdvance(title))
            << title.toStdString();
    }
    EXPECT_LE(header->length(), table->viewport()->width()) << "no sideways scrolling";
    // The column sorted by gets room for its arrow beside its title.
    const int before = header->sectionSize(MemberTableModel::MeanOutlyingness);
    panel.table()->sortByColumn(MemberTableModel::MeanOutlyingness, Qt::DescendingOrder);
    EXPECT_GE(header->sectionSize(MemberTableModel::MeanOutlyingness),
              header->sectionSizeHint(MemberTableModel::MeanOutlyingness));
    EXPECT_GE(header->sectionSize(MemberTableModel::MeanOutlyingness), before) << "never narrower";
}

TEST(MemberTableModel, TheVisibleCheckboxHidesTheMember) {
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    test::loadTwoGroups(s);
    const QModelIndex box = model.index(4, MemberTableModel::Visible);
    EXPECT_TRUE(model.flags(box).testFlag(Qt::ItemIsUserCheckable));
    EXPECT_FALSE(
        model.flags(model.index(4, MemberTableModel::Name)).testFlag(Qt::ItemIsUserCheckable));
    ASSERT_TRUE(model.setData(box, Qt::Unchecked, Qt::CheckStateRole));
    EXPECT_FALSE(s.isMemberVisible(4));
    EXPECT_EQ(box.data(Qt::CheckStateRole).toInt(), Qt::Unchecked);
    EXPECT_FALSE(model.setData(model.index(4, MemberTableModel::Name), "x", Qt::EditRole));
}

TEST(MemberTableModel, TintsTheHoveredMembersRow) {
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    test::loadTwoGroups(s);
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    s.setHovered(3);
    s.setHovered(1);
    for (int m = 0; m < 6; ++m) {
        EXPECT_EQ(model.index(m, MemberTableModel::Name).data(Qt::BackgroundRole).isValid(), m == 1)
            << m;
    }
    ASSERT_EQ(changed.count(), 3) << "row 3 tinted, row 3 cleared, row 1 tinted";
    EXPECT_EQ(changed.at(1).at(0).toModelIndex().row(), 3);
    EXPECT_EQ(changed.at(2).at(0).toModelIndex().row(), 1);
}

TEST(MemberFilterProxy, SortsNumbersAsNumbersWithUnknownValuesLast) {
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    ui::MemberFilterProxy proxy;
    proxy.setSourceModel(&model);
    s.setMembers(test::figuresOnALine({3.0, 20.0, 100.0, 1.0}));
    proxy.sort(MemberTableModel::MeanOutlyingness, Qt::AscendingOrder);
    QList<int> order;
    for (int r = 0; r < proxy.rowCount(); ++r) order << proxy.mapToSource(proxy.index(r, 0)).row();
    // 6, 40, (member 2 unknown), 2 -> 2, 6, 40, unknown. Text order would put 40 before 6.
    EXPECT_EQ(order, (QList<int>{3, 0, 1, 2}));
}

TEST(MemberFilterProxy, FiltersByNameOrIndex) {
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    ui::MemberFilterProxy proxy;
    proxy.setSourceModel(&model);
    auto figures = test::figuresOnALine({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
    figures.names[11] = QStringLiteral("Control run");
    s.setMembers(figures);
    proxy.setFilterText(QStringLiteral("M1"));
    EXPECT_EQ(proxy.rowCount(), 2);  // m1, m10
    proxy.setFilterText(QStringLiteral("control"));
    ASSERT_EQ(proxy.rowCount(), 1);
    EXPECT_EQ(proxy.mapToSource(proxy.index(0, 0)).row(), 11);
    proxy.setFilterText(QStringLiteral("3"));  // name m3, and the member whose # is 3 (m2)
    EXPECT_EQ(proxy.rowCount(), 2);
    proxy.setFilterText(QString());
    EXPECT_EQ(proxy.rowCount(), 12);
}

TEST_F(ShownMemberTable, SelectingRowsSelectsMembersAndTheOtherWayRound) {
    // Sorted by distance to the mean, descending: row 0 is member 5 (12.0).
    panel.table()->sortByColumn(MemberTableModel::DistanceToMean, Qt::DescendingOrder);
    ASSERT_EQ(panel.memberAtRow(0), 5);

    QSignalSpy changed(&s, &workbench::MemberSelection::selectionChanged);
    panel.table()->selectRow(0);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{5}));
    const QRect row2 = panel.table()->visualRect(panel.proxy()->index(2, MemberTableModel::Name));
    QTest::mouseClick(panel.table()->viewport(), Qt::LeftButton, Qt::ControlModifier,
                      row2.center());
    EXPECT_EQ(s.selectedMembers(), (QList<int>{1, 5})) << "row 2 is member 1 (10.0)";
    EXPECT_EQ(changed.count(), 2);

    s.setSelection({0, 2});
    EXPECT_EQ(selectedTableMembers(panel), (QList<int>{0, 2}));
    EXPECT_EQ(changed.count(), 3) << "showing the selection must not feed back";

    // Members the filter hides stay selected; new rows selected add to them.
    panel.filterBox()->setText(QStringLiteral("m4"));
    ASSERT_EQ(panel.proxy()->rowCount(), 1);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{0, 2})) << "filtering selects nothing";
    panel.table()->selectRow(0);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{0, 2, 4}));
    panel.filterBox()->clear();
    EXPECT_EQ(selectedTableMembers(panel), (QList<int>{0, 2, 4}));
}

TEST_F(ShownMemberTable, HoveringARowHoversItsMember) {
    const QRect row3 = panel.table()->visualRect(panel.proxy()->index(3, MemberTableModel::Name));
    test::moveMouse(panel.table()->viewport(), row3.center());
    EXPECT_EQ(s.hovered(), panel.memberAtRow(3));
    // Below the last row there is no member.
    test::moveMouse(panel.table()->viewport(), QPoint(row3.center().x(), 290));
    EXPECT_EQ(s.hovered(), -1);
}

TEST_F(ShownMemberTable, LongNamesAreElidedInTheMiddleSoTheirEndsStayApart) {
    auto* table = panel.findChild<QTableView*>();
    ASSERT_NE(table, nullptr);
    EXPECT_EQ(table->textElideMode(), Qt::ElideMiddle);
}

TEST(MemberTableModel, TheNumberColumnCountsFromOneWhateverTheFileCallsItsMembers) {
    // Issue 37: ERA5 calls its members "member 0" ... "member 9" (its `number` coordinate); the
    // # column is ensil's number, 1..N as every output gives it, and the name the file's.
    workbench::MemberSelection s;
    MemberTableModel model(&s);
    s.setMembers(namesOnly({QStringLiteral("member 0"), QStringLiteral("member 9")}));
    EXPECT_EQ(model.data(model.index(0, MemberTableModel::Index), Qt::DisplayRole).toInt(), 1);
    EXPECT_EQ(model.data(model.index(1, MemberTableModel::Index), Qt::DisplayRole).toInt(), 2);
    EXPECT_EQ(model.data(model.index(0, MemberTableModel::Name), Qt::DisplayRole).toString(),
              QStringLiteral("member 0"));
    s.setMembers(
        namesOnly({QStringLiteral("2017-01-01T00:00"), QStringLiteral("2017-01-02T00:00")}));
    EXPECT_EQ(model.data(model.index(0, MemberTableModel::Index), Qt::DisplayRole).toInt(), 1);
    EXPECT_EQ(model.data(model.index(1, MemberTableModel::Index), Qt::DisplayRole).toInt(), 2);
}

// Clusters over time (issue 17): one optional column per step, each member's cluster there in
// the strip's number and colour, bold where it moved, empty for a step not clustered yet.
TEST(MemberTableModel, ShowsEachMembersClusterPerStepInTheStripsColours) {
    workbench::MemberSelection s;
    s.setMembers(test::figuresOnALine({0.0, 1.0, 2.0, 3.0}));
    MemberTableModel model(&s);
    test::ModelContractCheck check(&model);
    QSignalSpy steps(&model, &MemberTableModel::stepsChanged);
    model.setSteps({QStringLiteral("2017-01-01T00:00"), QStringLiteral("2017-01-01T12:00"),
                    QStringLiteral("2017-01-02T00:00")});
    ASSERT_EQ(steps.count(), 1);
    EXPECT_EQ(steps.front().front().toInt(), 3);
    model.setStepClusters(0, {0, 0, 1, 1});
    EXPECT_EQ(model.columnCount(), MemberTableModel::ColumnCount) << "hidden until asked for";

    model.setStepColumnsShown(true);
    ASSERT_EQ(model.columnCount(), MemberTableModel::ColumnCount + 3);
    // Member 1 leaves cluster 1 for cluster 2 at the second step, clustered after being shown.
    model.setStepClusters(1, {0, 1, 1, 1});
    const auto cell = [&](int member, int step, int role = Qt::DisplayRole) {
        return model.data(model.index(member, MemberTableModel::stepColumn(step)), role);
    };
    EXPECT_EQ(cell(0, 0).toInt(), 1);
    EXPECT_EQ(cell(2, 0).toInt(), 2);
    EXPECT_EQ(cell(1, 1).toInt(), 2);
    const glm::vec3 second = gl::clusterColor(1);
    EXPECT_EQ(cell(1, 1, Qt::DecorationRole).value<QColor>(),
              QColor::fromRgbF(second.r, second.g, second.b));
    EXPECT_TRUE(cell(1, 1, Qt::FontRole).value<QFont>().bold()) << "member 1 moved at step 1";
    EXPECT_FALSE(cell(2, 1, Qt::FontRole).value<QFont>().bold()) << "member 2 stayed";
    EXPECT_FALSE(cell(1, 0, Qt::FontRole).value<QFont>().bold()) << "nothing before step 0";
    EXPECT_FALSE(cell(0, 2).isValid()) << "step 2 is not clustered yet";
    EXPECT_TRUE(cell(0, 2, Qt::ToolTipRole).toString().contains(QStringLiteral("not clustered")));
    // Sorting by a step's column groups its clusters.
    EXPECT_EQ(cell(1, 1, MemberTableModel::SortRole).toInt(), 2);

    const int header = MemberTableModel::stepColumn(1);
    EXPECT_EQ(model.headerData(header, Qt::Horizontal, Qt::DisplayRole).toString(),
              QStringLiteral("01-01 12:00"))
        << "the year the steps share is left out";
    model.setCurrentStep(1);
    EXPECT_TRUE(model.headerData(header, Qt::Horizontal, Qt::FontRole).value<QFont>().bold());
    EXPECT_FALSE(model.headerData(header - 1, Qt::Horizontal, Qt::FontRole).value<QFont>().bold());

    model.setSteps({QStringLiteral("a"), QStringLiteral("b")});
    EXPECT_EQ(model.columnCount(), MemberTableModel::ColumnCount + 2);
    EXPECT_FALSE(cell(0, 0).isValid()) << "new steps forget the old steps' clusters";
    EXPECT_TRUE(test::ModelContractCheck::failures().isEmpty())
        << test::ModelContractCheck::failures().join('\n').toStdString();
}

TEST_F(ShownMemberTable, PerStepButtonShowsTheStepsColumnsLinkedWithTheSelection) {
    EXPECT_FALSE(panel.stepsButton()->isVisibleTo(&panel)) << "no time steps";
    panel.model()->setSteps({QStringLiteral("t0"), QStringLiteral("t1")});
    panel.model()->setStepClusters(1, {0, 1, 0, 1, 0, 1});
    ASSERT_TRUE(panel.stepsButton()->isVisibleTo(&panel));
    panel.stepsButton()->click();
    ASSERT_EQ(panel.proxy()->columnCount(), MemberTableModel::ColumnCount + 2);
    // A click in a step's column selects that row's member, as anywhere in the table.
    const int row = panel.rowOfMember(3);
    const QRect at =
        panel.table()->visualRect(panel.proxy()->index(row, MemberTableModel::stepColumn(1)));
    ASSERT_FALSE(at.isEmpty());
    QTest::mouseClick(panel.table()->viewport(), Qt::LeftButton, Qt::NoModifier, at.center());
    EXPECT_EQ(s.selectedMembers(), (QList<int>{3}));
    EXPECT_EQ(panel.proxy()->index(row, MemberTableModel::stepColumn(1)).data().toInt(), 2);
    panel.stepsButton()->click();
    EXPECT_EQ(panel.proxy()->columnCount(), MemberTableModel::ColumnCount);
    EXPECT_EQ(s.selectedMembers(), (QList<int>{3})) << "hiding the columns keeps the selection";
}
