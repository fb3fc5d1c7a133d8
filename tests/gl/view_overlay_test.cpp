// Axis ticks, tick formatting and the overlay's labels and legend.
#include "gl/view_overlay.h"

#include <gtest/gtest.h>

#include <QImage>
#include <QPainter>
#include <algorithm>

#include "gl/axis_ticks.h"
#include "gl/camera.h"
#include "gl/palette.h"

using namespace ensil;

TEST(AxisTicks, AreRoundNumbersCoveringTheRangeInEitherOrder) {
    // 120 / 5 = 24 rounds up to steps of 25.
    EXPECT_EQ(gl::niceTicks(-80.0, 40.0), (std::vector<double>{-75, -50, -25, 0, 25}));
    EXPECT_EQ(gl::niceTicks(1000.0, 100.0), (std::vector<double>{200, 400, 600, 800, 1000}));
    EXPECT_EQ(gl::niceTicks(0.0, 1.0),
              (std::vector<double>{0, 0.2, 0.4, 0.6000000000000001, 0.8, 1}));
    EXPECT_EQ(gl::niceTicks(0.0, 10.0, 4), (std::vector<double>{0, 2.5, 5, 7.5, 10}));
    EXPECT_TRUE(gl::niceTicks(3.0, 3.0).empty());
    EXPECT_TRUE(gl::niceTicks(0.0, std::numeric_limits<double>::infinity()).empty());
}

TEST(AxisTicks, FormattingDropsTrailingZerosAndKeepsTinyAndHugeValuesShort) {
    EXPECT_EQ(gl::formatTick(0.6000000000000001), QStringLiteral("0.6"));
    EXPECT_EQ(gl::formatTick(-80.0), QStringLiteral("-80"));
    EXPECT_EQ(gl::formatTick(0.0), QStringLiteral("0"));
    EXPECT_EQ(gl::formatTick(2.5e-5), QStringLiteral("2.5e-05"));
    EXPECT_EQ(gl::formatTick(1.5e7), QStringLiteral("1.5e+07"));
}

TEST(AxisLabelling, PressureIsInHectopascalsAtTheStandardLevelsMainOnesFirst) {
    const gl::AxisLabelling pa =
        gl::labellingFor(data::makeUniformAxis("plev", "Pa", 100000.0, 10000.0, 10));
    EXPECT_EQ(pa.units, "hPa");
    EXPECT_DOUBLE_EQ(pa.shownPerUnit, 0.01);
    // 1000 and 100 hPa lie at the ends of the range and must be there.
    EXPECT_EQ(pa.ticks, (std::vector<double>{100000, 85000, 70000, 50000, 30000, 20000, 10000,
                                             92500, 60000, 40000, 25000, 15000}));
    const gl::AxisLabelling mbar =
        gl::labellingFor(data::makeUniformAxis("level", "millibars", 1000.0, 100.0, 10));
    EXPECT_EQ(mbar.units, "hPa");
    EXPECT_EQ(mbar.ticks.front(), 1000.0);
    // A narrow range falls back to round numbers in hPa.
    const gl::AxisLabelling narrow =
        gl::labellingFor(data::makeUniformAxis("p", "Pa", 101000.0, 99000.0, 5));
    EXPECT_EQ(narrow.ticks, (std::vector<double>{99000, 99500, 100000, 100500, 101000}));
}

TEST(AxisLabelling, HeightsBeyondTenKilometresAreInKilometresOthersInTheirOwnUnits) {
    const gl::AxisLabelling high =
        gl::labellingFor(data::makeUniformAxis("z", "m", 0.0, 20000.0, 10));
    EXPECT_EQ(high.units, "km");
    EXPECT_EQ(high.ticks, (std::vector<double>{0, 5000, 10000, 15000, 20000}));
    const gl::AxisLabelling low =
        gl::labellingFor(data::makeUniformAxis("z", "m", 0.0, 5000.0, 10));
    EXPECT_EQ(low.units, "m");
    EXPECT_EQ(low.ticks, gl::niceTicks(0.0, 5000.0));
}

namespace {
struct Scene {
    data::Grid grid{data::makeUniformAxis("lon", "degrees_east", -80, 40, 121),
                    data::makeUniformAxis("lat", "degrees_north", 25, 75, 51),
                    data::makeUniformAxis("height", "m", 0, 10000, 11)};
    data::DisplayFrame frame{grid, 1.0F};
    gl::Camera camera;
    std::vector<gl::MemberAppearance> look = gl::clusterAppearance({0, 1, 1, 0, 1});
    gl::OverlayInput input(int width = 800, int height = 600) {
        camera.reset(frame.center(), 0.5F * glm::length(frame.boxMax()));
        gl::OverlayInput in;
        in.grid = &grid;
        in.frame = &frame;
        in.viewProjection =
            camera.viewProjection(static_cast<float>(width) / static_cast<float>(height));
        in.eye = camera.eye();
        in.width = width;
        in.height = height;
        in.appearance = &look;
        in.showMean = true;
        return in;
    }
};

bool hasLabel(const gl::ViewOverlay& o, const QString& text) {
    return std::any_of(o.labels.begin(), o.labels.end(),
                       [&](const gl::OverlayLabel& l) { return l.text == text; });
}
}  // namespace

TEST(ViewOverlay, LabelsTheThreeAxesInDataUnitsOnScreenAndAwayFromTheBox) {
    Scene scene;
    const gl::ViewOverlay o = gl::computeOverlay(scene.input());
    for (const char* text :
         {"-75", "25", "30", "70", "0", "10000", "lon (degrees_east)", "lat (degrees_north)"}) {
        EXPECT_TRUE(hasLabel(o, QString::fromLatin1(text))) << text;
    }
    // The vertical axis states its stretch: 10 km drawn 0.2 high under 120 degrees of longitude
    // (13,343 km at 111.195 km a degree) is 267 times true, said to two significant digits.
    EXPECT_TRUE(hasLabel(o, QStringLiteral("height (m), vertical \u00d7270")));
    // Every label lies in the picture.
    for (const gl::OverlayLabel& l : o.labels) {
        EXPECT_GT(l.pixel.x, 0.0F) << l.text.toStdString();
        EXPECT_LT(l.pixel.x, 800.0F) << l.text.toStdString();
        EXPECT_GT(l.pixel.y, 0.0F) << l.text.toStdString();
        EXPECT_LT(l.pixel.y, 600.0F) << l.text.toStdString();
    }
    // The default camera looks from the south: longitude ticks run along the bottom edge on
    // the viewer's side (south), left to right, below the box's centre on screen.
    const auto at = [&](const char* text) {
        return std::find_if(o.labels.begin(), o.labels.end(),
                            [&](const gl::OverlayLabel& l) { return l.text == text; })
            ->pixel;
    };
    EXPECT_LT(at("-75").x, at("-25").x);
    EXPECT_GT(at("-25").y, 300.0F);
    // Off: nothing to label.
    gl::OverlayInput off = scene.input();
    off.showAxes = false;
    off.showLegend = false;
    EXPECT_TRUE(gl::computeOverlay(off).labels.empty());
    // From straight above, the vertical edge is a point: it gets no labels.
    scene.camera.setAngles(-90.0F, 90.0F);
    const gl::ViewOverlay top = gl::computeOverlay([&] {
        gl::OverlayInput in = scene.input();
        scene.camera.setAngles(-90.0F, 90.0F);
        in.viewProjection = scene.camera.viewProjection(800.0F / 600.0F);
        in.eye = scene.camera.eye();
        return in;
    }());
    EXPECT_FALSE(hasLabel(top, "height (m)"));
    EXPECT_TRUE(hasLabel(top, "lon (degrees_east)"));
    EXPECT_TRUE(gl::computeOverlay(off).legend.empty());
}

TEST(ViewOverlay, TheLegendCountsVisibleMembersPerClusterAndNamesTheMean) {
    Scene scene;
    scene.look[4].visible = false;
    const gl::ViewOverlay o = gl::computeOverlay(scene.input());
    ASSERT_EQ(o.legend.size(), 3u);
    EXPECT_EQ(o.legend[0].text, QStringLiteral("Cluster 1 \u00b7 2 members"));
    EXPECT_EQ(o.legend[0].color, gl::clusterColor(0));
    EXPECT_EQ(o.legend[1].text, QStringLiteral("Cluster 2 \u00b7 2 members"));
    EXPECT_EQ(o.legend[2].text, QStringLiteral("Mean member"));
}

TEST(ViewOverlay, PlaneCurvesHaveALegendEntryInThePlanesColourWhenThePlaneIsOn) {
    Scene scene;
    gl::OverlayInput in = scene.input();
    EXPECT_EQ(gl::computeOverlay(in).legend.size(), 3u) << "no entry while the plane is off";
    in.planeCurves = true;
    in.planeColor = {1.0F, 0.85F, 0.55F};
    const gl::ViewOverlay o = gl::computeOverlay(in);
    ASSERT_EQ(o.legend.size(), 4u);
    EXPECT_EQ(o.legend.back().text, QStringLiteral("Plane curves (dashed)"));
    EXPECT_EQ(o.legend.back().color, in.planeColor);
}

TEST(ViewOverlay, AHiddenClusterReadsHiddenAndEntriesTakeTheMembersColours) {
    Scene scene;
    // Cluster 2 (stable identity 1) drawn in another colour, all its members hidden.
    for (gl::MemberAppearance& a : scene.look) {
        if (a.cluster == 1) {
            a.visible = false;
            a.color = gl::clusterColor(9);
        }
    }
    const gl::ViewOverlay o = gl::computeOverlay(scene.input());
    ASSERT_GE(o.legend.size(), 2u);
    EXPECT_EQ(o.legend[1].text, QStringLiteral("Cluster 2 \u00b7 hidden"));
    EXPECT_EQ(o.legend[1].color, gl::clusterColor(9));
}

TEST(ViewOverlay, TextIsLightOnDarkBackgroundsAndDarkOnLightOnes) {
    Scene scene;
    gl::OverlayInput in = scene.input();
    in.background = {0.1F, 0.1F, 0.12F};
    EXPECT_GT(gl::computeOverlay(in).text.lightness(), 180);
    in.background = {0.95F, 0.95F, 0.95F};
    EXPECT_LT(gl::computeOverlay(in).text.lightness(), 80);
}

TEST(ViewOverlay, PaintsTheLegendSwatchesAndTextIntoTheImage) {
    Scene scene;
    const gl::ViewOverlay o = gl::computeOverlay(scene.input());
    QImage image(800, 600, QImage::Format_RGB32);
    image.fill(Qt::black);
    {
        QPainter painter(&image);
        gl::paintOverlay(painter, o, 1.0);
    }
    // The legend's first swatch, in the top-left corner, has cluster 1's colour.
    const glm::vec3 c = gl::clusterColor(0);
    bool swatch = false;
    for (int y = 10; y < 40 && !swatch; ++y) {
        for (int x = 10; x < 40 && !swatch; ++x) {
            const QColor p = image.pixelColor(x, y);
            swatch = std::abs(p.red() - int(c.r * 255)) < 3 &&
                     std::abs(p.green() - int(c.g * 255)) < 3 &&
                     std::abs(p.blue() - int(c.b * 255)) < 3;
        }
    }
    EXPECT_TRUE(swatch);
    // Text was drawn somewhere below the legend (tick labels): light pixels exist there.
    int light = 0;
    for (int y = 150; y < 600; ++y) {
        for (int x = 0; x < 800; ++x) light += image.pixelColor(x, y).lightness() > 150 ? 1 : 0;
    }
    EXPECT_GT(light, 200);
}

// From the side, the vertical axis's title is written upwards beyond its tick values, as a
// plot's y axis: written across, it covered the 300 hPa tick (which was then left out).
TEST(ViewOverlay, TheVerticalTitleOfASideViewStandsBesideEveryLevelTick) {
    Scene scene;
    scene.grid = data::Grid(data::makeUniformAxis("lon", "degrees_east", -80, 40, 121),
                            data::makeUniformAxis("lat", "degrees_north", 25, 75, 51),
                            data::Axis{"plev",
                                       "hPa",
                                       "air_pressure",
                                       {1000, 850, 700, 500, 400, 300, 250, 200, 150, 100},
                                       false});
    scene.frame = data::DisplayFrame(scene.grid, 1.0F);
    gl::OverlayInput in = scene.input(1400, 800);
    scene.camera.setAngles(-90.0F, 0.0F);  // from the south, as View > From the South
    scene.camera.setProjection(gl::Camera::Projection::Orthographic);
    in.appearance = nullptr;  // no legend in the corner
    in.viewProjection = scene.camera.viewProjection(1400.0F / 800.0F);
    in.eye = scene.camera.eye();
    const gl::ViewOverlay o = gl::computeOverlay(in);
    QImage image(1400, 800, QImage::Format_RGB32);
    std::vector<gl::PaintedItem> painted;
    {
        QPainter painter(&image);
        gl::paintOverlay(painter, o, 1.0, QSizeF(1400, 800), &painted);
    }
    const auto title = std::find_if(painted.begin(), painted.end(), [](const gl::PaintedItem& p) {
        return p.text.startsWith(QStringLiteral("plev (hPa)"));
    });
    QStringList said;
    for (const gl::PaintedItem& p : painted) said << p.text;
    ASSERT_NE(title, painted.end()) << said.join(QStringLiteral(" | ")).toStdString();
    EXPECT_GT(title->rect.height(), 2.0 * title->rect.width()) << "written upwards";
    for (const char* level : {"1000", "700", "500", "300", "200", "100"}) {
        const auto tick = std::find_if(painted.begin(), painted.end(),
                                       [&](const gl::PaintedItem& p) { return p.text == level; });
        ASSERT_NE(tick, painted.end())
            << level << " hPa was left out: " << said.join(QStringLiteral(" | ")).toStdString();
        EXPECT_FALSE(tick->rect.intersects(title->rect)) << level;
        EXPECT_LT(title->rect.right(), tick->rect.left()) << "beyond the tick values";
    }
}

// The legend keeps clear of the data: with the box over the top-left quarter it moves to the
// top right; the title line sits above it, centred.
TEST(ViewOverlay, TheLegendTakesACornerClearOfTheDataBoxBelowTheTitle) {
    gl::ViewOverlay o;
    o.text = QColor(225, 225, 225);
    o.legend = {{gl::clusterColor(0), QStringLiteral("Cluster 1 \u00b7 5 members")}};
    o.box = QRectF(0.0, 0.0, 400.0, 300.0);
    o.title = QStringLiteral("t [K] \u00b7 isovalue 260 K");
    QImage image(800, 600, QImage::Format_RGB32);
    image.fill(Qt::black);
    {
        QPainter painter(&image);
        gl::paintOverlay(painter, o, 1.0);
    }
    const glm::vec3 c = gl::clusterColor(0);
    const auto swatchIn = [&](QRect r) {
        for (int y = r.top(); y <= r.bottom(); ++y) {
            for (int x = r.left(); x <= r.right(); ++x) {
                const QColor p = image.pixelColor(x, y);
                if (std::abs(p.red() - int(c.r * 255)) < 3 &&
                    std::abs(p.green() - int(c.g * 255)) < 3 &&
                    std::abs(p.blue() - int(c.b * 255)) < 3) {
                    return true;
                }
            }
        }
        return false;
    };
    EXPECT_FALSE(swatchIn(QRect(0, 0, 400, 300))) << "not over the data box";
    EXPECT_TRUE(swatchIn(QRect(400, 0, 400, 300))) << "in the top-right corner";
    int titlePixels = 0;
    for (int y = 0; y < 24; ++y) {
        for (int x = 300; x < 500; ++x) titlePixels += image.pixelColor(x, y).lightness() > 150;
    }
    EXPECT_GT(titlePixels, 20) << "the title, centred at the top";
}

// The floor's colour bar runs from the scale's first colour to its last (the floor shader's
// own, from gl/palette.h), with its caption, in a corner clear of the legend.
TEST(ViewOverlay, TheFloorsColourBarShowsTheFloorsColours) {
    gl::ViewOverlay o;
    o.text = QColor(225, 225, 225);
    o.legend = {{gl::clusterColor(0), QStringLiteral("Cluster 1")}};
    o.colourScales = {
        gl::ColourScale{QStringLiteral("floor: column maximum of the mean t [K]"), 237.8F, 303.7F}};
    QImage image(800, 600, QImage::Format_RGB32);
    image.fill(Qt::black);
    {
        QPainter painter(&image);
        gl::paintOverlay(painter, o, 1.0);
    }
    const auto found = [&](const glm::vec3& c) {
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QColor p = image.pixelColor(x, y);
                if (std::abs(p.red() - int(c.r * 255)) < 8 &&
                    std::abs(p.green() - int(c.g * 255)) < 8 &&
                    std::abs(p.blue() - int(c.b * 255)) < 8) {
                    return QPoint(x, y);
                }
            }
        }
        return QPoint(-1, -1);
    };
    const QPoint low = found(glm::clamp(gl::viridis(0.0F), 0.0F, 1.0F));
    const QPoint high = found(glm::clamp(gl::viridis(1.0F), 0.0F, 1.0F));
    ASSERT_GE(low.x(), 0) << "the dark purple end";
    ASSERT_GE(high.x(), 0) << "the yellow end";
    EXPECT_LT(low.x(), high.x()) << "low values on the left";
    EXPECT_GT(low.x(), 400) << "the legend took the top-left corner: the bar the top right";
}

// Twenty clusters: the first 12 keep their own colours, no two alike; the 8 beyond the palette
// share the "other" colour and one legend entry that counts them, instead of repeating colours.
TEST(ViewOverlay, BeyondTwelveClustersTheRestAreOneOtherEntryAndNoColourRepeats) {
    std::vector<int> labels;
    for (int c = 0; c < 20; ++c) labels.insert(labels.end(), {c, c});
    std::vector<gl::MemberAppearance> look = gl::clusterAppearance(labels);
    gl::OverlayInput in;
    in.width = 800;
    in.height = 600;
    in.appearance = &look;
    const gl::ViewOverlay o = gl::computeOverlay(in);
    ASSERT_EQ(o.legend.size(), 13U);
    EXPECT_EQ(o.legend.back().text, QStringLiteral("8 other clusters \u00b7 16 members"));
    EXPECT_EQ(o.legend.back().color, gl::kOtherClustersColor);
    for (std::size_t i = 0; i < o.legend.size(); ++i) {
        for (std::size_t j = i + 1; j < o.legend.size(); ++j) {
            EXPECT_NE(o.legend[i].color, o.legend[j].color) << i << " and " << j;
        }
        EXPECT_NE(o.legend[i].color, gl::kMeanSurfaceColor);
        EXPECT_NE(o.legend[i].color, gl::kUnclusteredColor);
    }
    EXPECT_EQ(gl::clusterColor(12), gl::clusterColor(19)) << "one other colour";
    EXPECT_NE(gl::clusterColor(12), gl::clusterColor(0)) << "not a repeat of the first";
}

// The band's and the dashed entries' swatches once were the same filled square as the
// members': each now shows how its thing is drawn.
TEST(ViewOverlay, TheBandAndTheDashedEntriesHaveSwatchesOfTheirOwn) {
    Scene scene;
    gl::OverlayInput in = scene.input();
    in.band = true;
    in.outliers = 2;
    in.planeCurves = true;
    const gl::ViewOverlay o = gl::computeOverlay(in);
    ASSERT_GE(o.legend.size(), 3u);
    const auto entry = [&](const QString& text) {
        for (const gl::LegendEntry& e : o.legend) {
            if (e.text == text) return e.swatch;
        }
        ADD_FAILURE() << "no entry " << text.toStdString();
        return gl::Swatch::Filled;
    };
    EXPECT_EQ(o.legend.front().swatch, gl::Swatch::Filled);
    EXPECT_EQ(entry(QStringLiteral("50 % band")), gl::Swatch::Band);
    EXPECT_EQ(entry(QStringLiteral("2 outliers (dashed)")), gl::Swatch::Dashed);
    EXPECT_EQ(entry(QStringLiteral("Plane curves (dashed)")), gl::Swatch::Dashed);
}

// With the contour boxplot's band shown the members step back towards the background (all but
// the outliers and any selected); their legend entries once stayed bright. Both take the colour
// from gl::steppedBack, which the renderer draws the members with.
TEST(ViewOverlay, WithTheBandShownTheClusterSwatchesStepBackAsTheMembersDo) {
    Scene scene;
    gl::OverlayInput in = scene.input();
    in.background = {0.11F, 0.12F, 0.14F};
    const glm::vec3 bright = gl::computeOverlay(in).legend.front().color;
    EXPECT_EQ(bright, gl::clusterColor(0));
    in.band = true;
    const glm::vec3 drawn = gl::computeOverlay(in).legend.front().color;
    EXPECT_EQ(drawn, gl::steppedBack(gl::clusterColor(0), in.background));
    EXPECT_LT(glm::length(drawn - in.background), 0.5F * glm::length(bright - in.background));
}

TEST(ViewOverlay, ADashedSwatchIsPaintedAsDashesAndTheBandTranslucent) {
    // One magenta entry painted each way; the pixels of the swatch's own colour are counted.
    const auto magentaPixels = [](gl::Swatch swatch, int* blended) {
        gl::ViewOverlay o;
        o.legend.push_back({{1.0F, 0.0F, 1.0F}, QStringLiteral("entry"), swatch});
        QImage image(400, 200, QImage::Format_ARGB32);
        image.fill(Qt::black);
        QPainter painter(&image);
        gl::paintOverlay(painter, o, 1.0, QSizeF(400.0, 200.0), nullptr);
        painter.end();
        int exact = 0;
        *blended = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                if (c.red() > 230 && c.blue() > 230 && c.green() < 40) ++exact;
                // Magenta mixed with the panel's grey: the band's translucent inside (and a
                // filled square's antialiased rim).
                if (c.red() > 60 && c.red() < 235 && std::abs(c.red() - c.blue()) < 20 &&
                    c.green() < c.red() - 60) {
                    ++*blended;
                }
            }
        }
        return exact;
    };
    int filledBlend = 0, dashedBlend = 0, bandBlend = 0;
    const int filled = magentaPixels(gl::Swatch::Filled, &filledBlend);
    const int dashed = magentaPixels(gl::Swatch::Dashed, &dashedBlend);
    const int band = magentaPixels(gl::Swatch::Band, &bandBlend);
    EXPECT_GT(filled, 60) << "a filled square";
    EXPECT_GT(dashed, 4) << "the dashes are there";
    EXPECT_LT(dashed, filled / 2) << "and thinner than a square, with gaps";
    EXPECT_LT(band, filled) << "only the band's outline is in full colour";
    EXPECT_GT(bandBlend, filledBlend + filled / 3) << "its inside is translucent over the panel";
}

// A title wider than the picture goes on two lines, broken between its facts, so a date is never
// cut (issue 40: at 640 x 400 the title was elided in the middle of the date); one that fits
// stays one line, and the strip the panels leave the box grows by the second line.
TEST(ViewOverlay, ATitleTooWideForThePictureBreaksBetweenItsFactsNotInADate) {
    const QString title = QStringLiteral(
        "t (Temperature) [K] \u00b7 isovalue 269.4 K \u00b7 time 2016-10-06T03:00 \u00b7 "
        "10 members along number");
    QFont font;
    font.setPointSizeF(10.5);
    font.setBold(true);
    const QFontMetricsF metrics(font);
    const double wide = metrics.horizontalAdvance(title) + 10.0;
    EXPECT_EQ(gl::titleLines(title, metrics, wide), QStringList{title});

    const double narrow = metrics.horizontalAdvance(title) * 0.6;
    const QStringList lines = gl::titleLines(title, metrics, narrow);
    ASSERT_EQ(lines.size(), 2);
    EXPECT_EQ(lines.join(QStringLiteral(" \u00b7 ")), title) << "nothing left out or cut";
    for (const QString& line : lines) EXPECT_LE(metrics.horizontalAdvance(line), narrow);
    EXPECT_TRUE(lines[0].contains(QStringLiteral("2016-10-06T03:00")) ||
                lines[1].contains(QStringLiteral("2016-10-06T03:00")));

    gl::ViewOverlay o;
    o.title = title;
    const double oneLine = gl::panelRoom(o, 4000.0).top;
    const double twoLines = gl::panelRoom(o, 640.0 * 0.5).top;
    EXPECT_GT(twoLines, oneLine + 0.8 * metrics.height());
    const gl::PanelPlaces places = gl::placePanels(o, QSizeF(320.0, 200.0), QRectF());
    EXPECT_NEAR(places.title.height(), twoLines - 12.0, 1e-6);
}
