#include "engine/time_series.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <mutex>
#include <set>

#include "engine/floor_map.h"
#include "engine/workbench_reading.h"
#include "preprocessing/cluster_identity.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/similarity.h"
#include "preprocessing/streaming_preprocess.h"

namespace ensil::engine {
namespace {

std::optional<std::size_t> parseIndex(const std::string& text) {
    std::size_t value = 0;
    const char* end = text.data() + text.size();
    const auto [at, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || at != end) return std::nullopt;
    return value;
}

}  // namespace

std::optional<StepRange> parseStepRange(const std::string& text, std::size_t steps,
                                        const std::string& what, std::string& problem) {
    const std::string refused = "--times '" + text + "' is refused: ";
    const std::string has = what + " has " + std::to_string(steps) +
                            (steps == 1 ? " time step" : " time steps") +
                            (steps == 0 ? "" : ", 0 to " + std::to_string(steps - 1));
    if (steps == 0) {
        problem = refused + what +
                  " has no time steps (no dimension besides the members and the grid's axes)";
        return std::nullopt;
    }
    if (text == "all") return StepRange{0, steps - 1};
    const std::size_t colon = text.find(':');
    const auto first =
        colon == std::string::npos ? std::nullopt : parseIndex(text.substr(0, colon));
    const auto last =
        colon == std::string::npos ? std::nullopt : parseIndex(text.substr(colon + 1));
    if (!first || !last) {
        problem = refused +
                  "it must be 'all' or A:B, the first and last time index (both "
                  "included, from 0), e.g. 0:3";
        return std::nullopt;
    }
    if (*first > *last) {
        problem = refused + "the first step " + std::to_string(*first) + " comes after the last " +
                  std::to_string(*last);
        return std::nullopt;
    }
    if (*last >= steps) {
        problem = refused + has;
        return std::nullopt;
    }
    return StepRange{*first, *last};
}

std::vector<int> matchStepIdentities(const prep::MergeTree& tree, int k,
                                     const std::vector<int>& labels,
                                     const std::vector<int>& previous) {
    const bool known = std::any_of(previous.begin(), previous.end(), [](int i) { return i >= 0; });
    if (!known) return prep::identitiesFromTree(tree, k);
    return prep::matchIdentities(labels, k, previous);
}

std::vector<int> previousIdentitiesByName(const std::vector<std::string>& previousMembers,
                                          const std::vector<int>& previousIdentities,
                                          const std::vector<std::string>& members) {
    std::map<std::string, int> byName;
    for (std::size_t m = 0; m < previousMembers.size() && m < previousIdentities.size(); ++m) {
        byName.emplace(previousMembers[m], previousIdentities[m]);
    }
    std::vector<int> result;
    result.reserve(members.size());
    for (const std::string& name : members) {
        const auto at = byName.find(name);
        result.push_back(at == byName.end() ? -1 : at->second);
    }
    return result;
}

StepClusters clusterTimeStep(const StepClusteringRequest& request, const std::stop_token& stop,
                             const data::Progress& progress) {
    StepClusters step;
    prep::DistanceMatrix distances;
    std::optional<StreamedSource> streamed;
    data::EnsembleDescription description;
    if (request.memoryLimit != 0) {
        description = data::describeEnsemble(request.selection);
        streamed = streamedSourceFor(request.selection, description, request.memoryLimit);
    }
    std::vector<std::string> names;
    if (streamed) {
        // The distances need only the slab pass (preprocessing/streaming_preprocess.h).
        const prep::SlabSums sums =
            prep::sumSlabs(request.selection, description, streamed->plan.slabs, request.isovalue,
                           stop, [&](double f) { data::report(progress, f); });
        prep::StreamedEnsemble concluded;
        (void)prep::concludeSlabs(sums, request.selection, description, {}, concluded);
        distances = std::move(concluded.distances);
        names = std::move(concluded.memberNames);
    } else {
        data::Ensemble ensemble = data::openEnsemble(
            request.selection, stop, [&](double f) { data::report(progress, 0.5 * f); });
        data::leaveOutMembersWithoutData(ensemble);
        distances = prep::computeDistanceMatrix(ensemble, request.isovalue, stop, [&](double f) {
            data::report(progress, 0.5 + 0.5 * f);
        });
        for (const data::Member& member : ensemble.members) names.push_back(member.name);
    }
    const prep::MergeTree tree = prep::clusterMembers(distances, request.linkage, stop);
    const int k = std::clamp(request.k, 1, static_cast<int>(names.size()));
    const std::vector<int> labels = prep::clusterLabels(tree, k);
    // Named as the workbench names them ("member 3" for one the file leaves unnamed).
    for (std::size_t m = 0; m < names.size(); ++m) {
        step.members.push_back(names[m].empty() ? "member " + std::to_string(m + 1) : names[m]);
    }
    const std::vector<int> previous =
        previousIdentitiesByName(request.previousMembers, request.previousIdentities, step.members);
    step.memberIdentities =
        prep::memberIdentities(labels, matchStepIdentities(tree, k, labels, previous));
    data::report(progress, 1.0);
    return step;
}

std::optional<std::pair<float, float>> floorScaleOverSteps(const data::DataSelection& selection,
                                                           const StepRange& steps,
                                                           const gl::RenderSettings& settings,
                                                           const std::stop_token& stop) {
    if (steps.count() < 2 || settings.floor == gl::FloorContent::None ||
        settings.floor == gl::FloorContent::ProbabilityMaximum) {
        return std::nullopt;
    }
    std::optional<std::pair<float, float>> scale;
    for (std::size_t t = steps.first; t <= steps.last; ++t) {
        data::DataSelection step = selection;
        step.timeIndex = t;
        std::vector<std::string> withoutData;
        const auto ensemble = withoutMembersWithoutData(
            std::make_shared<const data::Ensemble>(data::openEnsemble(step, stop)), withoutData);
        const prep::EnsembleMoments moments = prep::computeEnsembleMoments(*ensemble, stop);
        const ColumnMaxima maxima = computeColumnMaxima(*ensemble, moments.mean, stop);
        const gl::FloorMap floor = floorMapFor(*ensemble, moments.mean, maxima, settings);
        if (floor.values.empty()) continue;
        scale = scale ? std::pair{std::min(scale->first, floor.minimum),
                                  std::max(scale->second, floor.maximum)}
                      : std::pair{floor.minimum, floor.maximum};
    }
    return scale;
}

std::vector<TimeStepResult> preprocessTimeSeries(const TimeSeriesRequest& request,
                                                 const PreprocessNotice& notice,
                                                 const std::stop_token& stop,
                                                 const data::Progress& progress,
                                                 const StepDone& stepDone) {
    std::vector<TimeStepResult> steps;
    const std::size_t count = request.steps.count();
    // The job's workers report as they finish; the whole series' fraction only rises.
    std::mutex progressMutex;
    double reported = 0.0;
    const auto reportStep = [&](std::size_t done, double fraction) {
        if (!progress) return;
        const std::lock_guard lock(progressMutex);
        const double overall = (static_cast<double>(done) + std::clamp(fraction, 0.0, 1.0)) /
                               static_cast<double>(count);
        if (overall < reported) return;
        reported = overall;
        progress(overall);
    };
    PreprocessRequest preprocess = request.preprocess;
    std::vector<std::string> previousMembers;
    std::vector<int> previousIdentities;
    std::set<std::string> said;  // a note true of every step (few levels) is said once
    for (std::size_t s = 0; s < count; ++s) {
        data::throwIfStopped(stop);
        TimeStepResult step;
        step.index = request.steps.first + s;
        data::DataSelection selection = request.selection;
        selection.timeIndex = step.index;
        auto ensemble = std::make_shared<const data::Ensemble>(data::openEnsemble(selection, stop));
        const data::TimeSteps& times = ensemble->timeSteps;
        step.time =
            step.index < times.count() ? times.labels[step.index] : std::to_string(step.index);
        preprocess.sourceKey = data::sourceIdentity(selection);
        const auto stepNotice = [&](const std::string& kind, const std::string& text) {
            if (said.insert(kind + ": " + text).second) notice(kind, step.time + ": " + text);
        };
        try {
            step.result = preprocessEnsemble(std::move(ensemble), preprocess, stepNotice, stop,
                                             [&](double fraction) { reportStep(s, fraction); });
        } catch (const PreprocessRefused& e) {
            throw PreprocessRefused(
                "at " + step.time + " (time index " + std::to_string(step.index) + "): " + e.what(),
                e.exitCode());
        }
        // Every later step at the first one's isovalue.
        preprocess.isovalue = step.result.meshes.isovalue;
        std::vector<std::string> members;
        for (const data::Member& m : step.result.ensemble->members) members.push_back(m.name);
        const std::vector<int> previous =
            previousIdentitiesByName(previousMembers, previousIdentities, members);
        step.identities =
            matchStepIdentities(step.result.tree, step.result.k, step.result.labels, previous);
        step.memberIdentities = prep::memberIdentities(step.result.labels, step.identities);
        numberClusters(step.result, step.identities);
        previousMembers = std::move(members);
        previousIdentities = step.memberIdentities;
        reportStep(s, 1.0);
        if (stepDone) stepDone(step);
        steps.push_back(std::move(step));
    }
    return steps;
}

}  // namespace ensil::engine
