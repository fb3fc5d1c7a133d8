// A scene of analytic spheres for the renderer's tests: members are spheres |x - c_m| = 8 on a
// 32^3 unit grid, their meshes built by the real preprocessing pipeline, drawn offscreen at a
// fixed size, looking along +y. Spheres give exact expectations for where silhouettes, plane
// curves and picks must and must not be.
#pragma once

#include <gtest/gtest.h>

#include <QColor>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "data/ensemble.h"
#include "gl/palette.h"
#include "gl/renderer.h"
#include "preprocessing/isosurface_pipeline.h"
#include "tests/support/image_compare.h"
#include "tests/support/offscreen_gl.h"

namespace ensil::test {
// Member m is the field |x - c_m| - offset_m on a 32^3 unit grid (centres in cells, offsets 0
// unless given), so its isosurface at 8 is a sphere of radius 8 + offset_m. Fields that differ
// by constants give every member a constant outlyingness over its surface.
inline data::Ensemble spheres(const std::vector<glm::vec3>& centres,
                              const std::vector<float>& offsets = {}) {
    data::Ensemble e;
    e.grid = data::Grid(data::makeUniformAxis("x", "m", 0, 31, 32),
                        data::makeUniformAxis("y", "m", 0, 31, 32),
                        data::makeUniformAxis("z", "m", 0, 31, 32));
    for (std::size_t n = 0; n < centres.size(); ++n) {
        const glm::vec3 c = centres[n];
        const float offset = n < offsets.size() ? offsets[n] : 0.0F;
        data::Member m;
        m.values.resize(e.grid.pointCount());
        for (std::size_t k = 0; k < 32; ++k) {
            for (std::size_t j = 0; j < 32; ++j) {
                for (std::size_t i = 0; i < 32; ++i) {
                    m.values[e.grid.index(i, j, k)] = glm::length(glm::vec3(i, j, k) - c) - offset;
                }
            }
        }
        e.members.push_back(std::move(m));
    }
    return e;
}

// The meshes of an ensemble at an isovalue (8: the spheres' radius), attributes in the display
// space of that vertical exaggeration.
inline std::shared_ptr<data::MeshSet> meshesOf(const data::Ensemble& e, float isovalue = 8.0F,
                                               float exaggeration = 1.0F) {
    prep::PipelineOptions options;
    options.isovalue = isovalue;
    auto built = prep::buildIsovalueMeshes(e, prep::computeEnsembleMoments(e),
                                           data::DisplayFrame(e.grid, exaggeration), options);
    auto set = std::make_shared<data::MeshSet>();
    set->members = std::move(built.members);
    set->mean = std::move(built.mean);
    return set;
}

inline int channelDistance(const QColor& c, const glm::vec3& e) {
    return std::max({std::abs(c.red() - int(e.r * 255)), std::abs(c.green() - int(e.g * 255)),
                     std::abs(c.blue() - int(e.b * 255))});
}

class SphereSceneTest : public OffscreenGlTest {
protected:
    void SetUp() override {
        OffscreenGlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        m_renderer.initialize();
        m_renderer.setBackground({0, 0, 0, 1});
    }
    void TearDown() override {
        if (m_renderer.isInitialized()) m_renderer.releaseGpuResources();
        OffscreenGlTest::TearDown();
    }
    void show(const data::Ensemble& e, const std::vector<glm::vec3>& colours) {
        m_renderer.setGrid(e.grid);
        m_renderer.camera().setAngles(-90.0F, 0.0F);  // looking along +y
        m_renderer.camera().fit(m_renderer.frame().center(), 0.45F);
        m_renderer.setMeshes(meshesOf(e));
        std::vector<gl::MemberAppearance> look;
        look.reserve(colours.size());
        for (const glm::vec3& c : colours) look.push_back({c, true, false});
        m_renderer.setAppearance(look);
    }
    QImage draw() {
        m_renderer.render(framebuffer(), kWidth, kHeight);
        return grab();
    }
    QPoint project(const glm::vec3& p) {
        const glm::vec4 c =
            m_renderer.camera().viewProjection(float(kWidth) / kHeight) * glm::vec4(p, 1.0F);
        return {int((c.x / c.w * 0.5F + 0.5F) * kWidth),
                int((1.0F - (c.y / c.w * 0.5F + 0.5F)) * kHeight)};
    }
    // Display position of grid index (i, j, k) on the 32^3 unit grid.
    glm::vec3 display(glm::vec3 index) { return m_renderer.frame().indexToDisplay(index); }
    gl::Renderer m_renderer;
};

// Two overlapping spheres in the first two cluster colours, seen head-on.
class TwoSpheresTest : public SphereSceneTest {
protected:
    void SetUp() override {
        SphereSceneTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        show(spheres({{12, 15.5F, 15.5F}, {19, 15.5F, 17}}),
             {gl::clusterColor(0), gl::clusterColor(1)});
    }
};

}  // namespace ensil::test
