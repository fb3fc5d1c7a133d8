// An ensemble over time, preprocessed step by step: for each time index of a range, the
// ensemble at that index is read, preprocessed at one isovalue (preprocessEnsemble: cache,
// meshes, similarity, clustering) and its clusters matched to the previous step's, so that a
// group of members keeps its identity, and so its colour, from step to step (METHODS.md
// section 8). Shared by `ensil preprocess --times`, the benchmark and the workbench's
// cluster-over-time strip (which clusters the steps not visited with clusterTimeStep). Any
// thread.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "data/ensemble_reader.h"
#include "data/job.h"
#include "engine/preprocess_run.h"
#include "gl/render_settings.h"
#include "preprocessing/clustering.h"

namespace ensil::engine {

// Time indices first..last, both included.
struct StepRange {
    std::size_t first = 0;
    std::size_t last = 0;
    [[nodiscard]] std::size_t count() const { return last - first + 1; }
    bool operator==(const StepRange&) const = default;
};

// "all" or "A:B" (A and B included, 0-based, A <= B) against `steps` steps. nullopt with
// `problem` set ("--times 2:7 is refused: ... has 4 time steps, 0 to 3") otherwise; `what`
// names the data in that message.
std::optional<StepRange> parseStepRange(const std::string& text, std::size_t steps,
                                        const std::string& what, std::string& problem);

// One cluster identity per cluster label (0..k-1) of `labels`, matched to the identities the
// same members had at the previous step (`previous`: one per member, -1 for a member that had
// none): the matching of a new tree of the same members (prep::matchIdentities; the largest
// total overlap keeps its identity, so a group followed by most of its members keeps its
// colour). With no previous identity at all (the first step) the identities come from the tree
// alone (prep::identitiesFromTree), as `ensil preprocess` gives them.
std::vector<int> matchStepIdentities(const prep::MergeTree& tree, int k,
                                     const std::vector<int>& labels,
                                     const std::vector<int>& previous);

// Each of `members`' previous identity, by name, from the previous step's members and their
// identities; -1 for a member the previous step did not have (no data there).
std::vector<int> previousIdentitiesByName(const std::vector<std::string>& previousMembers,
                                          const std::vector<int>& previousIdentities,
                                          const std::vector<std::string>& members);

struct TimeSeriesRequest {
    data::DataSelection selection;  // its timeIndex is set to each step in turn
    StepRange steps;
    // isovalue: none means the first step's default, kept for every step (a surface keeps its
    // meaning over time). sourceKey is each step's data::sourceIdentity.
    PreprocessRequest preprocess;
};

struct TimeStepResult {
    std::size_t index = 0;  // the time index
    std::string time;       // its label (TimeSteps), ISO 8601 where the file dates it
    // The step's results; colors are those of the matched identities.
    PreprocessResult result;
    std::vector<int> identities;        // per cluster label
    std::vector<int> memberIdentities;  // per member of result.ensemble
};

// Called after each step is done, with it, before the next is read.
using StepDone = std::function<void(const TimeStepResult&)>;

// Throws PreprocessRefused (as preprocessEnsemble, naming the step), data::Error, Cancelled.
// `progress` runs from 0 to 1 over all steps.
std::vector<TimeStepResult> preprocessTimeSeries(const TimeSeriesRequest& request,
                                                 const PreprocessNotice& notice,
                                                 const std::stop_token& stop = {},
                                                 const data::Progress& progress = {},
                                                 const StepDone& stepDone = {});

// One time step's clusters without its surfaces, for the workbench's strip to fill the steps
// not visited (in the background): the step read at its time index, members without data left
// out (as the workbench does), the distance matrix at the isovalue, the merge tree with the
// linkage, its k clusters (k at most the members) and their identities matched to the
// neighbouring step's by member name (matchStepIdentities), so colours agree with the strip's.
// No meshes: a fraction of a step's preprocessing.
struct StepClusteringRequest {
    data::DataSelection selection;  // at the step's time index
    float isovalue = 0.0F;
    int k = 1;
    prep::Linkage linkage = prep::Linkage::Average;
    // The neighbouring step's members and their identities (-1: none); empty for none.
    std::vector<std::string> previousMembers;
    std::vector<int> previousIdentities;
    // The workbench's memory budget: data whose in-memory peak is larger are read in slabs
    // for their distances (engine/workbench_reading.h); 0: read whole.
    std::size_t memoryLimit = 0;
};

struct StepClusters {
    std::vector<std::string> members;   // the step's members with data, by name
    std::vector<int> memberIdentities;  // per member: its cluster's identity
};

// Throws data::Error, data::Cancelled.
StepClusters clusterTimeStep(const StepClusteringRequest& request, const std::stop_token& stop,
                             const data::Progress& progress = {});

// One colour scale for the floor over the steps of a range (ensil render --times), so that a
// colour means the same value in every frame: the smallest and largest value any step's floor
// shows (each step read, its members without data left out, its mean and column maxima made as
// renderEnsemble makes them). nullopt for a floor whose scale is fixed already (none, or a
// probability's 0 to 1) and for a single step. Throws data::Error, data::Cancelled.
std::optional<std::pair<float, float>> floorScaleOverSteps(const data::DataSelection& selection,
                                                           const StepRange& steps,
                                                           const gl::RenderSettings& settings,
                                                           const std::stop_token& stop = {});

}  // namespace ensil::engine
