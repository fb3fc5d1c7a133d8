// File > Export Surfaces in the workbench: what is written follows what the user looks at (the
// selected members, else the visible ones), read back with VTK's reader as ParaView would.
#include <gtest/gtest.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLMultiBlockDataReader.h>

#include <QSignalSpy>
#include <QTest>

#include "app/main_window.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/temp_dir.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

namespace ensil::test {
namespace {

using WorkbenchExport = SmallDemoWorkbench;

// The blocks of an exported .vtm, by name.
std::vector<std::string> blockNames(const QString& vtm) {
    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(vtm.toStdString().c_str());
    reader->Update();
    std::vector<std::string> names;
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    if (blocks == nullptr) return names;
    for (unsigned b = 0; b < blocks->GetNumberOfBlocks(); ++b) {
        names.emplace_back(blocks->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()));
    }
    return names;
}

TEST_F(WorkbenchExport, TheSelectedMembersAreWrittenWithTheMeanForParaView) {
    TempDir dir;
    workbench::MemberSelection& selection = *window.memberSelection();
    selection.setSelection({1, 4});
    QSignalSpy written(&window, &app::MainWindow::surfacesExported);
    window.exportSurfaces(QString::fromStdString((dir.path() / "jet.vtm").string()));
    ASSERT_TRUE(written.count() > 0 || written.wait(60000));
    const QStringList files = written.takeFirst().at(0).toStringList();
    ASSERT_FALSE(files.isEmpty());
    EXPECT_TRUE(files.front().endsWith("/jet.vtm")) << files.front().toStdString();
    const std::vector<std::string> names = blockNames(files.front());
    ASSERT_GE(names.size(), 3u);
    EXPECT_EQ(names[0], "member 2");
    EXPECT_EQ(names[1], "member 5");
    EXPECT_EQ(names[2], "mean");
}

TEST_F(WorkbenchExport, WithoutASelectionTheVisibleMembersAreWritten) {
    TempDir dir;
    workbench::MemberSelection& selection = *window.memberSelection();
    selection.clearSelection();
    selection.setMemberVisible(0, false);
    QSignalSpy written(&window, &app::MainWindow::surfacesExported);
    window.exportSurfaces(QString::fromStdString((dir.path() / "shown.ply").string()));
    ASSERT_TRUE(written.count() > 0 || written.wait(60000));
    const QStringList files = written.takeFirst().at(0).toStringList();
    int memberFiles = 0;
    for (const QString& f : files) memberFiles += f.contains("shown_member") ? 1 : 0;
    EXPECT_EQ(memberFiles, selection.memberCount() - 1);
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "shown_member01.ply"));
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "shown_member02.ply"));
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "shown_mean.ply"));
}

}  // namespace
}  // namespace ensil::test
