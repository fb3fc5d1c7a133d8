#include "app/render_command.h"

#include <QCommandLineParser>
#include <QGuiApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

#include "app/data_selection_options.h"
#include "app/generate_command.h"
#include "app/project.h"
#include "app/project_renderer.h"
#include "app/subcommand.h"

namespace ensil::app {
namespace {

struct Options {
    QCommandLineOption iso{"iso", "The isovalue (required).", "X"};
    QCommandLineOption output{"out", "The PNG file to write (required).", "FILE.png"};
    QCommandLineOption size{"size", "Image size in pixels (default 1600x1000).", "WxH",
                            "1600x1000"};
    QCommandLineOption mode{"mode", "shaded (default), spaghetti, surfaces or opaque.", "M",
                            "shaded"};
    QCommandLineOption clusters{"clusters", "Number of clusters to colour by (default 5).", "K",
                                "5"};
    QCommandLineOption linkage{"linkage", "average (default), single, complete or ward.", "L",
                               "average"};
    QCommandLineOption mean{"mean", "Draw the mean member's surface (the default)."};
    QCommandLineOption noMean{"no-mean", "Do not draw the mean member's surface."};
    QCommandLineOption thickness{"thickness", "Silhouette thickness tau (default 0.006).", "T",
                                 "0.006"};
    QCommandLineOption exaggeration{"exaggeration", "Vertical exaggeration (default 1).", "F", "1"};
    QCommandLineOption azimuth{"azimuth", "Camera azimuth in degrees (default -75).", "A", "-75"};
    QCommandLineOption elevation{"elevation", "Camera elevation in degrees (default 30).", "E",
                                 "30"};
    QCommandLineOption plane{
        "plane",
        "Cutting plane with normal NX,NY,NZ (x east, y north, z up) at OFFSET across the data "
        "box: -1 and 1 touch its far corners, 0 is its centre. The side the camera looks from "
        "is cut away.",
        "NX,NY,NZ,OFFSET"};
    QCommandLineOption planeThickness{
        "plane-thickness", "Width eps of the intersection curves (default 0.004).", "EPS", "0.004"};
    QCommandLineOption removal{"removal",
                               "Density-based silhouette removal between o*_min and o*_max (in "
                               "the variable's units squared).",
                               "MIN,MAX"};
    QCommandLineOption groupSize{"group-size", "Group size s_G of the removal (default 4).", "S",
                                 "4"};
    QCommandLineOption noLabels{"no-labels", "Leave out the axis labels and the cluster legend."};
    QCommandLineOption frames{"frames", "Frames to time for frame_ms (default 20).", "N", "20"};
    QCommandLineOption noCache{"no-cache", "Neither read nor write the preprocessing cache."};
    QCommandLineOption demo{"demo", "Use the built-in demo ensemble instead of files."};
    QCommandLineOption json{"json", "Print frame_ms, gpu_bytes, width, height as JSON."};
};

std::optional<gl::RenderMode> parseMode(const QString& name) {
    if (name == QLatin1String("shaded")) return gl::RenderMode::ShadedSilhouettes;
    if (name == QLatin1String("spaghetti")) return gl::RenderMode::Spaghetti;
    if (name == QLatin1String("surfaces")) return gl::RenderMode::Surfaces;
    if (name == QLatin1String("opaque")) return gl::RenderMode::OpaqueSurfaces;
    return std::nullopt;
}

// N comma-separated numbers, or nothing when the text is not exactly that.
std::optional<std::vector<float>> parseNumbers(const QString& text, int count) {
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() != count) return std::nullopt;
    std::vector<float> numbers;
    for (const QString& part : parts) {
        bool ok = false;
        numbers.push_back(part.trimmed().toFloat(&ok));
        if (!ok || !std::isfinite(numbers.back())) return std::nullopt;
    }
    return numbers;
}

}  // namespace

int runRenderCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Draw an ensemble's isosurfaces as silhouettes into a PNG, without a window. With no "
        "display server (a batch node), it draws through Mesa's EGL surfaceless platform."));
    parser.addHelpOption();
    const DataSelectionOptions selectionOptions;
    selectionOptions.addTo(parser);
    const Options o;
    parser.addOptions({o.iso,     o.output,    o.size,     o.mode,      o.clusters,
                       o.linkage, o.mean,      o.noMean,   o.thickness, o.exaggeration,
                       o.azimuth, o.elevation, o.plane,    o.frames,    o.planeThickness,
                       o.removal, o.groupSize, o.noLabels, o.noCache,   o.demo,
                       o.json});
    if (auto done = parseSubcommand(parser, args, QStringLiteral("render"), out, err)) return *done;
    QString problem;
    const auto selection = selectionOptions.selection(parser, problem);
    std::size_t width = 0, height = 0, ignored = 0;
    bool isoOk = false;
    const float iso = parser.value(o.iso).toFloat(&isoOk);
    const auto mode = parseMode(parser.value(o.mode));
    const int frames = std::max(1, parser.value(o.frames).toInt());
    const auto plane = parser.isSet(o.plane) ? parseNumbers(parser.value(o.plane), 4)
                                             : std::optional<std::vector<float>>{};
    const auto removal = parser.isSet(o.removal) ? parseNumbers(parser.value(o.removal), 2)
                                                 : std::optional<std::vector<float>>{};
    bool groupOk = false;
    const int groupSize = parser.value(o.groupSize).toInt(&groupOk);
    if (!selection) {
        problem = problem.isEmpty() ? QStringLiteral("bad data selection") : problem;
    } else if (selection->paths.empty() != parser.isSet(o.demo)) {
        problem = QStringLiteral("name the files to render, or use --demo");
    } else if (!isoOk) {
        problem = QStringLiteral("say which isovalue with --iso X");
    } else if (!parser.isSet(o.output)) {
        problem = QStringLiteral("say where to write the image with --out FILE.png");
    } else if (!parseGridSize(parser.value(o.size) + QStringLiteral("x2"), width, height,
                              ignored)) {
        problem = QStringLiteral("--size must look like 1600x1000");
    } else if (!mode) {
        problem = QStringLiteral("--mode must be shaded, spaghetti, surfaces or opaque");
    } else if (parser.isSet(o.plane) &&
               (!plane || glm::length(glm::vec3((*plane)[0], (*plane)[1], (*plane)[2])) == 0.0F)) {
        problem = QStringLiteral("--plane must be NX,NY,NZ,OFFSET with a non-zero normal");
    } else if (parser.isSet(o.removal) && (!removal || (*removal)[0] >= (*removal)[1])) {
        problem = QStringLiteral("--removal must be MIN,MAX with MIN below MAX");
    } else if (!groupOk || groupSize < 1) {
        problem = QStringLiteral("--group-size must be a positive whole number");
    }
    const bool fromProject =
        selection && selection->paths.size() == 1 &&
        QString::fromStdString(selection->paths.front()).endsWith(QLatin1String(".ensil"));
    if (fromProject) {
        // The project defines the picture; only where it goes and how big it is may be given.
        problem.clear();
        for (const QCommandLineOption* scene :
             {&o.iso, &o.mode, &o.clusters, &o.linkage, &o.mean, &o.noMean, &o.thickness,
              &o.exaggeration, &o.azimuth, &o.elevation, &o.plane, &o.planeThickness, &o.removal,
              &o.groupSize, &o.demo}) {
            if (parser.isSet(*scene)) {
                problem = QStringLiteral(
                              "--%1 comes from the project; change it in the "
                              "workbench and save the project")
                              .arg(scene->names().front());
            }
        }
        if (problem.isEmpty() && !parser.isSet(o.output)) {
            problem = QStringLiteral("say where to write the image with --out FILE.png");
        } else if (problem.isEmpty() && !parseGridSize(parser.value(o.size) + QStringLiteral("x2"),
                                                       width, height, ignored)) {
            problem = QStringLiteral("--size must look like 1600x1000");
        }
    }
    if (!problem.isEmpty()) {
        err << "ensil render: " << problem << "\n";
        return 2;
    }
    try {
        RenderRequest request;
        request.width = static_cast<int>(width);
        request.height = static_cast<int>(height);
        request.frames = frames;
        request.useCache = !parser.isSet(o.noCache);
        request.labels = !parser.isSet(o.noLabels);
        Project project;
        if (fromProject) {
            project = loadProject(QString::fromStdString(selection->paths.front()));
        } else {
            project.demo = parser.isSet(o.demo);
            if (!project.demo) project.data = *selection;
            project.isovalue = iso;
            project.clusters = parser.value(o.clusters).toInt();
            project.linkage = parser.value(o.linkage).toLower().toStdString();
            project.verticalExaggeration = parser.value(o.exaggeration).toFloat();
            gl::RenderSettings& settings = project.render;
            settings.mode = *mode;
            settings.showMean = !parser.isSet(o.noMean);
            settings.thickness = parser.value(o.thickness).toFloat();
            settings.groupSize = groupSize;
            if (removal) {
                settings.removal = true;
                settings.removalMin = (*removal)[0];
                settings.removalMax = (*removal)[1];
            }
            if (plane) {
                settings.plane.enabled = true;
                settings.plane.thickness = parser.value(o.planeThickness).toFloat();
                request.planeAcrossBox =
                    glm::vec4((*plane)[0], (*plane)[1], (*plane)[2], (*plane)[3]);
            }
            request.azimuth = parser.value(o.azimuth).toFloat();
            request.elevation = parser.value(o.elevation).toFloat();
        }
        const RenderOutcome result = renderProject(project, request);
        if (!result.image.save(parser.value(o.output))) {
            err << "ensil render: cannot write '" << parser.value(o.output) << "'\n";
            return 1;
        }
        if (parser.isSet(o.json)) {
            const QJsonObject json{
                {"frame_ms", result.frameMs},
                {"gpu_bytes", static_cast<qint64>(result.gpuBytes)},
                {"width", static_cast<qint64>(width)},
                {"height", static_cast<qint64>(height)},
                {"frames", frames},
                {"isovalue", result.isovalue},
                {"triangles", static_cast<qint64>(result.triangles)},
                {"members", static_cast<qint64>(result.members)},
                {"gl_renderer", QString::fromStdString(result.glRenderer)},
                {"display", result.withoutDisplay ? QStringLiteral("none (EGL surfaceless)")
                                                  : QGuiApplication::platformName()}};
            out << QJsonDocument(json).toJson(QJsonDocument::Compact) << "\n";
        } else {
            out << "wrote " << parser.value(o.output) << ": " << width << " x " << height << ", "
                << result.members << " members at " << result.isovalue << ", median frame "
                << QString::number(result.frameMs, 'f', 1) << " ms over " << frames << " frames\n";
        }
        return 0;
    } catch (const std::exception& e) {
        err << "ensil render: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace ensil::app
