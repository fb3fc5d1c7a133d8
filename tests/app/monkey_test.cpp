// The monkey test (issue 37): the real workbench window fed random user actions from a fixed
// seed, a bounded number of them: open the demo, real files and damaged ones, change the
// isovalue, the clusters and the linkage, select and hide members, move the cutting plane,
// step through time, undo and redo, save a project and reopen it, resize, escape, and close
// the window for a new one. Each action waits until the work it started has ended (the window
// idle), and dismisses any message it raised, as a user clicks OK. It passes when nothing
// crashes, hangs or trips AddressSanitizer (CI runs it in the asan build too) and the window
// still answers. ENSIL_MONKEY_ACTIONS and ENSIL_MONKEY_SEED set a longer run by hand
// (CONTRIBUTING.md, "The monkey test"); each action is logged, so a failure names the seed
// and the step.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDialog>
#include <QFileInfo>
#include <QTest>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "app/main_window.h"
#include "session/session_history.h"
#include "tests/app/workbench_helpers.h"
#include "tests/support/scoped_cache_home.h"
#include "tests/support/temp_dir.h"
#include "widgets/cluster_panel.h"
#include "widgets/cutting_plane_panel.h"
#include "widgets/render_toolbar.h"
#include "widgets/time_bar.h"
#include "workbench/member_selection.h"

using namespace ensil;

namespace {

constexpr int kDefaultActions = 2000;
constexpr unsigned kDefaultSeed = 37;
constexpr int kIdleTimeoutMs = 120000;

long environmentNumber(const char* name, long fallback) {
    const char* text = std::getenv(name);
    return text == nullptr ? fallback : std::strtol(text, nullptr, 10);
}

// Real files and damaged ones: every one opens or is refused with a message.
std::vector<std::string> filesToOpen() {
    const std::string real = ENSIL_SHARED_DATA_DIR;
    const std::string bad = ENSIL_SOURCE_DIR "/tests/data/bad/";
    std::vector<std::string> files{real + "/era5_eda_members.nc", real + "/contour.cdf",
                                   real + "/ironProt.vtk"};
    for (const char* name :
         {"infinite_values.nc", "member_without_data.nc", "members_without_overlap.nc",
          "netcdf_truncated_data.nc", "vtk_huge_dimensions.vtk", "vtk_zero_dimension.vtk",
          "vtk_negative_dimensions.vtk"}) {
        files.push_back(bad + name);
    }
    return files;
}

class Monkey {
public:
    Monkey(unsigned seed, const test::TempDir& dir) : m_random(seed), m_dir(dir) {}

    // Runs `count` actions; false (with the step logged) when the window stopped answering.
    bool run(int count) {
        newWindow();
        for (int step = 0; step < count; ++step) {
            const int action = pick(0, 15);
            std::printf("monkey step %d: action %d\n", step, action);
            std::fflush(stdout);
            act(action);
            if (!settle()) {
                std::printf("monkey step %d: the window stayed busy\n", step);
                return false;
            }
        }
        m_window.reset();
        return true;
    }

private:
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_random); }
    double uniform(double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(m_random);
    }

    void newWindow() {
        m_window.reset();
        m_window = std::make_unique<app::MainWindow>();
        m_window->setMissingFileLocator([](const QString&) { return QString(); });
        m_window->resize(pick(500, 1400), pick(400, 1000));
        m_window->show();
        m_window->loadDemo(kDemo);
    }

    void act(int action) {
        app::MainWindow& w = *m_window;
        workbench::MemberSelection* selection = w.memberSelection();
        const int members = selection->memberCount();
        switch (action) {
            case 0:
                w.loadDemo({.members = static_cast<std::size_t>(pick(2, 12)),
                            .nx = 32,
                            .ny = 16,
                            .nz = 6,
                            .seed = static_cast<std::uint64_t>(pick(1, 9))});
                break;
            case 1: {
                const std::vector<std::string> files = filesToOpen();
                data::DataSelection chosen;
                chosen.paths = {
                    files[static_cast<std::size_t>(pick(0, static_cast<int>(files.size()) - 1))]};
                w.openFiles(chosen);
                break;
            }
            case 2: {
                const double iso = w.renderToolbar()->isovalue();
                emit w.renderToolbar()->isovalueChanged(iso * uniform(0.8, 1.2));
                break;
            }
            case 3:
                if (members > 0) selection->setClusterCount(pick(1, members));
                break;
            case 4: {
                auto* linkage = w.clusterPanel()->findChild<QComboBox*>();
                linkage->setCurrentIndex(pick(0, linkage->count() - 1));
                break;
            }
            case 5: {
                QList<int> chosen;
                for (int m = 0; m < members; ++m) {
                    if (pick(0, 3) == 0) chosen << m;
                }
                selection->click(chosen, pick(0, 1) == 0 ? Qt::NoModifier : Qt::ControlModifier);
                break;
            }
            case 6:
                if (members > 0) selection->setMemberVisible(pick(0, members - 1), pick(0, 1) == 0);
                break;
            case 7: {
                ui::CuttingPlanePanel* plane = w.cuttingPlanePanel();
                plane->setOrientation(static_cast<ui::CuttingPlanePanel::Orientation>(pick(0, 2)));
                plane->setPosition(uniform(-1.0, 1.0));
                plane->setCutting(pick(0, 2) != 0);
                break;
            }
            case 8:
                w.timeBar()->step(pick(0, 1) == 0 ? -1 : 1);
                break;
            case 9:
                w.history()->stack()->undo();
                break;
            case 10:
                w.history()->stack()->redo();
                break;
            case 11: {
                const QString path = QString::fromStdString(m_dir.file("monkey.ensil"));
                if (w.saveProjectTo(path)) w.openProject(path);
                break;
            }
            case 12:
                w.resize(pick(300, 1600), pick(250, 1100));
                break;
            case 13:
                w.escape();
                break;
            case 14:
                if (pick(0, 9) == 0) newWindow();  // closing is rarer than the rest
                break;
            default:
                selection->showAll();
                break;
        }
    }

    // Waits until the window is idle, answering what it asks as a user would (OK, Cancel).
    bool settle() {
        app::MainWindow& w = *m_window;
        const bool idle = QTest::qWaitFor(
            [&] {
                for (QDialog* dialog : w.findChildren<QDialog*>()) {
                    if (dialog->isVisible()) dialog->reject();
                }
                return !w.isBusy();
            },
            kIdleTimeoutMs);
        QCoreApplication::processEvents();
        return idle;
    }

    static constexpr data::DemoEnsembleParams kDemo{
        .members = 6, .nx = 32, .ny = 16, .nz = 6, .seed = 5};
    std::mt19937 m_random;
    const test::TempDir& m_dir;
    std::unique_ptr<app::MainWindow> m_window;
};

}  // namespace

TEST(Monkey, RandomUserActionsNeitherCrashNorHangTheWorkbench) {
    test::ScopedCacheHome cache;
    test::TempDir dir;
    const auto actions =
        static_cast<int>(environmentNumber("ENSIL_MONKEY_ACTIONS", kDefaultActions));
    const auto seed = static_cast<unsigned>(environmentNumber("ENSIL_MONKEY_SEED", kDefaultSeed));
    std::printf("monkey: %d actions from seed %u\n", actions, seed);
    Monkey monkey(seed, dir);
    EXPECT_TRUE(monkey.run(actions)) << "seed " << seed;
}
