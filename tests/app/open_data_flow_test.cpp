#include "app/open_data_flow.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QTreeWidget>
#include <fstream>

#include "app/main_window.h"
#include "tests/support/temp_dir.h"
#include "widgets/ensemble_info_panel.h"
#include "widgets/open_data_dialog.h"

using namespace ensil;

namespace {
constexpr int kWaitMs = 30000;

// Waits for the answer to the latest probe request.
bool waitForProbe(ui::OpenDataDialog* dialog) {
    if (!dialog->isProbing()) return true;
    QSignalSpy shown(dialog, &ui::OpenDataDialog::probeShown);
    return shown.wait(kWaitMs);
}

QTreeWidgetItem* itemNamed(QTreeWidget* list, const QString& name) {
    const auto found = list->findItems(name, Qt::MatchExactly, 0);
    return found.isEmpty() ? nullptr : found.front();
}
}  // namespace

TEST(OpenDataFlow, ChoosesVariableAndTimeIndexThenLoadsThem) {
    app::MainWindow window;
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    ui::OpenDataDialog* dialog =
        window.chooseData({QStringLiteral(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc")});
    ASSERT_TRUE(waitForProbe(dialog)) << "the headers were not probed";
    EXPECT_TRUE(dialog->errorText().isEmpty()) << dialog->errorText().toStdString();
    QTreeWidget* list = dialog->variableList();
    ASSERT_NE(itemNamed(list, "t"), nullptr);
    ASSERT_NE(itemNamed(list, "z"), nullptr);
    EXPECT_EQ(itemNamed(list, "t")->text(3), "Temperature");
    EXPECT_TRUE(dialog->memberDimensionBox()->currentText().startsWith("number"));
    EXPECT_EQ(dialog->timeIndexBox()->maximum(), 3);
    // Measured against the workbench's memory budget (its default: ERA5 fits whole).
    EXPECT_TRUE(dialog->findChild<QLabel*>("openDataDetails")
                    ->text()
                    .contains(QStringLiteral("Size: 0.6 MiB of values")))
        << dialog->findChild<QLabel*>("openDataDetails")->text().toStdString();
    // The layout follows the new details before the picture is taken.
    QApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QApplication::processEvents();
    dialog->grab().save(QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/open_data_dialog.png"));

    list->setCurrentItem(itemNamed(list, "t"));
    ASSERT_TRUE(waitForProbe(dialog));
    dialog->timeIndexBox()->setValue(2);
    ASSERT_TRUE(waitForProbe(dialog));
    ASSERT_TRUE(dialog->canAccept()) << dialog->errorText().toStdString();
    dialog->accept();
    ASSERT_TRUE(loaded.wait(kWaitMs));
    const data::Ensemble& e = *window.overview()->ensemble;
    EXPECT_EQ(e.variable, "t");
    EXPECT_EQ(e.memberCount(), 10u);
    EXPECT_TRUE(window.infoPanel()->text().contains("Variable: t (Temperature)"));
}

TEST(OpenDataFlow, AFileWithoutMemberDimensionOpensWithTheChosenOne) {
    app::MainWindow window;
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    ui::OpenDataDialog* dialog =
        window.chooseData({QStringLiteral(ENSIL_SHARED_DATA_DIR "/contour.cdf")});
    ASSERT_TRUE(waitForProbe(dialog));
    EXPECT_FALSE(dialog->canAccept()) << "nothing to open before the member dimension is chosen";
    QComboBox* members = dialog->memberDimensionBox();
    const int frtime = members->findData(QStringLiteral("frtime"));
    ASSERT_GE(frtime, 0);
    members->setCurrentIndex(frtime);
    ASSERT_TRUE(waitForProbe(dialog));
    ASSERT_TRUE(dialog->canAccept()) << dialog->errorText().toStdString();
    dialog->accept();
    ASSERT_TRUE(loaded.wait(kWaitMs));
    EXPECT_EQ(window.overview()->ensemble->memberDimension, "frtime");
    EXPECT_EQ(window.overview()->ensemble->memberCount(), 7u);
}

TEST(OpenDataFlow, AGarbageFileIsExplainedInTheDialogAndNothingIsOpened) {
    test::TempDir dir;
    const std::string path = dir.file("broken.nc");
    {
        std::ofstream out(path, std::ios::binary);
        for (int i = 0; i < 2048; ++i) out.put(static_cast<char>((i * 7919) & 0xFF));
    }
    app::MainWindow window;
    QSignalSpy failed(&window, &app::MainWindow::loadingFailed);
    ui::OpenDataDialog* dialog = window.chooseData({QString::fromStdString(path)});
    ASSERT_TRUE(waitForProbe(dialog));
    EXPECT_TRUE(dialog->errorText().contains("broken.nc")) << dialog->errorText().toStdString();
    EXPECT_TRUE(dialog->errorText().contains("not in a format ensil reads"));
    EXPECT_FALSE(dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled());
    const QPointer<ui::OpenDataDialog> closed(dialog);
    dialog->reject();
    // Rejected, the dialog deletes itself; whatever the rejection set off has been handled.
    ASSERT_TRUE(QTest::qWaitFor([&] { return closed.isNull(); }, 60000));
    EXPECT_FALSE(window.isLoading());
    EXPECT_EQ(failed.count(), 0) << "nothing was started";
    EXPECT_EQ(window.overview(), nullptr);
}
