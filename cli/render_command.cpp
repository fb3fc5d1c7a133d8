#include "cli/render_command.h"

#include <QCommandLineParser>
#include <QGuiApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <glm/geometric.hpp>
#include <optional>

#include "cli/command_progress.h"
#include "cli/data_selection_options.h"
#include "cli/subcommand.h"
#include "engine/session_renderer.h"
#include "engine/time_series.h"
#include "session/project_file.h"
#include "session/setting_options.h"
#include "session/view_presets.h"

namespace ensil::cli {
namespace {

struct Options {
    QCommandLineOption iso{"iso",
                           "The isovalue (default: the workbench's, where most members have a "
                           "surface in the middle of the box and differ; --json reports it).",
                           "X"};
    QCommandLineOption output{"out", "The PNG file to write (required).", "FILE.png"};
    QCommandLineOption size{"size", "Image size in pixels (default 1600x1000).", "WxH",
                            "1600x1000"};
    QCommandLineOption plane{
        "plane",
        "Cutting plane with normal NX,NY,NZ (x east, y north, z up) at OFFSET across the data "
        "box: -1 and 1 touch its far corners, 0 is its centre. The side the camera looks from "
        "is cut away.",
        "NX,NY,NZ,OFFSET"};
    QCommandLineOption removal{"removal",
                               "Density-based silhouette removal between o*_min and o*_max (in "
                               "the variable's units squared).",
                               "MIN,MAX"};
    QCommandLineOption noLabels{"no-labels",
                                "Leave out the axis labels and the cluster legend (as "
                                "--no-axis-labels --no-legend)."};
    QCommandLineOption view{
        "view",
        QString::fromStdString(
            "Look from a named view: " + session::viewPresetNames() +
            " (top: a map, north up, orthographic unless --projection says otherwise). "
            "--azimuth and --elevation, when given too, override its angles."),
        "NAME"};
    // One picture is drawn once; timing is asked for (benchmarks draw more to take a median).
    QCommandLineOption frames{
        "frames",
        "Draw the picture N times and report the median time as frame_ms (default 1: drawn once).",
        "N", "1"};
    QCommandLineOption noCache{"no-cache", "Neither read nor write the preprocessing cache."};
    QCommandLineOption demo{"demo", "Use the built-in demo ensemble instead of files."};
    QCommandLineOption json{"json",
                            "Print frame_ms, gpu_bytes, width, height, vertical_scale... as JSON."};
    QCommandLineOption times{
        "times",
        "Draw one picture per time step from A to B, both included (time indices from 0, as "
        "--time-index counts them), or all of them, with the same camera and settings, each "
        "titled with its time and its clusters matched to the previous step's so colours follow "
        "the groups. --out must then hold one printf-style number, e.g. frame_%03d.png, which "
        "becomes the time index.",
        "all|A:B"};
    QCommandLineOption quiet = CommandProgress::quietOption();
    QCommandLineOption saveProject{
        "save-project",
        "Also write the session drawn as a project: `ensil render P.ensil` then draws the same "
        "picture, and the workbench opens it as drawn.",
        "P.ensil"};
};

// The settings the command line sets, each with its range from the one setting table.
const session::SettingOptions& sceneOptions() {
    // A table, four names a row.
    // clang-format off
    static const session::SettingOptions options{
        "mode",        "clusters",        "linkage",         "show_mean",
        "thickness",   "surface_opacity", "group_size",      "vertical_exaggeration",
        "azimuth",     "elevation",       "projection",      "background",
        "axis_labels", "legend",          "plane_thickness", "coastlines",
        "borders",     "graticule",       "mean_opacity",    "title",
        "floor",       "floor_level",     "rims",            "context",
        "band",        "section",         "context_spread",  "vertical_axis"};
    // clang-format on
    return options;
}

// N comma-separated finite numbers, or nothing when the text is not exactly that.
std::optional<std::vector<double>> parseNumbers(const QString& name, const QString& text,
                                                const QString& form, QString& problem) {
    const QStringList parts = text.split(QLatin1Char(','));
    const auto count = form.count(QLatin1Char(',')) + 1;
    if (parts.size() != count) {
        problem = QStringLiteral(
                      "%1 '%2' is refused: it must be %3 (%4 numbers separated by "
                      "commas)")
                      .arg(name, text, form)
                      .arg(count);
        return std::nullopt;
    }
    std::vector<double> numbers;
    for (const QString& part : parts) {
        const auto v = session::parseBoundedNumber(name, part, -1e30, 1e30, false, problem);
        if (!v) return std::nullopt;
        numbers.push_back(*v);
    }
    return numbers;
}

// The session the options describe; nullopt with `problem` set when one is refused.
std::optional<session::SessionState> sessionFromOptions(const QCommandLineParser& parser,
                                                        const Options& o,
                                                        const data::DataSelection& selection,
                                                        engine::RenderRequest& request,
                                                        QString& problem) {
    session::SessionState state;
    state.demo = parser.isSet(o.demo);
    if (!state.demo) state.data = selection;
    if (parser.isSet(o.iso)) {  // otherwise the workbench's default for the variable
        const auto iso = session::parseBoundedNumber(QStringLiteral("--iso"), parser.value(o.iso),
                                                     -1e30, 1e30, false, problem);
        if (!iso) return std::nullopt;
        state.isovalue = static_cast<float>(*iso);
    }
    // The view first: the angles and projection given as options then override it.
    if (parser.isSet(o.view)) {
        const session::ViewPreset* preset =
            session::findViewPreset(parser.value(o.view).toStdString());
        if (preset == nullptr) {
            problem =
                QStringLiteral("--view '%1' is refused: it must be one of %2")
                    .arg(parser.value(o.view), QString::fromStdString(session::viewPresetNames()));
            return std::nullopt;
        }
        session::lookFrom(*preset, state.camera);
    }
    if (!sceneOptions().applyTo(parser, state, problem)) return std::nullopt;
    request.clustersGiven = sceneOptions().given(parser).contains(QStringLiteral("--clusters"));
    if (parser.isSet(o.noLabels)) state.render.showAxes = state.render.showLegend = false;
    if (parser.isSet(o.removal)) {
        const auto range = parseNumbers(QStringLiteral("--removal"), parser.value(o.removal),
                                        QStringLiteral("MIN,MAX"), problem);
        if (!range) return std::nullopt;
        const session::Setting& low = session::setting("removal_min");
        for (const double v : *range) {
            if (const std::string why = low.problemWith(v); !why.empty()) {
                problem = QStringLiteral("--removal '%1' is refused: each bound %2")
                              .arg(parser.value(o.removal), QString::fromStdString(why));
                return std::nullopt;
            }
        }
        if ((*range)[0] >= (*range)[1]) {
            problem = QStringLiteral("--removal '%1' is refused: MIN must be below MAX")
                          .arg(parser.value(o.removal));
            return std::nullopt;
        }
        state.render.removal = true;
        state.render.removalMin = static_cast<float>((*range)[0]);
        state.render.removalMax = static_cast<float>((*range)[1]);
    }
    if (parser.isSet(o.plane)) {
        const auto p = parseNumbers(QStringLiteral("--plane"), parser.value(o.plane),
                                    QStringLiteral("NX,NY,NZ,OFFSET"), problem);
        if (!p) return std::nullopt;
        const glm::vec3 normal((*p)[0], (*p)[1], (*p)[2]);
        if (!(glm::length(normal) > 0.0F) || !std::isfinite(glm::length(normal)) ||
            (*p)[3] < -4.0 || (*p)[3] > 4.0) {
            problem = QStringLiteral(
                          "--plane '%1' is refused: it must be NX,NY,NZ,OFFSET with a non-zero "
                          "normal and OFFSET from -4 to 4")
                          .arg(parser.value(o.plane));
            return std::nullopt;
        }
        state.render.plane.enabled = true;
        request.planeAcrossBox = glm::vec4(normal, static_cast<float>((*p)[3]));
    }
    // A fill nothing would show is refused rather than drawn as an empty face.
    const QString fill = QString::fromStdString(
        session::setting("section").format(static_cast<double>(state.render.plane.fill)));
    if (state.render.plane.fill != gl::SectionField::None && !state.render.plane.enabled) {
        problem =
            QStringLiteral("--section %1 needs --plane: it fills the plane's cut face").arg(fill);
        return std::nullopt;
    }
    if (state.render.plane.fill == gl::SectionField::Member) {
        problem = QStringLiteral(
            "--section member shows the first selected member, and the command line selects "
            "none: select members in the workbench, save a project (.ensil) and render it");
        return std::nullopt;
    }
    return state;
}

// True when `pattern` holds exactly one printf-style whole-number field (%d, %03d) and no other
// conversion, so that QString::asprintf gives one file name per step.
bool isFramePattern(const QString& pattern) {
    static const QRegularExpression one(QStringLiteral("^[^%]*%0?[0-9]{0,2}d[^%]*$"));
    return one.match(pattern).hasMatch();
}

// One picture per step of `range`: the first step's drawn session (isovalue, camera) is the
// next one's, only the time index changes; each step's clusters are matched to the previous,
// and the floor's colours span one scale over all the steps.
int renderTimes(const session::SessionState& first, engine::RenderRequest request,
                const engine::StepRange& range, const QString& pattern, CommandProgress& progress,
                QTextStream& out, QTextStream& err) {
    session::SessionState state = first;
    // One colour scale for the floor over every frame, so that a colour means the same value
    // in each; the colour bar says so.
    if (const auto scale = engine::floorScaleOverSteps(first.data, range, first.render)) {
        request.floorRange = scale;
        request.floorRangeNote = ", one scale for all " + std::to_string(range.count()) + " steps";
        out << "floor colours: one scale for all " << range.count() << " steps, " << scale->first
            << " to " << scale->second << "\n";
    }
    for (std::size_t t = range.first; t <= range.last; ++t) {
        state.data.timeIndex = t;
        const std::string step = "time step " + std::to_string(t - range.first + 1) + " of " +
                                 std::to_string(range.count()) + ", ";
        request.progress = [&progress, step](const std::string& stage, double fraction) {
            progress.report(QString::fromStdString(step + stage), fraction);
        };
        const engine::RenderOutcome result = engine::renderSession(state, request);
        progress.endLine();
        const QString path =
            range.count() == 1 && !isFramePattern(pattern)
                ? pattern
                : QString::asprintf(pattern.toUtf8().constData(), static_cast<int>(t));
        if (!result.image.save(path)) {
            err << "ensil render: cannot write '" << path << "'\n";
            return 1;
        }
        out << "wrote " << path << ": time index " << t << ", " << result.members << " members at "
            << result.drawn.isovalue.value_or(0.0F) << "\n";
        state = result.drawn;
        request.previousMembers = result.memberNames;
        request.previousIdentities = result.memberIdentities;
    }
    return 0;
}

}  // namespace

int runRenderCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Draw an ensemble's isosurfaces as silhouettes into a PNG, without a window. With no "
        "display server (a batch node), it draws through Mesa's EGL surfaceless platform. "
        "Give data files with the options below, or one project (.ensil), which defines the "
        "whole picture."));
    parser.addHelpOption();
    const DataSelectionOptions selectionOptions;
    selectionOptions.addTo(parser);
    const Options o;
    parser.addOptions({o.iso, o.output, o.size, o.plane, o.removal, o.noLabels, o.view, o.frames,
                       o.noCache, o.demo, o.json, o.saveProject, o.times, o.quiet});
    sceneOptions().addTo(parser);
    if (auto done = parseSubcommand(parser, args, QStringLiteral("render"), out, err)) return *done;

    QString problem;
    engine::RenderRequest request;
    std::optional<session::SessionState> state;
    const auto selection = selectionOptions.selection(parser, problem);
    const auto size =
        session::parseImageSize(QStringLiteral("--size"), parser.value(o.size), problem);
    const auto frames = session::parseBoundedNumber(
        QStringLiteral("--frames"), parser.value(o.frames), 1, 10000, true, problem);
    const bool fromProject =
        selection && selection->paths.size() == 1 &&
        QString::fromStdString(selection->paths.front()).endsWith(QLatin1String(".ensil"));
    if (!selection || !size || !frames) {
        if (problem.isEmpty()) problem = QStringLiteral("bad data selection");
    } else if (!parser.isSet(o.output)) {
        problem = QStringLiteral("say where to write the image with --out FILE.png");
    } else if (fromProject) {
        // The project defines the picture; only where it goes and how big it is may be given.
        QStringList scene = sceneOptions().given(parser);
        for (const QCommandLineOption* option : {&o.iso, &o.plane, &o.removal, &o.demo}) {
            if (parser.isSet(*option)) scene << QStringLiteral("--") + option->names().front();
        }
        if (!scene.isEmpty()) {
            problem = QStringLiteral(
                          "%1 comes from the project; change it in the workbench and save the "
                          "project")
                          .arg(scene.front());
        }
    } else if (selection->paths.empty() != parser.isSet(o.demo)) {
        problem = QStringLiteral("name the files to render, or use --demo");
    } else if (parser.isSet(o.times) &&
               (parser.isSet(o.demo) || parser.isSet(QStringLiteral("time-index")) ||
                parser.isSet(o.saveProject) || parser.isSet(o.json))) {
        problem = parser.isSet(o.demo)
                      ? QStringLiteral(
                            "--times is refused with --demo: the built-in demo has no "
                            "time steps; write one that has with ensil generate "
                            "--times T --out FILE.nc")
                      : QStringLiteral(
                            "--times is refused with --time-index, --save-project "
                            "and --json: it draws several steps");
    } else {
        state = sessionFromOptions(parser, o, *selection, request, problem);
    }
    if (problem.isEmpty() && parser.isSet(o.times) && fromProject) {
        problem = QStringLiteral("--times draws data files, not a project: name the files");
    }
    std::optional<engine::StepRange> range;
    if (problem.isEmpty() && parser.isSet(o.times)) {
        std::string why;
        try {
            range = engine::parseStepRange(parser.value(o.times).toStdString(),
                                           data::describeEnsemble(*selection).timeSteps.count(),
                                           "'" + selection->paths.front() + "'", why);
        } catch (const std::exception& e) {
            err << "ensil render: " << e.what() << "\n";
            return dataFailureStatus(e);
        }
        if (!range) {
            problem = QString::fromStdString(why);
        } else if (range->count() > 1 && !isFramePattern(parser.value(o.output))) {
            // Concatenated, not arg()-ed: QString::arg would take "%03" for a place marker.
            problem = QStringLiteral("--out '") + parser.value(o.output) +
                      QStringLiteral("' is refused with --times ") + parser.value(o.times) +
                      QStringLiteral(": it draws ") + QString::number(range->count()) +
                      QStringLiteral(
                          " pictures, so --out must hold one number pattern such as "
                          "frame_%03d.png");
        }
    }
    if (!problem.isEmpty()) {
        err << "ensil render: " << problem << "\n";
        return 2;
    }
    CommandProgress progress(err, QStringLiteral("ensil render"),
                             CommandProgress::shownOnThisTerminal(parser.isSet(o.quiet)));
    try {
        if (fromProject)
            state = session::loadProject(QString::fromStdString(selection->paths.front()));
        request.width = size->first;
        request.height = size->second;
        request.frames = static_cast<int>(*frames);
        request.useCache = !parser.isSet(o.noCache);
        if (range) {
            return renderTimes(*state, request, *range, parser.value(o.output), progress, out, err);
        }
        request.progress = [&progress](const std::string& stage, double fraction) {
            progress.report(QString::fromStdString(stage), fraction);
        };
        const engine::RenderOutcome result = engine::renderSession(*state, request);
        progress.endLine();
        if (!result.image.save(parser.value(o.output))) {
            err << "ensil render: cannot write '" << parser.value(o.output) << "'\n";
            return 1;
        }
        if (!result.note.empty()) {
            err << "ensil render: note: " << QString::fromStdString(result.note) << "\n";
        }
        if (parser.isSet(o.saveProject))
            session::saveProject(result.drawn, parser.value(o.saveProject));
        if (parser.isSet(o.json)) {
            QJsonObject json{
                {"frame_ms", result.frameMs},
                {"gpu_bytes", static_cast<qint64>(result.gpuBytes)},
                {"width", result.image.width()},
                {"height", result.image.height()},
                {"frames", request.frames},
                {"isovalue", result.drawn.isovalue.value_or(0.0F)},
                {"variable", QString::fromStdString(result.variable)},
                {"triangles", static_cast<qint64>(result.triangles)},
                {"members", static_cast<qint64>(result.members)},
                {"gl_renderer", QString::fromStdString(result.glRenderer)},
                {"display", result.withoutDisplay ? QStringLiteral("none (EGL surfaceless)")
                                                  : QGuiApplication::platformName()}};
            // The figure's stated vertical scale ("vertical ×480"), and whence its heights came.
            if (result.verticalScale) {
                json.insert("vertical_scale", result.verticalScale->factor);
                json.insert("vertical_heights", result.verticalScale->standardAtmosphere
                                                    ? QStringLiteral("standard atmosphere")
                                                    : QStringLiteral("the axis"));
            }
            out << QJsonDocument(json).toJson(QJsonDocument::Compact) << "\n";
        } else {
            out << "wrote " << parser.value(o.output) << ": " << result.image.width() << " x "
                << result.image.height() << ", " << result.members << " members at "
                << result.drawn.isovalue.value_or(0.0F);
            if (request.frames == 1) {
                out << ", drawn in " << QString::number(result.frameMs, 'f', 1) << " ms\n";
            } else {
                out << ", median frame " << QString::number(result.frameMs, 'f', 1) << " ms over "
                    << request.frames << " frames\n";
            }
        }
        return 0;
    } catch (const std::exception& e) {
        progress.endLine();
        err << "ensil render: " << e.what() << "\n";
        return dataFailureStatus(e);
    }
}

}  // namespace ensil::cli
