// Checks a GRIB 2 message's complex packing (data representation templates 5.2 and 5.3, the
// packing of NCEP's GFS and GEFS files) against the bytes of its data section before ecCodes
// decodes it. ecCodes 2.28 walks the groups the header announces without checking them against
// the section's length, so a damaged group count or width reads past the message and crashes
// the program. The layout is WMO's (GRIB 2 templates 5.2, 5.3, 7.2 and 7.3); this walk reads
// only the groups' descriptions, never the values. Internal to data/.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace ensil::data {

// Section 5's keys for the complex packings, by their ecCodes names.
struct ComplexPacking {
    bool spatialDifferencing = false;  // template 5.3
    std::int64_t numberOfValues = 0;
    std::int64_t bitsPerValue = 0;  // of each group's reference
    std::int64_t numberOfGroupsOfDataValues = 0;
    std::int64_t referenceForGroupWidths = 0;
    std::int64_t numberOfBitsUsedForTheGroupWidths = 0;
    std::int64_t referenceForGroupLengths = 0;
    std::int64_t lengthIncrementForTheGroupLengths = 0;
    std::int64_t trueLengthOfLastGroup = 0;
    std::int64_t numberOfBitsUsedForTheScaledGroupLengths = 0;
    std::int64_t orderOfSpatialDifferencing = 0;      // template 5.3 only
    std::int64_t numberOfOctetsExtraDescriptors = 0;  // template 5.3 only
};

// Why the data section `data` (section 7 after its 5-byte head) cannot hold what `packing`
// describes, in words for the user; nullopt when it can: the groups' references, widths and
// lengths fit, the lengths add up to the number of values, and the values of every group fit.
[[nodiscard]] std::optional<std::string> complexPackingDamage(const ComplexPacking& packing,
                                                              std::span<const std::uint8_t> data);

}  // namespace ensil::data
