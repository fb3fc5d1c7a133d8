#include <gtest/gtest.h>

#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include "app/command_line.h"
#include "gl/palette.h"
#include "tests/support/image_compare.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

TEST(RenderCommand, WritesThePictureWithoutAWindowAndReportsFrameTime) {
    test::TempDir dir;
    const QString png = QString::fromStdString(dir.file("era5.png"));
    QString outText, errText;
    QTextStream out(&outText), err(&errText);
    const int code = app::runCommandLine(
                         {"ensil",      "render",      ENSIL_SHARED_DATA_DIR "/era5_eda_members.nc",
                          "--var",      "t",           "--iso",
                          "260",        "--out",       png,
                          "--size",     "400x300",     "--frames",
                          "3",          "--clusters",  "2",
                          "--no-mean",  "--thickness", "0.05",
                          "--no-cache", "--json"},
                         out, err)
                         .exitCode;
    out.flush();
    err.flush();
    ASSERT_EQ(code, 0) << errText.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(outText.toUtf8()).object();
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
