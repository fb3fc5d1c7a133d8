// Small helpers the file readers share: checking paths before a library sees them, naming
// members after their files, and wording shapes and name lists the same way in every message.
// Pure functions; callable from any thread.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "data/ensemble_reader.h"
#include "data/grid.h"

namespace ensil::data {

// Throws Error(FileNotFound) naming the path when it is missing, not a regular file or not
// readable, and Error(InvalidArgument) when `paths` is empty.
void requireFiles(const std::vector<std::string>& paths);

// Up to `count` bytes from the start of the file; empty when it cannot be opened.
std::string readFileStart(const std::string& path, std::size_t count);

bool startsWith(std::string_view text, std::string_view prefix);

// One name per file: its stem ("run_07" for /data/run_07.vti). Files that share a stem in
// different folders (run_01/out.vtk, run_02/out.vtk) are named "run_01/out", "run_02/out".
std::vector<std::string> memberNamesFromPaths(const std::vector<std::string>& paths);

// The path of a single file, or "N files in DIR" with DIR the folder of the first file.
std::string sourceOf(const std::vector<std::string>& paths);

// An ensemble holding what its description says (variable, units, grid, map projection, fixed
// dimensions, time steps, warnings, where it came from) and room for its members, for a
// reader to fill.
Ensemble ensembleDescribedBy(const EnsembleDescription& description,
                             const std::vector<std::string>& paths);

// A size in bytes as people read it: "3.13 GiB" from 1 GiB up, "21 MiB" from 10 MiB up, "0.6 MiB"
// below (powers of 1024). The one format of every memory figure ensil says.
std::string sizeText(double bytes);

// "68 x 68 x 1": sizes along x, y, z.
std::string shapeText(std::size_t nx, std::size_t ny, std::size_t nz);

// "'a', 'b', 'c'", or "none" for an empty list.
std::string quotedList(const std::vector<std::string>& names);

// n points origin + spacing * (first + i), i = 0 .. n-1.
Axis uniformAxis(std::string name, double origin, double spacing, std::size_t n,
                 double first = 0.0);

// Throws Error(NotThreeDimensional) when an axis has fewer than 2 points: `what` names the
// file and variable, the message gives the grid as nx x ny x nz.
void requireThreeDimensional(const std::string& what, std::size_t nx, std::size_t ny,
                             std::size_t nz);

// Members from several files must be of one time: where a later file's step at the time index
// is not the first file's (two forecasts valid on different days), a warning names both files
// and both times, and the step's label, which the picture's title shows, says that the
// members' times differ. firstLabel is the first file's own label at the time index.
void noteTimesThatDiffer(EnsembleDescription& d, std::size_t timeIndex,
                         const std::string& firstLabel, const std::string& firstPath,
                         const TimeSteps& steps, const std::string& path);

// The derived variable wind_speed that the NetCDF and GRIB readers offer when a file holds u and
// v: its long name, "wind speed sqrt(u^2 + v^2), derived by ensil" for components u and v...
std::string windSpeedLongName(const std::string& u, const std::string& v);
// ...and its values: u[i] = sqrt(u[i]^2 + v[i]^2) for i < n (NaN where either is missing).
void toWindSpeed(float* u, const float* v, std::size_t n);

// Throws Error(GridMismatch) naming both files and their grid sizes when the grids differ.
void checkSameGrid(const std::string& firstPath, const Grid& first, const std::string& path,
                   const Grid& grid);

}  // namespace ensil::data
