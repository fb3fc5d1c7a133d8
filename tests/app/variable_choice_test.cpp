// Another variable of the files from the Ensemble panel, without File > Open: the panel lists
// what the files hold once they are on screen, and a pick opens that variable in place.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QSignalSpy>
#include <QTest>

#include "app/main_window.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "widgets/ensemble_info_panel.h"
#include "workbench/isovalue_session.h"

using namespace ensil;

TEST(VariableChoice, TheEnsemblePanelOpensAnotherVariableOfTheFilesInPlace) {
    const test::ScopedCacheHome cache;
    app::MainWindow window;
    ASSERT_TRUE(test::showWorkbench(window, {1100, 700}));
    QSignalSpy loaded(&window, &app::MainWindow::ensembleLoaded);
    data::DataSelection selection;
    selection.paths = {ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc"};
    selection.timeIndex = 2;
    window.openFiles(selection);
    ASSERT_TRUE(loaded.wait(30000));
    EXPECT_EQ(window.overview()->ensemble->variable, "t");  // the default (variable_choice.h)
    // The variables of the file came with it: the variable is a list of both.
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return window.infoPanel()->variableChoice() != nullptr; }, 30000));
    QComboBox* choice = window.infoPanel()->variableChoice();
    ASSERT_EQ(choice->count(), 2);
    EXPECT_EQ(choice->currentData().toString(), "t");  // the item reads "t (Temperature)"
    EXPECT_TRUE(window.infoPanel()->text().contains("Variable: t"))
        << window.infoPanel()->text().toStdString();

    // A pick, as a user makes it: the same file and time step, with z.
    const int z = choice->findData(QStringLiteral("z"));
    ASSERT_GE(z, 0);
    choice->setCurrentIndex(z);
    emit choice->activated(z);
    ASSERT_TRUE(loaded.wait(30000));
    EXPECT_EQ(window.overview()->ensemble->variable, "z");
    const data::DataSelection shown = window.captureSession().data;
    EXPECT_EQ(shown.variable, "z");
    EXPECT_EQ(shown.timeIndex, 2U);
    // The list follows: z is now the one shown.
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return window.infoPanel()->variableChoice() != nullptr &&
                   window.infoPanel()->variableChoice()->currentData().toString() == "z";
        },
        30000));
}
