// Speed of the Sections dock and `ensil section` on the paper-sized demo ensemble (50 members,
// 256 x 128 x 16 points) at its default isovalue: finding the default places, sampling a map
// at a grid level and between levels, a cross-section along a latitude and along a great-circle
// path (every member's values, the fill, every member's contours), and drawing a map as the
// dock draws it (1000 x 500 pixels) and as a figure. The goal (issue 39): a section on screen
// within 100 ms of moving its level or path. Prints medians over several runs, in ms.
//
//   ensil_section_benchmark [--runs N]   (9 by default)
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "data/demo_ensemble.h"
#include "engine/ensemble_section.h"
#include "engine/section_painter.h"
#include "engine/section_place.h"
#include "preprocessing/default_isovalue.h"
#include "preprocessing/field_statistics.h"
#include "timing.h"

using namespace ensil;

int main(int argc, char** argv) {
    int runs = 9;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::string(argv[i]) == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
    }
    qputenv("QT_QPA_PLATFORM", "offscreen");  // fonts for the drawing, no display server
    QGuiApplication app(argc, argv);
    const data::Ensemble demo = data::makeDemoEnsemble({}).ensemble;
    const float iso = prep::defaultIsovalue(
        demo, prep::computeFieldStatistics(demo, prep::kIsovalueHistogramBins));
    std::printf("demo: %zu members, %zu x %zu x %zu, isovalue %.3f, %d runs\n", demo.memberCount(),
                demo.grid.nx(), demo.grid.ny(), demo.grid.nz(), static_cast<double>(iso), runs);

    engine::DefaultSections defaults;
    const double defaultsMs =
        bench::medianMs(runs, [&] { defaults = engine::defaultSections(demo, iso); });
    std::printf("default places:                 %8.1f ms\n", defaultsMs);

    std::string problem;
    const auto request = [&](engine::SectionPlace place) {
        engine::SectionRequest r;
        r.place = place;
        r.isovalue = iso;
        return r;
    };
    const struct {
        const char* name;
        engine::SectionPlace place;
    } cases[] = {
        {"map at the default level", defaults.map},
        {"map between levels (300 hPa)", *engine::parseLevel("300hPa", problem)},
        {"cross-section along 45N", *engine::parseLatitude("45N", problem)},
        {"cross-section along a path", *engine::parsePath("-60,35:10,60", problem)},
    };
    engine::SectionView map;
    for (const auto& c : cases) {
        engine::SectionView view;
        const double ms =
            bench::medianMs(runs, [&] { view = engine::buildSection(demo, request(c.place)); });
        std::size_t points = 0;
        for (const engine::MemberContour& m : view.members) {
            for (const engine::SectionLine& l : m.lines) points += l.points.size();
        }
        std::printf("%-32s %8.1f ms  (%zu x %zu samples, %zu contour points)\n", c.name, ms,
                    view.columns, view.rows, points);
        if (map.members.empty()) map = view;
    }
    QImage dock(1000, 500, QImage::Format_ARGB32_Premultiplied);
    engine::SectionStyle compact;
    compact.compact = true;
    const double dockMs = bench::medianMs(runs, [&] {
        QPainter painter(&dock);
        engine::paintSection(painter, map, QRectF(0, 0, 1000, 500), {}, compact);
    });
    std::printf("drawing the map in the dock:    %8.1f ms  (1000 x 500)\n", dockMs);
    // Where that time goes: the fill alone, and the lines alone.
    engine::SectionView fillOnly = map;
    fillOnly.members.clear();
    fillOnly.meanContour.clear();
    fillOnly.mapLines.clear();
    engine::SectionView linesOnly = map;
    linesOnly.fill.clear();
    for (const auto& [name, part] : {std::pair{"  of which the fill:", &fillOnly},
                                     std::pair{"  of which the lines:", &linesOnly}}) {
        const double ms = bench::medianMs(runs, [&] {
            QPainter painter(&dock);
            engine::paintSection(painter, *part, QRectF(0, 0, 1000, 500), {}, compact);
        });
        std::printf("%-32s %8.1f ms\n", name, ms);
    }
    const QSize figure = engine::sectionPictureSize(map, 1400);
    QImage picture(figure, QImage::Format_ARGB32_Premultiplied);
    const double figureMs = bench::medianMs(runs, [&] {
        QPainter painter(&picture);
        engine::paintSection(painter, map, QRectF(QPointF(0, 0), QSizeF(figure)));
    });
    std::printf("drawing the map as a figure:    %8.1f ms  (%d x %d)\n", figureMs, figure.width(),
                figure.height());
    return 0;
}
