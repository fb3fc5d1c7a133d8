// Project files (the session's serialisation): what is saved comes back, paths travel with the
// project, bad files are refused with the line or field and the reason, newer formats are refused,
// and a failed write leaves the previous file as it was.
#include "session/project_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <csignal>
#include <vector>

#include "session/setting_table.h"
#include "tests/support/temp_dir.h"

using namespace ensil;

namespace {
session::SessionState sample(const QString& dataFile) {
    session::SessionState p;
    p.data.paths = {dataFile.toStdString()};
    p.data.variable = "t";
    p.data.memberDimension = "number";
    p.data.timeIndex = 2;
    p.data.levels = data::LevelRange{1000, 100, "hPa"};
    p.data.region = data::Region{350, 20.5, 72, 35};
    p.isovalue = 261.5F;
    p.camera.azimuth = -40.0F;
    p.camera.elevation = 55.0F;
    p.camera.orthographic = true;
    p.camera.placement = session::CameraState::Placement{2.25F, {0.4F, 0.3F, 0.05F}};
    p.render.mode = gl::RenderMode::Spaghetti;
    p.render.thickness = 0.011F;
    p.render.surfaceAlpha = 0.4F;
    p.render.showMean = false;
    p.render.showLegend = false;
    p.render.removal = true;
    p.render.removalMin = 1.5F;
    p.render.removalMax = 7.0F;
    p.render.groupSize = 3;
    p.render.plane = gl::CuttingPlane::through({0, 1, 0}, {0.5F, 0.2F, 0.1F});
    p.render.plane.thickness = 0.006F;
    p.verticalExaggeration = 4.0F;
    p.background = {1.0F, 1.0F, 0.9F};
    p.clusters = 3;
    p.linkage = prep::Linkage::Ward;
    p.hiddenClusters = {2};
    p.hiddenMembers = {0, 7};
    p.selection = {3, 4};
    p.windowState = QByteArray("\x01\x02state", 7);
    p.windowGeometry = QByteArray("geometry");
    p.sections.level = "500 hPa";
    p.sections.crossKind = session::SectionPlaces::Cross::Path;
    p.sections.cross = "-10,50:20,40";
    p.sectionsFill = session::SectionsFill::Probability;
    return p;
}

QString writeText(const test::TempDir& dir, const char* name, const QByteArray& text) {
    QString path = QString::fromStdString(dir.file(name));
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(text);
    return path;
}
}  // namespace

TEST(Project, EverythingSavedComesBack) {
    const test::TempDir dir;
    const QString data = writeText(dir, "members.nc", "not read here");
    const QString path = QString::fromStdString(dir.file("session.ensil"));
    session::saveProject(sample(data), path);
    const session::SessionState p = session::loadProject(path);
    const session::SessionState e = sample(data);
    EXPECT_EQ(p.data.paths, e.data.paths);
    EXPECT_EQ(p.data.variable, "t");
    EXPECT_EQ(p.data.memberDimension, "number");
    EXPECT_EQ(p.data.timeIndex, 2u);
    EXPECT_EQ(p.data.levels, (data::LevelRange{1000, 100, "hPa"}));
    EXPECT_EQ(p.data.region, (data::Region{350, 20.5, 72, 35}));
    ASSERT_TRUE(p.isovalue);
    EXPECT_FLOAT_EQ(*p.isovalue, 261.5F);
    EXPECT_FLOAT_EQ(p.camera.azimuth, -40.0F);
    EXPECT_FLOAT_EQ(p.camera.elevation, 55.0F);
    ASSERT_TRUE(p.camera.placement);
    EXPECT_FLOAT_EQ(p.camera.placement->distance, 2.25F);
    EXPECT_FLOAT_EQ(p.camera.placement->target.y, 0.3F);
    EXPECT_TRUE(p.camera.orthographic);
    EXPECT_EQ(p.render.mode, gl::RenderMode::Spaghetti);
    EXPECT_FLOAT_EQ(p.render.thickness, 0.011F);
    EXPECT_FLOAT_EQ(p.render.surfaceAlpha, 0.4F);
    EXPECT_FALSE(p.render.showMean);
    EXPECT_TRUE(p.render.showAxes);
    EXPECT_FALSE(p.render.showLegend);
    EXPECT_TRUE(p.render.removal);
    EXPECT_FLOAT_EQ(p.render.removalMin, 1.5F);
    EXPECT_FLOAT_EQ(p.render.removalMax, 7.0F);
    EXPECT_EQ(p.render.groupSize, 3);
    EXPECT_TRUE(p.render.plane.enabled);
    EXPECT_FLOAT_EQ(p.render.plane.normal.y, 1.0F);
    EXPECT_FLOAT_EQ(p.render.plane.offset, 0.2F);
    EXPECT_FLOAT_EQ(p.render.plane.thickness, 0.006F);
    EXPECT_FLOAT_EQ(p.verticalExaggeration, 4.0F);
    // Colours are kept to 8 bits a channel, as the colour dialog gives them.
    EXPECT_NEAR(p.background.z, 0.9F, 1.0F / 255.0F);
    EXPECT_EQ(p.clusters, 3);
    EXPECT_EQ(p.linkage, prep::Linkage::Ward);
    EXPECT_EQ(p.hiddenClusters, e.hiddenClusters);
    EXPECT_EQ(p.hiddenMembers, e.hiddenMembers);
    EXPECT_EQ(p.selection, e.selection);
    EXPECT_EQ(p.windowState, e.windowState);
    EXPECT_EQ(p.windowGeometry, e.windowGeometry);
    EXPECT_EQ(p.sections, e.sections);
    EXPECT_EQ(p.sectionsFill, session::SectionsFill::Probability);
}

TEST(Project, DataPathsAreRelativeSoTheProjectCanMoveWithItsData) {
    const test::TempDir dir;
    QDir(QString::fromStdString(dir.path().string())).mkpath("a/data");
    const QString data = writeText(dir, "a/data/members.nc", "x");
    const QString path = QString::fromStdString(dir.file("a/session.ensil"));
    session::saveProject(sample(data), path);
    QFile saved(path);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    EXPECT_TRUE(saved.readAll().contains("\"path\": \"data/members.nc\""));
    // Move the folder: the project finds the data beside it, not at the old absolute path.
    const QString root = QString::fromStdString(dir.path().string());
    ASSERT_TRUE(QDir(root).rename("a", "b"));
    const session::SessionState moved = session::loadProject(root + "/b/session.ensil");
    EXPECT_EQ(QString::fromStdString(moved.data.paths.front()), root + "/b/data/members.nc");
}

// Hidden clusters and hidden and selected members are written with the numbers the workbench
// shows (from 1, format 3); files of formats 1 and 2 held indices from 0 and still open so.
TEST(Project, MembersAndClustersAreSavedByTheirShownNumbersAndOlderFilesByIndex) {
    const test::TempDir dir;
    const QDir projectDir(QString::fromStdString(dir.path().string()));
    session::SessionState state;
    state.demo = true;
    state.hiddenMembers = {0, 3};
    state.selection = {2};
    state.hiddenClusters = {1};
    const QJsonObject saved =
        QJsonDocument::fromJson(session::projectToJson(state, projectDir)).object();
    EXPECT_EQ(saved["schema_version"].toInt(), 3);
    EXPECT_EQ(saved["members"]["hidden"].toArray(), (QJsonArray{1, 4}));
    EXPECT_EQ(saved["members"]["selected"].toArray(), (QJsonArray{3}));
    EXPECT_EQ(saved["clusters"]["hidden"].toArray(), (QJsonArray{2}));

    const auto read = [&](int version, const char* lists) {
        return session::projectFromJson(
            QByteArray(R"({"format": "ensil project", "schema_version": )") +
                QByteArray::number(version) + R"(, "data": {"demo": {}}, )" + lists + "}",
            projectDir);
    };
    const char* lists =
        R"("members": {"hidden": [1, 4], "selected": [3]}, "clusters": {"hidden": [2]})";
    const session::SessionState now = read(3, lists);
    EXPECT_EQ(now.hiddenMembers, (std::vector<int>{0, 3}));
    EXPECT_EQ(now.selection, (std::vector<int>{2}));
    EXPECT_EQ(now.hiddenClusters, (std::vector<int>{1}));
    const session::SessionState older = read(2, lists);
    EXPECT_EQ(older.hiddenMembers, (std::vector<int>{1, 4}));
    EXPECT_EQ(older.selection, (std::vector<int>{3}));
    EXPECT_EQ(older.hiddenClusters, (std::vector<int>{2}));
    try {
        (void)read(3, R"("members": {"selected": [0]})");
        ADD_FAILURE() << "member 0 was taken";
    } catch (const session::ProjectError& e) {
        EXPECT_STREQ(e.what(), "members.selected must be a list of numbers (whole numbers from 1)");
    }
}

TEST(Project, AMinimalFileOpensWithDefaultsForEverythingLeftOut) {
    const test::TempDir dir;
    const session::SessionState p = session::projectFromJson(
        R"({"format": "ensil project", "schema_version": 1, "data": {"demo": {"members": 8}}})",
        QDir(QString::fromStdString(dir.path().string())));
    EXPECT_TRUE(p.demo);
    EXPECT_EQ(p.demoParams.members, 8u);
    EXPECT_FALSE(p.isovalue);
    EXPECT_FALSE(p.camera.placement) << "no saved camera: fitted to the data";
    EXPECT_EQ(p.render.mode, gl::RenderMode::ShadedSilhouettes);
    EXPECT_EQ(p.clusters, 5);
}

TEST(Project, ANewerFormatIsRefusedSayingSo) {
    try {
        (void)session::projectFromJson(
            R"({"format": "ensil project", "schema_version": 7, "written_by": "ensil 9.0.0",
                "data": {"demo": {}}})",
            QDir::temp());
        FAIL() << "a newer format must be refused";
    } catch (const session::ProjectError& e) {
        EXPECT_TRUE(std::string(e.what()).find("newer ensil (ensil 9.0.0") != std::string::npos)
            << e.what();
        EXPECT_TRUE(std::string(e.what()).find("Update ensil") != std::string::npos) << e.what();
    }
}

TEST(Project, MalformedFilesAreRefusedWithTheLineOrFieldAndTheReason) {
    const auto error = [](const char* json) -> std::pair<std::string, int> {
        try {
            (void)session::projectFromJson(json, QDir::temp());
        } catch (const session::ProjectError& e) {
            return {e.what(), e.line()};
        }
        return {"accepted", -1};
    };
    const auto [syntax, line] =
        error("{\n  \"format\": \"ensil project\",\n  \"schema_version\": 1\n  \"data\": {}\n}");
    EXPECT_EQ(line, 4) << syntax;
    EXPECT_TRUE(syntax.find("line 4") != std::string::npos) << syntax;
    EXPECT_EQ(error(R"({"format": "something else"})").first.find("not an ensil project") !=
                  std::string::npos,
              true);
    const std::string thickness =
        error(
            R"({"format": "ensil project", "schema_version": 1, "data": {"demo": {}},
            "rendering": {"thickness": "thick"}})")
            .first;
    EXPECT_EQ(thickness, "rendering.thickness must be a number from 0.0001 to 0.5");
    const std::string band =
        error(
            R"({"format": "ensil project", "schema_version": 1, "data": {"demo": {}},
            "rendering": {"removal": {"min": 5, "max": 2}}})")
            .first;
    EXPECT_EQ(band, "rendering.removal.min must be below rendering.removal.max");
    const std::string members =
        error(
            R"({"format": "ensil project", "schema_version": 1, "data": {"demo": {}},
            "members": {"selected": [1, -2]}})")
            .first;
    EXPECT_EQ(members, "members.selected must be a list of indices (whole numbers from 0)");
    EXPECT_EQ(error(R"({"format": "ensil project", "schema_version": 1, "data": {}})").first,
              "data.files is missing: name the data files or the demo");
    EXPECT_EQ(error(R"({"format": "ensil project", "schema_version": 3, "data": {"demo": {}},
            "sections": {"cross_kind": "diagonal"}})")
                  .first,
              "sections.cross_kind must be latitude, longitude or path");
    EXPECT_EQ(error(R"({"format": "ensil project", "schema_version": 3, "data": {"demo": {}},
            "sections": {"fill": "median"}})")
                  .first.find("sections.fill must be"),
              0U);
    EXPECT_EQ(error(R"({"format": "ensil project", "schema_version": 3,
            "data": {"files": [{"path": "t.nc"}], "levels": "1000 to 100"}})")
                  .first.find("data.levels "),
              0U);
    const auto region = error(R"({"format": "ensil project", "schema_version": 3,
            "data": {"files": [{"path": "t.nc"}], "region": "-10,40,95,72"}})")
                            .first;
    EXPECT_EQ(region.find("data.region "), 0U) << region;
    EXPECT_NE(region.find("LAT0 = 95, not a latitude"), std::string::npos) << region;
}

TEST(Project, AFailedWriteLeavesThePreviousFileIntact) {
    const test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("session.ensil"));
    session::SessionState small;
    small.demo = true;
    session::saveProject(small, path);
    QFile before(path);
    ASSERT_TRUE(before.open(QIODevice::ReadOnly));
    const QByteArray original = before.readAll();
    before.close();

    // A disk that fills up: no file may grow past 200 bytes while saving a bigger project.
    session::SessionState big = sample(QString::fromStdString(dir.file("members.nc")));
    big.windowState = QByteArray(4096, 'x');
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit previous{};
    getrlimit(RLIMIT_FSIZE, &previous);
    rlimit limited = previous;
    limited.rlim_cur = 200;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
    bool refused = false;
    try {
        session::saveProject(big, path);
    } catch (const session::ProjectError& e) {
        refused = true;
        EXPECT_TRUE(std::string(e.what()).find("as it was") != std::string::npos) << e.what();
    }
    setrlimit(RLIMIT_FSIZE, &previous);
    EXPECT_TRUE(refused);
    QFile after(path);
    ASSERT_TRUE(after.open(QIODevice::ReadOnly));
    EXPECT_EQ(after.readAll(), original);
    EXPECT_EQ(QDir(QString::fromStdString(dir.path().string())).entryList(QDir::Files).size(), 1)
        << "no temporary file is left behind";
}

TEST(Project, WhatCannotBeAProjectIsRefusedBeforeItIsRead) {
    const test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("huge.ensil"));
    {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(17 << 20, ' '));
    }
    try {
        (void)session::loadProject(path);
        FAIL() << "a 17 MiB file is not a project";
    } catch (const session::ProjectError& e) {
        EXPECT_TRUE(std::string(e.what()).find("far more than a project holds") !=
                    std::string::npos)
            << e.what();
    }
    // A name of two million characters is refused naming the field, not echoed back.
    const QByteArray json =
        R"({"format": "ensil project", "schema_version": 1, "data": {"files": [{"path": "a.nc"}], "variable": ")" +
        QByteArray(2 << 20, 'x') + R"("}})";
    try {
        (void)session::projectFromJson(json, QDir::temp());
        FAIL() << "accepted";
    } catch (const session::ProjectError& e) {
        EXPECT_EQ(std::string(e.what()), "data.variable is longer than 1048576 characters");
    }
}

// A project saved with every number setting at its bounds reopens: the bounds' floats (0.0001
// is 0.000099999997 as a float) are inside the range (found by the project fuzzer).
TEST(ProjectFile, SettingsAtTheirBoundsSurviveSavingAndReopening) {
    for (const bool atMaximum : {false, true}) {
        session::SessionState state;
        state.demo = true;
        for (const session::Setting& s : session::settingTable()) {
            // The removal band's two ends must stay apart, so they keep their defaults.
            if (s.kind == session::SettingKind::Number && !s.id.starts_with("removal_")) {
                s.set(state, atMaximum ? s.maximum : s.minimum);
            }
        }
        const QByteArray saved = session::projectToJson(state, QDir::temp());
        EXPECT_NO_THROW((void)session::projectFromJson(saved, QDir::temp()))
            << (atMaximum ? "maxima" : "minima");
    }
}

// A camera target a float cannot hold (7.8e75) would be saved as infinity and the project
// would not reopen: it is refused when read, naming the field and the range (found by the
// project fuzzer's save-and-reopen check).
TEST(ProjectFile, ACameraTargetBeyondWhatAFloatHoldsIsRefused) {
    const QByteArray json = R"({"format": "ensil project", "schema_version": 2,
        "data": {"demo": {}},
        "camera": {"distance": 2.5, "target": [7.8e75, 0.5, 0.25]}})";
    try {
        (void)session::projectFromJson(json, QDir::temp());
        ADD_FAILURE() << "accepted";
    } catch (const session::ProjectError& e) {
        EXPECT_NE(std::string(e.what()).find("camera.target must be a list of 3 numbers from -1e6 "
                                             "to 1e6"),
                  std::string::npos)
            << e.what();
    }
}

// The isovalue and the camera's distance at their bounds survive saving and reopening: the
// bounds' floats lie just outside the doubles (1e30 as a float is 1.0000000150e30).
TEST(ProjectFile, AnIsovalueAndDistanceAtTheirBoundsReopen) {
    for (const char* json :
         {R"({"format": "ensil project", "schema_version": 2, "data": {"demo": {}},
              "isovalue": 1e30, "camera": {"distance": 1e-6, "target": [0.5, 0.5, 0.1]}})",
          R"({"format": "ensil project", "schema_version": 2, "data": {"demo": {}},
              "isovalue": -1e30, "camera": {"distance": 1e6, "target": [0.5, 0.5, 0.1]}})"}) {
        const session::SessionState first = session::projectFromJson(json, QDir::temp());
        const QByteArray saved = session::projectToJson(first, QDir::temp());
        EXPECT_NO_THROW((void)session::projectFromJson(saved, QDir::temp())) << saved.constData();
    }
}
