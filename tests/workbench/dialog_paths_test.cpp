// Where Save Project starts and what Open lists.
#include "workbench/dialog_paths.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QRegularExpression>
#include <QStringList>

#include "tests/support/temp_dir.h"

namespace ensil::workbench {
namespace {

TEST(DialogPaths, ANewProjectIsSavedBesideItsDataNotAtTheRoot) {
    test::TempDir dir;
    const QString data = QString::fromStdString((dir.path() / "wrfout_d01").string());
    const QString folder = QString::fromStdString(dir.path().string());
    EXPECT_EQ(suggestedProjectPath({}, {}, data), QDir(folder).filePath("session.ensil"));
    EXPECT_EQ(suggestedProjectPath({}, "/tmp", data), "/tmp/session.ensil")
        << "the folder last saved into comes first";
    EXPECT_EQ(suggestedProjectPath("/x/mine.ensil", "/tmp", data), "/x/mine.ensil");
    EXPECT_EQ(suggestedProjectPath({}, {}, {}), QDir(QDir::homePath()).filePath("session.ensil"))
        << "the demo: the home folder, never /";
}

TEST(DialogPaths, TheOpenDialogsFirstFilterListsWrfOutputWithoutAnExtension) {
    const QString first = ensembleFileFilters().split(";;").front();
    QStringList patterns;
    const QRegularExpressionMatch m = QRegularExpression(R"(\((.*)\))").match(first);
    ASSERT_TRUE(m.hasMatch()) << first.toStdString();
    patterns = m.captured(1).split(' ');
    const auto matches = [&](const QString& name) {
        for (const QString& p : patterns) {
            if (QRegularExpression::fromWildcard(p, Qt::CaseInsensitive).match(name).hasMatch()) {
                return true;
            }
        }
        return false;
    };
    EXPECT_TRUE(matches("wrfout_d01_2020-01-01_00:00:00"));
    EXPECT_TRUE(matches("era5.nc"));
    EXPECT_TRUE(matches("gfs.grib2"));
    EXPECT_FALSE(matches("notes.txt"));
}

}  // namespace
}  // namespace ensil::workbench
