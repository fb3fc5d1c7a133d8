// The picture every real file opens with (issue: defaults that show something): at the default
// variable and isovalue, from the default 3D view and from the map view, most members are seen,
// by their silhouettes or by their rims where they meet the box, counted in the id pass.
#include <gtest/gtest.h>

#include <string>

#include "data/ensemble_reader.h"
#include "preprocessing/default_isovalue.h"
#include "preprocessing/field_statistics.h"
#include "tests/gl/renderer_fixture.h"
#include "tests/gl/sphere_scene.h"

using namespace ensil;

namespace {
struct RealFile {
    const char* file;
    const char* memberDim;  // empty: the file's own member dimension
};

// Every file in tests/data/real that holds a 3D ensemble, at its default variable.
constexpr RealFile kFiles[] = {{"era5_eda_members.nc", ""},
                               {"eraint_uvz.nc", "month"},
                               {"uk_hires.nc", "time"},
                               {"contour.cdf", "frtime"}};
}  // namespace

class DefaultPictureTest : public test::RendererFixture {
protected:
    // Members with a pixel in the id pass over the whole view.
    std::size_t membersSeen() {
        (void)draw();
        return m_renderer.membersIn(0, 0, kWidth - 1, kHeight - 1).size();
    }
};

TEST_F(DefaultPictureTest, OnEveryRealFileMostMembersAreSeenFromTheDefaultAndTheMapView) {
    for (const RealFile& f : kFiles) {
        SCOPED_TRACE(f.file);
        data::Ensemble e =
            data::openEnsemble({.paths = {std::string(ENSIL_SHARED_DATA_DIR "/") + f.file},
                                .memberDimension = f.memberDim});
        (void)data::leaveOutMembersWithoutData(e);
        const float iso =
            prep::defaultIsovalue(e, prep::computeFieldStatistics(e, prep::kIsovalueHistogramBins));
        m_renderer.setViewSize(kWidth, kHeight);
        m_renderer.setGrid(e.grid);
        m_renderer.setMeshes(test::meshesOf(e, iso));
        std::vector<gl::MemberAppearance> look(e.memberCount());
        for (std::size_t m = 0; m < look.size(); ++m) {
            look[m] = {gl::clusterColor(static_cast<int>(m)), true, false};
        }
        m_renderer.setAppearance(look);
        m_renderer.settings() = gl::RenderSettings{};
        const double most = prep::kMostMembers * static_cast<double>(e.memberCount());

        m_renderer.resetCamera();
        m_renderer.camera().setProjection(gl::Camera::Projection::Perspective);
        EXPECT_GE(static_cast<double>(membersSeen()), most) << e.variable << " at " << iso;

        m_renderer.lookFrom(-90.0F, 90.0F);
        m_renderer.camera().setProjection(gl::Camera::Projection::Orthographic);
        EXPECT_GE(static_cast<double>(membersSeen()), most)
            << e.variable << " at " << iso << ", from the top";
    }
}
