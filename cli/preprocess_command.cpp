#include "cli/preprocess_command.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "cli/data_selection_options.h"
#include "engine/isovalue_job.h"
#include "engine/preprocess_run.h"
#include "engine/run_memory.h"
#include "engine/streaming_run.h"
#include "engine/surface_export.h"
#include "engine/surface_series.h"
#ifdef ENSIL_WITH_MPI
#include "cli/preprocess_mpi.h"
#endif
#include "cli/command_progress.h"
#include "cli/subcommand.h"
#include "data/demo_ensemble.h"
#include "data/error.h"
#include "engine/time_series.h"
#include "preprocessing/clustering.h"
#include "session/setting_options.h"

namespace ensil::cli {
namespace {

struct Options {
    QCommandLineOption iso{QStringLiteral("iso"),
                           QStringLiteral("The isovalue (default: the workbench's, where most "
                                          "members have a surface in the middle of the box and "
                                          "differ; --json reports it)."),
                           QStringLiteral("X")};
    QCommandLineOption error{QStringLiteral("error"),
                             QStringLiteral("Decimation error bound in grid cells (default 0.25; a "
                                            "number from 0.001 to 10)."),
                             QStringLiteral("CELLS"), QStringLiteral("0.25")};
    QCommandLineOption noDecimation{QStringLiteral("no-decimation"),
                                    QStringLiteral("Keep every marching-cubes triangle.")};
    QCommandLineOption noCache{QStringLiteral("no-cache"),
                               QStringLiteral("Neither read nor write the preprocessing cache.")};
    QCommandLineOption cacheDir{QStringLiteral("cache-dir"),
                                QStringLiteral("Folder of the preprocessing cache (default: the "
                                               "user's cache folder)."),
                                QStringLiteral("DIR")};
    QCommandLineOption demo{QStringLiteral("demo"),
                            QStringLiteral("Use the built-in demo ensemble instead of files.")};
    QCommandLineOption json{QStringLiteral("json"), QStringLiteral("Print one JSON object.")};
    QCommandLineOption times{
        QStringLiteral("times"),
        QStringLiteral("Preprocess every time step from A to B, both included (time indices "
                       "from 0, as --time-index counts them), or all of them, at one isovalue "
                       "(--iso, else the first step's default), matching each step's clusters "
                       "to the previous step's so a group keeps its number and colour. --json "
                       "then gives 'steps', one object per step with its 'time'."),
        QStringLiteral("all|A:B")};
    QCommandLineOption memoryLimit{
        QStringLiteral("memory-limit"),
        QStringLiteral("Memory the preprocessing may hold (default: three quarters of what is "
                       "available now). A NetCDF ensemble that would take more in memory (1.5 "
                       "times its values) is read in slabs of layers and member by member "
                       "instead, with the same results but no contour boxplot; --iso is then "
                       "needed. E.g. 1GiB, 512M."),
        QStringLiteral("SIZE")};
    QCommandLineOption exportDir{
        QStringLiteral("export"),
        QStringLiteral("Write the surfaces into DIR for other tools: every member's, the mean's "
                       "and the summary surfaces, with vertices in the data's coordinates and "
                       "each vertex's member, cluster, depth, outlyingness and curvatures "
                       "(docs/command-line.md, \"Surfaces for other tools\"). With --times, "
                       "every step's, and for vtp a .pvd that ParaView plays over time."),
        QStringLiteral("DIR")};
    QCommandLineOption format{
        QStringLiteral("format"),
        QStringLiteral("The format of --export: vtp (ParaView: a .vtm gathering a .vtp per "
                       "surface; the default), ply (MeshLab, CloudCompare, Blender; binary, "
                       "with the per-vertex values), obj or stl (positions only)."),
        QStringLiteral("vtp|ply|obj|stl"), QStringLiteral("vtp")};
    QCommandLineOption coordinates{
        QStringLiteral("coordinates"),
        QStringLiteral("The vertices of --export: data (the axes' own values, to lie over the "
                       "same file in ParaView; the default) or display (the workbench's box, "
                       "its sides in proportion, for MeshLab or Blender)."),
        QStringLiteral("data|display"), QStringLiteral("data")};
    QCommandLineOption quiet = CommandProgress::quietOption();
};

double seconds(const QElapsedTimer& t) { return static_cast<double>(t.nsecsElapsed()) * 1e-9; }

// The shared result, with what only the command reports.
struct Result : engine::PreprocessResult {
    QString cache;
    std::optional<engine::RunMemory> memory;           // none where the kernel gives no figure
    std::optional<engine::ExportedSurfaces> exported;  // with --export
};

// Where --export writes, and in which format; none without --export.
struct ExportRequest {
    engine::SurfaceFormat format = engine::SurfaceFormat::Vtp;
    std::filesystem::path directory;
    bool displayFrame = false;  // --coordinates display
};

// The surfaces of one result as --export writes them.
engine::ExportedSurfaces exportResult(const engine::PreprocessResult& r, const ExportRequest& to) {
    engine::SurfaceSet set = engine::surfaceSetOf(r);
    if (to.displayFrame) set.displayFrame = data::DisplayFrame(r.ensemble->grid, 1.0F);
    return engine::exportSurfaces(set, to.format, to.directory);
}

QJsonObject exportJson(const engine::ExportedSurfaces& exported) {
    QJsonArray files;
    for (const auto& file : exported.files) files.append(QString::fromStdString(file.string()));
    return QJsonObject{{"files", files},
                       {"surfaces", static_cast<qint64>(exported.surfaces)},
                       {"triangles", static_cast<qint64>(exported.triangles)},
                       {"triangles_left_out", static_cast<qint64>(exported.trianglesLeftOut)}};
}

void printExport(QTextStream& out, const engine::ExportedSurfaces& exported) {
    out << "Exported:   " << exported.surfaces << " surfaces, " << exported.triangles
        << " triangles, to " << QString::fromStdString(exported.files.front().string())
        << (exported.files.size() > 1
                ? QStringLiteral(" and %1 more files").arg(exported.files.size() - 1)
                : QString())
        << "\n";
    if (exported.trianglesLeftOut > 0) {
        out << "            " << exported.trianglesLeftOut
            << " triangles left out: OpenMesh keeps surfaces manifold, and these would have "
               "joined sheets of a surface at one edge (vtp keeps them)\n";
    }
}

QString memberName(const data::Member& member, std::size_t index) {
    return member.name.empty() ? QStringLiteral("member %1").arg(index + 1)
                               : QString::fromStdString(member.name);
}

QJsonObject toJson(const Result& r, prep::Linkage linkage) {
    QJsonObject o;
    const data::Ensemble& e = *r.ensemble;
    const data::Grid& g = e.grid;
    o[QStringLiteral("member_count")] = static_cast<qint64>(e.memberCount());
    QJsonArray withoutData;
    for (const std::string& name : r.membersWithoutData) {
        withoutData.append(QString::fromStdString(name));
    }
    o[QStringLiteral("members_without_data")] = withoutData;
    o[QStringLiteral("grid")] = QJsonArray{static_cast<qint64>(g.nx()), static_cast<qint64>(g.ny()),
                                           static_cast<qint64>(g.nz())};
    o[QStringLiteral("variable")] = QString::fromStdString(e.variable);
    o[QStringLiteral("isovalue")] = r.meshes.isovalue;
    QJsonObject secs;
    for (const auto& [name, value] : r.seconds) secs[QString::fromStdString(name)] = value;
    o[QStringLiteral("seconds")] = secs;
    o[QStringLiteral("cache")] = r.cache;
    o[QStringLiteral("vertices")] = static_cast<qint64>(r.meshes.vertices);
    o[QStringLiteral("triangles")] = static_cast<qint64>(r.meshes.triangles);
    o[QStringLiteral("triangles_extracted")] = static_cast<qint64>(r.meshes.trianglesExtracted);
    o[QStringLiteral("decimation_error_cells")] = r.meshes.worstErrorCells;
    o[QStringLiteral("bytes_per_vertex")] = static_cast<int>(sizeof(data::PackedVertex));
    o[QStringLiteral("gpu_bytes")] = static_cast<qint64>(r.meshes.gpuBytes());
    // Of those, the summaries' surfaces (the P = 0.5 surface and the band's two), which the
    // vertex and triangle counts above leave out.
    o[QStringLiteral("context_gpu_bytes")] =
        static_cast<qint64>(r.meshes.probability.gpuBytes() + r.meshes.bandInner.gpuBytes() +
                            r.meshes.bandOuter.gpuBytes());
    QJsonArray matrix;
    for (std::size_t i = 0; i < r.distances.size; ++i) {
        QJsonArray row;
        for (std::size_t j = 0; j < r.distances.size; ++j) row.append(r.distances.at(i, j));
        matrix.append(row);
    }
    o[QStringLiteral("distance_matrix")] = matrix;
    // Members are named by their numbers, 1..N in the ensemble's order (the member table's #);
    // rows and columns of the matrix above and every per-member array are in that order.
    const auto memberNumber = [](std::size_t index) { return static_cast<qint64>(index) + 1; };
    QJsonArray withoutOverlap;  // pairs whose distance was placed, not measured
    for (const auto& [i, j] : r.distances.pairsWithoutOverlap) {
        withoutOverlap.append(QJsonArray{memberNumber(i), memberNumber(j)});
    }
    o[QStringLiteral("pairs_without_overlap")] = withoutOverlap;
    o[QStringLiteral("linkage_method")] = QString::fromStdString(prep::linkageName(linkage));
    // SciPy's linkage matrix as it is (its node indices count from 0, members first).
    QJsonArray rows;
    for (const prep::Merge& m : r.tree.merges) rows.append(QJsonArray{m.a, m.b, m.height, m.size});
    o[QStringLiteral("linkage")] = rows;
    o[QStringLiteral("k")] = r.k;
    // Each member's cluster by the number the legend, the cluster list and the table show.
    QJsonArray clusterNumbers;
    for (const int number : r.clusterNumbers) clusterNumbers.append(number);
    o[QStringLiteral("clusters")] = clusterNumbers;
    // The colour each member is drawn in (the workbench's for this tree and k).
    QJsonArray colors;
    for (const std::string& color : r.colors) colors.append(QString::fromStdString(color));
    o[QStringLiteral("colors")] = colors;
    // What the workbench's member table shows; NaN (no isosurface) and infinity are null.
    const auto figure = [](double v) { return std::isfinite(v) ? QJsonValue(v) : QJsonValue(); };
    QJsonArray members;
    for (std::size_t m = 0; m < e.memberCount(); ++m) {
        members.append(QJsonObject{{"number", memberNumber(m)},
                                   {"name", memberName(e.members[m], m)},
                                   {"cluster", r.clusterNumbers.at(m)},
                                   {"distance_to_mean", figure(r.distancesToMean[m])},
                                   {"mean_outlyingness", figure(r.meanOutlyingness[m])}});
    }
    o[QStringLiteral("members")] = members;
    // The contour boxplot (METHODS.md section 17): one depth per member, in member order.
    QJsonArray depth, outliers;
    for (const double d : r.boxplot.depth) depth.append(d);
    for (const std::size_t m : r.boxplot.outliers) outliers.append(memberNumber(m));
    o[QStringLiteral("depth")] = depth;
    o[QStringLiteral("median_member")] = memberNumber(r.boxplot.median);
    o[QStringLiteral("outliers")] = outliers;
    if (r.exported) o[QStringLiteral("export")] = exportJson(*r.exported);
    if (r.memory) {
        o[QStringLiteral("memory")] =
            QJsonObject{{"resident_at_start_bytes", static_cast<qint64>(r.memory->residentAtStart)},
                        {"peak_resident_bytes", static_cast<qint64>(r.memory->peakResident)}};
    }
    // How it was read when it was streamed (absent when it was read whole: every value in the
    // JSON is a number or a string, never null).
    if (r.streaming) {
        std::size_t thickest = 0;
        for (const auto& slab : r.streaming->slabs) thickest = std::max(thickest, slab.layerCount);
        o[QStringLiteral("streaming")] =
            QJsonObject{{"memory_limit_bytes", static_cast<qint64>(r.streaming->memoryLimit)},
                        {"slabs", static_cast<qint64>(r.streaming->slabs.size())},
                        {"layers_per_slab", static_cast<qint64>(thickest)},
                        {"members_at_once", static_cast<qint64>(r.streaming->membersAtOnce)},
                        {"planned_peak_bytes", static_cast<qint64>(r.streaming->peakBytes())},
                        {"rank_work_cpu_seconds", [&] {
                             QJsonArray seconds;
                             for (const double s : r.rankWorkSeconds) seconds.append(s);
                             return seconds;
                         }()}};
    }
    return o;
}

void printText(QTextStream& out, const Result& r) {
    const auto& m = r.meshes;
    const data::Ensemble& e = *r.ensemble;
    const int k = r.k;
    out << "Ensemble:   " << e.memberCount() << " members of " << QString::fromStdString(e.variable)
        << " on " << e.grid.nx() << " x " << e.grid.ny() << " x " << e.grid.nz() << ", isovalue "
        << m.isovalue;
    if (!r.membersWithoutData.empty()) {
        out << " (" << r.membersWithoutData.size() << " without data left out)";
    }
    out << "\n";
    out << "Triangles:  " << m.trianglesExtracted << " extracted, " << m.triangles
        << " after decimation (error <= " << m.worstErrorCells << " cells); " << m.vertices
        << " vertices, " << sizeof(data::PackedVertex) << " bytes each\n";
    out << "GPU data:   " << QString::number(static_cast<double>(m.gpuBytes()) / 1048576.0, 'f', 2)
        << " MiB (cache: " << r.cache << ")\n";
    out << "Seconds:   ";
    for (const auto& [name, value] : r.seconds) {
        out << " " << QString::fromStdString(name) << " " << QString::number(value, 'f', 3);
    }
    out << "\n";
    if (r.memory) {
        const auto mibText = [](std::size_t bytes) {
            return QString::number(static_cast<double>(bytes) / 1048576.0, 'f', 0);
        };
        out << "Memory:     peak " << mibText(r.memory->peakResident) << " MiB resident, "
            << mibText(r.memory->residentAtStart) << " MiB of it before the run\n";
    }
    if (r.exported) printExport(out, *r.exported);
    std::map<int, int> sizes;  // by cluster number
    for (const int number : r.clusterNumbers) ++sizes[number];
    out << "Clusters:   " << k << ", members in each (cluster:members)";
    for (const auto& [number, size] : sizes) out << " " << number << ":" << size;
    out << "\n";
    if (!r.boxplot.depth.empty()) {
        const std::size_t median = r.boxplot.median;
        out << "Boxplot:    median " << memberName(e.members[median], median) << " (depth "
            << r.boxplot.depth[median] << "), ";
        if (r.boxplot.outliers.empty()) {
            out << "no outliers";
        } else {
            out << "outliers";
            const char* separator = " ";
            for (const std::size_t outlier : r.boxplot.outliers) {
                out << separator << memberName(e.members[outlier], outlier);
                separator = ", ";
            }
        }
        out << "\n";
    }
}

// What a step adds to the one-isovalue JSON: its time (its "clusters" are numbered as matched
// to the previous step's, so that a group keeps its number).
QJsonObject stepJson(const engine::TimeStepResult& step, prep::Linkage linkage,
                     const QString& cache) {
    Result r;
    static_cast<engine::PreprocessResult&>(r) = step.result;
    r.cache = cache;
    QJsonObject o = toJson(r, linkage);
    o[QStringLiteral("time")] = QString::fromStdString(step.time);
    o[QStringLiteral("time_index")] = static_cast<qint64>(step.index);
    return o;
}

// One line a step: its time, the clusters by the number the legend shows (identity + 1) with
// their sizes, and the members that changed cluster since the previous step.
void printStep(QTextStream& out, const engine::TimeStepResult& step,
               const engine::TimeStepResult* previous) {
    std::map<int, int> sizes;
    for (const int identity : step.memberIdentities) ++sizes[identity];
    out << QString::fromStdString(step.time) << "  clusters";
    for (const auto& [identity, size] : sizes) out << " " << identity + 1 << ":" << size;
    if (previous != nullptr) {
        std::map<std::string, int> before;
        const auto& members = previous->result.ensemble->members;
        for (std::size_t m = 0; m < members.size(); ++m) {
            before[members[m].name] = previous->memberIdentities[m];
        }
        QStringList moved;
        const auto& now = step.result.ensemble->members;
        for (std::size_t m = 0; m < now.size(); ++m) {
            const auto at = before.find(now[m].name);
            if (at != before.end() && at->second != step.memberIdentities[m]) {
                moved << QStringLiteral("%1 %2->%3")
                             .arg(QString::fromStdString(now[m].name))
                             .arg(at->second + 1)
                             .arg(step.memberIdentities[m] + 1);
            }
        }
        out << "; moved: " << (moved.isEmpty() ? QStringLiteral("none") : moved.join(", "));
    }
    out << "\n";
}

int runTimeSeries(const QString& times, const data::DataSelection& selection,
                  const engine::PreprocessRequest& preprocess, bool json, CommandProgress& progress,
                  const std::optional<ExportRequest>& exportTo, QTextStream& out,
                  QTextStream& err) {
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    std::string problem;
    const auto range = engine::parseStepRange(times.toStdString(), d.timeSteps.count(),
                                              "'" + selection.paths.front() + "'", problem);
    if (!range) {
        err << "ensil preprocess: " << QString::fromStdString(problem) << "\n";
        return 2;
    }
    engine::TimeSeriesRequest request{
        .selection = selection, .steps = *range, .preprocess = preprocess};
    const QString cache = !preprocess.cacheDirectory ? QStringLiteral("off") : QString();
    std::vector<engine::TimeStepResult> steps = engine::preprocessTimeSeries(
        request,
        [&](const std::string& kind, const std::string& text) {
            progress.endLine();
            err << "ensil preprocess: " << QString::fromStdString(kind) << ": "
                << QString::fromStdString(text) << "\n";
        },
        {}, progress.callback(QStringLiteral("time steps")));
    progress.endLine();
    std::optional<engine::ExportedSurfaces> exported;
    if (exportTo) {
        exported = engine::exportTimeSeriesSurfaces(steps, exportTo->format, exportTo->directory,
                                                    exportTo->displayFrame);
    }
    const auto cacheOf = [&](const engine::TimeStepResult& step) {
        return !cache.isEmpty()        ? cache
               : step.result.fromCache ? QStringLiteral("hit")
                                       : QStringLiteral("miss");
    };
    if (json) {
        QJsonObject o;
        o[QStringLiteral("variable")] = QString::fromStdString(d.variable);
        o[QStringLiteral("time_dimension")] = QString::fromStdString(d.timeSteps.dimension);
        o[QStringLiteral("isovalue")] = steps.front().result.meshes.isovalue;
        o[QStringLiteral("k")] = steps.front().result.k;
        QJsonArray array;
        for (const engine::TimeStepResult& step : steps) {
            array.append(stepJson(step, preprocess.linkage, cacheOf(step)));
        }
        o[QStringLiteral("steps")] = array;
        if (exported) o[QStringLiteral("export")] = exportJson(*exported);
        out << QJsonDocument(o).toJson(QJsonDocument::Compact) << "\n";
        return 0;
    }
    const engine::TimeStepResult& first = steps.front();
    out << "Ensemble:   " << first.result.ensemble->memberCount() << " members of "
        << QString::fromStdString(d.variable) << ", isovalue " << first.result.meshes.isovalue
        << ", " << steps.size() << (steps.size() == 1 ? " step" : " steps") << " of "
        << QString::fromStdString(d.timeSteps.dimension) << "; clusters by number (colour)\n";
    for (std::size_t s = 0; s < steps.size(); ++s) {
        printStep(out, steps[s], s == 0 ? nullptr : &steps[s - 1]);
    }
    if (exported) printExport(out, *exported);
    return 0;
}

}  // namespace

int runPreprocessCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Mesh every member's isosurface and the mean's, decimate, compute per-vertex "
        "attributes, the similarity matrix and the clustering, for one isovalue."));
    parser.addHelpOption();
    const DataSelectionOptions selectionOptions;
    selectionOptions.addTo(parser);
    const Options o;
    parser.addOptions({o.iso, o.error, o.noDecimation, o.noCache, o.cacheDir, o.demo, o.json,
                       o.times, o.memoryLimit, o.exportDir, o.format, o.coordinates, o.quiet});
    clusterOptions().addTo(parser);
    if (auto done = parseSubcommand(parser, args, QStringLiteral("preprocess"), out, err))
        return *done;
    QString problem;
    const auto selection = selectionOptions.selection(parser, problem);
    session::SessionState requested;
    if (selection && selection->paths.empty() != parser.isSet(o.demo)) {
        problem = QStringLiteral("name the files to preprocess, or use --demo");
    } else if (selection && parser.isSet(o.times) && parser.isSet(QStringLiteral("time-index"))) {
        problem = QStringLiteral(
            "--times and --time-index are refused together: --times names the steps");
    } else if (selection && parser.isSet(o.times) && parser.isSet(o.demo)) {
        problem = QStringLiteral(
            "--times is refused with --demo: the built-in demo has no time steps; write one "
            "that has with ensil generate --times T --out FILE.nc");
    }
    if (selection && problem.isEmpty() && parser.isSet(o.memoryLimit) &&
        (parser.isSet(o.times) || parser.isSet(o.demo))) {
        problem = QStringLiteral(
            "--memory-limit is refused with --times and --demo: it applies to one ensemble read "
            "from files");
    }
    const auto exportFormat = engine::surfaceFormatNamed(parser.value(o.format).toStdString());
    if (selection && problem.isEmpty()) {
        if (!exportFormat) {
            problem = QStringLiteral("--format %1 is refused: it is one of %2")
                          .arg(parser.value(o.format),
                               QString::fromStdString(engine::surfaceFormatNames()));
        } else if ((parser.isSet(o.format) || parser.isSet(o.coordinates)) &&
                   !parser.isSet(o.exportDir)) {
            problem = QStringLiteral(
                "--format and --coordinates are for --export DIR, which is "
                "missing");
        } else if (parser.value(o.coordinates) != QStringLiteral("data") &&
                   parser.value(o.coordinates) != QStringLiteral("display")) {
            problem = QStringLiteral("--coordinates %1 is refused: it is data or display")
                          .arg(parser.value(o.coordinates));
        } else if (parser.isSet(o.exportDir) && parser.value(o.exportDir).trimmed().isEmpty()) {
            problem = QStringLiteral("--export '' is refused: name a folder to write into");
        }
    }
    std::optional<std::size_t> memoryLimit;
    if (selection && problem.isEmpty() && parser.isSet(o.memoryLimit)) {
        std::string why;
        memoryLimit = engine::parseMemorySize(parser.value(o.memoryLimit).toStdString(), why);
        if (!memoryLimit) problem = QString::fromStdString(why);
    }
    // No --iso: the workbench's default for the variable, chosen once the data is read.
    std::optional<double> iso;
    if (problem.isEmpty() && selection && parser.isSet(o.iso)) {
        iso = session::parseBoundedNumber(QStringLiteral("--iso"), parser.value(o.iso), -1e30, 1e30,
                                          false, problem);
    }
    const bool isoOk = !parser.isSet(o.iso) || iso.has_value();
    const auto errorCells =
        isoOk && problem.isEmpty()
            ? session::parseBoundedNumber(QStringLiteral("--error"), parser.value(o.error), 0.001,
                                          10.0, false, problem)
            : std::nullopt;
    if (!selection || !isoOk || !errorCells || (parser.isSet(o.memoryLimit) && !memoryLimit) ||
        !clusterOptions().applyTo(parser, requested, problem)) {
        err << "ensil preprocess: " << problem << "\n";
        return 2;
    }
    const engine::RunMemoryMeter memory;
    CommandProgress progress(err, QStringLiteral("ensil preprocess"),
                             CommandProgress::shownOnThisTerminal(parser.isSet(o.quiet)));
    QElapsedTimer total, stage;
    total.start();
    try {
        const prep::Linkage linkage = requested.linkage;
        const data::DemoEnsembleParams demo;
        engine::PreprocessRequest request;
        request.isovalue = iso;
        request.clusters = requested.clusters;
        request.clustersGiven = clusterOptions().given(parser).contains("--clusters");
        request.linkage = linkage;
        request.decimate = !parser.isSet(o.noDecimation);
        request.errorCells = *errorCells;
        if (!parser.isSet(o.noCache)) {
            if (parser.isSet(o.cacheDir) && parser.value(o.cacheDir).trimmed().isEmpty()) {
                err << "ensil preprocess: --cache-dir '' is refused: name a folder, or use "
                       "--no-cache\n";
                return 2;
            }
            request.cacheDirectory = parser.isSet(o.cacheDir)
                                         ? parser.value(o.cacheDir).toStdString()
                                         : engine::defaultMeshCacheDirectory();
        }
        std::optional<ExportRequest> exportTo;
        if (parser.isSet(o.exportDir)) {
            exportTo = ExportRequest{*exportFormat, parser.value(o.exportDir).toStdString(),
                                     parser.value(o.coordinates) == QStringLiteral("display")};
        }
        const auto printResult = [&](Result& r) {
            if (exportTo) r.exported = exportResult(r, *exportTo);
            progress.endLine();
            r.seconds["total"] = seconds(total);
            r.memory = memory.read();
            if (parser.isSet(o.json)) {
                out << QJsonDocument(toJson(r, linkage)).toJson(QJsonDocument::Compact) << "\n";
            } else {
                printText(out, r);
            }
        };
#ifdef ENSIL_WITH_MPI
        if (runningUnderMpi()) {
            if (parser.isSet(o.times) || parser.isSet(o.demo)) {
                err << "ensil preprocess: --times and --demo are refused under mpirun: it "
                       "preprocesses one ensemble read from NetCDF files\n";
                return 2;
            }
            return runDistributedPreprocess(
                *selection, request, memoryLimit,
                [&](engine::PreprocessResult&& result) {
                    Result r;
                    static_cast<engine::PreprocessResult&>(r) = std::move(result);
                    r.cache =
                        request.cacheDirectory ? QStringLiteral("stored") : QStringLiteral("off");
                    printResult(r);
                },
                err);
        }
#endif
        if (parser.isSet(o.times)) {
            return runTimeSeries(parser.value(o.times), *selection, request, parser.isSet(o.json),
                                 progress, exportTo, out, err);
        }
        const auto notice = [&](const std::string& kind, const std::string& text) {
            progress.endLine();
            err << "ensil preprocess: " << QString::fromStdString(kind) << ": "
                << QString::fromStdString(text) << "\n";
        };
        if (!parser.isSet(o.demo)) {
            // An ensemble larger than the memory budget is read in slabs instead of refused.
            const std::size_t limit = memoryLimit.value_or(engine::defaultMemoryLimit());
            const data::EnsembleDescription description = data::describeEnsemble(*selection);
            if (engine::inMemoryPeakBytes(description) > limit && engine::canStream(*selection)) {
                request.sourceKey = data::sourceIdentity(*selection);
                Result r;
                static_cast<engine::PreprocessResult&>(r) =
                    engine::preprocessStreaming(*selection, description, request, limit, notice, {},
                                                progress.callback(QStringLiteral("preprocessing")));
                r.cache = request.cacheDirectory ? QStringLiteral("stored") : QStringLiteral("off");
                printResult(r);
                return 0;
            }
        }
        stage.start();
        auto ensemble = std::make_shared<const data::Ensemble>(
            parser.isSet(o.demo)
                ? data::makeDemoEnsemble(demo, {}, progress.callback(QStringLiteral("generating")))
                      .ensemble
                : data::openEnsemble(*selection, {}, progress.callback(QStringLiteral("reading"))));
        const double loadSeconds = seconds(stage);
        request.sourceKey = parser.isSet(o.demo) ? "demo members=" + std::to_string(demo.members) +
                                                       " seed=" + std::to_string(demo.seed)
                                                 : data::sourceIdentity(*selection);
        Result r;
        static_cast<engine::PreprocessResult&>(r) =
            engine::preprocessEnsemble(std::move(ensemble), request, notice, {},
                                       progress.callback(QStringLiteral("preprocessing")));
        r.seconds["load"] = loadSeconds;
        r.cache = !request.cacheDirectory ? QStringLiteral("off")
                  : r.fromCache           ? QStringLiteral("hit")
                                          : QStringLiteral("miss");
        printResult(r);
        return 0;
    } catch (const engine::PreprocessRefused& e) {
        progress.endLine();
        err << "ensil preprocess: " << e.what() << "\n";
        return e.exitCode();
    } catch (const data::Error& e) {
        progress.endLine();
        err << "ensil preprocess: " << e.what() << "\n";
        return dataFailureStatus(e);
    } catch (const std::bad_alloc&) {
        progress.endLine();
        err << "ensil preprocess: not enough memory\n";
        return 1;
    }
}

}  // namespace ensil::cli
