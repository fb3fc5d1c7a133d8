// What the streaming tests compare between a run in slabs and one in memory: meshes bit for
// bit, distances within 1e-9 relative (the sums' order differs), merge trees exactly.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "data/packed_mesh.h"
#include "preprocessing/clustering.h"
#include "preprocessing/similarity.h"

namespace ensil::test {

inline bool sameMesh(const data::PackedMesh& a, const data::PackedMesh& b) {
    return a.vertices.size() == b.vertices.size() && a.indices == b.indices &&
           std::memcmp(a.vertices.data(), b.vertices.data(),
                       a.vertices.size() * sizeof(data::PackedVertex)) == 0;
}

inline void expectSameDistances(const prep::DistanceMatrix& got, const prep::DistanceMatrix& want) {
    ASSERT_EQ(got.size, want.size);
    ASSERT_EQ(got.values.size(), want.values.size());
    for (std::size_t i = 0; i < want.values.size(); ++i) {
        EXPECT_NEAR(got.values[i], want.values[i], 1e-9 * want.values[i]) << "entry " << i;
    }
}

// Each member's distance to the mean: the in-memory job sums it with the matrix (one more
// column of its products), a streamed run member by member, so they agree to the matrix's
// tolerance.
inline void expectSameDistancesToMean(const std::vector<double>& got,
                                      const std::vector<double>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t m = 0; m < want.size(); ++m) {
        EXPECT_NEAR(got[m], want[m], 1e-9 * want[m]) << "member " << m;
    }
}

inline void expectSameTree(const prep::MergeTree& got, const prep::MergeTree& want) {
    ASSERT_EQ(got.merges.size(), want.merges.size());
    for (std::size_t m = 0; m < want.merges.size(); ++m) {
        EXPECT_EQ(got.merges[m].a, want.merges[m].a) << "merge " << m;
        EXPECT_EQ(got.merges[m].b, want.merges[m].b) << "merge " << m;
        EXPECT_EQ(got.merges[m].size, want.merges[m].size) << "merge " << m;
    }
}

}  // namespace ensil::test
