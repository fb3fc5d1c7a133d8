// The isovalue the workbench starts a variable at (preprocessing/default_isovalue.h), computed
// here the way the workbench does, for the commands' tests to compare against.
#pragma once

#include <string>

#include "data/ensemble_reader.h"
#include "preprocessing/default_isovalue.h"

namespace ensil::test {

inline float workbenchDefaultIsovalue(const std::string& path, const std::string& variable) {
    const data::Ensemble ensemble = data::openEnsemble({{path}, variable, {}, 0});
    const prep::FieldStatistics stats =
        prep::computeFieldStatistics(ensemble, prep::kIsovalueHistogramBins);
    return prep::defaultIsovalue(ensemble, stats);
}

}  // namespace ensil::test
