#include "app/project.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <cmath>

#include "app/version.h"

namespace ensil::app {
namespace {
constexpr const char* kFormatName = "ensil project";

const char* modeName(gl::RenderMode mode) {
    switch (mode) {
        case gl::RenderMode::ShadedSilhouettes:
            return "shaded";
        case gl::RenderMode::Spaghetti:
            return "spaghetti";
        case gl::RenderMode::Surfaces:
            return "surfaces";
        case gl::RenderMode::OpaqueSurfaces:
            return "opaque";
    }
    return "shaded";
}

QJsonArray vec3Json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

QJsonArray intsJson(const std::vector<int>& values) {
    QJsonArray array;
    for (const int v : values) array.append(v);
    return array;
}

// Reads one JSON object, naming the field in every complaint ("rendering.thickness must be ...").
class Fields {
public:
    Fields(QJsonObject object, QString path)
        : m_object(std::move(object)), m_path(std::move(path)) {}

    [[nodiscard]] bool has(const char* key) const { return m_object.contains(QLatin1String(key)); }
    [[nodiscard]] Fields object(const char* key) const {
        const QJsonValue v = value(key);
        if (!v.isObject()) fail(key, "must be an object");
        return {v.toObject(), name(key)};
    }
    [[nodiscard]] double number(const char* key, double fallback, double lo, double hi) const {
        if (!has(key)) return fallback;
        const QJsonValue v = value(key);
        if (!v.isDouble() || !std::isfinite(v.toDouble())) fail(key, "must be a number");
        const double d = v.toDouble();
        if (d < lo || d > hi) {
            fail(key, QStringLiteral("must lie between %1 and %2").arg(lo).arg(hi).toStdString());
        }
        return d;
    }
    [[nodiscard]] int integer(const char* key, int fallback, int lo, int hi) const {
        const double d = number(key, fallback, lo, hi);
        if (d != std::floor(d)) fail(key, "must be a whole number");
        return static_cast<int>(d);
    }
    [[nodiscard]] bool boolean(const char* key, bool fallback) const {
        if (!has(key)) return fallback;
        if (!value(key).isBool()) fail(key, "must be true or false");
        return value(key).toBool();
    }
    [[nodiscard]] QString text(const char* key, const QString& fallback) const {
        if (!has(key)) return fallback;
        if (!value(key).isString()) fail(key, "must be a string");
        return value(key).toString();
    }
    [[nodiscard]] glm::vec3 vec3(const char* key, const glm::vec3& fallback) const {
        if (!has(key)) return fallback;
        const QJsonArray a = value(key).toArray();
        if (!value(key).isArray() || a.size() != 3) fail(key, "must be a list of 3 numbers");
        glm::vec3 v;
        for (int i = 0; i < 3; ++i) {
            if (!a[i].isDouble() || !std::isfinite(a[i].toDouble())) {
                fail(key, "must be a list of 3 numbers");
            }
            v[i] = static_cast<float>(a[i].toDouble());
        }
        return v;
    }
    [[nodiscard]] std::vector<int> indices(const char* key) const {
        std::vector<int> out;
        if (!has(key)) return out;
        if (!value(key).isArray()) fail(key, "must be a list of indices");
        for (const auto& v : value(key).toArray()) {
            const double d = v.toDouble(-1.0);
            if (!v.isDouble() || d < 0 || d != std::floor(d) || d > 1e6) {
                fail(key, "must be a list of indices (whole numbers from 0)");
            }
            out.push_back(static_cast<int>(d));
        }
        return out;
    }
    [[nodiscard]] QJsonArray array(const char* key) const {
        if (!value(key).isArray()) fail(key, "must be a list");
        return value(key).toArray();
    }
    [[noreturn]] void fail(const char* key, const std::string& why) const {
        throw ProjectError(name(key).toStdString() + " " + why);
    }

private:
    [[nodiscard]] QJsonValue value(const char* key) const {
        return m_object.value(QLatin1String(key));
    }
    [[nodiscard]] QString name(const char* key) const {
        return m_path.isEmpty() ? QString::fromLatin1(key)
                                : m_path + QLatin1Char('.') + QLatin1String(key);
    }

    QJsonObject m_object;
    QString m_path;
};

gl::RenderMode parseMode(const Fields& f, const char* key) {
    const QString name = f.text(key, QStringLiteral("shaded"));
    for (const gl::RenderMode m : {gl::RenderMode::ShadedSilhouettes, gl::RenderMode::Spaghetti,
                                   gl::RenderMode::Surfaces, gl::RenderMode::OpaqueSurfaces}) {
        if (name == QLatin1String(modeName(m))) return m;
    }
    f.fail(key, "must be shaded, spaghetti, surfaces or opaque");
}

int lineOf(const QByteArray& json, int offset) {
    return 1 + static_cast<int>(json.left(offset).count('\n'));
}
}  // namespace

QByteArray projectToJson(const Project& p, const QDir& projectDir) {
    QJsonObject data;
    if (p.demo) {
        data[QStringLiteral("demo")] =
            QJsonObject{{"members", static_cast<qint64>(p.demoParams.members)},
                        {"grid", QJsonArray{static_cast<qint64>(p.demoParams.nx),
                                            static_cast<qint64>(p.demoParams.ny),
                                            static_cast<qint64>(p.demoParams.nz)}},
                        {"seed", static_cast<qint64>(p.demoParams.seed)}};
    } else {
        QJsonArray files;
        for (const std::string& path : p.data.paths) {
            const QString absolute = QFileInfo(QString::fromStdString(path)).absoluteFilePath();
            files.append(QJsonObject{{"path", projectDir.relativeFilePath(absolute)},
                                     {"absolute_path", absolute}});
        }
        data[QStringLiteral("files")] = files;
        data[QStringLiteral("variable")] = QString::fromStdString(p.data.variable);
        data[QStringLiteral("member_dimension")] = QString::fromStdString(p.data.memberDimension);
        data[QStringLiteral("time_index")] = static_cast<qint64>(p.data.timeIndex);
    }
    const gl::RenderSettings& r = p.render;
    QJsonObject root{
        {"format", kFormatName},
        {"schema_version", Project::kSchemaVersion},
        {"written_by", QStringLiteral("ensil " ENSIL_VERSION)},
        {"data", data},
        {"rendering", QJsonObject{{"mode", modeName(r.mode)},
                                  {"thickness", r.thickness},
                                  {"surface_opacity", r.surfaceAlpha},
                                  {"show_mean", r.showMean},
                                  {"axis_labels", r.showAxes},
                                  {"legend", r.showLegend},
                                  {"removal", QJsonObject{{"enabled", r.removal},
                                                          {"min", r.removalMin},
                                                          {"max", r.removalMax},
                                                          {"group_size", r.groupSize}}},
                                  {"vertical_exaggeration", p.verticalExaggeration},
                                  {"background", vec3Json(p.background)}}},
        {"cutting_plane", QJsonObject{{"enabled", r.plane.enabled},
                                      {"normal", vec3Json(r.plane.normal)},
                                      {"offset", r.plane.offset},
                                      {"thickness", r.plane.thickness}}},
        {"clusters", QJsonObject{{"count", p.clusters},
                                 {"linkage", QString::fromStdString(p.linkage)},
                                 {"hidden", intsJson(p.hiddenClusters)}}},
        {"members",
         QJsonObject{{"hidden", intsJson(p.hiddenMembers)}, {"selected", intsJson(p.selection)}}},
        {"layout", QJsonObject{{"geometry", QString::fromLatin1(p.windowGeometry.toBase64())},
                               {"state", QString::fromLatin1(p.windowState.toBase64())}}}};
    if (p.isovalue) root[QStringLiteral("isovalue")] = *p.isovalue;
    if (p.camera) {
        const ProjectCamera& c = *p.camera;
        root[QStringLiteral("camera")] =
            QJsonObject{{"azimuth", c.azimuth},
                        {"elevation", c.elevation},
                        {"distance", c.distance},
                        {"target", vec3Json(c.target)},
                        {"projection", c.orthographic ? "orthographic" : "perspective"}};
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

Project projectFromJson(const QByteArray& json, const QDir& projectDir) {
    QJsonParseError parseError{};
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const int line = lineOf(json, parseError.offset);
        throw ProjectError(
            "line " + std::to_string(line) + ": " + parseError.errorString().toStdString(), line);
    }
    if (!document.isObject()) throw ProjectError("the file does not hold a JSON object", 1);
    const Fields root(document.object(), {});
    if (root.text("format", {}) != QLatin1String(kFormatName)) {
        throw ProjectError(R"(this is not an ensil project (its "format" is not "ensil project"))");
    }
    const int version = root.integer("schema_version", 0, 0, 1 << 20);
    if (version < 1) root.fail("schema_version", "must be 1 or more");
    if (version > Project::kSchemaVersion) {
        throw ProjectError("the project was written by a newer ensil (" +
                           root.text("written_by", QStringLiteral("unknown")).toStdString() +
                           ", format version " + std::to_string(version) +
                           "); this ensil " ENSIL_VERSION " reads format versions up to " +
                           std::to_string(Project::kSchemaVersion) + ". Update ensil to open it.");
    }

    Project p;
    const Fields data = root.object("data");
    if (data.has("demo")) {
        const Fields demo = data.object("demo");
        p.demo = true;
        p.demoParams.members = static_cast<std::size_t>(demo.integer("members", 50, 2, 10000));
        const glm::vec3 grid = demo.vec3("grid", glm::vec3(256, 128, 16));
        for (int i = 0; i < 3; ++i) {
            if (grid[i] < 2 || grid[i] > 4096 || grid[i] != std::floor(grid[i])) {
                demo.fail("grid", "must be 3 whole numbers from 2 to 4096");
            }
        }
        p.demoParams.nx = static_cast<std::size_t>(grid.x);
        p.demoParams.ny = static_cast<std::size_t>(grid.y);
        p.demoParams.nz = static_cast<std::size_t>(grid.z);
        p.demoParams.seed = static_cast<std::uint64_t>(demo.integer("seed", 1, 0, 1 << 30));
    } else {
        if (!data.has("files")) data.fail("files", "is missing: name the data files or the demo");
        const QJsonArray files = data.array("files");
        if (files.isEmpty()) data.fail("files", "must name at least one file");
        for (int i = 0; i < files.size(); ++i) {
            const Fields file(files[i].toObject(), QStringLiteral("data.files[%1]").arg(i));
            if (!files[i].isObject()) file.fail("path", "must be given");
            const QString relative = file.text("path", {});
            const QString absolute = file.text("absolute_path", {});
            if (relative.isEmpty() && absolute.isEmpty()) file.fail("path", "must be given");
            // The path beside the project wins; the absolute one is where it was when saved.
            QString chosen = relative.isEmpty() ? absolute : projectDir.absoluteFilePath(relative);
            if (!QFileInfo::exists(chosen) && !absolute.isEmpty()) chosen = absolute;
            p.data.paths.push_back(QDir::cleanPath(chosen).toStdString());
        }
        p.data.variable = data.text("variable", {}).toStdString();
        p.data.memberDimension = data.text("member_dimension", {}).toStdString();
        p.data.timeIndex = static_cast<std::size_t>(data.integer("time_index", 0, 0, 1 << 30));
    }
    if (root.has("isovalue")) {
        p.isovalue = static_cast<float>(root.number("isovalue", 0.0, -1e30, 1e30));
    }
    if (root.has("camera")) {
        const Fields c = root.object("camera");
        ProjectCamera cam;
        cam.azimuth = static_cast<float>(c.number("azimuth", cam.azimuth, -1e6, 1e6));
        cam.elevation = static_cast<float>(c.number("elevation", cam.elevation, -90, 90));
        cam.distance = static_cast<float>(c.number("distance", cam.distance, 1e-6, 1e6));
        cam.target = c.vec3("target", cam.target);
        const QString projection = c.text("projection", QStringLiteral("perspective"));
        if (projection != QLatin1String("perspective") &&
            projection != QLatin1String("orthographic")) {
            c.fail("projection", "must be perspective or orthographic");
        }
        cam.orthographic = projection == QLatin1String("orthographic");
        p.camera = cam;
    }
    gl::RenderSettings& r = p.render;
    if (root.has("rendering")) {
        const Fields f = root.object("rendering");
        r.mode = parseMode(f, "mode");
        r.thickness = static_cast<float>(f.number("thickness", r.thickness, 1e-5, 1.0));
        r.surfaceAlpha = static_cast<float>(f.number("surface_opacity", r.surfaceAlpha, 0.0, 1.0));
        r.showMean = f.boolean("show_mean", r.showMean);
        r.showAxes = f.boolean("axis_labels", r.showAxes);
        r.showLegend = f.boolean("legend", r.showLegend);
        if (f.has("removal")) {
            const Fields removal = f.object("removal");
            r.removal = removal.boolean("enabled", r.removal);
            r.removalMin = static_cast<float>(removal.number("min", r.removalMin, 0.0, 1e30));
            r.removalMax = static_cast<float>(removal.number("max", r.removalMax, 0.0, 1e30));
            r.groupSize = removal.integer("group_size", r.groupSize, 1, 1024);
            if (r.removalMin >= r.removalMax) removal.fail("min", "must be below max");
        }
        p.verticalExaggeration = static_cast<float>(
            f.number("vertical_exaggeration", p.verticalExaggeration, 0.01, 1000));
        p.background = f.vec3("background", p.background);
    }
    if (root.has("cutting_plane")) {
        const Fields f = root.object("cutting_plane");
        r.plane.enabled = f.boolean("enabled", false);
        const glm::vec3 normal = f.vec3("normal", r.plane.normal);
        if (glm::length(normal) < 1e-6F) f.fail("normal", "must not be zero");
        r.plane.normal = glm::normalize(normal);
        r.plane.offset = static_cast<float>(f.number("offset", 0.0, -1e6, 1e6));
        r.plane.thickness = static_cast<float>(f.number("thickness", r.plane.thickness, 1e-6, 1.0));
    }
    if (root.has("clusters")) {
        const Fields f = root.object("clusters");
        p.clusters = f.integer("count", p.clusters, 1, 100000);
        p.linkage = f.text("linkage", QStringLiteral("average")).toLower().toStdString();
        if (p.linkage != "average" && p.linkage != "single" && p.linkage != "complete" &&
            p.linkage != "ward") {
            f.fail("linkage", "must be average, single, complete or ward");
        }
        p.hiddenClusters = f.indices("hidden");
    }
    if (root.has("members")) {
        const Fields f = root.object("members");
        p.hiddenMembers = f.indices("hidden");
        p.selection = f.indices("selected");
    }
    if (root.has("layout")) {
        const Fields f = root.object("layout");
        p.windowGeometry = QByteArray::fromBase64(f.text("geometry", {}).toLatin1());
        p.windowState = QByteArray::fromBase64(f.text("state", {}).toLatin1());
    }
    return p;
}

void saveProject(const Project& project, const QString& path) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        throw ProjectError("cannot write '" + path.toStdString() +
                           "': " + file.errorString().toStdString());
    }
    const QByteArray json = projectToJson(project, QFileInfo(path).absoluteDir());
    // Qt 6.4's QSaveFile commits even after a short write (a full disk, a file size limit):
    // check the write error ourselves, after flushing, before the rename replaces the old file.
    const bool written =
        file.write(json) == json.size() && file.flush() && file.error() == QFileDevice::NoError;
    if (!written || !file.commit()) {
        const std::string why = file.errorString().toStdString();
        file.cancelWriting();
        throw ProjectError("the project was not saved to '" + path.toStdString() + "' (" + why +
                           "); the file there is as it was");
    }
}

Project loadProject(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        throw ProjectError("cannot read '" + path.toStdString() +
                           "': " + file.errorString().toStdString());
    }
    try {
        return projectFromJson(file.readAll(), QFileInfo(path).absoluteDir());
    } catch (const ProjectError& e) {
        throw ProjectError(QFileInfo(path).fileName().toStdString() + ": " + e.what(), e.line());
    }
}

}  // namespace ensil::app
