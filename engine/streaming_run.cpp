#include "engine/streaming_run.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "data/error.h"
#include "data/platform.h"
#include "data/reader_support.h"
#include "preprocessing/clustering.h"
#include "preprocessing/member_summaries.h"
#include "preprocessing/mesh_cache.h"

namespace ensil::engine {
namespace {

double since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::size_t defaultMemoryLimit() {
    const std::size_t available = data::availableMemoryBytes();
    return available > 0 ? available / 4 * 3 : std::size_t{4} << 30;
}

std::size_t inMemoryPeakBytes(const data::EnsembleDescription& description) {
    return description.bytes() + description.bytes() / 2;
}

std::optional<std::size_t> parseMemorySize(const std::string& text, std::string& problem) {
    const std::string what = "--memory-limit '" + text + "'";
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    std::string unit(end);
    unit.erase(std::remove_if(unit.begin(), unit.end(),
                              [](unsigned char c) { return std::isspace(c) != 0; }),
               unit.end());
    for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    double scale = 0.0;
    for (const auto& [names, factor] :
         {std::pair{std::vector<std::string>{"", "b"}, 1.0},
          std::pair{std::vector<std::string>{"k", "kb", "kib"}, 1024.0},
          std::pair{std::vector<std::string>{"m", "mb", "mib"}, 1048576.0},
          std::pair{std::vector<std::string>{"g", "gb", "gib"}, 1073741824.0},
          std::pair{std::vector<std::string>{"t", "tb", "tib"}, 1099511627776.0}}) {
        if (std::find(names.begin(), names.end(), unit) != names.end()) scale = factor;
    }
    if (end == text.c_str() || scale == 0.0 || !std::isfinite(number) || number <= 0.0) {
        problem = what +
                  " is not a size: give a positive number with K, M, G or T (powers of "
                  "1024), e.g. 1GiB or 512M";
        return std::nullopt;
    }
    const double bytes = number * scale;
    if (bytes > 1e18) {
        problem = what + " is more memory than any machine has";
        return std::nullopt;
    }
    return static_cast<std::size_t>(bytes);
}

void recordStreamedSeconds(std::map<std::string, double>& seconds,
                           const prep::StreamedEnsemble& streamed) {
    seconds["slabs"] = streamed.slabSeconds;
    seconds["members"] = streamed.memberSeconds;
    seconds["meshes"] = streamed.meshes.seconds.meshes;
    seconds["decimation"] = streamed.meshes.seconds.decimation;
    seconds["attributes"] = streamed.meshes.seconds.attributes;
}

bool canStream(const data::DataSelection& selection) {
    return data::readerFor(selection).readsParts();
}

PreprocessResult preprocessStreaming(const data::DataSelection& selection,
                                     const data::EnsembleDescription& d,
                                     const PreprocessRequest& request, std::size_t memoryLimit,
                                     const PreprocessNotice& notice, const std::stop_token& stop,
                                     const data::Progress& progress) {
    StreamBackend here;
    here.run = [&](const prep::StreamingPlan& plan, const prep::PipelineOptions& options,
                   const prep::RangeCheck& checkRange) {
        return std::optional<prep::StreamedEnsemble>(
            prep::streamPreprocess(selection, d, plan, options, 1.0F, checkRange, stop, progress));
    };
    return *preprocessStreamingWith(selection, d, request, memoryLimit, notice, here, stop,
                                    progress);
}

std::optional<PreprocessResult> preprocessStreamingWith(
    const data::DataSelection& selection, const data::EnsembleDescription& d,
    const PreprocessRequest& request, std::size_t memoryLimit, const PreprocessNotice& notice,
    const StreamBackend& backend, const std::stop_token& stop, const data::Progress& progress) {
    (void)progress;
    if (!request.isovalue) {
        throw PreprocessRefused("'" + d.variable +
                                    "' is preprocessed in slabs, and then --iso is needed: the "
                                    "default isovalue is chosen from every value at once",
                                2);
    }
    prep::StreamingPlan plan = prep::planStreaming(d, memoryLimit, 0);
    if (backend.refinePlan) plan = backend.refinePlan(plan);
    PreprocessResult r;
    r.streaming = plan;
    std::size_t thickest = 0;
    for (const data::EnsemblePart& slab : plan.slabs)
        thickest = std::max(thickest, slab.layerCount);
    const std::string how =
        std::to_string(plan.slabs.size()) + (plan.slabs.size() == 1 ? " slab" : " slabs") +
        " of up to " + std::to_string(thickest) + " layers, " + std::to_string(plan.membersAtOnce) +
        (plan.membersAtOnce == 1 ? " member" : " members") + " meshed at a time";
    if (backend.where.empty()) {
        notice("note", "'" + d.variable + "' (" + data::sizeText(static_cast<double>(d.bytes())) +
                           " of values) would take more than the memory limit of " +
                           data::sizeText(static_cast<double>(memoryLimit)) +
                           " in memory: it is preprocessed in " + how +
                           ", without the contour boxplot");
    } else {
        notice("note", "'" + d.variable + "' (" + data::sizeText(static_cast<double>(d.bytes())) +
                           " of values) is preprocessed " + backend.where + ": " + how +
                           " on each within its memory limit of " +
                           data::sizeText(static_cast<double>(memoryLimit)) +
                           ", without the contour boxplot");
    }
    if (const auto note = data::fewLevelsWarning(d.grid)) notice("note", *note);
    for (const std::string& note : d.warnings) notice("warning", note);
    prep::PipelineOptions options;
    options.isovalue = static_cast<float>(*request.isovalue);
    options.decimate = request.decimate;
    options.maxErrorCells = static_cast<float>(request.errorCells);
    const auto start = std::chrono::steady_clock::now();
    std::optional<prep::StreamedEnsemble> ran =
        backend.run(plan, options, [&](double minimum, double maximum) {
            checkIsovalueRange(*request.isovalue, minimum, maximum, d.variable, d.units);
        });
    if (!ran) return std::nullopt;
    prep::StreamedEnsemble& streamed = *ran;
    // The ensemble as the results describe it: names, grid, variable; no values.
    auto ensemble = std::make_shared<data::Ensemble>(data::ensembleDescribedBy(d, selection.paths));
    ensemble->infiniteValues = static_cast<std::size_t>(streamed.infiniteValues);
    if (const auto note = data::infiniteValuesWarning(*ensemble)) notice("warning", *note);
    ensemble->members.clear();
    for (const std::string& name : streamed.memberNames) {
        ensemble->members.push_back(data::Member{name, {}});
    }
    for (const std::size_t m : streamed.membersWithoutData) {
        const std::string& name = d.memberNames.at(m);
        r.membersWithoutData.push_back(name.empty() ? "member " + std::to_string(m + 1) : name);
        notice("warning", data::memberWithoutDataWarning(*ensemble, r.membersWithoutData.back()));
    }
    r.k = clustersFor(request, static_cast<int>(ensemble->memberCount()),
                      !r.membersWithoutData.empty());
    recordStreamedSeconds(r.seconds, streamed);
    r.meshes = std::move(streamed.meshes);
    r.distances = std::move(streamed.distances);
    r.distancesToMean = std::move(streamed.distancesToMean);
    r.rankWorkSeconds = std::move(streamed.rankWorkSeconds);
    if (request.cacheDirectory) {
        // The key the in-memory path stores these meshes under (engine/isovalue_job), so
        // the workbench and `ensil render` find them.
        const std::string key = request.sourceKey +
                                data::membersWithoutDataKey(r.membersWithoutData) + "; " +
                                prep::pipelineKey(options, 1.0F);
        try {
            prep::MeshCache(*request.cacheDirectory).store(key, r.meshes);
        } catch (const data::Error& e) {
            notice("warning", std::string(e.what()) + "; going on without storing the results");
        }
    }
    if (const std::string warning = prep::pairsWithoutOverlapWarning(*ensemble, r.distances);
        !warning.empty()) {
        notice("warning", warning);
    }
    const auto clustering = std::chrono::steady_clock::now();
    r.tree = prep::clusterMembers(r.distances, request.linkage, stop);
    r.seconds["clustering"] = since(clustering);
    labelMembers(r);
    for (const data::PackedMesh& mesh : r.meshes.members) {
        r.meanOutlyingness.push_back(prep::meanOutlyingness(mesh));
    }
    r.seconds["streaming"] = since(start);
    r.ensemble = std::move(ensemble);
    return r;
}

}  // namespace ensil::engine
