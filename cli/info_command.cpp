#include "cli/info_command.h"

#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>

#include "cli/data_selection_options.h"
#include "cli/subcommand.h"
#include "data/error.h"
#include "data/region.h"
#include "engine/ensemble_facts.h"
#include "engine/ensemble_info.h"
#include "preprocessing/field_statistics.h"

namespace ensil::cli {
namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

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
            << (QLatin1Char('(') + engine::describeDimensions(v) + QLatin1Char(')')) << "  "
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
    if (d.timeSteps.count() > 1) {  // what --time-index and --times pick from
        out << "Times:      " << d.timeSteps.count() << " along '" << qs(d.timeSteps.dimension)
            << "', " << qs(d.timeSteps.labels.front()) << " ... " << qs(d.timeSteps.labels.back())
            << "\n";
    }
    out << "Grid:       " << d.grid.nx() << " x " << d.grid.ny() << " x " << d.grid.nz() << "\n";
    for (int a = 0; a < 3; ++a) {
        out << "  "
            << "xyz"[a] << "  " << engine::describeAxis(d.grid.axis(a)) << "\n";
    }
    if (d.keptLevels) {  // --levels
        out << "            levels " << d.keptLevels->first + 1 << " to "
            << d.keptLevels->first + d.grid.nz() << " of the file's " << d.keptLevels->fileZ.size()
            << " kept (--levels)\n";
    }
    if (d.keptRegion) {  // --bbox
        const data::Grid& file = data::fileDescription(d).grid;
        out << "            region " << qs(data::regionText(d.keptRegion->region)) << ": "
            << d.grid.nx() << " x " << d.grid.ny() << " of the file's " << file.nx() << " x "
            << file.ny() << " columns and rows kept (--bbox)\n";
    }
    if (!d.gridMapping.empty()) out << "Mapping:    " << qs(d.gridMapping.name) << "\n";
    const engine::Geography geography = engine::geographyOf(d);
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
    parser.setApplicationDescription(QStringLiteral(
        "Describe the ensembles in NetCDF, HDF5, VTK or GRIB files: usable variables, "
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
        for (const std::string& note : ensemble.warnings) {
            err << "ensil info: warning: " << qs(note) << "\n";
        }
        if (const auto note = data::infiniteValuesWarning(ensemble)) {
            err << "ensil info: warning: " << qs(*note) << "\n";
        }
        const QStringList withoutData = membersWithoutData(ensemble, err);
        if (parser.isSet(json)) {
            out << QJsonDocument(
                       engine::ensembleInfoJson(description, stats, ensemble, withoutData))
                       .toJson(QJsonDocument::Indented);
        } else {
            printText(out, *selection, description, stats, ensemble);
        }
        return 0;
    } catch (const data::Error& e) {
        err << "ensil info: " << e.what() << "\n";
        return dataFailureStatus(e);
    } catch (const std::bad_alloc&) {
        err << "ensil info: not enough memory to read the ensemble\n";
        return 1;
    }
}

}  // namespace ensil::cli
