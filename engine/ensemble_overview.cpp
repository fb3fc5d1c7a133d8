#include "engine/ensemble_overview.h"

#include "data/error.h"
#include "preprocessing/default_isovalue.h"

namespace ensil::engine {

SameDataParts sameDataParts(const EnsembleOverview& overview) {
    return {overview.defaultIsovalue, overview.mapLines, overview.ensemble->grid,
            overview.ensemble->gridMapping};
}

EnsembleOverview buildEnsembleOverview(std::shared_ptr<const data::Ensemble> ensemble,
                                       const std::stop_token& stop, const data::Progress& progress,
                                       const SameDataParts* sameData) {
    const bool same = sameData != nullptr && sameData->mapLines != nullptr &&
                      sameData->grid.sameShapeAndCoordinates(ensemble->grid) &&
                      sameData->gridMapping == ensemble->gridMapping;
    EnsembleOverview overview;
    overview.statistics =
        prep::computeFieldStatistics(*ensemble, prep::kIsovalueHistogramBins, stop,
                                     [&](double f) { data::report(progress, 0.5 * f); });
    if (overview.statistics.validCount == 0) {
        throw data::Error(data::ErrorKind::AllValuesMissing,
                          "every value of '" + ensemble->variable + "' in " + ensemble->source +
                              " is missing: there is nothing to draw");
    }
    auto moments = std::make_shared<prep::EnsembleMoments>(prep::computeEnsembleMoments(
        *ensemble, stop, [&](double f) { data::report(progress, 0.5 + 0.45 * f); }));
    overview.defaultIsovalue =
        same ? sameData->defaultIsovalue : prep::defaultIsovalue(*ensemble, overview.statistics);
    overview.columnMaxima = computeColumnMaxima(*ensemble, moments->mean, stop);
    overview.mapLines = same ? sameData->mapLines
                             : std::make_shared<const std::vector<geo::MapLine>>(
                                   geo::mapLinesFor(ensemble->grid, ensemble->gridMapping));
    overview.moments = std::move(moments);
    data::report(progress, 1.0);
    overview.ensemble = std::move(ensemble);
    return overview;
}

EnsembleOverview readEnsembleOverview(const WorkbenchRead& read,
                                      const std::function<std::string()>& identify,
                                      const std::stop_token& stop, const data::Progress& progress,
                                      const SameDataParts* sameData) {
    WorkbenchEnsemble loaded = read(stop, [&](double f) { data::report(progress, 0.6 * f); });
    std::vector<std::string> withoutData = data::leaveOutMembersWithoutData(loaded.ensemble);
    EnsembleOverview overview = buildEnsembleOverview(
        std::make_shared<const data::Ensemble>(std::move(loaded.ensemble)), stop,
        [&](double f) { data::report(progress, 0.6 + 0.4 * f); }, sameData);
    overview.sourceKey = identify() + data::membersWithoutDataKey(withoutData);
    overview.membersWithoutData = std::move(withoutData);
    overview.variables = std::move(loaded.variables);
    if (loaded.streamed) {
        overview.streamed = std::make_shared<const StreamedSource>(std::move(*loaded.streamed));
    }
    return overview;
}

}  // namespace ensil::engine
