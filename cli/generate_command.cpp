#include "cli/generate_command.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>

#include "cli/subcommand.h"
#include "data/demo_ensemble.h"
#include "data/error.h"
#include "data/netcdf_writer.h"

namespace ensil::cli {

bool parseGridSize(const QString& text, std::size_t& nx, std::size_t& ny, std::size_t& nz) {
    static const QRegularExpression pattern(QStringLiteral("^(\\d+)[xX](\\d+)[xX](\\d+)$"));
    const QRegularExpressionMatch match = pattern.match(text.trimmed());
    if (!match.hasMatch()) return false;
    bool ok[3] = {false, false, false};
    const qulonglong a = match.captured(1).toULongLong(&ok[0]);
    const qulonglong b = match.captured(2).toULongLong(&ok[1]);
    const qulonglong c = match.captured(3).toULongLong(&ok[2]);
    if (!ok[0] || !ok[1] || !ok[2] || a < 2 || b < 2 || c < 2) return false;
    nx = a;
    ny = b;
    nz = c;
    return true;
}

namespace {
constexpr qulonglong kMaxTimes = 1000;
}  // namespace

int runGenerateCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Write the built-in demo ensemble (jet streams over the North Atlantic "
                       "on pressure levels) as a CF NetCDF file with member dimension 'number' "
                       "and variable 'wind_speed' in m s-1."));
    parser.addHelpOption();
    const data::DemoEnsembleParams defaults;
    const QCommandLineOption members(
        QStringLiteral("members"),
        QStringLiteral("Number of members (default %1).").arg(defaults.members),
        QStringLiteral("N"), QString::number(defaults.members));
    const QCommandLineOption grid(
        QStringLiteral("grid"),
        QStringLiteral("Grid size as NXxNYxNZ: longitude x latitude x levels (default %1x%2x%3).")
            .arg(defaults.nx)
            .arg(defaults.ny)
            .arg(defaults.nz),
        QStringLiteral("NXxNYxNZ"),
        QStringLiteral("%1x%2x%3").arg(defaults.nx).arg(defaults.ny).arg(defaults.nz));
    const QCommandLineOption seed(QStringLiteral("seed"),
                                  QStringLiteral("Random seed; the same seed gives the same "
                                                 "file (default %1).")
                                      .arg(defaults.seed),
                                  QStringLiteral("S"), QString::number(defaults.seed));
    const QCommandLineOption output(QStringLiteral("out"),
                                    QStringLiteral("The NetCDF file to write (required)."),
                                    QStringLiteral("FILE.nc"));
    const QCommandLineOption times(
        QStringLiteral("times"),
        QStringLiteral("Write T time steps, %1 hours apart from 2026-01-01T00:00, in a CF time "
                       "dimension: the jets drift east and about a third of the members change "
                       "flow regime, each at its own step, so clusters split and merge "
                       "(ensil preprocess FILE --times all shows them). T from 1 to %2; "
                       "without it the file has no time dimension.")
            .arg(data::kDemoHoursPerStep)
            .arg(kMaxTimes),
        QStringLiteral("T"));
    parser.addOptions({members, grid, seed, output, times});

    if (auto done = parseSubcommand(parser, args, QStringLiteral("generate"), out, err)) {
        return *done;
    }
    if (!parser.positionalArguments().isEmpty()) {
        err << "ensil generate: unexpected argument '" << parser.positionalArguments().first()
            << "'; see ensil generate --help\n";
        return 2;
    }
    data::DemoEnsembleParams params;
    bool ok = false;
    const qulonglong memberCount = parser.value(members).toULongLong(&ok);
    if (!ok || memberCount < 1 || memberCount > 10000) {
        err << "ensil generate: --members must be a whole number from 1 to 10000, not '"
            << parser.value(members) << "'\n";
        return 2;
    }
    params.members = memberCount;
    if (!parseGridSize(parser.value(grid), params.nx, params.ny, params.nz)) {
        err << "ensil generate: --grid must look like 256x128x16 (at least 2 points per axis), "
               "not '"
            << parser.value(grid) << "'\n";
        return 2;
    }
    params.seed = parser.value(seed).toULongLong(&ok);
    if (!ok) {
        err << "ensil generate: --seed must be a non-negative whole number, not '"
            << parser.value(seed) << "'\n";
        return 2;
    }
    qulonglong steps = 0;  // no time dimension
    if (parser.isSet(times)) {
        steps = parser.value(times).toULongLong(&ok);
        if (!ok || steps < 1 || steps > kMaxTimes) {
            err << "ensil generate: --times must be a whole number from 1 to " << kMaxTimes
                << ", not '" << parser.value(times) << "'\n";
            return 2;
        }
    }
    if (!parser.isSet(output)) {
        err << "ensil generate: say where to write the file with --out FILE.nc\n";
        return 2;
    }
    const QString path = parser.value(output);
    try {
        QElapsedTimer timer;
        timer.start();
        double bytes = 0;
        if (steps == 0) {
            const data::DemoEnsemble demo = data::makeDemoEnsemble(params);
            data::writeNetcdf(demo.ensemble, path.toStdString());
            bytes = static_cast<double>(demo.ensemble.bytes());
        } else {
            data::TimeCoordinate time{.units = data::kDemoTimeUnits, .values = {}};
            for (std::size_t t = 0; t < steps; ++t) {
                time.values.push_back(data::kDemoHoursPerStep * static_cast<double>(t));
            }
            data::writeNetcdfSteps(
                [&](std::size_t t) { return data::makeDemoEnsembleAt(params, t, steps).ensemble; },
                time, path.toStdString());
            bytes = static_cast<double>(params.members * params.nx * params.ny * params.nz *
                                        sizeof(float) * steps);
        }
        const double mib = bytes / (1024.0 * 1024.0);
        out << "wrote " << path << ": " << params.members << " members of wind_speed (m s-1) on "
            << params.nx << " x " << params.ny << " x " << params.nz << " (lon x lat x plev)";
        if (steps > 0) {
            out << " at " << steps << (steps == 1 ? " time" : " times")
                << " from 2026-01-01T00:00, " << data::kDemoHoursPerStep << " hours apart";
        }
        out << ", " << QString::number(mib, 'f', 1) << " MiB in "
            << QString::number(static_cast<double>(timer.elapsed()) / 1000.0, 'f', 2) << " s\n";
        return 0;
    } catch (const data::Error& e) {
        err << "ensil generate: " << e.what() << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        err << "ensil generate: not enough memory for " << params.members << " members of "
            << params.nx << " x " << params.ny << " x " << params.nz
            << " points; choose fewer members or a smaller --grid\n";
        return 1;
    }
}

}  // namespace ensil::cli
