#include "cli/section_command.h"

#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <array>

#include "cli/command_progress.h"
#include "cli/data_selection_options.h"
#include "cli/subcommand.h"
#include "data/demo_ensemble.h"
#include "data/error.h"
#include "engine/ensemble_section.h"
#include "engine/isovalue_job.h"
#include "engine/preprocess_run.h"
#include "engine/section_painter.h"
#include "engine/section_place.h"
#include "engine/session_renderer.h"
#include "session/setting_options.h"

namespace ensil::cli {
namespace {

constexpr int kDefaultWidth = 1400;

struct Options {
    QCommandLineOption level{"level",
                             "A map at this level: 500hPa, 85000Pa, 5km, 1500m, a number in the "
                             "vertical axis's own units, or index:N (a level from 0).",
                             "LEVEL"};
    QCommandLineOption latitude{"lat",
                                "A cross-section along this latitude (45, 45N, 30S), through "
                                "the grid's map projection.",
                                "DEG"};
    QCommandLineOption longitude{"lon", "A cross-section along this longitude (10, 10E, 75W).",
                                 "DEG"};
    QCommandLineOption path{"path",
                            "A cross-section along the great circle between two points, "
                            "LON,LAT:LON,LAT in degrees (the grid's own X,Y:X,Y for data "
                            "without a map).",
                            "A:B"};
    QCommandLineOption fill{"fill",
                            "What fills the section: mean (default), spread (the members' "
                            "standard deviation), probability (of exceeding the isovalue), "
                            "member:N, anomaly:N (member N minus the mean; members count from 1), "
                            "or none.",
                            "FIELD", "mean"};
    QCommandLineOption iso{"iso",
                           "The isovalue of the contours (default: the workbench's, where most "
                           "members have a surface in the middle of the box and differ).",
                           "C"};
    QCommandLineOption output{"out", "The picture to write: .png, .svg or .pdf (required).",
                              "FILE"};
    QCommandLineOption size{"size",
                            "Picture size in pixels (PDF: points). Default: 1400 wide and as "
                            "high as the section's proportions need.",
                            "WxH"};
    QCommandLineOption noCache{"no-cache", "Neither read nor write the preprocessing cache."};
    QCommandLineOption demo{"demo", "Use the built-in demo ensemble instead of files."};
    QCommandLineOption json{"json", "Print what was drawn as one JSON object."};
    QCommandLineOption quiet = CommandProgress::quietOption();
};

// The fill named on the command line; nullopt with `problem` set when it is not one.
std::optional<std::pair<engine::SectionFill, int>> parseFill(const QString& text,
                                                             QString& problem) {
    std::string why;
    auto fill = engine::parseSectionFill(text.trimmed().toStdString(), why);
    if (!fill) problem = QStringLiteral("--fill is refused: ") + QString::fromStdString(why);
    return fill;
}

// The one place option given, read; nullopt with `problem` set.
std::optional<engine::SectionPlace> placeFrom(const QCommandLineParser& parser, const Options& o,
                                              QString& problem) {
    const std::array<std::pair<const QCommandLineOption*, engine::SectionKind>, 4> places{{
        {&o.level, engine::SectionKind::Map},
        {&o.latitude, engine::SectionKind::Latitude},
        {&o.longitude, engine::SectionKind::Longitude},
        {&o.path, engine::SectionKind::Path},
    }};
    const auto given = std::count_if(places.begin(), places.end(),
                                     [&](const auto& p) { return parser.isSet(*p.first); });
    if (given != 1) {
        problem = QStringLiteral(
            "say where the section lies with one of --level (a map), --lat, --lon or --path "
            "(a cross-section)");
        return std::nullopt;
    }
    const auto& [option, kind] = *std::find_if(
        places.begin(), places.end(), [&](const auto& p) { return parser.isSet(*p.first); });
    std::string why;
    auto place = engine::parseSectionPlace(kind, parser.value(*option).toStdString(), why);
    if (!place) {
        problem = QStringLiteral("--%1 is refused: %2")
                      .arg(option->names().front(), QString::fromStdString(why));
    }
    return place;
}

QJsonObject toJson(const engine::SectionView& view, const engine::PreprocessResult& clusters,
                   float isovalue, const QString& path) {
    QJsonArray members;
    for (const engine::MemberContour& c : view.members) {
        std::size_t points = 0;
        for (const engine::SectionLine& l : c.lines) points += l.points.size();
        members.append(
            QJsonObject{{"number", static_cast<qint64>(c.member + 1)},
                        {"name", QString::fromStdString(clusters.ensemble->members[c.member].name)},
                        {"cluster", clusters.clusterNumbers.at(c.member)},
                        {"color", QString::fromStdString(clusters.colors.at(c.member))},
                        {"contour_lines", static_cast<qint64>(c.lines.size())},
                        {"contour_points", static_cast<qint64>(points)}});
    }
    QJsonObject o{{"out", path},
                  {"title", QString::fromStdString(view.title)},
                  {"place", QString::fromStdString(view.placeText)},
                  {"isovalue", static_cast<double>(isovalue)},
                  {"columns", static_cast<qint64>(view.columns)},
                  {"rows", static_cast<qint64>(view.rows)},
                  {"members", members},
                  {"mean_contour_lines", static_cast<qint64>(view.meanContour.size())}};
    if (!view.fill.empty()) {
        o.insert("fill",
                 QJsonObject{
                     {"caption", QString::fromStdString(view.fillCaption)},
                     {"minimum", static_cast<double>(view.fillMinimum)},
                     {"maximum", static_cast<double>(view.fillMaximum)},
                     {"colour_map",
                      QString::fromStdString(session::setting("sections_colour_map")
                                                 .format(static_cast<double>(view.colourMap)))}});
    }
    if (view.medianMember >= 0) {
        // Members numbered from 1, as the workbench shows them; the band's samples are those
        // between the band members' union and intersection at the isovalue.
        QJsonArray outliers;
        for (const std::size_t m : view.outliers) outliers.append(static_cast<qint64>(m + 1));
        o.insert("boxplot",
                 QJsonObject{{"median", view.medianMember + 1},
                             {"outliers", outliers},
                             {"band_samples", static_cast<qint64>(engine::bandSampleCount(view))},
                             {"band_edge_lines", static_cast<qint64>(view.bandEdges.size())}});
    }
    return o;
}

}  // namespace

// --colour-map, --range-min, --range-max, --band and --vertical-axis, as the setting table
// names them.
const session::SettingOptions& sectionOptions() {
    static const session::SettingOptions options{"sections_colour_map", "sections_range_min",
                                                 "sections_range_max", "band", "vertical_axis"};
    return options;
}

int runSectionCommand(const QStringList& args, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Draw a map or a cross-section of an ensemble: every member's contour of the isovalue "
        "in its cluster's colour, the mean's contour, over a filled field, with coastlines, "
        "axes in degrees and hPa, and a colour bar. PNG, SVG (text as text, contours as "
        "paths) or PDF; no display server is needed."));
    parser.addHelpOption();
    const DataSelectionOptions selectionOptions;
    selectionOptions.addTo(parser);
    const Options o;
    parser.addOptions({o.level, o.latitude, o.longitude, o.path, o.fill, o.iso, o.output, o.size,
                       o.noCache, o.demo, o.json, o.quiet});
    clusterOptions().addTo(parser);
    sectionOptions().addTo(parser);
    if (auto done = parseSubcommand(parser, args, QStringLiteral("section"), out, err))
        return *done;

    QString problem;
    session::SessionState requested;
    const auto selection = selectionOptions.selection(parser, problem);
    const auto place = selection ? placeFrom(parser, o, problem) : std::nullopt;
    const auto fill = place ? parseFill(parser.value(o.fill), problem) : std::nullopt;
    const auto size =
        !fill ? std::nullopt
        : parser.isSet(o.size)
            ? session::parseImageSize(QStringLiteral("--size"), parser.value(o.size), problem)
            : std::optional<std::pair<int, int>>(std::pair{kDefaultWidth, 0});
    std::optional<double> iso;
    if (size && parser.isSet(o.iso)) {
        iso = session::parseBoundedNumber(QStringLiteral("--iso"), parser.value(o.iso), -1e30, 1e30,
                                          false, problem);
    }
    const QString path = parser.value(o.output);
    const QStringList rangeGiven = sectionOptions().given(parser).filter(QStringLiteral("range"));
    if (!size || (parser.isSet(o.iso) && !iso) ||
        !clusterOptions().applyTo(parser, requested, problem) ||
        !sectionOptions().applyTo(parser, requested, problem)) {
        // said below
    } else if (rangeGiven.size() == 2 &&
               !(requested.sectionsColours.minimum < requested.sectionsColours.maximum)) {
        problem = QStringLiteral(
                      "--range-min %1 --range-max %2 is refused: the lower end must "
                      "lie below the upper end")
                      .arg(parser.value(QStringLiteral("range-min")),
                           parser.value(QStringLiteral("range-max")));
    } else if (rangeGiven.size() == 1) {
        problem = QStringLiteral("%1 needs %2 too: a fixed colour range has both ends")
                      .arg(rangeGiven.front(), rangeGiven.front() == QLatin1String("--range-min")
                                                   ? QStringLiteral("--range-max")
                                                   : QStringLiteral("--range-min"));
    } else if (!parser.isSet(o.output)) {
        problem = QStringLiteral("say where to write the picture with --out FILE.png|.svg|.pdf");
    } else if (!engine::isSectionPictureName(path)) {
        problem = QStringLiteral("--out '%1' is refused: the name must end in .png, .svg or .pdf")
                      .arg(path);
    } else if (selection->paths.empty() != parser.isSet(o.demo)) {
        problem = QStringLiteral("name the files to draw, or use --demo");
    }
    if (!problem.isEmpty()) {
        err << "ensil section: " << problem << "\n";
        return 2;
    }

    CommandProgress progress(err, QStringLiteral("ensil section"),
                             CommandProgress::shownOnThisTerminal(parser.isSet(o.quiet)));
    try {
        const data::DemoEnsembleParams demo;
        auto ensemble = std::make_shared<const data::Ensemble>(
            parser.isSet(o.demo)
                ? data::makeDemoEnsemble(demo, {}, progress.callback(QStringLiteral("generating")))
                      .ensemble
                : data::openEnsemble(*selection, {}, progress.callback(QStringLiteral("reading"))));
        // The clusters the workbench shows at this isovalue (from the mesh cache when it has
        // them), so a member's colour here is its colour there.
        engine::PreprocessRequest request;
        request.isovalue = iso;
        request.clusters = requested.clusters;
        request.clustersGiven = clusterOptions().given(parser).contains("--clusters");
        request.linkage = requested.linkage;
        if (!parser.isSet(o.noCache)) request.cacheDirectory = engine::defaultMeshCacheDirectory();
        // The workbench's and Python's identity of the data, so they share cached meshes.
        request.sourceKey =
            parser.isSet(o.demo) ? engine::demoSourceKey(demo) : data::sourceIdentity(*selection);
        // Warnings about the data (members left out, infinities); the notes are about
        // silhouettes in 3D (too few levels for a shape), not about a section.
        const auto notice = [&](const std::string& kind, const std::string& text) {
            if (kind != "warning") return;
            progress.endLine();
            err << "ensil section: " << QString::fromStdString(kind) << ": "
                << QString::fromStdString(text) << "\n";
        };
        const engine::PreprocessResult clusters =
            engine::preprocessEnsemble(std::move(ensemble), request, notice, {},
                                       progress.callback(QStringLiteral("clustering")));
        engine::SectionRequest section =
            engine::sectionRequestFor(clusters, *place, fill->first, fill->second);
        section.place.verticalAxis = requested.render.verticalAxis;
        requested.sectionsColours.fixedRange = !rangeGiven.isEmpty();
        engine::applySectionColours(section, requested.sectionsColours);
        if (requested.render.showBand) {
            section.boxplot = engine::sectionBoxplotOf(clusters);
            if (!section.boxplot) {
                progress.endLine();
                err << "ensil section: note: no contour boxplot: the data were preprocessed in "
                       "slabs, which makes none\n";
            }
        }
        const engine::SectionView view = engine::buildSection(*clusters.ensemble, section);
        const QSize pictureSize = size->second > 0 ? QSize(size->first, size->second)
                                                   : engine::sectionPictureSize(view, size->first);
        engine::writeSectionPicture(view, path, pictureSize);
        progress.endLine();
        if (parser.isSet(o.json)) {
            out << QJsonDocument(toJson(view, clusters, section.isovalue, path))
                       .toJson(QJsonDocument::Compact)
                << "\n";
        } else {
            out << "ensil section: wrote " << path << ": " << QString::fromStdString(view.title)
                << ", " << view.members.size() << " members' contours at " << section.isovalue
                << "\n";
        }
        return 0;
    } catch (const engine::PreprocessRefused& e) {
        progress.endLine();
        err << "ensil section: " << e.what() << "\n";
        return e.exitCode();
    } catch (const data::Error& e) {
        progress.endLine();
        err << "ensil section: " << e.what() << "\n";
        return dataFailureStatus(e);
    }
}

}  // namespace ensil::cli
