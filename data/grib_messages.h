// The ecCodes side of the GRIB reader: walks a file's messages, reads the keys ensil needs into
// plain structs, and decodes one message's values into ensil's order (x fastest, west to east,
// north to south). No ecCodes type leaves data/grib_messages.cpp. Every ecCodes call is made
// under one lock: Debian's ecCodes is built without its own thread safety. Internal to data/;
// used by GribReader.
#pragma once

#include <cstddef>
#include <cstdio>
#include <memory>
#include <stop_token>
#include <string>
#include <vector>

#include "data/grid.h"

namespace ensil::data {

// What a message says about its horizontal grid.
struct GribGrid {
    std::string type;     // gridType: "regular_ll", "regular_gg", "reduced_gg", "sh", ...
    long ni = 0, nj = 0;  // points along a parallel (x) and along a meridian (y)
    long gaussianN = 0;   // regular_gg: number of parallels between a pole and the equator
    double firstLat = 0, firstLon = 0, lastLat = 0, lastLon = 0;  // degrees, as scanned
    // The scanning mode's flags (GRIB code table 8 / 3.4).
    bool iNegative = false, jPositive = false, jConsecutive = false, alternateRows = false;

    [[nodiscard]] std::size_t pointCount() const {
        return static_cast<std::size_t>(ni) * static_cast<std::size_t>(nj);
    }
    bool operator==(const GribGrid&) const = default;
};

// The keys of one message that place it in an ensemble.
struct GribMessage {
    std::size_t offset = 0;  // where it starts in the file, in bytes
    std::size_t number = 0;  // 1 for the file's first message
    // Which field of its message (0: the first): a GRIB 2 message may repeat its sections 2 to
    // 7 or 3 to 7 or 4 to 7 to hold several fields (levels, parameters, members), each its own
    // GribMessage here. length: the whole message's, in bytes (0 where not known).
    std::size_t field = 0;
    std::size_t length = 0;
    long edition = 0;
    std::string shortName, name, units;
    long paramId = 0;
    std::string typeOfLevel;
    double level = 0;   // "level"; for pressure levels in Pa (isobaricInhPa times 100)
    long member = 0;    // "number" (perturbation number); 0 for a control or a single run
    long validity = 0;  // reference time + step as YYYYMMDDhhmm (sorts by time)
    GribGrid grid;
    std::size_t values = 0;  // size of the "values" array
};

struct GribInventory {
    std::vector<GribMessage> messages;
    // One line per damaged message that was skipped, naming its byte offset.
    std::vector<std::string> warnings;
};

// The headers of every readable field in the file: one GribMessage per message, and one per
// field of a GRIB 2 message holding several. A damaged message is skipped with a
// warning naming its byte offset. Throws Error(FileNotFound) when the file cannot be opened,
// Error(CorruptFile) when it holds no readable message, Cancelled when `stop` is requested.
GribInventory scanGribFile(const std::string& path, const std::stop_token& stop);

// "2017-01-01T12:00" for a GribMessage::validity.
std::string validityText(long validity);

// The grid's x and y axes in ensil's order: longitude increasing, latitude from north to
// south (the GRIB default, and what cdo and grib_to_netcdf write to NetCDF). Empty `why`
// when they could be made; otherwise it says what is wrong, in words for the user.
struct GribAxes {
    Axis x, y;
    std::string why;
};
GribAxes gribAxes(const GribGrid& grid);

// What to do with a grid ensil does not read (reduced Gaussian, spherical harmonics, map
// projections): the regridding command; empty for regular_ll and regular_gg.
std::string unsupportedGridAdvice(const std::string& gridType, const std::string& path);

// One open GRIB file, for decoding the messages an inventory found. Not thread-safe itself;
// every decode takes the ecCodes lock.
class GribFile {
public:
    explicit GribFile(const std::string& path);  // throws Error(FileNotFound)
    ~GribFile();
    GribFile(const GribFile&) = delete;
    GribFile& operator=(const GribFile&) = delete;

    // Decodes `message` into out[0 .. grid.pointCount()) in ensil's order, NaN where its bitmap
    // (or its missing-value marker) says a value is missing. Throws Error(CorruptFile) naming
    // the file, message and byte offset when the message no longer decodes as the inventory
    // said.
    void decode(const GribMessage& message, float* out, std::vector<double>& scratch) const;

private:
    void decodeLocked(const GribMessage& message, float* out, std::vector<double>& scratch) const;

    std::string m_path;
    std::FILE* m_file = nullptr;
};

}  // namespace ensil::data
