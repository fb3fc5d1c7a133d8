#include <gtest/gtest.h>

#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include "cli/command_line.h"
#include "gl/palette.h"
#include "tests/app/default_isovalue.h"
#include "tests/app/ensil_run.h"
#include "tests/support/image_compare.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

TEST(RenderCommand, WritesThePictureWithoutAWindowAndReportsFrameTime) {
    test::TempDir dir;
    const QString png = QString::fromStdString(dir.file("era5.png"));
    const test::EnsilRun r = test::runEnsil(
        {"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t", "--iso", "260",
         "--out", png, "--size", "400x300", "--frames", "3", "--clusters", "2", "--no-mean",
         "--thickness", "0.05", "--no-cache", "--json"});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_EQ(o["width"].toInt(), 400);
    EXPECT_EQ(o["height"].toInt(), 300);
    EXPECT_GT(o["frame_ms"].toDouble(), 0.0);
    EXPECT_GT(o["gpu_bytes"].toInteger(), 0);
    const QImage image(png);
    ASSERT_EQ(image.size(), QSize(400, 300));
    // Silhouettes in the two cluster colours are in the picture.
    int clusterPixels = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            for (int k = 0; k < 2; ++k) {
                const glm::vec3 e = gl::clusterColor(k);
                if (std::abs(c.redF() - e.r) < 0.08 && std::abs(c.greenF() - e.g) < 0.08 &&
                    std::abs(c.blueF() - e.b) < 0.08)
                    ++clusterPixels;
            }
        }
    EXPECT_GT(clusterPixels, 50);
    image.save(test::testOutputDir() + "/render_command_era5.png");
}

namespace {
// Renders era5_eda_members.nc's temperature at 260 K, seen from above, with extra options;
// returns the image (null on failure, with the error in `error`).
QImage renderEra5(const QStringList& extra, QString* error, int* exitCode = nullptr) {
    test::TempDir dir;
    const QString png = QString::fromStdString(dir.file("out.png"));
    QString outText, errText;
    QTextStream out(&outText), err(&errText);
    QStringList args{"ensil",  "render",    ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc",
                     "--var",  "t",         "--iso",
                     "260",    "--out",     png,
                     "--size", "320x240",   "--frames",
                     "1",      "--no-mean", "--elevation",
                     "60",     "--no-cache"};
    args += extra;
    const int code = cli::runCommandLine(args, out, err).exitCode;
    err.flush();
    if (exitCode != nullptr) *exitCode = code;
    *error = errText;
    return code == 0 ? QImage(png) : QImage();
}
}  // namespace

TEST(RenderCommand, APlaneAtTheFarCornerCutsNothingAndOneThroughTheMiddleCutsTheNearSide) {
    QString error;
    const QImage whole = renderEra5({}, &error);
    ASSERT_FALSE(whole.isNull()) << error.toStdString();
    // Above the top of the box by more than eps (position 1 touches it, and surfaces that
    // reach the top level draw their intersection curves there): nothing is cut or drawn.
    const QImage untouched = renderEra5({"--plane", "0,0,1,1.2"}, &error);
    ASSERT_FALSE(untouched.isNull()) << error.toStdString();
    EXPECT_LT(test::differingFraction(whole, untouched, 8), 0.001);
    // Through the middle, the upper half (the viewer's side, looking from above) is removed
    // and the intersection curves are drawn: the picture changes a lot.
    const QImage cut = renderEra5({"--plane", "0,0,1,0", "--plane-thickness", "0.01"}, &error);
    ASSERT_FALSE(cut.isNull()) << error.toStdString();
    EXPECT_GT(test::differingFraction(whole, cut, 24), 0.01);
    cut.save(test::testOutputDir() + "/render_command_era5_plane.png");
}

TEST(RenderCommand, RemovalOverTheWholeRangeThinsTheSilhouettes) {
    QString error;
    const QImage whole = renderEra5({"--thickness", "0.02"}, &error);
    ASSERT_FALSE(whole.isNull()) << error.toStdString();
    const QImage thinned =
        renderEra5({"--thickness", "0.02", "--removal", "0,1e9", "--group-size", "8"}, &error);
    ASSERT_FALSE(thinned.isNull()) << error.toStdString();
    EXPECT_GT(test::differingFraction(whole, thinned, 24), 0.002);
}

TEST(RenderCommand, RefusesMalformedPlaneRemovalAndGroupSize) {
    for (const QStringList& bad :
         {QStringList{"--plane", "0,0,0,0.5"}, QStringList{"--plane", "0,0,1"},
          QStringList{"--plane", "a,b,c,d"}, QStringList{"--removal", "5,1"},
          QStringList{"--group-size", "0"}}) {
        QString error;
        int code = 0;
        EXPECT_TRUE(renderEra5(bad, &error, &code).isNull());
        EXPECT_EQ(code, 2) << bad.join(' ').toStdString();
        EXPECT_TRUE(error.contains(bad[0])) << error.toStdString();
    }
}

TEST(RenderCommand, BadValuesAreRefusedNamingTheOptionTheValueAndWhatIsAllowed) {
    // Each of these used to draw a wrong or blank picture and exit 0.
    for (const QStringList& bad :
         {QStringList{"--thickness", "abc"}, QStringList{"--thickness", "-5"},
          QStringList{"--thickness", "nan"}, QStringList{"--exaggeration", "0"},
          QStringList{"--exaggeration", "nan"}, QStringList{"--exaggeration", "1e30"},
          QStringList{"--azimuth", "nan"}, QStringList{"--size", "4294967298x200"},
          QStringList{"--clusters", "2.5"}, QStringList{"--frames", "0"},
          QStringList{"--mode", "wireframe"}, QStringList{"--background", "pinkish"}}) {
        QString error;
        int code = 0;
        EXPECT_TRUE(renderEra5(bad, &error, &code).isNull()) << bad.join(' ').toStdString();
        EXPECT_EQ(code, 2) << bad.join(' ').toStdString();
        EXPECT_TRUE(error.contains(QStringLiteral("%1 '%2' is refused").arg(bad[0], bad[1])))
            << error.toStdString();
        EXPECT_TRUE(error.contains(QStringLiteral("must be"))) << error.toStdString();
    }
}

TEST(RenderCommand, ASavedProjectDrawsTheIdenticalPicture) {
    test::TempDir dir;
    const QString project = QString::fromStdString(dir.file("drawn.ensil"));
    QString error;
    const QImage first = renderEra5(
        {"--azimuth", "20", "--clusters", "3", "--thickness", "0.02", "--plane", "0,1,0,0.2",
         "--background", "#204060", "--projection", "orthographic", "--save-project", project},
        &error);
    ASSERT_FALSE(first.isNull()) << error.toStdString();
    ASSERT_TRUE(QFile::exists(project));

    const QString png = QString::fromStdString(dir.file("again.png"));
    const test::EnsilRun again = test::runEnsil(
        {"render", project, "--out", png, "--size", "320x240", "--frames", "1", "--no-cache"});
    ASSERT_EQ(again.code, 0) << again.err.toStdString();
    const QImage second(png);
    ASSERT_EQ(second.size(), first.size());
    EXPECT_EQ(test::differingFraction(first, second, 0), 0.0)
        << "the project must hold everything the picture was drawn from";
    // And the project is not the default session: the options went into it.
    QFile file(project);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QJsonObject saved = QJsonDocument::fromJson(file.readAll()).object();
    EXPECT_EQ(saved["rendering"].toObject()["thickness"].toDouble(), 0.02F);
    EXPECT_EQ(saved["camera"].toObject()["projection"].toString(), "orthographic");
    EXPECT_EQ(saved["clusters"].toObject()["count"].toInt(), 3);
}

TEST(RenderCommand, AProjectDefinesThePictureSoSceneOptionsAreRefusedWithIt) {
    test::TempDir dir;
    const QString project = QString::fromStdString(dir.file("drawn.ensil"));
    QString error;
    ASSERT_FALSE(renderEra5({"--save-project", project}, &error).isNull()) << error.toStdString();
    const test::EnsilRun r =
        test::runEnsil({"render", project, "--out", QString::fromStdString(dir.file("x.png")),
                        "--thickness", "0.02"});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains("--thickness comes from the project")) << r.err.toStdString();
}

TEST(RenderCommand, WithoutAnIsovalueItDrawsTheWorkbenchsDefaultAndSaysWhich) {
    test::TempDir dir;
    const test::EnsilRun r = test::runEnsil(
        {"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t", "--out",
         QString::fromStdString(dir.file("t.png")), "--size", "320x240", "--no-cache", "--json"});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_EQ(o["variable"].toString(), "t");
    EXPECT_EQ(o["frames"].toInt(), 1);  // a picture is drawn once unless timing is asked for
    EXPECT_FLOAT_EQ(
        static_cast<float>(o["isovalue"].toDouble()),
        test::workbenchDefaultIsovalue(ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "t"));
    // The vertical scale the figure states: 850 to 500 hPa (1457 to 5574 m in the standard
    // atmosphere) drawn 0.2 high under the 357 degrees of longitude the file spans (the
    // longer axis spans the box's 1), about 1900 times true.
    EXPECT_NEAR(o["vertical_scale"].toDouble(), 0.2 * 357.0 * 111195.08 / (5574.0 - 1457.0), 5.0);
    EXPECT_EQ(o["vertical_heights"].toString(), "standard atmosphere");
}

// --view top is the map view: north up, from straight above, orthographic (and --view south the
// level orthographic view from the south); the same picture as
// the angles and projection given by hand. An explicit --projection overrides it, and a view
// that does not exist is refused, naming those that do.
TEST(RenderCommand, TheTopViewIsTheNorthUpOrthographicMapAndUnknownViewsAreRefused) {
    test::TempDir dir;
    const auto render = [&](const QString& name, const QStringList& extra) {
        const QString png = QString::fromStdString(dir.file(name.toStdString()));
        const test::EnsilRun r =
            test::runEnsil(QStringList{"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc",
                                       "--var", "t", "--iso", "260", "--out", png, "--size",
                                       "320x240", "--frames", "1", "--no-cache"} +
                           extra);
        EXPECT_EQ(r.code, 0) << r.err.toStdString();
        return QImage(png).convertToFormat(QImage::Format_RGB32);
    };
    const QImage top = render("top.png", {"--view", "top"});
    const QImage byHand = render(
        "hand.png", {"--azimuth", "-90", "--elevation", "90", "--projection", "orthographic"});
    const QImage perspective =
        render("persp.png", {"--view", "top", "--projection", "perspective"});
    const QImage south = render("south.png", {"--view", "south"});
    EXPECT_EQ(top, byHand);
    EXPECT_NE(top, perspective);
    EXPECT_NE(top, south);
    // A side view looks level and orthographic (issue 39: ticks on the near edge match a level
    // in the middle of the box).
    EXPECT_EQ(south, render("south-hand.png", {"--azimuth", "-90", "--elevation", "0",
                                               "--projection", "orthographic"}));

    const test::EnsilRun bad =
        test::runEnsil({"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t",
                        "--out", QString::fromStdString(dir.file("x.png")), "--view", "sideways"});
    EXPECT_EQ(bad.code, 2);
    EXPECT_TRUE(
        bad.err.contains("--view 'sideways' is refused: it must be one of top, north, "
                         "south, east, west, default"))
        << bad.err.toStdString();
}

// A picture twice as large looks like the view at 2x: the title line's text is about twice as
// tall at 2560 x 1600 as at 1280 x 800 (gl::exportTextScale), not the same 11 pixels.
TEST(RenderCommand, TextGrowsWithThePicturesSize) {
    test::TempDir dir;
    const auto titleHeight = [&](const QString& size) {
        const QString png = QString::fromStdString(dir.file(size.toStdString() + ".png"));
        const test::EnsilRun r =
            test::runEnsil({"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t",
                            "--iso", "260", "--out", png, "--size", size, "--frames", "1",
                            "--no-cache", "--no-legend", "--no-axis-labels"});
        EXPECT_EQ(r.code, 0) << r.err.toStdString();
        const QImage image(png);
        // Rows of the top band holding the title's light text.
        int first = -1, last = -1;
        for (int y = 0; y < image.height() / 8; ++y) {
            for (int x = 0; x < image.width(); ++x) {
                if (image.pixelColor(x, y).lightness() > 170) {
                    if (first < 0) first = y;
                    last = y;
                    break;
                }
            }
        }
        return first < 0 ? 0 : last - first + 1;
    };
    const int small = titleHeight("1280x800");
    const int large = titleHeight("2560x1600");
    ASSERT_GT(small, 5) << "a title is drawn";
    EXPECT_NEAR(static_cast<double>(large) / small, 2.0, 0.35);
}

// The floor shows what --floor asks: nothing (the background shows through the box's floor),
// the mean's column maximum (the default), or the mean at a level, each a different picture.
TEST(RenderCommand, TheFloorShowsNothingTheColumnMaximumOrTheMeanAtALevel) {
    test::TempDir dir;
    const auto render = [&](const QString& name, const QStringList& extra) {
        const QString png = QString::fromStdString(dir.file(name.toStdString()));
        const test::EnsilRun r =
            test::runEnsil(QStringList{"render",
                                       ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc",
                                       "--var",
                                       "t",
                                       "--iso",
                                       "250",
                                       "--out",
                                       png,
                                       "--size",
                                       "320x240",
                                       "--frames",
                                       "1",
                                       "--no-cache",
                                       "--view",
                                       "top",
                                       "--no-mean",
                                       "--no-coastlines",
                                       "--no-borders",
                                       "--no-labels",
                                       "--no-title"} +
                           extra);
        EXPECT_EQ(r.code, 0) << r.err.toStdString();
        return QImage(png).convertToFormat(QImage::Format_RGB32);
    };
    const QImage none = render("none.png", {"--floor", "none"});
    const QImage maximum = render("max.png", {});
    const QImage level0 = render("level0.png", {"--floor", "mean-at-level", "--floor-level", "0"});
    const QImage level1 = render("level1.png", {"--floor", "mean-at-level", "--floor-level", "1"});
    const QImage spread = render("spread.png", {"--floor", "spread-maximum"});
    // Near the box's middle (the equator, no isosurface at 250 K there).
    const QPoint middle(160, 125);
    const QColor background = none.pixelColor(5, 5);
    EXPECT_EQ(none.pixelColor(middle), background) << "no floor: the background";
    EXPECT_NE(maximum.pixelColor(middle), background);
    EXPECT_NE(level0, maximum);
    EXPECT_NE(level0, level1) << "each level its own map";
    EXPECT_NE(spread.pixelColor(middle), background);
    EXPECT_NE(spread, maximum) << "the spread's map, not the mean's";
    const test::EnsilRun bad =
        test::runEnsil({"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t",
                        "--out", QString::fromStdString(dir.file("x.png")), "--floor", "spread"});
    EXPECT_EQ(bad.code, 2);
}

TEST(RenderCommand, TheSectionFillsThePlanesCutFaceAndIsRefusedWhereNothingWouldShowIt) {
    test::TempDir dir;
    const auto render = [&](const QString& name, const QStringList& extra) {
        const QString png = QString::fromStdString(dir.file(name.toStdString()));
        const test::EnsilRun r = test::runEnsil(
            QStringList{"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t",
                        "--iso", "250", "--out", png, "--size", "320x240", "--frames", "1",
                        "--no-cache", "--no-labels", "--no-title", "--floor", "none"} +
            extra);
        EXPECT_EQ(r.code, 0) << r.err.toStdString();
        return QImage(png).convertToFormat(QImage::Format_RGB32);
    };
    // A plane across the latitudes through the middle of the box, seen from the default view.
    const QStringList plane{"--plane", "0,1,0,0"};
    const QImage unfilled = render("unfilled.png", plane);
    const QImage spread = render("spread.png", plane + QStringList{"--section", "stddev"});
    const QImage probability =
        render("probability.png", plane + QStringList{"--section", "probability"});
    EXPECT_GT(test::differingFraction(unfilled, spread, 8), 0.02) << "the face is filled";
    EXPECT_GT(test::differingFraction(spread, probability, 8), 0.01) << "each field its own";

    const QString out = QString::fromStdString(dir.file("x.png"));
    const test::EnsilRun noPlane =
        test::runEnsil({"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t",
                        "--out", out, "--section", "mean"});
    EXPECT_EQ(noPlane.code, 2);
    EXPECT_TRUE(noPlane.err.contains("--section mean needs --plane")) << noPlane.err.toStdString();
    const test::EnsilRun member =
        test::runEnsil({"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t",
                        "--out", out, "--plane", "0,1,0,0", "--section", "member"});
    EXPECT_EQ(member.code, 2);
    EXPECT_TRUE(member.err.contains("select members in the workbench")) << member.err.toStdString();
    const test::EnsilRun unknown =
        test::runEnsil({"render", ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc", "--var", "t",
                        "--out", out, "--plane", "0,1,0,0", "--section", "spread"});
    EXPECT_EQ(unknown.code, 2);
    EXPECT_TRUE(unknown.err.contains("stddev"))
        << "names what is allowed: " << unknown.err.toStdString();
}

// Four members drawn without --clusters get two clusters, as the workbench and `ensil
// preprocess` open them (session::defaultClusters), not one cluster per member; --clusters
// still decides when given.
TEST(RenderCommand, AFewMembersDrawnWithoutClustersGetAboutHalfAsMany) {
    test::TempDir dir;
    const QString data = QString::fromStdString(dir.file("four.nc"));
    ASSERT_EQ(
        test::runEnsil({"generate", "--members", "4", "--grid", "24x12x4", "--out", data}).code, 0);
    const auto clustersDrawn = [&](const QStringList& extra) {
        const QString project = QString::fromStdString(dir.file("drawn.ensil"));
        const test::EnsilRun r = test::runEnsil(
            QStringList{"render", data, "--iso", "20", "--size", "320x200", "--no-cache", "--quiet",
                        "--out", QString::fromStdString(dir.file("four.png")), "--save-project",
                        project} +
            extra);
        EXPECT_EQ(r.code, 0) << r.err.toStdString();
        QFile file(project);
        if (!file.open(QIODevice::ReadOnly)) return -1;
        return QJsonDocument::fromJson(file.readAll())
            .object()["clusters"]
            .toObject()["count"]
            .toInt();
    };
    EXPECT_EQ(clustersDrawn({}), 2);
    EXPECT_EQ(clustersDrawn({"--clusters", "4"}), 4);
}
