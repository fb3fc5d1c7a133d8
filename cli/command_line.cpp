#include "cli/command_line.h"

#include <QCommandLineParser>
#include <QSysInfo>
#include <array>
#include <exception>
#include <new>

#include "cli/data_selection_options.h"
#include "cli/generate_command.h"
#include "cli/info_command.h"
#include "cli/preprocess_command.h"
#include "cli/render_command.h"
#include "cli/section_command.h"
#include "cli/stats_command.h"
#include "cli/subcommand.h"
#include "data/library_versions.h"
#include "engine/streaming_run.h"
#include "session/version.h"

namespace ensil::cli {
namespace {

struct Subcommand {
    const char* name;
    const char* summary;
    int (*run)(const QStringList&, QTextStream&, QTextStream&);
};

constexpr std::array<Subcommand, 6> kSubcommands{{
    {"generate", "Write the built-in demo ensemble as a CF NetCDF file", &runGenerateCommand},
    {"stats", "Write ensemble statistics at an isovalue as a CF NetCDF file", &runStatsCommand},
    {"info", "Describe the ensembles in NetCDF, HDF5, VTK or GRIB files", &runInfoCommand},
    {"preprocess", "Mesh, analyse and cluster an ensemble at an isovalue", &runPreprocessCommand},
    {"render", "Draw an ensemble's silhouettes to a PNG without a window", &runRenderCommand},
    {"section", "Draw a map or cross-section with every member's contour", &runSectionCommand},
}};

const Subcommand* findSubcommand(const QString& name) {
    for (const Subcommand& sub : kSubcommands) {
        if (name == QLatin1String(sub.name)) return &sub;
    }
    return nullptr;
}

QString topLevelHelp() {
    QString text = QStringLiteral(
        "Usage: ensil [options] [PATH...]\n"
        "  or:  ensil <command> [options]\n"
        "\n"
        "ensil (ensemble silhouettes) shows ensembles of 3D isosurfaces as screen-space\n"
        "silhouettes. With no PATH it opens the workbench on the built-in demo ensemble;\n"
        "with PATHs it opens those data files or that project.\n"
        "\n"
        "Commands:\n");
    for (const Subcommand& sub : kSubcommands) {
        text += QStringLiteral("  %1%2\n")
                    .arg(QLatin1String(sub.name), -12)
                    .arg(QLatin1String(sub.summary));
    }
    text += QStringLiteral(
        "\n"
        "Options:\n"
        "  --var V           Variable to show (default: the one with three spatial\n"
        "                    dimensions and the most vertical levels).\n"
        "  --member-dim D    Dimension that holds the members, when ensil finds none.\n"
        "  --time-index I    Index along other dimensions such as time (default 0).\n"
        "  --levels A:B      Keep the vertical levels from A to B (e.g. 1000:100hPa).\n"
        "  --bbox LON0,LON1,LAT0,LAT1\n"
        "                    Keep the region within these longitudes and latitudes\n"
        "                    (e.g. -10,40,35,72; LON0 > LON1 crosses the date line).\n"
        "  --memory-limit S  Memory the workbench may hold for the data (default: three\n"
        "                    quarters of what is available now). NetCDF data that would\n"
        "                    take more (1.5 times its values) are opened as a copy at every\n"
        "                    few points, their surfaces built from the whole data read in\n"
        "                    slabs. E.g. 1GiB, 512M.\n"
        "  -h, --help        Show this help.\n"
        "  -V, --version     Show the version, the libraries' and the compiler's.\n"
        "\n"
        "Run 'ensil <command> --help' for the options of a command.\n");
    return text;
}

}  // namespace

QString versionText() {
    QStringList libraries{QStringLiteral("Qt ") + QString::fromLatin1(qVersion())};
    for (const data::LibraryVersion& library : data::readerLibraryVersions()) {
        libraries << QString::fromStdString(library.name + " " + library.version);
    }
#if defined(__clang__)
    const QString compiler = QStringLiteral("clang " __clang_version__);
#elif defined(__GNUC__)
    const QString compiler = QStringLiteral("GCC " __VERSION__);
#elif defined(_MSC_VER)
    const QString compiler = QStringLiteral("MSVC ") + QString::number(_MSC_VER);
#else
    const QString compiler = QStringLiteral("an unknown compiler");
#endif
    return QStringLiteral("ensil " ENSIL_VERSION "\nlibraries: ") +
           libraries.join(QStringLiteral(", ")) + QStringLiteral("\nbuilt with ") + compiler +
           QStringLiteral(" for ") + QSysInfo::buildAbi() + QStringLiteral("\n");
}

bool isHeadlessInvocation(const QStringList& args) {
    if (args.size() < 2) return false;
    const QString& first = args.at(1);
    return findSubcommand(first) != nullptr || first == QLatin1String("-h") ||
           first == QLatin1String("--help") || first == QLatin1String("-V") ||
           first == QLatin1String("--version");
}

CommandLineOutcome runCommandLine(const QStringList& args, QTextStream& out, QTextStream& err) {
    if (args.size() >= 2) {
        if (const Subcommand* sub = findSubcommand(args.at(1))) {
            QStringList rest = args.mid(2);
            rest.prepend(QStringLiteral("ensil ") + QLatin1String(sub->name));
            // The edge of every command: whatever a step throws is said, never an abort.
            try {
                return {sub->run(rest, out, err), std::nullopt};
            } catch (const std::bad_alloc&) {
                err << rest.front() << ": there is not enough memory for this\n";
            } catch (const std::exception& e) {
                err << rest.front() << ": " << e.what() << "\n";
                return {dataFailureStatus(e), std::nullopt};
            } catch (...) {
                err << rest.front() << ": an unexpected error stopped it\n";
            }
            return {1, std::nullopt};
        }
    }
    QCommandLineParser parser;
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help."));
    // -V as in gcc, cmake and python: -v means "verbose" to most tools.
    const QCommandLineOption version({QStringLiteral("V"), QStringLiteral("version")},
                                     QStringLiteral("Show the version."));
    const QCommandLineOption memoryLimit(QStringLiteral("memory-limit"),
                                         QStringLiteral("Memory the workbench may hold."),
                                         QStringLiteral("SIZE"));
    parser.addOptions({help, version, memoryLimit});
    const DataSelectionOptions selectionOptions;
    selectionOptions.addTo(parser);
    if (!parser.parse(args)) {
        err << "ensil: " << parser.errorText() << "\nRun 'ensil --help' for usage.\n";
        return {2, std::nullopt};
    }
    if (parser.isSet(help)) {
        out << topLevelHelp();
        return {0, std::nullopt};
    }
    if (parser.isSet(version)) {
        out << versionText();
        return {0, std::nullopt};
    }
    QString problem;
    auto selection = selectionOptions.selection(parser, problem);
    if (!selection) {
        err << "ensil: " << problem << "\n";
        return {2, std::nullopt};
    }
    WorkbenchRequest request{std::move(*selection)};
    if (parser.isSet(memoryLimit)) {
        std::string why;
        const auto bytes = engine::parseMemorySize(parser.value(memoryLimit).toStdString(), why);
        if (!bytes) {
            err << "ensil: " << QString::fromStdString(why) << "\n";
            return {2, std::nullopt};
        }
        request.memoryLimit = *bytes;
    }
    return {0, std::move(request)};
}

}  // namespace ensil::cli
