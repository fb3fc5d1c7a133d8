// The preprocessing pipeline on the paper-sized ensemble: 50 members + mean, 256 x 128 x 16,
// wind-speed-like demo, one isovalue. Prints the median time of each stage over several runs,
// triangles, bytes per vertex, GPU bytes and peak memory.
//
//   ensil_preprocess_benchmark [--runs N] [--iso X] [--error CELLS] [--no-decimation]
//                              [--no-vtk-decimation]
// (--no-vtk-decimation leaves out VTK's decimation and curvatures, which take most of the run.)
#include <meshoptimizer.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/working_memory.h"
#include "hausdorff.h"
#include "meshoptimizer_reference.h"
#include "preprocessing/clustering.h"
#include "preprocessing/decimation.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/isosurface_pipeline.h"
#include "preprocessing/marching_cubes.h"
#include "preprocessing/similarity.h"
#include "timing.h"
#include "vtk_reference.h"

using ensil::bench::median;
using ensil::bench::medianMs;

int main(int argc, char** argv) {
    int runs = 5;
    std::size_t vtkMembers = 51;
    bool vtkDecimation = true;
    ensil::prep::PipelineOptions options;
    options.isovalue = 30.0F;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else if (a == "--iso" && i + 1 < argc)
            options.isovalue = std::strtof(argv[++i], nullptr);
        else if (a == "--error" && i + 1 < argc)
            options.maxErrorCells = std::strtof(argv[++i], nullptr);
        else if (a == "--no-decimation")
            options.decimate = false;
        else if (a == "--no-vtk-decimation")
            vtkDecimation = false;
    }
    using Clock = std::chrono::steady_clock;
    auto t0 = Clock::now();
    const auto demo = ensil::data::makeDemoEnsemble({});
    const double generate = std::chrono::duration<double>(Clock::now() - t0).count();
    // As ensil does (data/working_memory.h), from here on. Set after the demo is made: the
    // generator's per-thread scratch (4 MiB), which the policy would keep, is the benchmark's
    // own, not the preprocessing's, and would count in the peak memory below.
    ensil::data::keepWorkingMemoryForReuse();
    const ensil::data::Ensemble& e = demo.ensemble;
    const ensil::data::DisplayFrame frame(e.grid, 1.0F);

    std::vector<double> moments, meshes, decimation, attributes, similarity, clustering, total;
    ensil::prep::IsovalueMeshes result;
    for (int r = 0; r < runs; ++r) {
        t0 = Clock::now();
        const auto m = ensil::prep::computeEnsembleMoments(e);
        moments.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
        result = {};  // the last run's meshes are not held while the next are built
        result = ensil::prep::buildIsovalueMeshes(e, m, frame, options);
        meshes.push_back(result.seconds.meshes);
        decimation.push_back(result.seconds.decimation);
        attributes.push_back(result.seconds.attributes);
        auto t1 = Clock::now();
        const auto distances = ensil::prep::computeDistanceMatrix(e, options.isovalue);
        similarity.push_back(std::chrono::duration<double>(Clock::now() - t1).count());
        t1 = Clock::now();
        const auto tree = ensil::prep::clusterMembers(distances);
        (void)ensil::prep::clusterLabels(tree, 5);
        clustering.push_back(std::chrono::duration<double>(Clock::now() - t1).count());
        total.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf(
        "ensemble: %zu members + mean, %zu x %zu x %zu, isovalue %.1f (generated in %.2f s)\n",
        e.memberCount(), e.grid.nx(), e.grid.ny(), e.grid.nz(), options.isovalue, generate);
    std::printf("median of %d runs (seconds):\n", runs);
    std::printf("  moments (mean + variance) %8.3f\n", median(moments));
    std::printf("  marching cubes            %8.3f\n", median(meshes));
    std::printf("  decimation (%s, %.2f cells) %8.3f\n", options.decimate ? "on" : "off",
                options.maxErrorCells, median(decimation));
    std::printf("  attributes + packing      %8.3f\n", median(attributes));
    std::printf("  similarity matrix         %8.3f\n", median(similarity));
    std::printf("  clustering (average, k=5) %8.3f\n", median(clustering));
    std::printf("  whole preprocess          %8.3f  (goal <= 0.5 s; the paper: about 300 s)\n",
                median(total));
    std::printf("triangles: %zu extracted, %zu after decimation (%.1f %%); vertices %zu\n",
                result.trianglesExtracted, result.triangles,
                100.0 * static_cast<double>(result.triangles) /
                    static_cast<double>(result.trianglesExtracted),
                result.vertices);
    std::printf("decimation error estimate: %.3f cells (worst mesh)\n", result.worstErrorCells);
    std::printf("bytes per vertex: %zu; GPU bytes: %.2f MiB for %zu meshes (goal <= 16 MiB)\n",
                sizeof(ensil::data::PackedVertex),
                static_cast<double>(result.gpuBytes()) / (1024.0 * 1024.0), e.memberCount() + 1);
    const double ensembleMiB = static_cast<double>(e.bytes()) / (1024.0 * 1024.0);
    const double peakMiB = static_cast<double>(usage.ru_maxrss) / 1024.0;
    std::printf(
        "peak memory (max RSS, whole process): %.1f MiB = %.3f x the ensemble's %.0f MiB "
        "(goal <= 2 x)\n",
        peakMiB, peakMiB / ensembleMiB, ensembleMiB);

    // Decimation quality and speed on a few members, against meshoptimizer's simplifier under the
    // same bound: every full-resolution vertex's distance to the decimated surface (the
    // one-sided Hausdorff distance, in grid cells), triangles kept, and the time of each alone
    // on one core, alternating so that both see the same load.
    const float bound = options.decimate ? options.maxErrorCells : 0.0F;
    const std::size_t sampled = std::min<std::size_t>(5, e.memberCount());
    std::vector<ensil::data::TriangleMesh> fullMeshes;
    for (std::size_t m = 0; m < sampled; ++m) {
        const std::size_t member = m * e.memberCount() / sampled;
        fullMeshes.push_back(
            ensil::prep::extractIsosurface(e.grid, e.members[member].values, options.isovalue));
    }
    struct Quality {
        double worst = 0.0, mean = 0.0;
        std::size_t triangles = 0;
        std::vector<double> seconds;  // per run, all sampled members
    } ensilRun, meshoptRun;
    for (int r = 0; r < runs; ++r) {
        ensilRun.seconds.push_back(0.0);
        meshoptRun.seconds.push_back(0.0);
        for (const auto& full : fullMeshes) {
            auto t = Clock::now();
            const auto reduced = ensil::prep::decimateMesh(full, bound);
            ensilRun.seconds.back() += std::chrono::duration<double>(Clock::now() - t).count();
            t = Clock::now();
            const auto referenceReduced = simplifyWithMeshoptimizer(full, bound);
            meshoptRun.seconds.back() += std::chrono::duration<double>(Clock::now() - t).count();
            if (r > 0) continue;
            for (auto [q, mesh] : {std::pair{&ensilRun, &reduced.mesh},
                                   std::pair{&meshoptRun, &referenceReduced.mesh}}) {
                const SurfaceDistance d = distanceToSurface(full, *mesh);
                q->worst = std::max(q->worst, d.maximum);
                q->mean += d.mean / static_cast<double>(sampled);
                q->triangles += mesh->triangleCount();
            }
        }
    }
    std::printf(
        "decimation quality on %zu members: Hausdorff (full -> decimated) max %.3f cells, "
        "mean %.3f cells; the setting, %.2f cells, bounds the simplification's estimate (%.3f: "
        "a root-mean-square distance to the planes of the triangles merged into a vertex), not "
        "this distance\n",
        sampled, ensilRun.worst, ensilRun.mean, bound, result.worstErrorCells);
    const double msPerSampledMember = 1000.0 / static_cast<double>(sampled);
    std::printf(
        "decimation alone on those members (one core, median of %d): ensil %.1f ms a member, "
        "%zu triangles, Hausdorff max %.3f mean %.3f; meshoptimizer %d.%d (meshopt_simplify) "
        "%.1f ms a member, %zu triangles, Hausdorff max %.3f mean %.3f: ensil is %.2fx as "
        "fast\n",
        runs, msPerSampledMember * median(ensilRun.seconds), ensilRun.triangles, ensilRun.worst,
        ensilRun.mean, MESHOPTIMIZER_VERSION / 1000, MESHOPTIMIZER_VERSION % 1000 / 10,
        msPerSampledMember * median(meshoptRun.seconds), meshoptRun.triangles, meshoptRun.worst,
        meshoptRun.mean, median(meshoptRun.seconds) / median(ensilRun.seconds));

    // Cancel latency: stop the pipeline at several moments, time until it has returned.
    std::vector<double> latencies;
    for (int delayMs : {20, 60, 120, 250, 400}) {
        std::stop_source stop;
        std::chrono::steady_clock::time_point requested;
        std::thread canceller([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
            requested = Clock::now();
            stop.request_stop();
        });
        const auto m = ensil::prep::computeEnsembleMoments(e);
        try {
            (void)ensil::prep::buildIsovalueMeshes(e, m, frame, options, stop.get_token());
        } catch (const ensil::data::Cancelled&) {
        }
        canceller.join();
        if (Clock::now() > requested) {
            latencies.push_back(std::chrono::duration<double>(Clock::now() - requested).count());
        }
    }
    if (!latencies.empty()) {
        std::printf(
            "cancel latency: median %.1f ms, worst %.1f ms over %zu cancels (goal <= 100 ms)\n",
            1000.0 * median(latencies),
            1000.0 * *std::max_element(latencies.begin(), latencies.end()), latencies.size());
    }

    // Marching cubes alone against vtkFlyingEdges3D on the same members, one after another
    // (each parallel inside: ours over z-layers, VTK's through its SMP backend), alternating so
    // that both see the same load.
    const std::size_t vtkCount = std::min(vtkMembers, e.memberCount());
    std::vector<double> oursAlone, vtkAlone;
    std::size_t oursTriangles = 0, vtkTriangles = 0;
    for (int r = 0; r < runs; ++r) {
        const auto t = Clock::now();
        oursTriangles = 0;
        for (std::size_t m = 0; m < vtkCount; ++m) {
            oursTriangles +=
                ensil::prep::extractIsosurface(e.grid, e.members[m].values, options.isovalue)
                    .triangleCount();
        }
        oursAlone.push_back(std::chrono::duration<double>(Clock::now() - t).count());
        const VtkIsosurfaceTime v = timeVtkFlyingEdges(e, options.isovalue, vtkCount);
        vtkAlone.push_back(v.seconds);
        vtkTriangles = v.triangles;
    }
    std::printf(
        "marching cubes alone on %zu members (median of %d): ensil %.3f s (%zu triangles), "
        "vtkFlyingEdges3D %.3f s (%zu triangles): ensil is %.2fx as fast\n",
        vtkCount, runs, median(oursAlone), oursTriangles, median(vtkAlone), vtkTriangles,
        median(vtkAlone) / median(oursAlone));

    if (!vtkDecimation) return 0;
    // The same work with VTK's filters, decimating to the triangle count reached above.
    const std::size_t perMember = result.triangles / (e.memberCount() + 1);
    const VtkReferenceTimes vtk = runVtkReference(e, options.isovalue, vtkCount, perMember);
    const double scale = static_cast<double>(e.memberCount() + 1) / static_cast<double>(vtkCount);
    const double vtkTotal = (vtk.isosurface + vtk.decimation + vtk.curvature) * scale;
    std::printf("VTK reference on %zu members (seconds, scaled to %zu meshes):\n", vtkCount,
                e.memberCount() + 1);
    std::printf("  vtkFlyingEdges3D          %8.3f\n", vtk.isosurface * scale);
    std::printf("  vtkQuadricDecimation      %8.3f  (%zu -> %zu triangles)\n",
                vtk.decimation * scale, vtk.trianglesIn, vtk.trianglesOut);
    std::printf("  vtkCurvatures (max + min) %8.3f\n", vtk.curvature * scale);
    std::printf("  total                     %8.3f\n", vtkTotal);
    const double ours = median(meshes) + median(decimation) + median(attributes);
    std::printf(
        "ratio VTK / ensil (meshes + decimation + attributes): %.1fx (goal >= 50x); "
        "vtkFlyingEdges3D / ensil's marching cubes stage: %.2fx\n",
        vtkTotal / ours, vtk.isosurface * scale / median(meshes));
    return 0;
}
