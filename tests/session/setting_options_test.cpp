// Command-line values of settings: typed and checked, refused naming the option, the value and
// what is allowed; sizes and counts never wrap.
#include "session/setting_options.h"

#include <gtest/gtest.h>

using namespace ensil;

namespace {
QString refusal(std::string_view id, const char* text) {
    QString problem;
    const auto value =
        session::parseSettingValue(session::setting(id), QString::fromLatin1(text), problem);
    return value ? QString() : problem;
}
}  // namespace

TEST(SettingOptions, BadNumbersAreRefusedNamingOptionValueAndRange) {
    for (const char* bad : {"abc", "-5", "nan", "inf", "", "0.5.1"}) {
        const QString problem = refusal("thickness", bad);
        EXPECT_TRUE(problem.startsWith(QStringLiteral("--thickness '%1' is refused").arg(bad)))
            << problem.toStdString();
        EXPECT_TRUE(problem.contains("from 0.0001 to 0.5")) << problem.toStdString();
    }
    for (const char* bad : {"0", "nan", "1e30"}) {
        EXPECT_FALSE(refusal("vertical_exaggeration", bad).isEmpty()) << bad;
    }
    EXPECT_FALSE(refusal("azimuth", "nan").isEmpty());
    EXPECT_FALSE(refusal("clusters", "2.5").isEmpty());
    EXPECT_FALSE(refusal("clusters", "4294967298").isEmpty());
    EXPECT_FALSE(refusal("mode", "wireframe").isEmpty());
    EXPECT_TRUE(refusal("mode", "wireframe").contains("shaded, spaghetti, surfaces or opaque"));
    EXPECT_FALSE(refusal("background", "not a colour").isEmpty());
}

TEST(SettingOptions, GoodValuesAreTakenAsTyped) {
    QString problem;
    EXPECT_DOUBLE_EQ(*session::parseSettingValue(session::setting("thickness"), "0.01", problem),
                     0.01);
    EXPECT_DOUBLE_EQ(*session::parseSettingValue(session::setting("mode"), "Opaque", problem), 3);
    EXPECT_DOUBLE_EQ(
        *session::parseSettingValue(session::setting("background"), "#ffffff", problem), 0xFFFFFF);
}

TEST(SettingOptions, ImageSizesNeverWrap) {
    QString problem;
    EXPECT_FALSE(session::parseImageSize("--size", "4294967298x200", problem));
    EXPECT_TRUE(problem.contains("4294967298x200")) << problem.toStdString();
    EXPECT_FALSE(session::parseImageSize("--size", "0x200", problem));
    EXPECT_FALSE(session::parseImageSize("--size", "20000x200", problem));
    EXPECT_FALSE(session::parseImageSize("--size", "-3x200", problem));
    const auto size = session::parseImageSize("--size", "640x480", problem);
    ASSERT_TRUE(size);
    EXPECT_EQ(size->first, 640);
    EXPECT_EQ(size->second, 480);
}

TEST(SettingOptions, AParserAppliesWhatWasGivenAndRefusesContradictions) {
    const session::SettingOptions options{"thickness", "show_mean", "clusters"};
    QCommandLineParser parser;
    options.addTo(parser);
    ASSERT_TRUE(parser.parse({"ensil", "--thickness", "0.02", "--no-mean"}));
    session::SessionState state;
    QString problem;
    ASSERT_TRUE(options.applyTo(parser, state, problem)) << problem.toStdString();
    EXPECT_FLOAT_EQ(state.render.thickness, 0.02F);
    EXPECT_FALSE(state.render.showMean);
    EXPECT_EQ(state.clusters, 5) << "not given: the default";
    EXPECT_EQ(options.given(parser), QStringList({"--thickness", "--no-mean"}));

    QCommandLineParser both;
    options.addTo(both);
    ASSERT_TRUE(both.parse({"ensil", "--mean", "--no-mean"}));
    EXPECT_FALSE(options.applyTo(both, state, problem));
    EXPECT_TRUE(problem.contains("contradict")) << problem.toStdString();
}
