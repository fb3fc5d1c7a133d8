// Coastlines drawn on the floor of ERA5's real grid, seen from straight above (north up,
// orthographic): known coastal places lie on the drawn line's pixels, inland places do not,
// and switching the coastlines off removes them.
#include <gtest/gtest.h>

#include <QColor>
#include <cmath>

#include "data/ensemble_reader.h"
#include "geo/map_lines.h"
#include "gl/renderer.h"
#include "tests/gl/renderer_fixture.h"

using namespace ensil;

namespace {

struct Place {
    const char* name;
    double lon;
    double lat;
};

// Capes and straits on the Natural Earth coast, and places far from any coast.
constexpr Place kCoastal[] = {
    {"Cape of Good Hope", 18.47, -34.36}, {"Cabo de Sao Roque", -35.26, -5.48},
    {"Cape Horn", -67.27, -55.98},        {"Cape York", 142.53, -10.69},
    {"Cape Lopatka", 156.65, 50.87},      {"Ras Hafun", 51.27, 10.44}};
constexpr Place kInland[] = {
    {"central Sahara", 15.0, 23.0}, {"Kansas", -100.0, 40.0}, {"central Australia", 134.0, -25.0}};

bool isLinePixel(const QColor& c) {
    // The coastline's light core over a black background and no floor map.
    return c.red() > 150 && c.green() > 150 && c.blue() > 150;
}

}  // namespace

class MapLinesRenderTest : public test::RendererFixture {
protected:
    static constexpr int kRadius = 2;

    void SetUp() override {
        test::RendererFixture::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        m_description = data::describeEnsemble(
            {.paths = {std::string(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc")},
             .variable = "t"});
        m_renderer.setViewSize(kWidth, kHeight);
        m_renderer.setGrid(m_description.grid);
        m_renderer.setBackground({0.0F, 0.0F, 0.0F, 1.0F});
        m_renderer.camera().setProjection(gl::Camera::Projection::Orthographic);
        m_renderer.lookFrom(-90.0F, 90.0F);
        m_renderer.settings().showBorders = false;
        m_renderer.setMapLines(std::make_shared<const std::vector<geo::MapLine>>(
            geo::mapLinesFor(m_description.grid, m_description.gridMapping)));
    }
    // The pixel (top-left origin) of a place on the floor; the grid's longitudes run 0..357.
    QPoint pixelOf(const Place& place) const {
        const double lon = place.lon < 0.0 ? place.lon + 360.0 : place.lon;
        glm::vec3 p =
            m_renderer.frame().toDisplay({lon, place.lat, m_description.grid.z().front()});
        p.z = 0.0F;  // on the floor
        return project(p);
    }
    static bool lineNear(const QImage& image, QPoint p) {
        for (int dy = -kRadius; dy <= kRadius; ++dy) {
            for (int dx = -kRadius; dx <= kRadius; ++dx) {
                const QPoint q = p + QPoint(dx, dy);
                if (image.rect().contains(q) && isLinePixel(image.pixelColor(q))) return true;
            }
        }
        return false;
    }

    data::EnsembleDescription m_description;
};

TEST_F(MapLinesRenderTest, KnownCoastalPlacesLieOnTheDrawnCoastlineAndInlandPlacesDoNot) {
    const QImage image = draw();
    image.save(QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/era5_coastlines_top.png"));
    for (const Place& place : kCoastal) {
        EXPECT_TRUE(lineNear(image, pixelOf(place)))
            << place.name << " at " << pixelOf(place).x() << ", " << pixelOf(place).y();
    }
    for (const Place& place : kInland) {
        EXPECT_FALSE(lineNear(image, pixelOf(place))) << place.name;
    }
}

TEST_F(MapLinesRenderTest, SwitchingTheCoastlinesOffRemovesThem) {
    m_renderer.settings().showCoastlines = false;
    const QImage image = draw();
    for (const Place& place : kCoastal) EXPECT_FALSE(lineNear(image, pixelOf(place))) << place.name;
}
