// How members are drawn from a session: hidden members and clusters, the selection, and cluster
// colours; what the workbench and headless rendering share.
#include "session/member_appearance.h"

#include <gtest/gtest.h>

#include "gl/palette.h"

using namespace ensil;

TEST(MemberAppearance, HiddenClustersHideTheirMembersAndSelectionIsKept) {
    session::SessionState state;
    state.hiddenMembers = {0, 99};  // 99: not a member of this ensemble, ignored
    state.hiddenClusters = {1};
    state.selection = {2, 4, -1};
    const std::vector<int> labels{0, 1, 0, 1, 2};
    const session::MemberFlags flags = session::memberFlags(state, labels, 5);
    EXPECT_EQ(flags.visible, (std::vector<bool>{false, false, true, false, true}));
    EXPECT_EQ(flags.selected, (std::vector<bool>{false, false, true, false, true}));
    // Label 2's stable identity is 7: its colour and the number it is reported by.
    const auto look = session::memberAppearance(labels, {0, 1, 7}, flags);
    ASSERT_EQ(look.size(), 5u);
    EXPECT_EQ(look[4].cluster, 7);
    EXPECT_EQ(look[4].color, gl::clusterColor(7));
    EXPECT_NE(look[4].color, gl::clusterColor(2));
    EXPECT_TRUE(look[4].selected);
    EXPECT_FALSE(look[3].visible);
}

TEST(MemberAppearance, UnclusteredMembersAreGray) {
    const session::MemberFlags flags = session::memberFlags({}, {}, 3);
    const auto look = session::memberAppearance({}, {}, flags);
    ASSERT_EQ(look.size(), 3u);
    EXPECT_EQ(look[1].cluster, -1);
    EXPECT_EQ(look[1].color, gl::kUnclusteredColor);
    EXPECT_TRUE(look[1].visible);
}
