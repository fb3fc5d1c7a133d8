#include "preprocessing/member_summaries.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stop_token>
#include <vector>

#include "data/error.h"
#include "fixtures.h"
#include "preprocessing/mesh_packing.h"
#include "preprocessing/similarity.h"
#include "tests/support/special_values.h"

using namespace ensil;

namespace {
using test::kNaN;
}

TEST(DistancesToField, ConstantMembersGiveSquaredDifferencesOfRootDistances) {
    // mu = 10; members 10, 14, 1 -> roots 0, 2, 3; the field 19 -> root 3.
    const auto e = test::analyticEnsemble(3, 4, 3, 2, [](std::size_t m, auto, auto, auto) {
        return std::array{10.0F, 14.0F, 1.0F}[m];
    });
    const std::vector<float> field(e.grid.pointCount(), 19.0F);
    const auto d = prep::distancesToField(e, field, 10.0F);
    ASSERT_EQ(d.size(), 3u);
    EXPECT_DOUBLE_EQ(d[0], 9.0);
    EXPECT_DOUBLE_EQ(d[1], 1.0);
    EXPECT_DOUBLE_EQ(d[2], 0.0);
}

TEST(DistancesToField, AgreesWithTheSimilarityMatrixWhenTheFieldIsAMember) {
    const auto e = test::analyticEnsemble(
        4, 8, 6, 5, [](std::size_t m, std::size_t i, std::size_t j, std::size_t k) {
            if (m == 2 && i == 3 && j == 2) return kNaN;  // a gap in one member
            return std::sin(0.7F * static_cast<float>(i + m)) * static_cast<float>(j + 1) +
                   0.3F * static_cast<float>(k * m);
        });
    const auto matrix = prep::computeDistanceMatrix(e, 0.4F);
    const auto& reference = e.members[1].values;
    const auto d = prep::distancesToField(e, {reference.data(), reference.size()}, 0.4F);
    for (std::size_t m = 0; m < 4; ++m) {
        EXPECT_NEAR(d[m], matrix.at(m, 1), 1e-9 * (1.0 + matrix.at(m, 1))) << "member " << m;
    }
    EXPECT_EQ(d[1], 0.0);
}

TEST(DistancesToField, NoCommonPointIsInfinitelyFar) {
    auto e = test::analyticEnsemble(
        2, 3, 3, 3, [](std::size_t m, auto, auto, auto) { return m == 0 ? kNaN : 1.0F; });
    const std::vector<float> field(e.grid.pointCount(), 2.0F);
    const auto d = prep::distancesToField(e, field, 0.0F);
    EXPECT_TRUE(std::isinf(d[0]));
    EXPECT_TRUE(std::isfinite(d[1]));
}

TEST(DistancesToField, RejectsBadInputWithAClearMessage) {
    const auto e = test::analyticEnsemble(2, 3, 3, 3, [](auto, auto, auto, auto) { return 1.0F; });
    const std::vector<float> shortField(5, 1.0F);
    try {
        (void)prep::distancesToField(e, shortField, 1.0F);
        FAIL() << "a field of the wrong size was accepted";
    } catch (const data::Error& error) {
        EXPECT_NE(std::string(error.what()).find("27 points"), std::string::npos) << error.what();
    }
    const std::vector<float> field(e.grid.pointCount(), 1.0F);
    EXPECT_THROW((void)prep::distancesToField(e, field, kNaN), data::Error);
    EXPECT_THROW((void)prep::distancesToField(data::Ensemble{}, {}, 1.0F), data::Error);
}

TEST(DistancesToField, StopsWhenAsked) {
    const auto e = test::analyticEnsemble(3, 4, 4, 4, [](auto, auto, auto, auto) { return 1.0F; });
    const std::vector<float> field(e.grid.pointCount(), 1.0F);
    std::stop_source source;
    source.request_stop();
    EXPECT_THROW((void)prep::distancesToField(e, field, 1.0F, source.get_token()), data::Cancelled);
}

TEST(MeanOutlyingness, IsTheMeanOfTheStoredVertexValues) {
    data::TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.indices = {0, 1, 2, 0, 1, 3};
    prep::VertexAttributes a;
    a.normals.assign(4, {0, 0, 1});
    a.kappa1.assign(4, 0.0F);
    a.kappa2.assign(4, 0.0F);
    a.principalDirections.assign(4, {1, 0, 0});
    a.outlyingness = {1.0F, 2.0F, 4.0F, 9.0F};
    const auto packed = prep::packMesh(mesh, a);
    // Halves keep 2^-11 relative precision: the mean of 1, 2, 4, 9 is 4.
    EXPECT_NEAR(prep::meanOutlyingness(packed), 4.0, 4.0 * 1e-3);
}

TEST(MeanOutlyingness, IsNotANumberWithoutASurface) {
    EXPECT_TRUE(std::isnan(prep::meanOutlyingness(data::PackedMesh{})));
}
