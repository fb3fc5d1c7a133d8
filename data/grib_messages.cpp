#include "data/grib_messages.h"

#include <eccodes.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include "data/eccodes_library.h"
#include "data/error.h"
#include "data/grib_complex_packing.h"
#include "data/job.h"

namespace ensil::data {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct HandleDeleter {
    void operator()(codes_handle* h) const { codes_handle_delete(h); }
};
using Handle = std::unique_ptr<codes_handle, HandleDeleter>;

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

long getLong(codes_handle* h, const char* key, long fallback = 0) {
    long value = fallback;
    if (codes_is_defined(h, key) == 0 || codes_get_long(h, key, &value) != CODES_SUCCESS) {
        return fallback;
    }
    return value;
}

double getDouble(codes_handle* h, const char* key, double fallback = 0) {
    double value = fallback;
    if (codes_is_defined(h, key) == 0 || codes_get_double(h, key, &value) != CODES_SUCCESS) {
        return fallback;
    }
    return value;
}

std::string getString(codes_handle* h, const char* key) {
    std::array<char, 256> text{};
    std::size_t length = text.size();
    if (codes_is_defined(h, key) == 0 ||
        codes_get_string(h, key, text.data(), &length) != CODES_SUCCESS) {
        return {};
    }
    return text.data();
}

std::string atOffset(const std::string& path, std::size_t number, std::size_t offset,
                     std::size_t field = 0) {
    return "'" + path + "', GRIB message " + std::to_string(number) +
           (field > 0 ? " (its field " + std::to_string(field + 1) + ")" : std::string()) +
           " at byte offset " + std::to_string(offset);
}

// Section 0, a GRIB 1 section 1 (28 bytes at least) and "7777" already take 40 bytes; GRIB 2's
// sections 0 and 1 take 37, its end 4.
constexpr std::uint64_t kShortestMessage = 40;

// Where the next message begins: the first "GRIB" at or after `from`; nullopt when none is left.
std::optional<long> nextMessageStart(std::FILE* file, long from) {
    constexpr std::size_t kChunk = 1 << 16;
    std::string bytes(kChunk + 3, '\0');
    for (long at = from;; at += static_cast<long>(kChunk)) {
        if (std::fseek(file, at, SEEK_SET) != 0) return std::nullopt;
        const std::size_t got = std::fread(bytes.data(), 1, bytes.size(), file);
        const std::size_t found = std::string_view(bytes.data(), got).find("GRIB");
        if (found != std::string_view::npos) return at + static_cast<long>(found);
        if (got < bytes.size()) return std::nullopt;  // the 3 bytes overlap the next chunk
    }
}

// The smallest length the message at `start` says it has (section 0): GRIB 1's 3-byte length
// (without the flag of ECMWF's large messages, whose true length is larger still), GRIB 2's
// 8-byte one. nullopt for another edition number: ensil reads editions 1 and 2 only (ecCodes
// would take a damaged edition 3 for its experimental GRIB 3 and allocate what it claims).
std::optional<std::uint64_t> claimedLength(std::FILE* file, long start) {
    std::array<unsigned char, 16> head{};
    if (std::fseek(file, start, SEEK_SET) != 0) return std::nullopt;
    const std::size_t got = std::fread(head.data(), 1, head.size(), file);
    if (got < 8) return std::uint64_t{8};
    std::uint64_t length = 0;
    if (head[7] == 1) {
        length = (std::uint64_t{head[4]} << 16 | std::uint64_t{head[5]} << 8 | head[6]) & 0x7fffff;
    } else if (head[7] == 2) {
        if (got < 16) return std::uint64_t{16};
        for (std::size_t i = 8; i < 16; ++i) length = length << 8 | head[i];
    } else {
        return std::nullopt;
    }
    return length;
}

// How many fields the GRIB 2 message at `start` (`length` bytes, already checked against the
// file) holds: its data sections (number 7), counted by walking the sections' own lengths, so
// that the common single-field message costs a few small reads and no second decode. A walk
// that goes astray (a damaged length) stops there; what ecCodes makes of it decides.
std::size_t gribFieldCount(std::FILE* file, long start, std::uint64_t length) {
    std::size_t fields = 0;
    std::uint64_t at = 16;  // after section 0
    std::array<unsigned char, 5> head{};
    while (at + 5 <= length) {
        if (std::fseek(file, start + static_cast<long>(at), SEEK_SET) != 0 ||
            std::fread(head.data(), 1, head.size(), file) != head.size()) {
            break;
        }
        if (std::string_view(reinterpret_cast<const char*>(head.data()), 4) == "7777") break;
        const std::uint64_t section = std::uint64_t{head[0]} << 24 | std::uint64_t{head[1]} << 16 |
                                      std::uint64_t{head[2]} << 8 | head[3];
        if (section < 5) break;
        if (head[4] == 7) ++fields;
        at += section;
    }
    return std::max<std::size_t>(fields, 1);
}

// The fields of one GRIB 2 message with several, one handle at a time: the message is copied
// into memory and read with ecCodes's multi-field support, which is switched on only while
// this object lives, under the ecCodes lock (it is a setting of ecCodes's one context), and
// only for this message's bytes, so ecCodes never reads past them into the next message.
class MessageFields {
public:
    MessageFields(std::FILE* file, std::size_t offset, std::size_t length) : m_bytes(length, '\0') {
        if (std::fseek(file, static_cast<long>(offset), SEEK_SET) != 0 ||
            std::fread(m_bytes.data(), 1, length, file) != length) {
            return;
        }
        m_memory = fmemopen(m_bytes.data(), m_bytes.size(), "rb");
        if (m_memory != nullptr) codes_grib_multi_support_on(nullptr);
    }
    ~MessageFields() {
        if (m_memory == nullptr) return;
        codes_grib_multi_support_reset_file(nullptr, m_memory);
        codes_grib_multi_support_off(nullptr);
        std::fclose(m_memory);
    }
    MessageFields(const MessageFields&) = delete;
    MessageFields& operator=(const MessageFields&) = delete;

    // The next field's handle; null after the last (or when the message cannot be read).
    codes_handle* next(int* error) {
        if (m_memory == nullptr) return nullptr;
        return codes_handle_new_from_file(nullptr, m_memory, PRODUCT_GRIB, error);
    }

private:
    std::string m_bytes;
    std::FILE* m_memory = nullptr;
};

GribGrid readGrid(codes_handle* h) {
    GribGrid g;
    g.type = getString(h, "gridType");
    g.ni = getLong(h, "Ni");
    g.nj = getLong(h, "Nj");
    g.gaussianN = getLong(h, "N");
    g.firstLat = getDouble(h, "latitudeOfFirstGridPointInDegrees");
    g.firstLon = getDouble(h, "longitudeOfFirstGridPointInDegrees");
    g.lastLat = getDouble(h, "latitudeOfLastGridPointInDegrees");
    g.lastLon = getDouble(h, "longitudeOfLastGridPointInDegrees");
    g.iNegative = getLong(h, "iScansNegatively") != 0;
    g.jPositive = getLong(h, "jScansPositively") != 0;
    g.jConsecutive = getLong(h, "jPointsAreConsecutive") != 0;
    g.alternateRows = getLong(h, "alternativeRowScanning") != 0;
    return g;
}

// The validity time as YYYYMMDDhhmm: the reference date and time plus the forecast step,
// computed here because ecCodes's own validityDate loops for ever on some damaged steps.
// nullopt when the date is impossible.
std::optional<long> validityOf(codes_handle* h) {
    using namespace std::chrono;
    const long date = getLong(h, "dataDate"), time = getLong(h, "dataTime");
    long step = 0;
    std::size_t length = 1;
    if (codes_is_defined(h, "endStep") != 0 &&
        (codes_set_string(h, "stepUnits", "m", &length) != CODES_SUCCESS ||
         codes_get_long(h, "endStep", &step) != CODES_SUCCESS)) {
        return std::nullopt;
    }
    const year_month_day day{year(static_cast<int>(date / 10000)),
                             month(static_cast<unsigned>(date / 100 % 100)),
                             std::chrono::day(static_cast<unsigned>(date % 100))};
    constexpr long kCenturiesInMinutes = 100L * 366 * 24 * 60;
    if (date < 10000 || date > 99991231 || !day.ok() || time < 0 || time / 100 > 23 ||
        time % 100 > 59 || std::abs(step) > kCenturiesInMinutes) {
        return std::nullopt;
    }
    const auto valid = sys_days(day) + hours(time / 100) + minutes(time % 100 + step);
    const auto validDay = floor<days>(valid);
    const year_month_day ymd(validDay);
    const auto minute = duration_cast<minutes>(valid - validDay).count();
    const long yyyymmdd = static_cast<long>(static_cast<int>(ymd.year())) * 10000 +
                          static_cast<long>(static_cast<unsigned>(ymd.month())) * 100 +
                          static_cast<long>(static_cast<unsigned>(ymd.day()));
    return yyyymmdd * 10000 + minute / 60 * 100 + minute % 60;
}

GribMessage readKeys(codes_handle* h, std::size_t number) {
    GribMessage m;
    m.number = number;
    m.offset = static_cast<std::size_t>(std::max(0L, getLong(h, "offset")));
    m.edition = getLong(h, "edition");
    m.shortName = getString(h, "shortName");
    m.name = getString(h, "name");
    m.units = getString(h, "units");
    m.paramId = getLong(h, "paramId");
    m.typeOfLevel = getString(h, "typeOfLevel");
    m.level = getDouble(h, "level");
    if (m.typeOfLevel == "isobaricInhPa") m.level *= 100.0;  // one pressure axis, in Pa
    m.member = getLong(h, "number");
    m.validity = validityOf(h).value_or(-1);
    m.grid = readGrid(h);
    std::size_t size = 0;
    if (codes_get_size(h, "values", &size) == CODES_SUCCESS) m.values = size;
    return m;
}

// The index of `value` in `list` within `tolerance`; list.size() when there is none.
std::size_t nearestIndex(const std::vector<double>& list, double value, double tolerance) {
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (std::abs(list[i] - value) <= tolerance) return i;
    }
    return list.size();
}

// The complex packing's description (templates 5.2 and 5.3) checked against the data section's
// bytes: ecCodes would decode it without checking (data/grib_complex_packing.h).
std::optional<std::string> complexPackingDamageOf(codes_handle* h) {
    const long templateNumber = getLong(h, "dataRepresentationTemplateNumber", -1);
    if (getLong(h, "edition") != 2 || (templateNumber != 2 && templateNumber != 3)) {
        return std::nullopt;
    }
    ComplexPacking p;
    p.spatialDifferencing = templateNumber == 3;
    p.numberOfValues = getLong(h, "numberOfValues");
    p.bitsPerValue = getLong(h, "bitsPerValue");
    p.numberOfGroupsOfDataValues = getLong(h, "numberOfGroupsOfDataValues");
    p.referenceForGroupWidths = getLong(h, "referenceForGroupWidths");
    p.numberOfBitsUsedForTheGroupWidths = getLong(h, "numberOfBitsUsedForTheGroupWidths");
    p.referenceForGroupLengths = getLong(h, "referenceForGroupLengths");
    p.lengthIncrementForTheGroupLengths = getLong(h, "lengthIncrementForTheGroupLengths");
    p.trueLengthOfLastGroup = getLong(h, "trueLengthOfLastGroup");
    p.numberOfBitsUsedForTheScaledGroupLengths =
        getLong(h, "numberOfBitsUsedForTheScaledGroupLengths");
    if (p.spatialDifferencing) {
        p.orderOfSpatialDifferencing = getLong(h, "orderOfSpatialDifferencing");
        p.numberOfOctetsExtraDescriptors = getLong(h, "numberOfOctetsExtraDescriptors");
    }
    const void* bytes = nullptr;
    std::size_t size = 0;
    const long offset = getLong(h, "offsetSection7", -1), length = getLong(h, "section7Length");
    if (codes_get_message(h, &bytes, &size) != CODES_SUCCESS || offset < 0 || length < 5 ||
        static_cast<std::size_t>(offset) + static_cast<std::size_t>(length) > size) {
        return std::string("its data section lies outside the message");
    }
    const std::span<const std::uint8_t> data(static_cast<const std::uint8_t*>(bytes) + offset + 5,
                                             static_cast<std::size_t>(length) - 5);
    return complexPackingDamage(p, data);
}

// Why a message whose keys were read cannot be decoded safely, in words for the user; nullopt
// when it can. ecCodes allocates what a message says it packs when it decodes it: a damaged
// count would take gigabytes for a grid of a few hundred points.
std::optional<std::string> damageBeforeDecoding(codes_handle* h, const GribMessage& m) {
    if (m.validity < 0) {
        return std::string("its reference date, time or forecast step is impossible");
    }
    const long packed = std::max(getLong(h, "numberOfValues"), getLong(h, "numberOfCodedValues"));
    if (packed < 0 || static_cast<std::size_t>(packed) > m.values) {
        return "it says it packs " + std::to_string(packed) + " values, but its grid has " +
               std::to_string(m.values) + " points";
    }
    return complexPackingDamageOf(h);
}

// The fields after the first of a GRIB 2 message that holds several, with the first's place
// in the file (a field is decoded from its message, GribFile::decode). Skipped with a warning
// like a damaged message when one does not read or packs more values than its grid has.
void addFurtherFields(std::FILE* file, const GribMessage& first, const std::string& path,
                      GribInventory& inventory) {
    if (gribFieldCount(file, static_cast<long>(first.offset), first.length) < 2) return;
    MessageFields fields(file, first.offset, first.length);
    int error = CODES_SUCCESS;
    const Handle skipped(fields.next(&error));  // the first, already read
    for (std::size_t f = 1;; ++f) {
        Handle h;
        try {
            h.reset(fields.next(&error));
        } catch (const LibraryAssertion& e) {
            inventory.warnings.push_back(atOffset(path, first.number, first.offset, f) +
                                         " is damaged (ecCodes gave up on it: " + e.what() +
                                         "); ensil skipped it and the fields after it");
            break;
        }
        if (!h) break;
        GribMessage m = readKeys(h.get(), first.number);
        m.offset = first.offset;
        m.length = first.length;
        m.field = f;
        const std::string where = atOffset(path, m.number, m.offset, f);
        if (const auto why = damageBeforeDecoding(h.get(), m)) {
            inventory.warnings.push_back(where + " is damaged (" + *why + "); ensil skipped it");
        } else {
            inventory.messages.push_back(std::move(m));
        }
    }
}

}  // namespace

GribInventory scanGribFile(const std::string& path, const std::stop_token& stop) {
    const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        throw Error(ErrorKind::FileNotFound,
                    "cannot open '" + path + "' for reading: " + std::strerror(errno));
    }
    GribInventory inventory;
    std::fseek(file.get(), 0, SEEK_END);
    const long size = std::ftell(file.get());
    long position = 0;
    for (std::size_t number = 1;; ++number) {
        throwIfStopped(stop);
        const std::optional<long> start = nextMessageStart(file.get(), position);
        if (!start) break;
        const auto skip = [&](const std::string& why) {
            inventory.warnings.push_back(atOffset(path, number, static_cast<std::size_t>(*start)) +
                                         " is damaged (" + why + "); ensil skipped it");
        };
        // ecCodes allocates the length a message claims before reading it: a damaged length
        // would ask for gigabytes. A message longer than what is left of the file is cut.
        // One claiming less than its own first sections makes ecCodes copy them past the end of
        // the buffer it allocated for it.
        const auto length = claimedLength(file.get(), *start);
        const auto left = static_cast<std::uint64_t>(size - *start);
        if (!length) {
            skip("its edition number is neither 1 nor 2");
            position = *start + 4;
            continue;
        }
        if (*length > left || *length < kShortestMessage) {
            skip("it says it is " + std::to_string(*length) + " bytes long, but " +
                 (*length > left
                      ? "the file ends " + std::to_string(left) + " bytes after its start"
                      : "no GRIB message is shorter than " + std::to_string(kShortestMessage) +
                            " bytes"));
            position = *start + 4;
            continue;
        }
        const auto lock = lockEccodes();
        std::fseek(file.get(), *start, SEEK_SET);
        try {
            int error = CODES_SUCCESS;
            const Handle h(codes_handle_new_from_file(nullptr, file.get(), PRODUCT_GRIB, &error));
            // Go on after what ecCodes read, and at least after this "GRIB": never loop in place.
            position = std::max(std::ftell(file.get()), *start + 4);
            if (!h) {
                skip(error == CODES_SUCCESS ? "ecCodes found no message there"
                                            : libraryWords(error));
                continue;
            }
            GribMessage m = readKeys(h.get(), number);
            m.offset = static_cast<std::size_t>(*start);
            m.length = static_cast<std::size_t>(*length);
            if (const auto why = damageBeforeDecoding(h.get(), m)) {
                skip(*why);
            } else {
                const GribMessage first = m;
                inventory.messages.push_back(std::move(m));
                if (first.edition == 2) addFurtherFields(file.get(), first, path, inventory);
            }
        } catch (const LibraryAssertion& e) {
            skip(std::string("ecCodes gave up on it: ") + e.what());
            position = *start + 4;
        }
    }
    if (inventory.messages.empty()) {
        std::string why =
            inventory.warnings.empty() ? "it holds no GRIB message" : inventory.warnings.front();
        throw Error(ErrorKind::CorruptFile, "'" + path + "' has no readable GRIB message: " + why +
                                                ". Check the file with 'grib_ls " + path + "'");
    }
    return inventory;
}

std::string validityText(long validity) {
    const long date = validity / 10000, time = validity % 10000;
    std::array<char, 40> text{};
    std::snprintf(text.data(), text.size(), "%04ld-%02ld-%02ldT%02ld:%02ld", date / 10000,
                  date / 100 % 100, date % 100, time / 100, time % 100);
    return text.data();
}

GribAxes gribAxes(const GribGrid& g) {
    GribAxes axes;
    // A constant field packs any number of points into a few bytes: a damaged Ni or Nj would
    // have the axes alone take gigabytes before the ensemble's size is checked.
    constexpr long kMostAlongAnAxis = 1000000;  // 0.00036 degrees around the globe
    if (g.ni > kMostAlongAnAxis || g.nj > kMostAlongAnAxis) {
        axes.why = "lies on a grid of " + std::to_string(g.ni) + " x " + std::to_string(g.nj) +
                   " points, more than ensil reads (" + std::to_string(kMostAlongAnAxis) +
                   " along an axis); its header is likely damaged";
        return axes;
    }
    if (g.ni < 2 || g.nj < 2) {
        axes.why = "lies on a grid of " + std::to_string(g.ni) + " x " + std::to_string(g.nj) +
                   " points; isosurfaces need at least 2 along each axis";
        return axes;
    }
    // The western and northern ends, whichever way the points were scanned.
    const double west = g.iNegative ? g.lastLon : g.firstLon;
    double east = g.iNegative ? g.firstLon : g.lastLon;
    if (east <= west) east += 360.0;  // a grid across the date line or the meridian of 0
    axes.x = makeUniformAxis("lon", "degrees_east", west, east, static_cast<std::size_t>(g.ni));
    axes.x.standardName = "longitude";
    const double north = g.jPositive ? g.lastLat : g.firstLat;
    const double south = g.jPositive ? g.firstLat : g.lastLat;
    if (!(north > south) || north > 90.0 + 1e-6 || south < -90.0 - 1e-6) {
        axes.why = "has latitudes from " + std::to_string(g.firstLat) + " to " +
                   std::to_string(g.lastLat) + " degrees, which its scanning mode (j " +
                   (g.jPositive ? "northwards" : "southwards") + ") contradicts";
        return axes;
    }
    if (g.type == "regular_gg") {
        // Gaussian latitudes are uneven: the library's own, not a spacing from the header.
        if (g.gaussianN < 1 || g.gaussianN > 100000 || 2 * g.gaussianN < g.nj) {
            axes.why = "has the Gaussian number N = " + std::to_string(g.gaussianN) +
                       " does not fit its " + std::to_string(g.nj) + " latitudes";
            return axes;
        }
        std::vector<double> all(2 * static_cast<std::size_t>(g.gaussianN));
        {
            const auto lock = lockEccodes();
            int error = CODES_SUCCESS;
            try {
                error = codes_get_gaussian_latitudes(g.gaussianN, all.data());
            } catch (const LibraryAssertion&) {
                error = CODES_INTERNAL_ERROR;
            }
            if (error != CODES_SUCCESS) {
                axes.why =
                    "ecCodes has no Gaussian latitudes for N = " + std::to_string(g.gaussianN);
                return axes;
            }
        }
        // Headers store latitudes in milli- (GRIB 1) or micro-degrees (GRIB 2).
        const double tolerance = 0.002;
        const std::size_t first = nearestIndex(all, north, tolerance);
        const auto nj = static_cast<std::size_t>(g.nj);
        if (first == all.size() || first + nj > all.size() ||
            std::abs(all[first + nj - 1] - south) > tolerance) {
            axes.why = "has latitudes " + std::to_string(north) + " to " + std::to_string(south) +
                       " are not " + std::to_string(g.nj) +
                       " consecutive latitudes of the Gaussian grid N" +
                       std::to_string(g.gaussianN);
            return axes;
        }
        axes.y.name = "lat";
        axes.y.units = "degrees_north";
        axes.y.values.assign(all.begin() + static_cast<std::ptrdiff_t>(first),
                             all.begin() + static_cast<std::ptrdiff_t>(first + nj));
    } else {
        axes.y =
            makeUniformAxis("lat", "degrees_north", north, south, static_cast<std::size_t>(g.nj));
    }
    axes.y.standardName = "latitude";
    return axes;
}

std::string unsupportedGridAdvice(const std::string& gridType, const std::string& path) {
    if (gridType == "regular_ll" || gridType == "regular_gg") return {};
    if (gridType == "reduced_gg" || gridType == "reduced_rotated_gg") {
        return "lies on a reduced Gaussian grid (" + gridType +
               "), whose parallels hold different numbers of points; ensil reads regular "
               "grids. Interpolate it to the regular Gaussian grid first, e.g. 'cdo "
               "setgridtype,regular " +
               path + " regular.grib'";
    }
    if (gridType == "sh") {
        return "holds spherical harmonics (gridType sh), not values at grid points; ensil "
               "reads regular grids. Transform it to a regular Gaussian grid first, e.g. 'cdo "
               "sp2gp " +
               path + " gridpoint.grib'";
    }
    return "lies on a grid of type " + (gridType.empty() ? std::string("unknown") : gridType) +
           "; ensil reads regular latitude-longitude and regular Gaussian grids. Interpolate it "
           "to one first, e.g. 'cdo remapbil,r360x181 " +
           path + " latlon.grib' (a 1-degree grid)";
}

GribFile::GribFile(const std::string& path) : m_path(path), m_file(std::fopen(path.c_str(), "rb")) {
    if (m_file == nullptr) {
        throw Error(ErrorKind::FileNotFound,
                    "cannot open '" + path + "' for reading: " + std::strerror(errno));
    }
}

GribFile::~GribFile() { std::fclose(m_file); }

void GribFile::decode(const GribMessage& message, float* out, std::vector<double>& scratch) const {
    const auto lock = lockEccodes();
    try {
        decodeLocked(message, out, scratch);
    } catch (const LibraryAssertion& e) {
        throw Error(ErrorKind::CorruptFile,
                    atOffset(m_path, message.number, message.offset, message.field) +
                        " is damaged: ecCodes gave up on it (" + e.what() + ")");
    }
}

void GribFile::decodeLocked(const GribMessage& message, float* out,
                            std::vector<double>& scratch) const {
    const std::string where = atOffset(m_path, message.number, message.offset, message.field);
    if (std::fseek(m_file, static_cast<long>(message.offset), SEEK_SET) != 0) {
        throw Error(ErrorKind::CorruptFile, where + " cannot be reached: the file changed");
    }
    int error = CODES_SUCCESS;
    // A field after the first is read from its message's bytes with multi-field support; the
    // first (every field of most files) straight from the file, as ecCodes reads it by default.
    std::optional<MessageFields> fields;
    if (message.field > 0) fields.emplace(m_file, message.offset, message.length);
    Handle h(fields ? fields->next(&error)
                    : codes_handle_new_from_file(nullptr, m_file, PRODUCT_GRIB, &error));
    for (std::size_t f = 0; fields && h && f < message.field; ++f) h.reset(fields->next(&error));
    if (!h) {
        throw Error(ErrorKind::CorruptFile, where + " no longer reads: " + libraryWords(error) +
                                                ". Was the file changed while ensil read it?");
    }
    const GribGrid& g = message.grid;
    const std::size_t n = g.pointCount();
    std::size_t size = 0;
    if (codes_get_size(h.get(), "values", &size) != CODES_SUCCESS || size != n ||
        !(readGrid(h.get()) == g)) {
        throw Error(ErrorKind::CorruptFile,
                    where +
                        " no longer matches what its header said when the file was opened; "
                        "was the file changed while ensil read it?");
    }
    // Checked when the file was opened; again here, as the message is read anew.
    if (const auto why = complexPackingDamageOf(h.get())) {
        throw Error(ErrorKind::CorruptFile, where + " is damaged: " + *why);
    }
    scratch.resize(n);
    error = codes_get_double_array(h.get(), "values", scratch.data(), &size);
    if (error != CODES_SUCCESS || size != n) {
        throw Error(ErrorKind::CorruptFile,
                    where + ": its values do not decode (" + libraryWords(error) +
                        "); the message is damaged. Check it with "
                        "'grib_dump -O -w count=" +
                        std::to_string(message.number) + " " + m_path + "'");
    }
    // Missing values: where the bitmap says 0, or (GRIB 2 complex packing without a bitmap)
    // where the value is the message's missing-value marker.
    std::vector<long> bitmap;
    if (getLong(h.get(), "bitmapPresent") != 0) {
        std::size_t bits = 0;
        if (codes_get_size(h.get(), "bitmap", &bits) == CODES_SUCCESS && bits == n) {
            bitmap.resize(n);
            if (codes_get_long_array(h.get(), "bitmap", bitmap.data(), &bits) != CODES_SUCCESS) {
                bitmap.clear();
            }
        }
        if (bitmap.empty()) {
            throw Error(ErrorKind::CorruptFile,
                        where +
                            " says it has a bitmap of missing values, but its bitmap does not "
                            "decode to one bit per point; the message is damaged");
        }
    }
    const bool markerMeansMissing = getLong(h.get(), "missingValueManagementUsed") != 0;
    const double marker = getDouble(h.get(), "missingValue", 9999.0);

    const auto ni = static_cast<std::size_t>(g.ni), nj = static_cast<std::size_t>(g.nj);
    for (std::size_t s = 0; s < n; ++s) {
        // Where point s of the message lies: its column and row as scanned...
        std::size_t col = 0, row = 0;
        if (g.jConsecutive) {
            col = s / nj;
            row = s % nj;
            if (g.alternateRows && col % 2 == 1) row = nj - 1 - row;
        } else {
            row = s / ni;
            col = s % ni;
            if (g.alternateRows && row % 2 == 1) col = ni - 1 - col;
        }
        // ...then in ensil's order: west to east, north to south.
        const std::size_t x = g.iNegative ? ni - 1 - col : col;
        const std::size_t y = g.jPositive ? nj - 1 - row : row;
        const double v = scratch[s];
        const bool missing =
            (!bitmap.empty() && bitmap[s] == 0) || (markerMeansMissing && v == marker);
        out[x + ni * y] = missing ? kNaN : static_cast<float>(v);
    }
}

}  // namespace ensil::data
