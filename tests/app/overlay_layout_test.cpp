// Labels as scientists read them (issue 15): on every real file, at the smallest view size
// ensil supports (480 x 320) and at a usual one, in the default 3D view and from the top, no
// two painted texts or panels overlap, none is cut off by the picture's edge, the legend and
// the colour bar are shown and cover no part of the data box, every axis title that is
// computed for the view is painted, and each picture keeps tick values.
#include <gtest/gtest.h>

#include <QImage>
#include <QPainter>

#include "data/ensemble_reader.h"
#include "geo/map_lines.h"
#include "gl/palette.h"
#include "gl/renderer.h"
#include "gl/view_overlay.h"

using namespace ensil;

namespace {
struct RealFile {
    const char* file;
    const char* variable;
    const char* memberDim;
};

constexpr RealFile kFiles[] = {
    {"era5_eda_members.nc", "t", ""},
    {"eraint_uvz.nc", "z", "month"},
    {"uk_hires.nc", "air_potential_temperature", "time"},
    {"contour.cdf", "T", "frtime"},
};

std::vector<gl::PaintedItem> paintedOverlay(const gl::Renderer& renderer, QSize size,
                                            gl::ViewOverlay* overlay) {
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::black);
    QPainter painter(&image);
    *overlay = renderer.overlay(size.width(), size.height());
    std::vector<gl::PaintedItem> painted;
    gl::paintOverlay(painter, *overlay, 1.0, QSizeF(size), &painted);
    return painted;
}
}  // namespace

TEST(OverlayLayout, OnEveryRealFileNoLabelCollidesOrIsCutOffDownTo480x320) {
    for (const RealFile& f : kFiles) {
        const data::Ensemble e =
            data::openEnsemble({.paths = {std::string(ENSIL_SHARED_DATA_DIR "/") + f.file},
                                .variable = f.variable,
                                .memberDimension = f.memberDim});
        gl::Renderer renderer;  // the overlay needs no OpenGL
        renderer.setGrid(e.grid);
        renderer.setMapLines(std::make_shared<const std::vector<geo::MapLine>>(
            geo::mapLinesFor(e.grid, e.gridMapping)));
        std::vector<int> labels(e.memberCount());
        for (std::size_t m = 0; m < labels.size(); ++m) labels[m] = static_cast<int>(m % 5);
        renderer.setAppearance(gl::clusterAppearance(labels));
        renderer.setTitle(QStringLiteral("%1 [K] \u00b7 isovalue 273.15 K \u00b7 2017-01-01T00:00 "
                                         "\u00b7 %2 members")
                              .arg(f.variable)
                              .arg(e.memberCount()));
        renderer.setFloorMap(gl::FloorMap::spanning(
            std::vector<float>(e.grid.nx() * e.grid.ny(), 1.0F), QStringLiteral("floor: test")));
        for (const QSize size : {QSize(480, 320), QSize(1200, 750)}) {
            for (const bool top : {false, true}) {
                renderer.setViewSize(size.width(), size.height());
                if (top) {
                    renderer.lookFrom(-90.0F, 89.0F);
                } else {
                    renderer.resetCamera();
                }
                const std::string where =
                    std::string(f.file) + " at " + std::to_string(size.width()) + "x" +
                    std::to_string(size.height()) + (top ? " from the top" : " in 3D");
                gl::ViewOverlay overlay;
                const std::vector<gl::PaintedItem> painted =
                    paintedOverlay(renderer, size, &overlay);
                const QRectF picture(QPointF(0, 0), QSizeF(size));
                int ticks = 0;
                for (std::size_t i = 0; i < painted.size(); ++i) {
                    EXPECT_TRUE(picture.contains(painted[i].rect))
                        << where << ": '" << painted[i].text.toStdString() << "' is cut off";
                    for (std::size_t j = i + 1; j < painted.size(); ++j) {
                        EXPECT_FALSE(painted[i].rect.intersects(painted[j].rect))
                            << where << ": '" << painted[i].text.toStdString() << "' and '"
                            << painted[j].text.toStdString() << "' overlap";
                    }
                }
                // The legend and the colour bar never cover the data: where no corner is
                // free (from the top at 480 x 320) the box is framed beside them.
                const QRectF box = overlay.box;
                for (const gl::PaintedItem& item : painted) {
                    if (item.text == QStringLiteral("legend") ||
                        item.text == QStringLiteral("colour bar")) {
                        EXPECT_FALSE(item.rect.intersects(box))
                            << where << ": the " << item.text.toStdString()
                            << " covers the data box";
                    }
                }
                EXPECT_TRUE(std::any_of(painted.begin(), painted.end(),
                                        [](auto& p) { return p.text == "colour bar"; }))
                    << where << ": the colour bar was left out";
                for (const gl::OverlayLabel& label : overlay.labels) {
                    const bool shown = std::any_of(painted.begin(), painted.end(),
                                                   [&](auto& p) { return p.text == label.text; });
                    if (label.title) {
                        EXPECT_TRUE(shown) << where << ": the axis title '"
                                           << label.text.toStdString() << "' is missing";
                    } else if (shown) {
                        ++ticks;
                    }
                }
                EXPECT_GE(ticks, 4) << where << ": too few tick values are left";
                // The vertical axis's title states how much the box stretches heights (every
                // real file has pressures or heights over degrees). From the top, or where the
                // vertical edge is too short on screen for labels, it has no title.
                const QString vertical = QString::fromStdString(e.grid.z().name);
                for (const gl::PaintedItem& item : painted) {
                    if (item.text.startsWith(vertical + " (")) {
                        EXPECT_TRUE(item.text.contains(QStringLiteral(", vertical \u00d7")))
                            << where << ": '" << item.text.toStdString() << "' states no scale";
                    }
                }
                if (!top && size.width() >= 1200) {
                    EXPECT_TRUE(std::any_of(painted.begin(), painted.end(),
                                            [](auto& p) {
                                                return p.text.contains(
                                                    QStringLiteral(", vertical \u00d7"));
                                            }))
                        << where << ": the vertical scale is not stated";
                }
            }
        }
    }
}
