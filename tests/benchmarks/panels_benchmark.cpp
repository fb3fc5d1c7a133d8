// Speed of the linked panels with 200 members (the most the O(N^3) clustering is meant for),
// with the member table, the cluster list and the dendrogram shown on one MemberSelection:
//  - relinkage: clusterMembers on the kept distances, then setTree (the panels follow), and
//    the synchronous repaint of the three panels;
//  - a cut-line change: setClusterCount, the renderer's appearance, and the repaint;
//  - a selection change of 20 members and the repaint.
// The 3D view's frame is not included (see ensil_render_benchmark). Prints medians.
//
//   xvfb-run -a ensil_panels_benchmark [--runs N] [--grab FILE.png]
// --grab saves the dendrogram of the 200 members as drawn, to look at.
#include <QApplication>
#include <QTableView>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

#include "data/working_memory.h"
#include "point_distances.h"
#include "preprocessing/clustering.h"
#include "timing.h"
#include "widgets/cluster_panel.h"
#include "widgets/dendrogram_view.h"
#include "widgets/member_table_panel.h"
#include "workbench/member_selection.h"

using ensil::bench::medianMs;
namespace prep = ensil::prep;
namespace ui = ensil::ui;

namespace {
constexpr std::size_t kMembers = 200;

// Distances between members drawn around five centres in 4D, so there are clusters to find.
prep::DistanceMatrix clusteredDistances(std::size_t n) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, 0.3);
    std::uniform_int_distribution<int> centre(0, 4);
    std::vector<double> points(4 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const int c = centre(rng);
        for (std::size_t a = 0; a < 4; ++a)
            points[4 * i + a] = (c == static_cast<int>(a)) + noise(rng);
    }
    return ensil::bench::euclideanDistances(points, n, 4);
}

ensil::workbench::MemberFigures figures(std::size_t n) {
    ensil::workbench::MemberFigures f;
    for (std::size_t m = 0; m < n; ++m) {
        f.names << QStringLiteral("member %1").arg(m + 1);
        f.distanceToMean.push_back(0.01 * static_cast<double>(m));
        f.meanOutlyingness.push_back(0.02 * static_cast<double>(m));
    }
    return f;
}
}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    int runs = 15;
    const char* grabPath = nullptr;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0) runs = std::max(1, std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--grab") == 0) grabPath = argv[i + 1];
    }
    QApplication app(argc, argv);
    ensil::workbench::MemberSelection selection;
    ui::MemberTablePanel table(&selection);
    ui::ClusterPanel clusters(&selection);
    ui::DendrogramView dendrogram(&selection);
    table.resize(400, 600);
    clusters.resize(400, 240);
    dendrogram.resize(1200, 230);
    table.show();
    clusters.show();
    dendrogram.show();
    const prep::DistanceMatrix distances = clusteredDistances(kMembers);
    selection.setMembers(figures(kMembers));
    selection.setTree(prep::clusterMembers(distances));
    QApplication::processEvents();
    const auto repaint = [&] {
        table.table()->viewport()->repaint();
        clusters.list()->viewport()->repaint();
        dendrogram.viewport()->repaint();
    };

    std::printf("panels benchmark: %zu members, median of %d runs\n", kMembers, runs);
    const prep::Linkage linkages[] = {prep::Linkage::Single, prep::Linkage::Complete,
                                      prep::Linkage::Average, prep::Linkage::Ward};
    int next = 0;
    prep::MergeTree tree;
    const double clusterMs =
        medianMs(runs, [&] { tree = prep::clusterMembers(distances, linkages[next++ % 4]); });
    std::vector<prep::MergeTree> trees;
    for (const prep::Linkage linkage : linkages) {
        trees.push_back(prep::clusterMembers(distances, linkage));
    }
    const double setTreeMs =
        medianMs(runs, [&] { selection.setTree(trees[static_cast<std::size_t>(next++ % 4)]); });
    const double relinkMs = medianMs(runs, [&] {
        selection.setTree(prep::clusterMembers(distances, linkages[next++ % 4]));
        repaint();
    });
    std::printf(
        "relinkage: clusterMembers %.2f ms, setTree (panels follow) %.2f ms, "
        "with the repaint %.2f ms\n",
        clusterMs, setTreeMs, relinkMs);

    int k = 2;
    std::size_t sink = 0;
    const double cutMs = medianMs(runs, [&] {
        selection.setClusterCount(k = k % 12 + 2);
        sink += selection.appearance().size();
    });
    const double cutRepaintMs = medianMs(runs, [&] {
        selection.setClusterCount(k = k % 12 + 2);
        sink += selection.appearance().size();
        repaint();
    });
    std::printf("cut-line change: setClusterCount + appearance %.3f ms, with the repaint %.2f ms\n",
                cutMs, cutRepaintMs);

    int offset = 0;
    const auto twenty = [&] {
        QList<int> members;
        for (int i = 0; i < 20; ++i) members << (offset + 7 * i) % static_cast<int>(kMembers);
        ++offset;
        return members;
    };
    const double selectMs = medianMs(runs, [&] {
        selection.setSelection(twenty());
        sink += selection.appearance().size();
    });
    const double selectRepaintMs = medianMs(runs, [&] {
        selection.setSelection(twenty());
        sink += selection.appearance().size();
        repaint();
    });
    std::printf(
        "selection change (20 members): setSelection + appearance %.3f ms, with the "
        "repaint %.2f ms\n",
        selectMs, selectRepaintMs);
    if (grabPath != nullptr) {
        selection.setClusterCount(6);
        selection.setSelection(selection.membersOfCluster(2));
        if (!dendrogram.grab().save(QString::fromLocal8Bit(grabPath))) {
            std::fprintf(stderr, "could not write %s\n", grabPath);
            return 1;
        }
    }
    return sink > 0 ? 0 : 1;
}
