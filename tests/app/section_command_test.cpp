// `ensil section` as a user types it (cli/section_command.h): a map and a cross-section of the
// real ERA5 members, in each format, and every refusal with its exit status.
#include <gtest/gtest.h>

#include <QFile>
#include <QImage>
#include <QXmlStreamReader>

#include "gl/palette.h"
#include "tests/app/ensil_run.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

TEST(SectionCommand, DrawsAMapOfEveryMembersContourAsAPng) {
    test::TempDir dir;
    const QString png = QString::fromStdString(dir.file("t500.png"));
    const test::EnsilRun r =
        test::runEnsil({"section", test::kEra5, "--var", "t", "--level", "500hPa", "--iso", "250",
                        "--clusters", "3", "--out", png, "--no-cache", "--json"});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject o = test::jsonOf(r);
    EXPECT_EQ(o["title"].toString(), QStringLiteral("t at 500 hPa"));
    EXPECT_EQ(o["columns"].toInt(), 120);
    EXPECT_EQ(o["rows"].toInt(), 61);
    const QJsonArray members = o["members"].toArray();
    ASSERT_EQ(members.size(), 10);
    for (const QJsonValue m : members) {
        // 250 K at 500 hPa rings both poles: every member has contours there.
        EXPECT_GE(m["contour_lines"].toInt(), 2) << m["name"].toString().toStdString();
        EXPECT_GE(m["cluster"].toInt(), 1);
        EXPECT_LE(m["cluster"].toInt(), 3);
    }
    // The fill's scale is the section's own values, not the volume's (225.8 to 305 K).
    EXPECT_GT(o["fill"]["minimum"].toDouble(), 225.8);
    EXPECT_LT(o["fill"]["maximum"].toDouble(), 280.0);
    EXPECT_EQ(o["fill"]["colour_map"].toString(), QStringLiteral("viridis"));
    const QImage image(png);
    ASSERT_FALSE(image.isNull());
    EXPECT_EQ(image.width(), 1400);  // by default 1400 wide, as high as the map needs
    EXPECT_LT(image.height(), 900);
    // Pixels in the first cluster's colour: the contours were drawn in it.
    const glm::vec3 first = gl::clusterColor(0);
    int clusterPixels = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            clusterPixels += std::abs(c.redF() - first.r) < 0.06 &&
                             std::abs(c.greenF() - first.g) < 0.06 &&
                             std::abs(c.blueF() - first.b) < 0.06;
        }
    }
    EXPECT_GT(clusterPixels, 100);
}

TEST(SectionCommand, SvgHoldsTextAsTextAndContoursAsPaths) {
    test::TempDir dir;
    const QString svg = QString::fromStdString(dir.file("cross.svg"));
    const test::EnsilRun r =
        test::runEnsil({"section", test::kEra5, "--var", "t", "--lat", "45N", "--fill", "spread",
                        "--iso", "250", "--out", svg, "--size", "900x500", "--no-cache"});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("t along 45°N")));
    QFile file(svg);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QXmlStreamReader xml(&file);
    int paths = 0, images = 0;
    QStringList texts;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement) continue;
        if (xml.name() == QLatin1String("path") || xml.name() == QLatin1String("polyline")) ++paths;
        if (xml.name() == QLatin1String("image")) ++images;
        if (xml.name() == QLatin1String("text"))
            texts << xml.readElementText(QXmlStreamReader::IncludeChildElements);
    }
    ASSERT_FALSE(xml.hasError()) << xml.errorString().toStdString();
    EXPECT_TRUE(texts.contains(QStringLiteral("t along 45°N"))) << texts.join("|").toStdString();
    EXPECT_TRUE(texts.contains(QStringLiteral("500"))) << "the pressure ticks are text";
    EXPECT_GT(paths, 10);
    EXPECT_EQ(images, 2);  // the fill and its colour bar
}

TEST(SectionCommand, PdfAndPathsAcrossTheMap) {
    test::TempDir dir;
    const QString pdf = QString::fromStdString(dir.file("path.pdf"));
    const test::EnsilRun r =
        test::runEnsil({"section", test::kEra5, "--var", "t", "--path=-30,60:40,30", "--fill",
                        "anomaly:2", "--out", pdf, "--no-cache", "--quiet", "--colour-map", "greys",
                        "--range-min", "-4", "--range-max", "6", "--json", "--band"});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    // The colour map and fixed range asked for, not the anomaly's own (RdBu, symmetric).
    const QJsonObject fill = test::jsonOf(r)["fill"].toObject();
    EXPECT_EQ(fill["colour_map"].toString(), QStringLiteral("greys"));
    EXPECT_EQ(fill["minimum"].toDouble(), -4.0);
    EXPECT_EQ(fill["maximum"].toDouble(), 6.0);
    // --band: the contour boxplot, its median numbered as the workbench numbers members.
    const QJsonObject boxplot = test::jsonOf(r)["boxplot"].toObject();
    EXPECT_GE(boxplot["median"].toInt(), 1);
    EXPECT_LE(boxplot["median"].toInt(), 10);
    EXPECT_GT(boxplot["band_samples"].toInt(), 0);
    QFile file(pdf);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.read(5).startsWith("%PDF-"));
}

TEST(SectionCommand, RefusesWhatItCannotDrawSayingWhy) {
    test::TempDir dir;
    const QString png = QString::fromStdString(dir.file("x.png"));
    const auto run = [&](const QStringList& extra) {
        return test::runEnsil(QStringList{"section", test::kEra5, "--var", "t", "--no-cache"} +
                              extra);
    };
    // Bad options: exit status 2, nothing written.
    for (const QStringList& bad :
         {QStringList{"--out", png}, QStringList{"--level", "500hPa", "--lat", "45", "--out", png},
          QStringList{"--level", "500 furlongs", "--out", png},
          QStringList{"--lat", "91", "--out", png},
          QStringList{"--level", "500hPa", "--fill", "member:0", "--out", png},
          QStringList{"--level", "500hPa", "--out", QString::fromStdString(dir.file("x.jpg"))},
          QStringList{"--level", "500hPa"},
          QStringList{"--level", "500hPa", "--colour-map", "jet", "--out", png},
          QStringList{"--level", "500hPa", "--range-min", "250", "--out", png},
          QStringList{"--lat", "45", "--vertical-axis", "linear", "--out", png},
          QStringList{"--level", "500hPa", "--range-min", "260", "--range-max", "250", "--out",
                      png}}) {
        const test::EnsilRun r = run(bad);
        EXPECT_EQ(r.code, 2) << bad.join(' ').toStdString() << ": " << r.err.toStdString();
        EXPECT_TRUE(r.err.startsWith(QStringLiteral("ensil section: "))) << r.err.toStdString();
    }
    EXPECT_FALSE(QFile::exists(png));
    const test::EnsilRun half = run({"--level", "500hPa", "--range-max", "250", "--out", png});
    EXPECT_TRUE(half.err.contains(QStringLiteral("--range-max needs --range-min too")))
        << half.err.toStdString();
    // Places and members the data do not have: exit status 1, naming the range.
    const test::EnsilRun low = run({"--level", "1000hPa", "--out", png});
    EXPECT_EQ(low.code, 1);
    EXPECT_TRUE(low.err.contains(QStringLiteral("plev runs from 50000 to 85000")))
        << low.err.toStdString();
    const test::EnsilRun member = run({"--level", "500hPa", "--fill", "member:11", "--out", png});
    EXPECT_EQ(member.code, 1);
    EXPECT_TRUE(member.err.contains(QStringLiteral("1 to 10"))) << member.err.toStdString();
    EXPECT_FALSE(QFile::exists(png));
}
