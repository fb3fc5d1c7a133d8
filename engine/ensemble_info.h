// What `ensil info --json` says of an ensemble, as one JSON object: format, variable, members
// and how their dimension was found, grid and axes, grid mapping and true bounds, value range,
// missing values, the file's variables. Shared by the command and the Python module's
// Ensemble.info(), so both say the same. Any thread.
#pragma once

#include <QJsonObject>
#include <QStringList>
#include <optional>
#include <string>

#include "data/ensemble.h"
#include "data/ensemble_reader.h"
#include "geo/domain_bounds.h"
#include "preprocessing/field_statistics.h"

namespace ensil::engine {

// Where the grid lies on the Earth: its true longitude/latitude bounds, when it has geography.
struct Geography {
    std::optional<geo::LonLatBounds> bounds;
    std::string why;  // when there are no bounds
};
Geography geographyOf(const data::EnsembleDescription& description);

// `statistics` over the whole ensemble (prep::computeFieldStatistics); `withoutData` names the
// members with no valid value.
QJsonObject ensembleInfoJson(const data::EnsembleDescription& description,
                             const prep::FieldStatistics& statistics,
                             const data::Ensemble& ensemble, const QStringList& withoutData);

}  // namespace ensil::engine
