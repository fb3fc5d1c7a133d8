// The one setting table: every default lies in its own range, and no two settings share a
// name anywhere they are looked up (code, project file, command line, remembered settings).
#include "session/setting_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

using namespace ensil;

TEST(SettingTable, EveryDefaultIsAllowedByItsOwnRange) {
    for (const session::Setting& s : session::settingTable()) {
        EXPECT_EQ(s.problemWith(s.defaultValue()), "") << s.id;
        EXPECT_LT(s.minimum, s.maximum) << s.id;
        if (s.kind == session::SettingKind::Choice) {
            EXPECT_EQ(static_cast<std::size_t>(s.maximum) + 1, s.choices.size()) << s.id;
        }
    }
}

TEST(SettingTable, NamesAreUniqueInEveryPlaceTheyAreUsed) {
    std::set<std::string> ids, keys, options, remembered;
    for (const session::Setting& s : session::settingTable()) {
        EXPECT_TRUE(ids.insert(std::string(s.id)).second) << s.id;
        if (!s.projectKey.empty()) {
            EXPECT_TRUE(keys.insert(std::string(s.projectKey)).second) << s.id;
        }
        if (!s.option.empty()) {
            EXPECT_TRUE(options.insert(std::string(s.option)).second) << s.id;
        }
        if (!s.rememberedKey.empty()) {
            EXPECT_TRUE(remembered.insert(std::string(s.rememberedKey)).second) << s.id;
        }
    }
    EXPECT_THROW((void)session::setting("no such setting"), std::logic_error);
}

TEST(SettingTable, RangesRefuseWhatWouldDrawNothing) {
    const session::Setting& thickness = session::setting("thickness");
    for (const double bad : {-5.0, 0.0, std::nan(""), double(INFINITY), 1.0}) {
        EXPECT_NE(thickness.problemWith(bad), "") << bad;
    }
    EXPECT_EQ(thickness.problemWith(0.3), "") << "a project may hold a thick tau";
    EXPECT_EQ(thickness.problemWith(std::nan("")), "must be a number from 0.0001 to 0.5");
    const session::Setting& exaggeration = session::setting("vertical_exaggeration");
    for (const double bad : {0.0, 1e30, -1.0}) EXPECT_NE(exaggeration.problemWith(bad), "") << bad;
    const session::Setting& clusters = session::setting("clusters");
    EXPECT_EQ(clusters.problemWith(2.5), "must be a whole number from 1 to 10000");
    EXPECT_EQ(clusters.problemWith(3), "");
}

TEST(SettingTable, ValuesAreWrittenAsAUserTypesThem) {
    EXPECT_EQ(session::setting("mode").format(1), "spaghetti");
    EXPECT_EQ(session::setting("linkage").format(3), "ward");
    EXPECT_EQ(session::setting("show_mean").format(0), "false");
    EXPECT_EQ(session::setting("background").format(session::packColour({1.0F, 0.5F, 0.0F})),
              "#ff8000");
    const glm::vec3 rgb = session::unpackColour(session::packColour({0.2F, 0.4F, 0.6F}));
    EXPECT_NEAR(rgb.g, 0.4F, 0.5F / 255.0F);
}

TEST(SettingTable, GetAndSetReachTheSameField) {
    for (const session::Setting& s : session::settingTable()) {
        session::SessionState state;
        // A value other than the default, inside the range.
        const double other = s.kind == session::SettingKind::Colour ? 0x123456
                             : s.defaultValue() == s.maximum        ? s.minimum
                                                                    : s.maximum;
        s.set(state, other);
        EXPECT_NEAR(s.get(state), other, std::abs(other) * 1e-6) << s.id;
        // ... and only that setting changed.
        for (const session::Setting& t : session::settingTable()) {
            if (&t != &s) {
                EXPECT_DOUBLE_EQ(t.get(state), t.defaultValue()) << s.id << " moved " << t.id;
            }
        }
    }
}
