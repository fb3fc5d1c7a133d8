#include "app/info_command.h"

#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "app/data_selection_options.h"
#include "app/ensemble_facts.h"
#include "app/subcommand.h"
#include "data/error.h"
#include "geo/domain_bounds.h"
#include "preprocessing/field_statistics.h"

namespace ensil::app {
namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Where the grid lies on the Earth: its CF grid mapping (none for plain longitude/latitude
// axes) and its true longitude/latitude bounds, when it has geography.
struct Geography {
    std::optional<geo::LonLatBounds> bounds;
    std::string why;  // when there are no bounds
};

Geography geographyOf(const data::EnsembleDescription& d) {
    const geo::MapProjection projection = geo::MapProjection::forGrid(d.grid, d.gridMapping);
    return {geo::lonLatBounds(d.grid, projection), projection.reason()};
}

// The names of the members with no valid value, each said on `err`.
QStringList membersWithoutData(const data::Ensemble& e, QTextStream& err) {
    QStringList names;
    for (const std::size_t m : data::membersWithoutData(e)) {
        names << qs(e.members[m].name);
        err << "ensil info: warning: '" << names.back() << "' of '" << qs(e.variable)
            << "' has no valid value (every value is missing)\n";
    }
    return names;
}

QJsonObject toJson(const data::EnsembleDescription& d, const prep::FieldStatistics& s,
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
    QJsonArray fixed;
    for (const auto& f : d.fixedDimensions) fixed.append(qs(f));
    o[QStringLiteral("fixed_dimensions")] = fixed;
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

void printText(QTextStream& out, const data::DataSelection& sel, const data::EnsembleDescription& d,
               const prep::FieldStatistics& s, const data::Ensemble& e) {
    out << "File:       "
        << qs(sel.paths.size() == 1 ? sel.paths.front()
                                    : std::to_string(sel.paths.size()) + " files")
        << " (" << qs(d.format) << ")\n";
    out << "Variables usable as ensembles:\n";
    for (const auto& v : d.variables) {
        if (!v.usable) continue;
        out << "  " << qs(v.name).leftJustified(12) << ' '
            << (QLatin1Char('(') + describeDimensions(v) + QLatin1Char(')')) << "  "
            << qs(v.longName)
            << (v.units.empty() ? QString() : QStringLiteral(" [%1]").arg(qs(v.units))) << "\n";
    }
    bool headed = false;
    for (const auto& v : d.variables) {
        if (v.usable) continue;
        if (!headed) out << "Not usable:\n";
        headed = true;
        out << "  " << qs(v.name).leftJustified(12) << ' ' << qs(v.whyNotUsable) << "\n";
    }
    out << "Variable:   " << qs(d.variable)
        << (d.longName.empty() ? QString() : QStringLiteral(" (%1)").arg(qs(d.longName))) << "\n";
    out << "Units:      " << (d.units.empty() ? QStringLiteral("(none given)") : qs(d.units))
        << "\n";
    out << "Members:    " << d.members;
    if (!d.memberDimension.empty()) {
        out << " along '" << qs(d.memberDimension) << "' (" << qs(d.memberDimensionReason) << ")";
    } else {
        out << " ("
            << (d.memberDimensionReason.empty() ? QStringLiteral("one file per member")
                                                : qs(d.memberDimensionReason))
            << ")";
    }
    out << "\n";
    if (!d.memberNames.empty()) {
        out << "            " << qs(d.memberNames.front()) << " ... " << qs(d.memberNames.back())
            << "\n";
    }
    for (const auto& f : d.fixedDimensions) out << "Fixed:      " << qs(f) << "\n";
    out << "Grid:       " << d.grid.nx() << " x " << d.grid.ny() << " x " << d.grid.nz() << "\n";
    for (int a = 0; a < 3; ++a) {
        out << "  "
            << "xyz"[a] << "  " << describeAxis(d.grid.axis(a)) << "\n";
    }
    if (!d.gridMapping.empty()) out << "Mapping:    " << qs(d.gridMapping.name) << "\n";
    const Geography geography = geographyOf(d);
    if (geography.bounds) {
        const geo::LonLatBounds& b = *geography.bounds;
        out << "Domain:     longitude " << b.lonMin << " .. " << b.lonMax << ", latitude "
            << b.latMin << " .. " << b.latMax << " (true degrees)\n";
    } else {
        out << "Domain:     no geography (" << qs(geography.why) << ")\n";
    }
    out << "Values:     " << s.minimum << " .. " << s.maximum << " " << qs(d.units) << ", mean "
        << s.mean << "\n";
    out << "Missing:    " << s.missingCount << " of " << (s.missingCount + s.validCount)
        << " values";
    if (e.infiniteValues > 0) out << " (" << e.infiniteValues << " of them infinite)";
    out << "\n";
    out << "Memory:     "
        << QString::number(static_cast<double>(d.bytes()) / (1024.0 * 1024.0), 'f', 1) << " MiB\n";
}

}  // namespace

int runInfoCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Describe the ensembles in NetCDF, HDF5 or VTK files: usable variables, "
                       "member dimension and how it was found, grid and axes, units, value "
                       "range, missing values."));
    parser.addHelpOption();
    const DataSelectionOptions selectionOptions;
    selectionOptions.addTo(parser);
    const QCommandLineOption json(QStringLiteral("json"),
                                  QStringLiteral("Print one JSON object instead of text."));
    parser.addOption(json);
    if (auto done = parseSubcommand(parser, args, QStringLiteral("info"), out, err)) return *done;
    QString problem;
    const auto selection = selectionOptions.selection(parser, problem);
    if (!selection) {
        err << "ensil info: " << problem << "\n";
        return 2;
    }
    if (selection->paths.empty()) {
        err << "ensil info: name at least one file, e.g. ensil info data.nc\n";
        return 2;
    }
    try {
        data::EnsembleDescription description;
        const data::Ensemble ensemble = data::openEnsemble(*selection, {}, {}, &description);
        const prep::FieldStatistics stats = prep::computeFieldStatistics(ensemble, 0);
        if (const auto note = data::infiniteValuesWarning(ensemble)) {
            err << "ensil info: warning: " << qs(*note) << "\n";
        }
        const QStringList withoutData = membersWithoutData(ensemble, err);
        if (parser.isSet(json)) {
            out << QJsonDocument(toJson(description, stats, ensemble, withoutData))
                       .toJson(QJsonDocument::Indented);
        } else {
            printText(out, *selection, description, stats, ensemble);
        }
        return 0;
    } catch (const data::Error& e) {
        err << "ensil info: " << e.what() << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        err << "ensil info: not enough memory to read the ensemble\n";
        return 1;
    }
}

}  // namespace ensil::app
