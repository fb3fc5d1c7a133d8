// Reads ensembles from plain HDF5 files (HDF5 C API). Accepted layouts:
//   - one 4D dataset (member, z, y, x) in one file; members are named "member 1" ... ;
//   - one group, at any depth, holding one 3D dataset (z, y, x) per member, all of one shape, as
//     h5py writes them (/ensemble/member_00 ..., /data/t/m0 ...); members are named by dataset
//     name and ordered by it, numbers in names by value (m2 before m10); the root group counts
//     (/run_01, /run_02 ...);
//   - one file per member, each holding a 3D dataset (z, y, x) of the same name and shape;
//     members are named after the file stems.
// DataSelection::variable names the dataset or group ("wind_speed", "/members"). Left empty, the
// reader takes the first usable 4D dataset, else the first group of two or more 3D datasets (in
// depth-first name order; when there are several such ensembles, the description's reason names
// them all), else the first 3D dataset (a one-member ensemble); with several files, the first 3D
// dataset of the first file. Integer and floating-point elements are converted to float. Optional
// attributes on the dataset or group: `origin` and `spacing` (3 numbers each, x, y, z order) make
// uniform axes, otherwise axes are grid indices 0 .. n-1; `units`, `long_name` (strings);
// `_FillValue` and `missing_value` (numbers) mark values that become NaN. A group without an
// attribute falls back to its first member dataset's. Stateless; callable from any thread (the HDF5
// library is built thread-safe).
#pragma once

#include "data/ensemble_reader.h"

namespace ensil::data {

class Hdf5Reader final : public EnsembleReader {
public:
    [[nodiscard]] std::string name() const override { return "HDF5"; }
    // True for files starting with the HDF5 signature (NetCDF-4 files too: ask NetCDF first; it
    // leaves plain HDF5 files, without netCDF-4's marks, to this reader).
    [[nodiscard]] bool recognizes(const std::string& path) const override;
    [[nodiscard]] EnsembleDescription describe(const DataSelection& selection) const override;
    [[nodiscard]] Ensemble read(const DataSelection& selection, const std::stop_token& stop,
                                const Progress& progress) const override;
};

}  // namespace ensil::data
