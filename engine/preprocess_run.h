// `ensil preprocess`'s work on an ensemble already read, for one isovalue: the notes and
// warnings it gives, members without data left out, the number of clusters checked against the
// members, the default isovalue and its range check, the isovalue job (cache, meshes,
// similarity, clustering, contour boxplot) and each member's cluster and colour. Shared by the
// command and the Python module (Ensemble.preprocess), so both give the same results and the
// same messages. Any thread.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <vector>

#include "data/ensemble.h"
#include "data/job.h"
#include "preprocessing/clustering.h"
#include "preprocessing/inclusion_depth.h"
#include "preprocessing/isosurface_pipeline.h"
#include "preprocessing/similarity.h"
#include "preprocessing/streaming_preprocess.h"

namespace ensil::engine {

struct PreprocessRequest {
    std::optional<double> isovalue;  // none: the workbench's default for the variable
    int clusters = 5;
    // A default number of clusters is lowered to the members there are; one the user gave is
    // refused when it is more.
    bool clustersGiven = false;
    prep::Linkage linkage = prep::Linkage::Average;
    bool decimate = true;
    double errorCells = 0.25;                   // decimation error bound, in grid cells
    std::optional<std::string> cacheDirectory;  // no cache when empty
    std::string sourceKey;                      // the data's identity, for the cache key
};

struct PreprocessResult {
    // The ensemble the results are of: the one given, less any member without data.
    std::shared_ptr<const data::Ensemble> ensemble;
    std::vector<std::string> membersWithoutData;  // their names, left out of everything below
    prep::IsovalueMeshes meshes;
    prep::DistanceMatrix distances;
    prep::MergeTree tree;
    int k = 0;                // clusters, after lowering a default to the member count
    std::vector<int> labels;  // each member's cluster label of the cut, 0..k-1 (internal)
    // Each member's cluster by the number the legend shows (its stable identity + 1, METHODS.md
    // "Numbers of members and clusters") and the colour it is drawn in, "#rrggbb": from the
    // tree alone (the workbench's for this tree and k), or matched to the previous time step's.
    std::vector<int> clusterNumbers;
    std::vector<std::string> colors;
    std::vector<double> distancesToMean;  // per member; NaN where it has no isosurface
    std::vector<double> meanOutlyingness;
    prep::ContourBoxplot boxplot;
    bool fromCache = false;
    std::map<std::string, double> seconds;  // each stage's
    // Set when the ensemble was preprocessed in slabs (engine/streaming_run.h): the plan
    // it followed. Then `ensemble` holds the description and member names but no values, and
    // the contour boxplot (and its context surfaces) is not made.
    std::optional<prep::StreamingPlan> streaming;
    std::vector<double> rankWorkSeconds;  // under MPI: prep::StreamedEnsemble's
};

// A request the data cannot answer, with the command's exit status: 2 for a bad option (too
// many clusters), 1 for a bad value for this data (an isovalue outside its values).
class PreprocessRefused : public std::runtime_error {
public:
    PreprocessRefused(const std::string& message, int exitCode)
        : std::runtime_error(message), m_exitCode(exitCode) {}
    [[nodiscard]] int exitCode() const { return m_exitCode; }

private:
    int m_exitCode;
};

// The ensemble less its members with no valid value (the shared rule of
// data::leaveOutMembersWithoutData, as in the workbench), their names in `names`; the same
// ensemble, not a copy, when every member has data.
std::shared_ptr<const data::Ensemble> withoutMembersWithoutData(
    std::shared_ptr<const data::Ensemble> ensemble, std::vector<std::string>& names);

// Said along the way: kind is "note" or "warning", text what the command prints after it.
using PreprocessNotice = std::function<void(const std::string& kind, const std::string& text)>;

// The pieces the in-memory and the streaming runs share (engine/streaming_run.h):
// the clusters asked for, checked against the members with data (a default lowered to them,
// PreprocessRefused with exit status 2 for a given count above them)...
int clustersFor(const PreprocessRequest& request, int members, bool someWithoutData);
// ...the isovalue checked against the values' range (PreprocessRefused, exit status 1)...
void checkIsovalueRange(double iso, double minimum, double maximum, const std::string& variable,
                        const std::string& units);
// ...and each member's cluster and colour from r.tree and r.k.
void labelMembers(PreprocessResult& r);
// "#rrggbb" of a cluster identity (gl::clusterColor), as preprocess and the workbench draw it.
std::string identityColorName(int identity);
// Each member's cluster number and colour from the identities of r.labels' clusters.
void numberClusters(PreprocessResult& r, const std::vector<int>& identities);

// Throws PreprocessRefused, data::Error, data::Cancelled. `progress` and `notice` are called on
// the calling thread or on the job's workers.
PreprocessResult preprocessEnsemble(std::shared_ptr<const data::Ensemble> ensemble,
                                    const PreprocessRequest& request,
                                    const PreprocessNotice& notice,
                                    const std::stop_token& stop = {},
                                    const data::Progress& progress = {});

}  // namespace ensil::engine
