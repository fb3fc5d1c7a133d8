#include "session/project_file.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStringList>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "data/error.h"
#include "data/level_range.h"
#include "data/region.h"
#include "session/setting_table.h"
#include "session/version.h"

namespace ensil::session {
namespace {
constexpr const char* kFormatName = "ensil project";
// SectionPlaces::Cross by name, in its order.
const std::array<QLatin1String, 3> kCrossKinds{QLatin1String("latitude"),
                                               QLatin1String("longitude"), QLatin1String("path")};

QJsonArray vec3Json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

QJsonArray intsJson(const std::vector<int>& values) {
    QJsonArray array;
    for (const int v : values) array.append(v);
    return array;
}

// Indices from 0 as the numbers from 1 a user reads in the workbench.
std::vector<int> numbersOf(const std::vector<int>& indices) {
    std::vector<int> numbers;
    numbers.reserve(indices.size());
    for (const int i : indices) numbers.push_back(i + 1);
    return numbers;
}

// Reads one JSON object, naming the field in every complaint ("rendering.thickness must be ...").
class Fields {
public:
    Fields(QJsonObject object, QString path)
        : m_object(std::move(object)), m_path(std::move(path)) {}

    [[nodiscard]] bool has(const QString& key) const { return m_object.contains(key); }
    [[nodiscard]] Fields object(const QString& key) const {
        const QJsonValue v = m_object.value(key);
        if (!v.isObject()) fail(key, "must be an object");
        return {v.toObject(), name(key)};
    }
    [[nodiscard]] QJsonValue value(const QString& key) const { return m_object.value(key); }
    [[nodiscard]] double number(const QString& key, double fallback, double lo, double hi) const {
        if (!has(key)) return fallback;
        const QJsonValue v = value(key);
        if (!v.isDouble() || !std::isfinite(v.toDouble())) fail(key, "must be a number");
        const double d = v.toDouble();
        // Most numbers are kept as floats: a bound's float (1e30 is 1.0000000150e30) read back
        // from a saved project must still be inside, or the project would not reopen.
        const double low = std::min(lo, static_cast<double>(static_cast<float>(lo)));
        const double high = std::max(hi, static_cast<double>(static_cast<float>(hi)));
        if (d < low || d > high) {
            fail(key, QStringLiteral("must lie between %1 and %2").arg(lo).arg(hi).toStdString());
        }
        return d;
    }
    [[nodiscard]] int integer(const QString& key, int fallback, int lo, int hi) const {
        const double d = number(key, fallback, lo, hi);
        if (d != std::floor(d)) fail(key, "must be a whole number");
        return static_cast<int>(d);
    }
    [[nodiscard]] QString text(const QString& key, const QString& fallback) const {
        if (!has(key)) return fallback;
        if (!value(key).isString()) fail(key, "must be a string");
        // Names and paths; the layout's base64 is the longest text a project holds.
        constexpr qsizetype kMaxText = 1 << 20;
        if (value(key).toString().size() > kMaxText) {
            fail(key, "is longer than " + std::to_string(kMaxText) + " characters");
        }
        return value(key).toString();
    }
    [[nodiscard]] glm::vec3 vec3(const QString& key, const glm::vec3& fallback) const {
        if (!has(key)) return fallback;
        const QJsonArray a = value(key).toArray();
        // Kept as floats and written back: a number a float cannot hold (1e40) would come back
        // as infinity, and the saved project would not reopen. The data box is about 1 wide.
        constexpr double kLargest = 1e6;
        const char* const what = "must be a list of 3 numbers from -1e6 to 1e6";
        if (!value(key).isArray() || a.size() != 3) fail(key, what);
        glm::vec3 v;
        for (int i = 0; i < 3; ++i) {
            if (!a[i].isDouble() || !std::isfinite(a[i].toDouble()) ||
                std::abs(a[i].toDouble()) > kLargest) {
                fail(key, what);
            }
            v[i] = static_cast<float>(a[i].toDouble());
        }
        return v;
    }
    // A list of whole numbers counted from `first` (0: indices; 1: numbers, as the workbench
    // shows members and clusters), as indices from 0.
    [[nodiscard]] std::vector<int> indices(const QString& key, int first = 0) const {
        const std::string what = first == 0 ? "indices" : "numbers";
        std::vector<int> out;
        if (!has(key)) return out;
        if (!value(key).isArray()) fail(key, "must be a list of " + what);
        for (const auto& v : value(key).toArray()) {
            const double d = v.toDouble(-1.0);
            if (!v.isDouble() || d < first || d != std::floor(d) || d > 1e6) {
                fail(key, "must be a list of " + what + " (whole numbers from " +
                              std::to_string(first) + ")");
            }
            out.push_back(static_cast<int>(d) - first);
        }
        return out;
    }
    [[nodiscard]] QJsonArray array(const QString& key) const {
        if (!value(key).isArray()) fail(key, "must be a list");
        return value(key).toArray();
    }
    [[noreturn]] void fail(const QString& key, const std::string& why) const {
        throw ProjectError(name(key).toStdString() + " " + why);
    }

private:
    [[nodiscard]] QString name(const QString& key) const {
        return m_path.isEmpty() ? key : m_path + QLatin1Char('.') + key;
    }

    QJsonObject m_object;
    QString m_path;
};

QStringList keyPath(const Setting& s) {
    return QString::fromLatin1(s.projectKey.data(), static_cast<qsizetype>(s.projectKey.size()))
        .split(QLatin1Char('.'));
}

QJsonValue settingJson(const Setting& s, double value) {
    switch (s.kind) {
        case SettingKind::Flag:
            return value != 0.0;
        case SettingKind::Choice:
            return QString::fromStdString(s.format(value));
        case SettingKind::Colour:
            return vec3Json(unpackColour(value));
        case SettingKind::Integer:
            return static_cast<qint64>(value);
        case SettingKind::Number:
            break;
    }
    return value;
}

// Writes `value` at a dotted path, making the objects on the way.
void insertAt(QJsonObject& root, const QStringList& path, const QJsonValue& value) {
    if (path.size() == 1) {
        root[path.front()] = value;
        return;
    }
    QJsonObject child = root.value(path.front()).toObject();
    insertAt(child, path.mid(1), value);
    root[path.front()] = child;
}

// Reads the setting at its dotted path into `state` when the file has it; a malformed value is
// refused naming the field and what is allowed.
void readSetting(const Fields& root, const Setting& s, SessionState& state) {
    const QStringList path = keyPath(s);
    Fields fields = root;
    for (qsizetype i = 0; i + 1 < path.size(); ++i) {
        if (!fields.has(path[i])) return;
        fields = fields.object(path[i]);
    }
    const QString& key = path.back();
    if (!fields.has(key)) return;
    const QJsonValue v = fields.value(key);
    const auto refuse = [&] { fields.fail(key, s.problemWith(std::nan(""))); };
    double value = 0.0;
    switch (s.kind) {
        case SettingKind::Flag:
            if (!v.isBool()) refuse();
            value = v.toBool() ? 1.0 : 0.0;
            break;
        case SettingKind::Choice: {
            if (!v.isString()) refuse();
            const std::string name = v.toString().toLower().toStdString();
            value = -1.0;
            for (std::size_t i = 0; i < s.choices.size(); ++i) {
                if (s.choices[i] == name) value = static_cast<double>(i);
            }
            if (value < 0.0) refuse();
            break;
        }
        case SettingKind::Colour: {
            const glm::vec3 rgb = fields.vec3(key, {});
            if (glm::any(glm::lessThan(rgb, glm::vec3(0.0F))) ||
                glm::any(glm::greaterThan(rgb, glm::vec3(1.0F)))) {
                fields.fail(key, "must be a list of 3 numbers from 0 to 1 (red, green, blue)");
            }
            value = packColour(rgb);
            break;
        }
        case SettingKind::Number:
        case SettingKind::Integer:
            if (!v.isDouble()) refuse();
            value = v.toDouble();
            if (const std::string problem = s.problemWith(value); !problem.empty()) {
                fields.fail(key, problem);
            }
            break;
    }
    s.set(state, value);
}

int lineOf(const QByteArray& json, int offset) {
    return 1 + static_cast<int>(json.left(offset).count('\n'));
}

void readData(const Fields& root, const QDir& projectDir, SessionState& p) {
    const Fields data = root.object(QStringLiteral("data"));
    if (data.has(QStringLiteral("demo"))) {
        const Fields demo = data.object(QStringLiteral("demo"));
        p.demo = true;
        p.demoParams.members =
            static_cast<std::size_t>(demo.integer(QStringLiteral("members"), 50, 2, 10000));
        const glm::vec3 grid = demo.vec3(QStringLiteral("grid"), glm::vec3(256, 128, 16));
        for (int i = 0; i < 3; ++i) {
            if (grid[i] < 2 || grid[i] > 4096 || grid[i] != std::floor(grid[i])) {
                demo.fail(QStringLiteral("grid"), "must be 3 whole numbers from 2 to 4096");
            }
        }
        p.demoParams.nx = static_cast<std::size_t>(grid.x);
        p.demoParams.ny = static_cast<std::size_t>(grid.y);
        p.demoParams.nz = static_cast<std::size_t>(grid.z);
        p.demoParams.seed =
            static_cast<std::uint64_t>(demo.integer(QStringLiteral("seed"), 1, 0, 1 << 30));
        return;
    }
    if (!data.has(QStringLiteral("files"))) {
        data.fail(QStringLiteral("files"), "is missing: name the data files or the demo");
    }
    const QJsonArray files = data.array(QStringLiteral("files"));
    if (files.isEmpty()) data.fail(QStringLiteral("files"), "must name at least one file");
    for (int i = 0; i < files.size(); ++i) {
        const Fields file(files[i].toObject(), QStringLiteral("data.files[%1]").arg(i));
        if (!files[i].isObject()) file.fail(QStringLiteral("path"), "must be given");
        const QString relative = file.text(QStringLiteral("path"), {});
        const QString absolute = file.text(QStringLiteral("absolute_path"), {});
        if (relative.isEmpty() && absolute.isEmpty()) {
            file.fail(QStringLiteral("path"), "must be given");
        }
        // The path beside the project wins; the absolute one is where it was when saved.
        QString chosen = relative.isEmpty() ? absolute : projectDir.absoluteFilePath(relative);
        if (!QFileInfo::exists(chosen) && !absolute.isEmpty()) chosen = absolute;
        p.data.paths.push_back(QDir::cleanPath(chosen).toStdString());
    }
    p.data.variable = data.text(QStringLiteral("variable"), {}).toStdString();
    p.data.memberDimension = data.text(QStringLiteral("member_dimension"), {}).toStdString();
    p.data.timeIndex =
        static_cast<std::size_t>(data.integer(QStringLiteral("time_index"), 0, 0, 1 << 30));
    if (const QString levels = data.text(QStringLiteral("levels"), {}); !levels.isEmpty()) {
        try {
            p.data.levels = data::parseLevelRange(levels.toStdString());
        } catch (const data::Error& e) {
            data.fail(QStringLiteral("levels"), e.what());
        }
    }
    if (const QString region = data.text(QStringLiteral("region"), {}); !region.isEmpty()) {
        try {
            p.data.region = data::parseRegion(region.toStdString());
        } catch (const data::Error& e) {
            data.fail(QStringLiteral("region"), e.what());
        }
    }
}

QJsonObject dataJson(const SessionState& p, const QDir& projectDir) {
    QJsonObject data;
    if (p.demo) {
        data[QStringLiteral("demo")] =
            QJsonObject{{"members", static_cast<qint64>(p.demoParams.members)},
                        {"grid", QJsonArray{static_cast<qint64>(p.demoParams.nx),
                                            static_cast<qint64>(p.demoParams.ny),
                                            static_cast<qint64>(p.demoParams.nz)}},
                        {"seed", static_cast<qint64>(p.demoParams.seed)}};
        return data;
    }
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
    if (p.data.levels) {
        data[QStringLiteral("levels")] =
            QString::fromStdString(data::levelRangeText(*p.data.levels));
    }
    if (p.data.region) {
        data[QStringLiteral("region")] = QString::fromStdString(data::regionText(*p.data.region));
    }
    return data;
}
}  // namespace

QByteArray projectToJson(const SessionState& p, const QDir& projectDir) {
    QJsonObject root{
        {"format", kFormatName},
        {"schema_version", kProjectSchemaVersion},
        {"written_by", QStringLiteral("ensil " ENSIL_VERSION)},
        {"data", dataJson(p, projectDir)},
        {"cutting_plane", QJsonObject{{"normal", vec3Json(p.render.plane.normal)},
                                      {"offset", p.render.plane.offset}}},
        // Numbers from 1, as the workbench shows members and clusters (format version 3).
        {"clusters", QJsonObject{{"hidden", intsJson(numbersOf(p.hiddenClusters))},
                                 {"members", intsJson(p.memberClusters)}}},
        {"members", QJsonObject{{"hidden", intsJson(numbersOf(p.hiddenMembers))},
                                {"selected", intsJson(numbersOf(p.selection))}}},
        // As typed in the Sections dock; empty: where the members' contours are.
        {"sections",
         QJsonObject{{"level", QString::fromStdString(p.sections.level)},
                     {"cross_kind", kCrossKinds[static_cast<std::size_t>(p.sections.crossKind)]},
                     {"cross", QString::fromStdString(p.sections.cross)}}},
        {"layout", QJsonObject{{"geometry", QString::fromLatin1(p.windowGeometry.toBase64())},
                               {"state", QString::fromLatin1(p.windowState.toBase64())}}}};
    if (p.isovalue) root[QStringLiteral("isovalue")] = *p.isovalue;
    if (p.camera.placement) {
        QJsonObject camera;
        camera[QStringLiteral("distance")] = p.camera.placement->distance;
        camera[QStringLiteral("target")] = vec3Json(p.camera.placement->target);
        root[QStringLiteral("camera")] = camera;
    }
    for (const Setting& s : settingTable()) {
        if (!s.projectKey.empty()) insertAt(root, keyPath(s), settingJson(s, s.get(p)));
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

SessionState projectFromJson(const QByteArray& json, const QDir& projectDir) {
    QJsonParseError parseError{};
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const int line = lineOf(json, parseError.offset);
        throw ProjectError(
            "line " + std::to_string(line) + ": " + parseError.errorString().toStdString(), line);
    }
    if (!document.isObject()) throw ProjectError("the file does not hold a JSON object", 1);
    const Fields root(document.object(), {});
    if (root.text(QStringLiteral("format"), {}) != QLatin1String(kFormatName)) {
        throw ProjectError(R"(this is not an ensil project (its "format" is not "ensil project"))");
    }
    const int version = root.integer(QStringLiteral("schema_version"), 0, 0, 1 << 20);
    if (version < 1) root.fail(QStringLiteral("schema_version"), "must be 1 or more");
    if (version > kProjectSchemaVersion) {
        throw ProjectError(
            "the project was written by a newer ensil (" +
            root.text(QStringLiteral("written_by"), QStringLiteral("unknown")).toStdString() +
            ", format version " + std::to_string(version) +
            "); this ensil " ENSIL_VERSION " reads format versions up to " +
            std::to_string(kProjectSchemaVersion) + ". Update ensil to open it.");
    }

    // Format 3 numbers hidden clusters and hidden and selected members from 1, as the workbench
    // shows them; formats 1 and 2 wrote indices from 0.
    const int firstNumber = version >= 3 ? 1 : 0;
    SessionState p;
    readData(root, projectDir, p);
    if (root.has(QStringLiteral("isovalue"))) {
        p.isovalue = static_cast<float>(root.number(QStringLiteral("isovalue"), 0.0, -1e30, 1e30));
    }
    for (const Setting& s : settingTable()) {
        if (!s.projectKey.empty()) readSetting(root, s, p);
    }
    if (root.has(QStringLiteral("camera"))) {
        const Fields c = root.object(QStringLiteral("camera"));
        // Format 1 saved a camera only once it was placed; format 2 says so by its distance.
        if (version == 1 || c.has(QStringLiteral("distance"))) {
            CameraState::Placement placement;
            placement.distance = static_cast<float>(
                c.number(QStringLiteral("distance"), placement.distance, 1e-6, 1e6));
            placement.target = c.vec3(QStringLiteral("target"), placement.target);
            p.camera.placement = placement;
        }
    }
    if (p.render.removalMin >= p.render.removalMax) {
        throw ProjectError("rendering.removal.min must be below rendering.removal.max");
    }
    if (root.has(QStringLiteral("cutting_plane"))) {
        const Fields f = root.object(QStringLiteral("cutting_plane"));
        const glm::vec3 normal = f.vec3(QStringLiteral("normal"), p.render.plane.normal);
        if (glm::length(normal) < 1e-6F) f.fail(QStringLiteral("normal"), "must not be zero");
        p.render.plane.normal = glm::normalize(normal);
        p.render.plane.offset =
            static_cast<float>(f.number(QStringLiteral("offset"), 0.0, -1e6, 1e6));
    }
    if (root.has(QStringLiteral("clusters"))) {
        const Fields f = root.object(QStringLiteral("clusters"));
        p.hiddenClusters = f.indices(QStringLiteral("hidden"), firstNumber);
        p.memberClusters = f.indices(QStringLiteral("members"));
        if (std::ranges::find(p.memberClusters, 0) != p.memberClusters.end()) {
            f.fail(QStringLiteral("members"), "must be cluster numbers (whole numbers from 1)");
        }
    }
    if (root.has(QStringLiteral("members"))) {
        const Fields f = root.object(QStringLiteral("members"));
        p.hiddenMembers = f.indices(QStringLiteral("hidden"), firstNumber);
        p.selection = f.indices(QStringLiteral("selected"), firstNumber);
    }
    if (root.has(QStringLiteral("sections"))) {
        const Fields f = root.object(QStringLiteral("sections"));
        // A place is a short text ("500 hPa", "-10,50:20,40"); whether it lies in the data is
        // for the data to say when the section is drawn.
        constexpr qsizetype kLongestPlace = 200;
        const auto place = [&](const QString& key) {
            const QString text = f.text(key, {});
            if (text.size() > kLongestPlace) {
                f.fail(key, "is longer than " + std::to_string(kLongestPlace) + " characters");
            }
            return text.toStdString();
        };
        p.sections.level = place(QStringLiteral("level"));
        p.sections.cross = place(QStringLiteral("cross"));
        const QString kind = f.text(QStringLiteral("cross_kind"), QLatin1String(kCrossKinds[0]));
        const auto* found = std::find(kCrossKinds.begin(), kCrossKinds.end(), kind);
        if (found == kCrossKinds.end()) {
            f.fail(QStringLiteral("cross_kind"), "must be latitude, longitude or path");
        }
        p.sections.crossKind =
            static_cast<SectionPlaces::Cross>(std::distance(kCrossKinds.begin(), found));
    }
    if (root.has(QStringLiteral("layout"))) {
        const Fields f = root.object(QStringLiteral("layout"));
        p.windowGeometry =
            QByteArray::fromBase64(f.text(QStringLiteral("geometry"), {}).toLatin1());
        p.windowState = QByteArray::fromBase64(f.text(QStringLiteral("state"), {}).toLatin1());
    }
    return p;
}

void saveProject(const SessionState& state, const QString& path) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        throw ProjectError("cannot write '" + path.toStdString() +
                           "': " + file.errorString().toStdString());
    }
    const QByteArray json = projectToJson(state, QFileInfo(path).absoluteDir());
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

SessionState loadProject(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        throw ProjectError("cannot read '" + path.toStdString() +
                           "': " + file.errorString().toStdString());
    }
    // A project is a few kilobytes (its layout included); refuse what cannot be one before
    // reading it, rather than spend memory on it and echo it back.
    constexpr qint64 kMaxProjectBytes = qint64{16} << 20;
    if (file.size() > kMaxProjectBytes) {
        throw ProjectError(QFileInfo(path).fileName().toStdString() + ": it is " +
                           std::to_string(file.size() >> 20) +
                           " MiB, far more than a project holds (at most 16 MiB); it is not "
                           "an ensil project");
    }
    try {
        return projectFromJson(file.readAll(), QFileInfo(path).absoluteDir());
    } catch (const ProjectError& e) {
        throw ProjectError(QFileInfo(path).fileName().toStdString() + ": " + e.what(), e.line());
    }
}

}  // namespace ensil::session
