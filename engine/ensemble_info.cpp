#include "engine/ensemble_info.h"

#include <QJsonArray>

namespace ensil::engine {
namespace {
QString qs(const std::string& s) { return QString::fromStdString(s); }
}  // namespace

Geography geographyOf(const data::EnsembleDescription& d) {
    const geo::MapProjection projection = geo::MapProjection::forGrid(d.grid, d.gridMapping);
    return {geo::lonLatBounds(d.grid, projection), projection.reason()};
}

QJsonObject ensembleInfoJson(const data::EnsembleDescription& d, const prep::FieldStatistics& s,
                             const data::Ensemble& e, const QStringList& withoutData) {
    QJsonObject o;
    o[QStringLiteral("format")] = qs(d.format);
    o[QStringLiteral("variable")] = qs(d.variable);
    o[QStringLiteral("long_name")] = qs(d.longName);
    o[QStringLiteral("units")] = qs(d.units);
    o[QStringLiteral("member_dim")] = qs(d.memberDimension);
    o[QStringLiteral("member_dim_reason")] = qs(d.memberDimensionReason);
    o[QStringLiteral("members")] = static_cast<qint64>(d.members);
    QJsonArray names;
    for (const auto& n : d.memberNames) names.append(qs(n));
    o[QStringLiteral("member_names")] = names;
    o[QStringLiteral("grid")] =
        QJsonArray{static_cast<qint64>(d.grid.nx()), static_cast<qint64>(d.grid.ny()),
                   static_cast<qint64>(d.grid.nz())};
    QJsonArray axes;
    for (int a = 0; a < 3; ++a) {
        const data::Axis& axis = d.grid.axis(a);
        axes.append(QJsonObject{{QStringLiteral("name"), qs(axis.name)},
                                {QStringLiteral("units"), qs(axis.units)},
                                {QStringLiteral("first"), axis.front()},
                                {QStringLiteral("last"), axis.back()},
                                {QStringLiteral("size"), static_cast<qint64>(axis.size())},
                                {QStringLiteral("uniform"), axis.isUniform()}});
    }
    o[QStringLiteral("axes")] = axes;
    // The file's levels that --levels keeps, from 0; absent when it keeps all.
    if (d.keptLevels) {
        o[QStringLiteral("kept_levels")] =
            QJsonObject{{QStringLiteral("first"), static_cast<qint64>(d.keptLevels->first)},
                        {QStringLiteral("count"), static_cast<qint64>(d.grid.nz())},
                        {QStringLiteral("of"), static_cast<qint64>(d.keptLevels->fileZ.size())}};
    }
    // The region --bbox keeps: the box asked for, the columns and rows kept of the file's, and
    // which (runs of columns from 0, in the order kept; the first row); absent for the whole grid.
    if (d.keptRegion) {
        const data::EnsembleDescription::KeptRegion& kept = *d.keptRegion;
        QJsonArray runs;
        for (const data::ColumnRun& run : kept.window.columns) {
            runs.append(QJsonObject{{QStringLiteral("first"), static_cast<qint64>(run.first)},
                                    {QStringLiteral("count"), static_cast<qint64>(run.count)}});
        }
        o[QStringLiteral("kept_region")] = QJsonObject{
            {QStringLiteral("bbox"),
             QJsonArray{kept.region.lon0, kept.region.lon1, kept.region.lat0, kept.region.lat1}},
            {QStringLiteral("columns"), static_cast<qint64>(d.grid.nx())},
            {QStringLiteral("rows"), static_cast<qint64>(d.grid.ny())},
            {QStringLiteral("of"), QJsonArray{static_cast<qint64>(kept.fileX.size()),
                                              static_cast<qint64>(kept.fileY.size())}},
            {QStringLiteral("column_runs"), runs},
            {QStringLiteral("first_row"), static_cast<qint64>(kept.window.firstRow)}};
    }
    QJsonArray fixed;
    for (const auto& f : d.fixedDimensions) fixed.append(qs(f));
    o[QStringLiteral("fixed_dimensions")] = fixed;
    QJsonArray timeLabels;
    for (const auto& label : d.timeSteps.labels) timeLabels.append(qs(label));
    // The steps --time-index and --times pick from; an empty list when there are none.
    o[QStringLiteral("time_steps")] =
        QJsonObject{{QStringLiteral("dimension"), qs(d.timeSteps.dimension)},
                    {QStringLiteral("labels"), timeLabels}};
    o[QStringLiteral("grid_mapping")] =
        d.gridMapping.empty() ? QJsonValue() : QJsonValue(qs(d.gridMapping.name));
    const Geography geography = geographyOf(d);
    o[QStringLiteral("lon_lat_bounds")] =
        geography.bounds
            ? QJsonValue(QJsonArray{geography.bounds->lonMin, geography.bounds->lonMax,
                                    geography.bounds->latMin, geography.bounds->latMax})
            : QJsonValue();
    o[QStringLiteral("range")] = QJsonArray{s.minimum, s.maximum};
    o[QStringLiteral("mean")] = s.mean;
    o[QStringLiteral("missing")] = static_cast<qint64>(s.missingCount);
    o[QStringLiteral("infinite")] = static_cast<qint64>(e.infiniteValues);  // among the missing
    o[QStringLiteral("members_without_data")] = QJsonArray::fromStringList(withoutData);
    o[QStringLiteral("bytes")] = static_cast<qint64>(d.bytes());
    QJsonArray variables;
    for (const data::VariableInfo& v : d.variables) {
        QJsonArray dims;
        for (const auto& dim : v.dimensions) dims.append(qs(dim));
        variables.append(QJsonObject{{QStringLiteral("name"), qs(v.name)},
                                     {QStringLiteral("usable"), v.usable},
                                     {QStringLiteral("derived"), v.derived},
                                     {QStringLiteral("why_not_usable"), qs(v.whyNotUsable)},
                                     {QStringLiteral("dimensions"), dims}});
    }
    o[QStringLiteral("variables")] = variables;
    return o;
}

}  // namespace ensil::engine
