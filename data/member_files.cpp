#include "data/member_files.h"

#include <filesystem>

#include "data/error.h"

namespace ensil::data {
namespace {
std::string sizeText(const Grid& g) {
    return std::to_string(g.nx()) + " x " + std::to_string(g.ny()) + " x " + std::to_string(g.nz());
}
}  // namespace

std::string fileStem(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

std::string sourceLabel(const std::vector<std::string>& paths) {
    if (paths.size() == 1) return paths.front();
    const std::filesystem::path first(paths.front());
    const std::filesystem::path last(paths.back());
    return std::to_string(paths.size()) + " files in " + first.parent_path().string() + " (" +
           first.filename().string() + " ... " + last.filename().string() + ")";
}

void checkSameGrid(const std::string& firstPath, const Grid& first, const std::string& path,
                   const Grid& grid) {
    if (first.sameShapeAndCoordinates(grid)) return;
    const bool sameShape =
        first.nx() == grid.nx() && first.ny() == grid.ny() && first.nz() == grid.nz();
    throw Error(ErrorKind::GridMismatch,
                "members lie on different grids: '" + path + "' has " + sizeText(grid) +
                    " points, '" + firstPath + "' has " + sizeText(first) +
                    (sameShape ? " (same size, different coordinates)" : "") +
                    ". Every member of an ensemble must share one grid");
}

}  // namespace ensil::data
