#include "data/reader_support.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "data/error.h"

namespace ensil::data {

namespace fs = std::filesystem;

void requireFiles(const std::vector<std::string>& paths) {
    if (paths.empty()) {
        throw Error(ErrorKind::InvalidArgument, "no file given: name one file, or one per member");
    }
    for (const std::string& path : paths) {
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) {
            throw Error(ErrorKind::FileNotFound, fs::exists(path, ec)
                                                     ? "'" + path + "' is not a regular file"
                                                     : "file '" + path + "' does not exist");
        }
        // Otherwise an unreadable file would look like one in an unknown format.
        if (!std::ifstream(path, std::ios::binary)) {
            throw Error(ErrorKind::FileNotFound,
                        "cannot open '" + path + "' for reading: " + std::strerror(errno));
        }
    }
}

std::string readFileStart(const std::string& path, std::size_t count) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    std::string bytes(count, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(count));
    bytes.resize(static_cast<std::size_t>(in.gcount()));
    return bytes;
}

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

std::vector<std::string> memberNamesFromPaths(const std::vector<std::string>& paths) {
    std::vector<std::string> names;
    std::set<std::string> seen;
    bool unique = true;
    for (const std::string& path : paths) {
        names.push_back(fs::path(path).stem().string());
        unique = seen.insert(names.back()).second && unique;
    }
    if (unique) return names;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const fs::path path(paths[i]);
        names[i] = (path.parent_path().filename() / path.stem()).string();
    }
    return names;
}

std::string sourceOf(const std::vector<std::string>& paths) {
    if (paths.size() == 1) return paths.front();
    std::string folder = fs::path(paths.front()).parent_path().string();
    if (folder.empty()) folder = ".";
    return std::to_string(paths.size()) + " files in " + folder;
}

Ensemble ensembleDescribedBy(const EnsembleDescription& d, const std::vector<std::string>& paths) {
    Ensemble e;
    e.variable = d.variable;
    e.longName = d.longName;
    e.units = d.units;
    e.memberDimension = d.memberDimension;
    e.source = sourceOf(paths);
    e.grid = d.grid;
    e.gridMapping = d.gridMapping;
    e.fixedDimensions = d.fixedDimensions;
    e.timeSteps = d.timeSteps;
    e.warnings = d.warnings;
    e.members.resize(d.members);
    return e;
}

std::string sizeText(double bytes) {
    char text[32];
    if (bytes >= 1073741824.0) {
        std::snprintf(text, sizeof text, "%.2f GiB", bytes / 1073741824.0);
    } else if (bytes >= 10.0 * 1048576.0) {
        std::snprintf(text, sizeof text, "%.0f MiB", bytes / 1048576.0);
    } else {
        std::snprintf(text, sizeof text, "%.1f MiB", bytes / 1048576.0);
    }
    return text;
}

std::string shapeText(std::size_t nx, std::size_t ny, std::size_t nz) {
    return std::to_string(nx) + " x " + std::to_string(ny) + " x " + std::to_string(nz);
}

std::string quotedList(const std::vector<std::string>& names) {
    if (names.empty()) return "none";
    std::string text;
    for (const std::string& name : names) {
        if (!text.empty()) text += ", ";
        text += "'" + name + "'";
    }
    return text;
}

Axis uniformAxis(std::string name, double origin, double spacing, std::size_t n, double first) {
    Axis axis;
    axis.name = std::move(name);
    axis.values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        axis.values[i] = origin + spacing * (first + static_cast<double>(i));
    }
    return axis;
}

void requireThreeDimensional(const std::string& what, std::size_t nx, std::size_t ny,
                             std::size_t nz) {
    if (nx >= 2 && ny >= 2 && nz >= 2) return;
    throw Error(ErrorKind::NotThreeDimensional,
                what + ": the grid is " + shapeText(nx, ny, nz) +
                    " (x by y by z); isosurfaces need at least 2 points along every axis");
}

std::string windSpeedLongName(const std::string& u, const std::string& v) {
    return "wind speed sqrt(" + u + "^2 + " + v + "^2), derived by ensil";
}

void toWindSpeed(float* u, const float* v, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) u[i] = std::sqrt(u[i] * u[i] + v[i] * v[i]);
}

void checkSameGrid(const std::string& firstPath, const Grid& first, const std::string& path,
                   const Grid& grid) {
    if (first.sameShapeAndCoordinates(grid)) return;
    const bool sameShape =
        first.nx() == grid.nx() && first.ny() == grid.ny() && first.nz() == grid.nz();
    throw Error(ErrorKind::GridMismatch,
                "members lie on different grids: '" + path + "' has " +
                    shapeText(grid.nx(), grid.ny(), grid.nz()) + " points, '" + firstPath +
                    "' has " + shapeText(first.nx(), first.ny(), first.nz()) +
                    (sameShape ? " (same size, different coordinates)" : "") +
                    ". Every member of an ensemble must share one grid");
}

void noteTimesThatDiffer(EnsembleDescription& d, std::size_t timeIndex,
                         const std::string& firstLabel, const std::string& firstPath,
                         const TimeSteps& steps, const std::string& path) {
    if (timeIndex >= steps.count() || timeIndex >= d.timeSteps.count()) return;
    const std::string& label = steps.labels[timeIndex];
    if (label == firstLabel) return;
    d.warnings.push_back("'" + path + "' is at " + steps.dimension + " " + label + " where '" +
                         firstPath + "' is at " + firstLabel +
                         ": the members are not of one time, and are compared as if they were");
    static constexpr std::string_view kDiffer = " (members' times differ)";
    std::string& shown = d.timeSteps.labels[timeIndex];
    if (!shown.ends_with(kDiffer)) shown += kDiffer;
}

}  // namespace ensil::data
