#include "engine/preprocess_run.h"

#include <QColor>
#include <QString>
#include <chrono>

#include "data/ensemble_reader.h"
#include "engine/isovalue_job.h"
#include "gl/palette.h"
#include "preprocessing/cluster_identity.h"
#include "preprocessing/default_isovalue.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/field_statistics.h"
#include "session/session_state.h"

namespace ensil::engine {
namespace {

// Numbers in messages as the command line's text streams write them (6 significant digits).
std::string number(double v) { return QString::number(v, 'g', 6).toStdString(); }

}  // namespace

std::shared_ptr<const data::Ensemble> withoutMembersWithoutData(
    std::shared_ptr<const data::Ensemble> ensemble, std::vector<std::string>& names) {
    if (data::membersWithoutData(*ensemble).empty()) return ensemble;
    auto reduced = std::make_shared<data::Ensemble>(*ensemble);
    names = data::leaveOutMembersWithoutData(*reduced);
    return reduced;
}

int clustersFor(const PreprocessRequest& request, int members, bool someWithoutData) {
    // Not asked for: the workbench's default for this many members.
    if (!request.clustersGiven) return session::defaultClusters(members);
    if (request.clusters <= members) return request.clusters;
    throw PreprocessRefused(
        "--clusters " + std::to_string(request.clusters) + " is more than the " +
            std::to_string(members) + " members of this ensemble" +
            (someWithoutData ? " with data" : "") + "; give at most " + std::to_string(members),
        2);
}

void checkIsovalueRange(double iso, double minimum, double maximum, const std::string& variable,
                        const std::string& units) {
    if (iso <= minimum || iso >= maximum) {
        throw PreprocessRefused("isovalue " + number(iso) + " is outside the values of '" +
                                    variable + "' (" + number(minimum) + " .. " + number(maximum) +
                                    " " + units +
                                    "): no member has a surface there. Choose an isovalue "
                                    "inside that range",
                                1);
    }
}

void labelMembers(PreprocessResult& r) {
    r.labels = prep::clusterLabels(r.tree, r.k);
    numberClusters(r, prep::identitiesFromTree(r.tree, r.k));
}

void numberClusters(PreprocessResult& r, const std::vector<int>& identities) {
    r.clusterNumbers.clear();
    r.colors.clear();
    for (const int identity : prep::memberIdentities(r.labels, identities)) {
        r.clusterNumbers.push_back(identity + 1);
        r.colors.push_back(identityColorName(identity));
    }
}

std::string identityColorName(int identity) {
    const glm::vec3 c = gl::clusterColor(identity);
    return QColor::fromRgbF(c.r, c.g, c.b).name().toStdString();
}

PreprocessResult preprocessEnsemble(std::shared_ptr<const data::Ensemble> given,
                                    const PreprocessRequest& request,
                                    const PreprocessNotice& notice, const std::stop_token& stop,
                                    const data::Progress& progress) {
    PreprocessResult r;
    if (const auto note = data::fewLevelsWarning(given->grid)) notice("note", *note);
    for (const std::string& note : given->warnings) notice("warning", note);  // damaged input
    if (const auto note = data::infiniteValuesWarning(*given)) notice("warning", *note);
    // So every number the results give is one.
    r.ensemble = withoutMembersWithoutData(std::move(given), r.membersWithoutData);
    const data::Ensemble& ensemble = *r.ensemble;
    for (const std::string& name : r.membersWithoutData) {
        notice("warning", data::memberWithoutDataWarning(ensemble, name));
    }
    r.k = clustersFor(request, static_cast<int>(ensemble.memberCount()),
                      !r.membersWithoutData.empty());
    const prep::FieldStatistics stats =
        prep::computeFieldStatistics(ensemble, prep::kIsovalueHistogramBins, stop);
    const double iso = request.isovalue.value_or(prep::defaultIsovalue(ensemble, stats));
    checkIsovalueRange(iso, stats.minimum, stats.maximum, ensemble.variable, ensemble.units);
    IsovalueJobInput job;
    job.ensemble = &ensemble;
    job.options.isovalue = static_cast<float>(iso);
    job.options.decimate = request.decimate;
    job.options.maxErrorCells = static_cast<float>(request.errorCells);
    job.linkage = request.linkage;
    job.cacheDirectory = request.cacheDirectory;
    // Meshes of fewer members than the file holds must not be taken for the file's.
    job.sourceKey = request.sourceKey + data::membersWithoutDataKey(r.membersWithoutData);
    const auto start = std::chrono::steady_clock::now();
    const prep::EnsembleMoments moments = prep::computeEnsembleMoments(ensemble, stop);
    r.seconds["moments"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    job.moments = &moments;
    IsovalueOutcome outcome = runIsovalueJob(job, stop, progress);
    r.seconds.insert(outcome.seconds.begin(), outcome.seconds.end());
    if (!outcome.cacheWarning.empty()) {
        notice("warning", outcome.cacheWarning + "; going on without storing the results");
    }
    r.fromCache = outcome.fromCache;
    r.meshes = std::move(outcome.meshes);
    r.distances = std::move(outcome.distances);
    if (const std::string warning = prep::pairsWithoutOverlapWarning(ensemble, r.distances);
        !warning.empty()) {
        notice("warning", warning);
    }
    r.tree = std::move(outcome.tree);
    labelMembers(r);
    r.distancesToMean = std::move(outcome.distancesToMean);
    r.meanOutlyingness = std::move(outcome.meanOutlyingness);
    r.boxplot = std::move(outcome.boxplot);
    return r;
}

}  // namespace ensil::engine
