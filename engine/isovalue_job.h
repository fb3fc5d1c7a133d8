// Everything one isovalue needs, in one job: the meshes (read from the disk cache when this data,
// isovalue and display mapping were processed before, built and stored otherwise), the
// similarity matrix, the merge tree and the per-member figures. Shared by the workbench, `ensil
// preprocess` and `ensil render`. A pure function; runs on any thread.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "data/ensemble.h"
#include "preprocessing/clustering.h"
#include "preprocessing/context_surfaces.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/inclusion_depth.h"
#include "preprocessing/isosurface_pipeline.h"
#include "preprocessing/similarity.h"

namespace ensil::engine {

struct IsovalueJobInput {
    const data::Ensemble* ensemble = nullptr;
    const prep::EnsembleMoments* moments = nullptr;
    prep::PipelineOptions options;
    float verticalExaggeration = 1.0F;
    prep::Linkage linkage = prep::Linkage::Average;
    std::optional<std::string> cacheDirectory;  // no cache when empty
    std::string sourceKey;                      // identity of the data, for the cache key
    // Whether the context surfaces' meshes are made (prep::ContextParts); the boxplot's
    // figures and P(f > c) always are. The workbench leaves them out while nothing draws them.
    prep::ContextParts context = prep::ContextParts::FiguresAndSurfaces;
};

struct IsovalueOutcome {
    prep::IsovalueMeshes meshes;
    prep::DistanceMatrix distances;
    prep::MergeTree tree;
    // Per member (preprocessing/member_summaries.h): the distance to the mean member in the
    // similarity measure, and the mean outlyingness over its isosurface's vertices.
    std::vector<double> distancesToMean;
    std::vector<double> meanOutlyingness;
    // The contour boxplot (METHODS.md section 17): depths, median member, band and outliers;
    // its surfaces are in `meshes`.
    prep::ContourBoxplot boxplot;
    std::vector<float> exceedanceColumnMaximum;           // for the floor: max over z of P(f > c)
    std::shared_ptr<const data::FieldValues> exceedance;  // P(f > c), for a section
    bool fromCache = false;
    // Why the results could not be stored in the cache (a read-only folder, a full disk);
    // empty when they were, or when there is no cache.
    std::string cacheWarning;
    std::map<std::string, double> seconds;  // cache_read or meshes/decimation/attributes,
                                            // context_surfaces, similarity, clustering
};

// The context surfaces (P = 0.5, the 50 % band, as input.context asks), the contour boxplot
// and P(f > c) of input.ensemble, in the display space of input.verticalExaggeration. Any
// thread; touches nothing shared.
prep::ContextSurfaces buildContextOf(const IsovalueJobInput& input, const std::stop_token& stop,
                                     const data::Progress& progress);

// The same, added to out.meshes and out; `progress` runs from `from` to `to`.
void addContextOf(const IsovalueJobInput& input, IsovalueOutcome& out, double from, double to,
                  const std::stop_token& stop, const data::Progress& progress);

// Throws Cancelled; data::Error from the steps. A cache that cannot be written is ignored.
IsovalueOutcome runIsovalueJob(const IsovalueJobInput& input, const std::stop_token& stop = {},
                               const data::Progress& progress = {});

// The user's cache folder for meshes (QStandardPaths::CacheLocation + "/meshes").
std::string defaultMeshCacheDirectory();

}  // namespace ensil::engine
