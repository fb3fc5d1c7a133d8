// Writing the demo's surfaces for other tools (engine/surface_export.h): the paper-sized demo
// (50 members, 256 x 128 x 16) preprocessed once at 30 m/s, then its 50 member surfaces and the
// mean (51, the workbench's default view; --context adds the three summary surfaces) written
// in each format. Prints the median of --runs writes per format and the bytes written.
// Usage: ensil_export_benchmark [--runs N] [--context] [--out DIR]
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include "data/demo_ensemble.h"
#include "data/working_memory.h"
#include "engine/preprocess_run.h"
#include "engine/surface_export.h"
#include "tests/benchmarks/timing.h"

int main(int argc, char** argv) {
    using namespace ensil;
    data::keepWorkingMemoryForReuse();
    int runs = 5;
    bool context = false;
    std::filesystem::path out = std::filesystem::temp_directory_path() / "ensil-export-benchmark";
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else if (std::strcmp(argv[i], "--context") == 0) {
            context = true;
        } else if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
            out = argv[++i];
        } else {
            std::fprintf(stderr, "usage: %s [--runs N] [--context] [--out DIR]\n", argv[0]);
            return 2;
        }
    }
    engine::PreprocessRequest request;
    request.isovalue = 30.0;
    const engine::PreprocessResult r = engine::preprocessEnsemble(
        std::make_shared<const data::Ensemble>(data::makeDemoEnsemble({}).ensemble), request,
        [](const std::string&, const std::string&) {});
    engine::SurfaceSet set = engine::surfaceSetOf(r);
    // The mean is written with the summary surfaces; without --context the other three are
    // left out, so the 51 surfaces are the members' and the mean's.
    data::MeshSet meshes = r.meshes;
    if (!context) {
        meshes.probability = {};
        meshes.bandInner = {};
        meshes.bandOuter = {};
    }
    set.meshes = &meshes;
    std::printf("demo: 50 members, 256 x 128 x 16, isovalue 30, %zu runs per format\n",
                static_cast<std::size_t>(runs));
    for (const auto format : {engine::SurfaceFormat::Vtp, engine::SurfaceFormat::Ply,
                              engine::SurfaceFormat::Obj, engine::SurfaceFormat::Stl}) {
        engine::ExportedSurfaces written;
        const double ms = bench::medianMs(runs, [&] {
            std::filesystem::remove_all(out);
            written = engine::exportSurfaces(set, format, out);
        });
        std::uintmax_t bytes = 0;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(out)) {
            if (entry.is_regular_file()) bytes += entry.file_size();
        }
        std::printf("%s: %zu surfaces, %zu triangles, %.1f MB in %zu files: median %.0f ms\n",
                    engine::surfaceFormatName(format).c_str(), written.surfaces, written.triangles,
                    static_cast<double>(bytes) / 1e6, written.files.size(), ms);
    }
    std::filesystem::remove_all(out);
    return 0;
}
