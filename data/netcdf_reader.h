// Reads ensembles from NetCDF files (classic, 64-bit offset, CDF-5 and NetCDF-4) following the
// CF conventions: one file with a member dimension, one file per member, or a file where
// another dimension (time, month) stands in for members. Applies _FillValue, missing_value,
// valid_min/valid_max/valid_range (masked points become NaN) and scale_factor/add_offset;
// any numeric type in, float out; spatial dimensions in any order. Offers the derived
// variable wind_speed = sqrt(u^2 + v^2) when u and v exist (WRF's staggered U and V are
// averaged onto the mass grid). Stateless; callable from any thread (library calls are
// serialised, because netCDF-C is not thread-safe).
#pragma once

#include "data/ensemble_reader.h"

namespace ensil::data {

class NetcdfReader final : public EnsembleReader {
public:
    [[nodiscard]] std::string name() const override { return "NetCDF"; }
    [[nodiscard]] bool recognizes(const std::string& path) const override;
    [[nodiscard]] EnsembleDescription describe(const DataSelection& selection) const override;
    [[nodiscard]] Ensemble read(const DataSelection& selection, const std::stop_token& stop,
                                const Progress& progress) const override;
    // Hyperslab reads: each member's values over the part's layers only (one more layer where
    // the variable is staggered along z, averaged away as in read()).
    [[nodiscard]] bool readsParts() const override { return true; }
    [[nodiscard]] Ensemble readPart(const DataSelection& selection,
                                    const EnsembleDescription& description,
                                    const EnsemblePart& part, const std::stop_token& stop,
                                    const Progress& progress) const override;
};

}  // namespace ensil::data
