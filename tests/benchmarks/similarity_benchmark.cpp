// Speed of the similarity matrix and the member clustering on the paper-sized demo ensemble
// (50 members, 256 x 128 x 16 points): computeDistanceMatrix at isovalue 30, also with missing
// values (the masked path), clusterMembers for each linkage, and clusterMembers on 200 random
// points (the largest N the O(N^3) clustering is meant for). Prints medians over several runs.
//
//   ensil_similarity_benchmark [--runs N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/working_memory.h"
#include "point_distances.h"
#include "preprocessing/clustering.h"
#include "preprocessing/similarity.h"
#include "timing.h"

using ensil::bench::median;
using ensil::bench::medianMs;

namespace {
using Clock = std::chrono::steady_clock;

// Euclidean distances between n random points in the unit cube.
ensil::prep::DistanceMatrix randomPointDistances(std::size_t n) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<double> points(3 * n);
    for (double& c : points) c = coordinate(rng);
    return ensil::bench::euclideanDistances(points, n, 3);
}
}  // namespace

int main(int argc, char** argv) {
    ensil::data::keepWorkingMemoryForReuse();  // as ensil does (data/working_memory.h)
    using namespace ensil;
    int runs = 5;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
    }
    const auto demo = data::makeDemoEnsemble({});
    const auto& e = demo.ensemble;
    std::printf("demo ensemble: %zu members x %zu x %zu x %zu = %zu points, %.1f MiB\n",
                e.memberCount(), e.grid.nx(), e.grid.ny(), e.grid.nz(), e.grid.pointCount(),
                static_cast<double>(e.bytes()) / (1024.0 * 1024.0));

    prep::DistanceMatrix d;
    const double matrixMs = medianMs(runs, [&] { d = prep::computeDistanceMatrix(e, 30.0F); });
    std::printf("computeDistanceMatrix (isovalue 30):       %8.1f ms  (median of %d)\n", matrixMs,
                runs);

    // The masked path: the lowest level missing in every member (like terrain below the
    // surface), so every block of points that touches it needs the mask products.
    data::Ensemble masked = e;
    const std::size_t level = e.grid.nx() * e.grid.ny();
    for (auto& member : masked.members) {
        std::fill_n(member.values.begin(), level, std::numeric_limits<float>::quiet_NaN());
    }
    const double maskedMs = medianMs(runs, [&] { prep::computeDistanceMatrix(masked, 30.0F); });
    std::printf("computeDistanceMatrix, lowest level NaN:  %8.1f ms\n", maskedMs);

    for (const auto linkage : {prep::Linkage::Average, prep::Linkage::Single,
                               prep::Linkage::Complete, prep::Linkage::Ward}) {
        const double ms = medianMs(runs, [&] { prep::clusterMembers(d, linkage); });
        std::printf("clusterMembers N=%zu %-9s               %8.3f ms\n", d.size,
                    prep::linkageName(linkage).c_str(), ms);
    }
    const auto random = randomPointDistances(200);
    for (const auto linkage : {prep::Linkage::Average, prep::Linkage::Ward}) {
        const double ms = medianMs(runs, [&] { prep::clusterMembers(random, linkage); });
        std::printf("clusterMembers N=200 random points %-9s %8.3f ms\n",
                    prep::linkageName(linkage).c_str(), ms);
    }
    return 0;
}
