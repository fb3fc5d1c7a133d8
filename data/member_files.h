// Helpers for ensembles made of one file per member: names from file stems, a label for the
// whole set, and the check that every file has the grid of the first. Used by every reader.
#pragma once

#include <string>
#include <vector>

#include "data/grid.h"

namespace ensil::data {

// "run_07" for "/data/run_07.nc".
std::string fileStem(const std::string& path);

// The path for one file; "56 files in /data (run_01.nc ... run_56.nc)" for several.
std::string sourceLabel(const std::vector<std::string>& paths);

// Throws Error(GridMismatch) naming both files and their grid sizes when the grids differ.
void checkSameGrid(const std::string& firstPath, const Grid& first, const std::string& path,
                   const Grid& grid);

}  // namespace ensil::data
