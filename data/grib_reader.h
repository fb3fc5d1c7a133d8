// Reads ensembles from GRIB 1 and GRIB 2 files through ecCodes. Messages are grouped into
// variables by shortName (by paramId when ecCodes has no short name) and by kind of vertical
// level: isobaricInhPa and isobaricInPa make one pressure axis "plev" in Pa; hybrid (model)
// levels, heights and any other level type with two or more levels make their own axis
// (a short name found on two kinds of level is named "t_hybrid", "t_isobaric"...). Members come
// from the key `number` (perturbation number; the control forecast is member 0), times from the
// validity date and time: DataSelection::timeIndex picks one ("time = 0 of 4 (2017-01-01T00:00)"),
// or --member-dim time makes the times the members. Regular latitude-longitude and regular
// Gaussian grids in any scanning mode come out x fastest, longitude increasing, latitude from
// north to south (as cdo and grib_to_netcdf write them to NetCDF); bitmaps become NaN. Reduced
// Gaussian grids, spherical harmonics and projected grids are refused with the cdo command that
// regrids them. A damaged message is skipped with a warning naming its byte offset
// (Ensemble::warnings), and the ensemble is refused only when a field it needs is missing.
// wind_speed = sqrt(u^2 + v^2) is offered when u and v exist, on the levels they share.
// One file with members, or one file per member. Callable from any thread (ecCodes calls are
// serialised); its only state is the message lists of the last few files it read, kept under
// each file's path and content hash so describe() and read() scan a file once.
#pragma once

#include "data/ensemble_reader.h"

namespace ensil::data {

class GribReader final : public EnsembleReader {
public:
    [[nodiscard]] std::string name() const override { return "GRIB"; }
    // True for files that start with "GRIB".
    [[nodiscard]] bool recognizes(const std::string& path) const override;
    [[nodiscard]] EnsembleDescription describe(const DataSelection& selection) const override;
    [[nodiscard]] Ensemble read(const DataSelection& selection, const std::stop_token& stop,
                                const Progress& progress) const override;
};

}  // namespace ensil::data
