#include "cli/stats_command.h"

#include <QCommandLineParser>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <span>
#include <string>

#include "cli/command_progress.h"
#include "cli/data_selection_options.h"
#include "cli/subcommand.h"
#include "data/error.h"
#include "data/statistics_writer.h"
#include "preprocessing/ensemble_statistics.h"
#include "session/setting_options.h"
#include "session/version.h"

namespace ensil::cli {
namespace {

struct Options {
    QCommandLineOption iso{QStringLiteral("iso"),
                           QStringLiteral("The isovalue C of P(f > C) and of the level-crossing "
                                          "probability, in the variable's units (required)."),
                           QStringLiteral("C")};
    QCommandLineOption members{
        QStringLiteral("members"),
        QStringLiteral("The members to summarise, by their numbers (1 to N in the order the file "
                       "holds them, the member table's #), as numbers and ranges: 1,3,5-9 "
                       "(default: every member with data)."),
        QStringLiteral("LIST")};
    QCommandLineOption output{QStringLiteral("out"),
                              QStringLiteral("The NetCDF file to write (required; an existing "
                                             "file is replaced)."),
                              QStringLiteral("STATS.nc")};
    QCommandLineOption json{QStringLiteral("json"), QStringLiteral("Print one JSON object.")};
    QCommandLineOption quiet = CommandProgress::quietOption();
};

double seconds(const QElapsedTimer& t) { return static_cast<double>(t.nsecsElapsed()) * 1e-9; }

QString memberName(const data::Member& member, std::size_t index) {
    return member.name.empty() ? QStringLiteral("member %1").arg(index + 1)
                               : QString::fromStdString(member.name);
}

// An argument as a shell would need it: as it is when plain, else in single quotes.
QString shellWord(const QString& arg) {
    static const QRegularExpression plain(QStringLiteral("^[A-Za-z0-9_@%+=:,./-]+$"));
    if (plain.match(arg).hasMatch()) return arg;
    QString quoted = arg;
    quoted.replace(QLatin1Char('\''), QStringLiteral("'\\''"));
    return QLatin1Char('\'') + quoted + QLatin1Char('\'');
}

// The command line as typed: "ensil stats" and the arguments after it.
QString commandLine(const QStringList& args) {
    QStringList words{QStringLiteral("ensil stats")};
    for (const QString& arg : args.mid(1)) words << shellWord(arg);
    return words.join(QLatin1Char(' '));
}

// Why `path` cannot be written, checked before the data is read; empty when it can be tried.
QString outputProblem(const QString& path) {
    const QFileInfo file(path);
    const QFileInfo folder(file.absolutePath());
    if (path.trimmed().isEmpty()) return QStringLiteral("--out '' is refused: name a file");
    if (!folder.exists()) {
        return QStringLiteral("cannot write '%1': the folder '%2' does not exist")
            .arg(path, QDir::toNativeSeparators(folder.filePath()));
    }
    if (!folder.isDir()) {
        return QStringLiteral("cannot write '%1': '%2' is not a folder")
            .arg(path, QDir::toNativeSeparators(folder.filePath()));
    }
    if (file.isDir()) return QStringLiteral("cannot write '%1': it is a folder").arg(path);
    if (file.exists() ? !file.isWritable() : !folder.isWritable()) {
        return QStringLiteral("cannot write '%1': permission denied").arg(path);
    }
    return {};
}

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code error;
    return std::filesystem::equivalent(a, b, error) && !error;
}

// The smallest and largest finite values of a field; nullopt when it has none.
std::optional<std::pair<float, float>> finiteRange(std::span<const float> values) {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    for (const float v : values) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    if (lo > hi) return std::nullopt;
    return std::pair{lo, hi};
}

struct Result {
    QString path;
    QString variable;
    QString units;
    double isovalue = 0.0;
    QStringList members;
    QStringList membersWithoutData;  // left out, with a warning (only without --members)
    std::array<std::size_t, 3> grid{};
    std::vector<std::pair<QString, std::optional<std::pair<float, float>>>> fields;
    std::map<std::string, double> seconds;
};

QJsonObject toJson(const Result& r) {
    QJsonObject o;
    o[QStringLiteral("output")] = r.path;
    o[QStringLiteral("variable")] = r.variable;
    o[QStringLiteral("units")] = r.units;
    o[QStringLiteral("isovalue")] = r.isovalue;
    o[QStringLiteral("member_count")] = static_cast<qint64>(r.members.size());
    o[QStringLiteral("members")] = QJsonArray::fromStringList(r.members);
    o[QStringLiteral("members_without_data")] = QJsonArray::fromStringList(r.membersWithoutData);
    o[QStringLiteral("grid")] =
        QJsonArray{static_cast<qint64>(r.grid[0]), static_cast<qint64>(r.grid[1]),
                   static_cast<qint64>(r.grid[2])};
    QJsonObject secs;
    for (const auto& [name, value] : r.seconds) secs[QString::fromStdString(name)] = value;
    o[QStringLiteral("seconds")] = secs;
    QJsonObject fields;
    for (const auto& [name, range] : r.fields) {
        fields[name] = range ? QJsonObject{{"min", static_cast<double>(range->first)},
                                           {"max", static_cast<double>(range->second)}}
                             : QJsonObject{{"min", QJsonValue()}, {"max", QJsonValue()}};
    }
    o[QStringLiteral("fields")] = fields;
    return o;
}

void printText(QTextStream& out, const Result& r) {
    out << "Wrote " << r.path << ": statistics of " << r.variable << " over " << r.members.size()
        << " members on " << r.grid[0] << " x " << r.grid[1] << " x " << r.grid[2] << ", isovalue "
        << r.isovalue << (r.units.isEmpty() ? "" : " ") << r.units << ", in "
        << QString::number(r.seconds.at("total"), 'f', 2) << " s\n";
    for (const auto& [name, range] : r.fields) {
        out << "  " << QString(name).leftJustified(28);
        if (range) {
            out << range->first << " .. " << range->second << "\n";
        } else {
            out << "no finite value\n";
        }
    }
}

// The members to summarise, as indices (number - 1) in the file's order: those listed (nullopt,
// with the fault said on `err`, when one is out of range or has no data), or every member with data
// (each one without named on `err` and in `r.membersWithoutData`). Members without data are
// skipped here rather than taken out of the ensemble (data::leaveOutMembersWithoutData), which
// would shift the indices a user's list refers to; the rule is the same
// (data::membersWithoutData).
std::optional<std::vector<std::size_t>> chooseMembers(
    const data::Ensemble& ensemble, const std::optional<std::vector<MemberRange>>& ranges,
    const QString& fileNames, Result& r, QTextStream& err) {
    const std::size_t inFile = ensemble.memberCount();
    const std::vector<std::size_t> withoutData = data::membersWithoutData(ensemble);
    const auto hasNoData = [&](std::size_t m) {
        return std::binary_search(withoutData.begin(), withoutData.end(), m);
    };
    std::vector<std::size_t> chosen;
    if (!ranges) {
        for (std::size_t m = 0; m < inFile; ++m) {
            if (!hasNoData(m)) {
                chosen.push_back(m);
                continue;
            }
            const QString name = memberName(ensemble.members[m], m);
            err << "ensil stats: warning: '" << name << "' of '" << r.variable
                << "' has no valid value (every value is missing); it is left out of the "
                   "statistics\n";
            r.membersWithoutData << name;
        }
        return chosen;
    }
    for (const MemberRange& range : *ranges) {
        if (range.last > inFile) {
            err << "ensil stats: --members: there is no member "
                << (range.first > inFile ? range.first : range.last) << ": " << fileNames
                << " holds " << inFile << " members of '" << r.variable << "' (1 to " << inFile
                << ")\n";
            return std::nullopt;
        }
        for (std::size_t m = range.first - 1; m < range.last; ++m) {
            if (hasNoData(m)) {
                err << "ensil stats: --members: member " << m + 1 << " ('"
                    << memberName(ensemble.members[m], m) << "') has no valid value of '"
                    << r.variable << "' (every value is missing); leave it out of --members\n";
                return std::nullopt;
            }
            chosen.push_back(m);
        }
    }
    return chosen;
}

// The smallest and largest finite values of every member.
std::pair<float, float> valueRange(const data::Ensemble& ensemble) {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    for (const data::Member& member : ensemble.members) {
        if (const auto range = finiteRange(member.values)) {
            lo = std::min(lo, range->first);
            hi = std::max(hi, range->second);
        }
    }
    return {lo, hi};
}

}  // namespace

std::optional<std::vector<MemberRange>> parseMemberList(const QString& text, QString& problem) {
    static const QRegularExpression entry(
        QStringLiteral("^\\s*(\\d{1,18})\\s*(?:-\\s*(\\d{1,18})\\s*)?$"));
    std::vector<MemberRange> ranges;
    for (const QString& part : text.split(QLatin1Char(','))) {
        const QRegularExpressionMatch match = entry.match(part);
        if (!match.hasMatch()) {
            problem = part.trimmed().isEmpty()
                          ? QStringLiteral(
                                "--members '%1' has an empty entry; write member numbers "
                                "and ranges such as 1,3,5-9")
                                .arg(text)
                          : QStringLiteral(
                                "--members '%1': '%2' is neither a member number nor a "
                                "range; write whole numbers from 1 (the member table's #) "
                                "and ranges such as 1,3,5-9")
                                .arg(text, part.trimmed());
            return std::nullopt;
        }
        MemberRange r;
        r.first = match.captured(1).toULongLong();
        r.last = match.captured(2).isEmpty() ? r.first : match.captured(2).toULongLong();
        if (r.first == 0) {
            problem = QStringLiteral(
                          "--members '%1': there is no member 0; members are numbered from 1, "
                          "as the member table's # shows them")
                          .arg(text);
            return std::nullopt;
        }
        if (r.last < r.first) {
            problem = QStringLiteral("--members '%1': the range %2-%3 runs backwards; write %3-%2")
                          .arg(text)
                          .arg(r.first)
                          .arg(r.last);
            return std::nullopt;
        }
        ranges.push_back(r);
    }
    std::vector<MemberRange> sorted = ranges;
    std::sort(sorted.begin(), sorted.end(),
              [](const MemberRange& a, const MemberRange& b) { return a.first < b.first; });
    for (std::size_t i = 1; i < sorted.size(); ++i) {
        if (sorted[i].first <= sorted[i - 1].last) {
            problem = QStringLiteral("--members '%1' lists member %2 twice; name each member once")
                          .arg(text)
                          .arg(sorted[i].first);
            return std::nullopt;
        }
    }
    return ranges;
}

int runStatsCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Write the ensemble's statistics per grid point (mean, sample standard deviation, "
        "minimum, maximum, range, the probability P(f > C) and the number of members with a "
        "value) and per grid cell (the probability that a member's C isosurface crosses it) as "
        "one CF-1.8 NetCDF file."));
    parser.addHelpOption();
    const DataSelectionOptions selectionOptions;
    selectionOptions.addTo(parser);
    const Options o;
    parser.addOptions({o.iso, o.members, o.output, o.json, o.quiet});
    if (auto done = parseSubcommand(parser, args, QStringLiteral("stats"), out, err)) return *done;

    QString problem;
    const auto selection = selectionOptions.selection(parser, problem);
    if (selection && selection->paths.empty()) {
        problem = QStringLiteral(
            "name the files to summarise: ensil stats FILE... --iso C --out STATS.nc");
    } else if (selection && !parser.isSet(o.iso)) {
        problem = QStringLiteral(
            "say which isovalue with --iso C (the C of P(f > C) and of the level-crossing "
            "probability, in the variable's units)");
    }
    std::optional<double> iso;
    if (selection && problem.isEmpty()) {
        iso = session::parseBoundedNumber(QStringLiteral("--iso"), parser.value(o.iso), -1e30, 1e30,
                                          false, problem);
    }
    std::optional<std::vector<MemberRange>> ranges;
    if (iso && parser.isSet(o.members)) ranges = parseMemberList(parser.value(o.members), problem);
    if (problem.isEmpty() && !parser.isSet(o.output)) {
        problem = QStringLiteral("say where to write the statistics with --out STATS.nc");
    }
    const QString outPath = parser.value(o.output);
    if (problem.isEmpty()) {
        for (const std::string& input : selection->paths) {
            if (sameFile(input, outPath.toStdString())) {
                problem = QStringLiteral(
                              "--out '%1' is one of the input files; write the statistics to "
                              "another file")
                              .arg(outPath);
            }
        }
    }
    if (!problem.isEmpty()) {
        err << "ensil stats: " << problem << "\n";
        return 2;
    }
    if (const QString unwritable = outputProblem(outPath); !unwritable.isEmpty()) {
        err << "ensil stats: " << unwritable << "\n";
        return 1;
    }

    const QString fileNames =
        QString::fromStdString(selection->paths.front()) +
        (selection->paths.size() > 1
             ? QStringLiteral(" (and %1 more files)").arg(selection->paths.size() - 1)
             : QString());
    QElapsedTimer total, stage;
    total.start();
    Result r;
    r.path = outPath;
    r.isovalue = *iso;
    data::Ensemble ensemble;
    CommandProgress progress(err, QStringLiteral("ensil stats"),
                             CommandProgress::shownOnThisTerminal(parser.isSet(o.quiet)));
    try {
        stage.start();
        ensemble = data::openEnsemble(*selection, {}, progress.callback(QStringLiteral("reading")));
        progress.endLine();
        r.seconds["load"] = seconds(stage);
    } catch (const data::Error& e) {
        progress.endLine();
        err << "ensil stats: " << e.what() << "\n";
        return dataFailureStatus(e);
    } catch (const std::bad_alloc&) {
        progress.endLine();
        err << "ensil stats: not enough memory to read " << fileNames << "\n";
        return 1;
    }
    r.variable = QString::fromStdString(ensemble.variable);
    r.units = QString::fromStdString(ensemble.units);
    r.grid = {ensemble.grid.nx(), ensemble.grid.ny(), ensemble.grid.nz()};
    for (const std::string& note : ensemble.warnings) {
        err << "ensil stats: warning: " << QString::fromStdString(note) << "\n";
    }
    if (const auto note = data::infiniteValuesWarning(ensemble)) {
        err << "ensil stats: warning: " << QString::fromStdString(*note) << "\n";
    }

    const auto chosen = chooseMembers(ensemble, ranges, fileNames, r, err);
    if (!chosen) return 2;
    for (const std::size_t m : *chosen) r.members << memberName(ensemble.members[m], m);
    const auto [lo, hi] = valueRange(ensemble);
    const auto c = static_cast<float>(*iso);
    if (!(c > lo && c < hi)) {
        err << "ensil stats: isovalue " << *iso << " is outside the values of '" << r.variable
            << "' in " << fileNames << " (" << lo << " .. " << hi << (r.units.isEmpty() ? "" : " ")
            << r.units
            << "): every member is on one side of it everywhere. Choose an isovalue inside that "
               "range\n";
        return 2;
    }

    try {
        stage.restart();
        const prep::EnsembleStatistics stats = prep::computeEnsembleStatistics(
            ensemble, c, *chosen, {}, progress.callback(QStringLiteral("statistics")));
        progress.endLine();
        r.seconds["statistics"] = seconds(stage);

        data::StatisticsFile file;
        file.variable = ensemble.variable;
        file.longName = ensemble.longName;
        file.units = ensemble.units;
        file.grid = ensemble.grid;
        file.gridMapping = ensemble.gridMapping;
        file.fixedDimensions = ensemble.fixedDimensions;
        file.isovalue = c;
        file.memberAxis = selection->memberDimension;  // the user's, when the file has none
        for (const QString& name : r.members) file.members.push_back(name.toStdString());
        for (const std::string& path : selection->paths) {
            file.sources.push_back(
                QFileInfo(QString::fromStdString(path)).absoluteFilePath().toStdString());
        }
        file.history = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString() + ": " +
                       commandLine(args).toStdString() + " (ensil " ENSIL_VERSION ")";
        file.count = stats.count;
        file.mean = stats.mean;
        file.stddev = stats.stddev;
        file.minimum = stats.minimum;
        file.maximum = stats.maximum;
        file.range = stats.range;
        file.exceedance = stats.exceedance;
        file.levelCrossing = stats.levelCrossing;
        for (const data::StatisticsField& field : data::statisticsFields(file)) {
            r.fields.emplace_back(QLatin1String(field.name), finiteRange(field.values));
        }

        stage.restart();
        data::writeStatisticsNetcdf(file, outPath.toStdString());
        r.seconds["write"] = seconds(stage);
    } catch (const data::Error& e) {
        progress.endLine();
        err << "ensil stats: " << e.what() << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        progress.endLine();
        err << "ensil stats: not enough memory for the statistics of " << chosen->size()
            << " members of '" << r.variable << "' on " << r.grid[0] << " x " << r.grid[1] << " x "
            << r.grid[2] << " points\n";
        return 1;
    }
    r.seconds["total"] = seconds(total);
    if (parser.isSet(o.json)) {
        out << QJsonDocument(toJson(r)).toJson(QJsonDocument::Compact) << "\n";
    } else {
        printText(out, r);
    }
    return 0;
}

}  // namespace ensil::cli
