#include "widgets/csv_export.h"

#include <gtest/gtest.h>

#include <QFile>

#include "panel_fixtures.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

TEST(CsvExport, WritesOneQuotedLinePerMemberWithItsCluster) {
    workbench::MemberSelection s;
    auto figures = test::figuresOnALine({0.25, 10.0, 1.0});
    figures.names[0] = QStringLiteral("run \"A\", control");
    s.setMembers(figures);
    s.setTree(test::treeOnALine({0.25, 10.0, 1.0}));
    s.setClusterCount(2);
    s.setMemberVisible(1, false);
    s.setSelection({2});
    const QStringList lines = ui::memberTableCsv(s).split(QStringLiteral("\r\n"));
    // The cluster's stable number, as the legend shows it.
    const auto number = [&s](int m) { return s.clusterNumber(s.clusterOf(m)); };
    ASSERT_EQ(lines.size(), 5) << "header, three members, the final line break";
    EXPECT_EQ(lines[0],
              "number,name,cluster,distance_to_mean,mean_outlyingness,depth,median,outlier,visible,"
              "selected");
    // No contour boxplot yet: its depth and flags are unknown, so empty.
    EXPECT_EQ(lines[1],
              QStringLiteral("1,\"run \"\"A\"\", control\",%1,0.25,0.5,,,,1,0").arg(number(0)));
    EXPECT_EQ(lines[2], QStringLiteral("2,m1,%1,10,20,,,,0,0").arg(number(1)));
    EXPECT_EQ(lines[3], QStringLiteral("3,m2,%1,1,,,,,1,1").arg(number(2)))
        << "unknown outlyingness is empty";
    EXPECT_EQ(s.clusterOf(0), s.clusterOf(2));
    EXPECT_NE(s.clusterOf(0), s.clusterOf(1));
}

TEST(CsvExport, WritesTheFileOrSaysWhyNot) {
    workbench::MemberSelection s;
    test::loadTwoGroups(s);
    test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("members.csv"));
    ASSERT_TRUE(ui::writeMemberTableCsv(s, path));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(QString::fromUtf8(file.readAll()), ui::memberTableCsv(s));
    QString error;
    EXPECT_FALSE(ui::writeMemberTableCsv(s, "/nonexistent-folder/m.csv", &error));
    EXPECT_TRUE(error.startsWith("Could not write '/nonexistent-folder/m.csv'"))
        << error.toStdString();
}
