#include "data/grib_complex_packing.h"

namespace ensil::data {
namespace {

// The widest field ecCodes decodes into a long without overflow, and the widest a group's
// reference, width or length can usefully be: GRIB 2 packs at most 32 bits a value.
constexpr std::int64_t kWidestField = 32;

// Reads unsigned big-endian bit fields of `data` one after another; the caller has checked
// that they lie within it.
class BitReader {
public:
    explicit BitReader(std::span<const std::uint8_t> data, std::uint64_t bit = 0)
        : m_data(data), m_bit(bit) {}
    std::uint64_t next(std::int64_t width) {
        std::uint64_t value = 0;
        for (std::int64_t b = 0; b < width; ++b, ++m_bit) {
            value = value << 1 | ((m_data[m_bit / 8] >> (7 - m_bit % 8)) & 1u);
        }
        return value;
    }

private:
    std::span<const std::uint8_t> m_data;
    std::uint64_t m_bit;
};

std::uint64_t bytesOf(std::uint64_t bits) { return (bits + 7) / 8; }

}  // namespace

std::optional<std::string> complexPackingDamage(const ComplexPacking& p,
                                                std::span<const std::uint8_t> data) {
    const std::int64_t groups = p.numberOfGroupsOfDataValues;
    // No groups: ecCodes reads none and gives every value the reference (a constant field).
    if (groups == 0) return std::nullopt;
    if (groups < 0 || groups > p.numberOfValues) {
        return "it says its " + std::to_string(p.numberOfValues) + " values form " +
               std::to_string(groups) + " groups";
    }
    for (const std::int64_t width : {p.bitsPerValue, p.numberOfBitsUsedForTheGroupWidths,
                                     p.numberOfBitsUsedForTheScaledGroupLengths}) {
        if (width < 0 || width > kWidestField) {
            return "it packs its groups' descriptions in fields of " + std::to_string(width) +
                   " bits";
        }
    }
    std::uint64_t extraBytes = 0;
    // Order 0 (written by ecCodes itself) differences nothing and has no extra descriptors.
    if (p.spatialDifferencing && p.orderOfSpatialDifferencing != 0) {
        if (p.orderOfSpatialDifferencing < 0 || p.orderOfSpatialDifferencing > 2 ||
            p.numberOfOctetsExtraDescriptors < 1 || p.numberOfOctetsExtraDescriptors > 4) {
            return "its spatial differencing of order " +
                   std::to_string(p.orderOfSpatialDifferencing) + " with " +
                   std::to_string(p.numberOfOctetsExtraDescriptors) +
                   "-byte descriptors is not GRIB's";
        }
        extraBytes = static_cast<std::uint64_t>((p.orderOfSpatialDifferencing + 1) *
                                                p.numberOfOctetsExtraDescriptors);
    }
    // Section 7: the spatial differencing's first values and minimum, then the groups'
    // references, widths and lengths, each list starting on a byte, then the values.
    const auto n = static_cast<std::uint64_t>(groups);
    const std::uint64_t references = extraBytes;
    const std::uint64_t widths =
        references + bytesOf(n * static_cast<std::uint64_t>(p.bitsPerValue));
    const std::uint64_t lengths =
        widths + bytesOf(n * static_cast<std::uint64_t>(p.numberOfBitsUsedForTheGroupWidths));
    const std::uint64_t values =
        lengths +
        bytesOf(n * static_cast<std::uint64_t>(p.numberOfBitsUsedForTheScaledGroupLengths));
    if (values > data.size()) {
        return "the descriptions of its " + std::to_string(groups) + " groups need " +
               std::to_string(values) + " bytes, but its data section holds " +
               std::to_string(data.size());
    }
    BitReader width(data, widths * 8), length(data, lengths * 8);
    std::uint64_t points = 0, valueBits = 0;
    for (std::uint64_t g = 0; g < n; ++g) {
        const std::int64_t bits =
            p.referenceForGroupWidths +
            static_cast<std::int64_t>(width.next(p.numberOfBitsUsedForTheGroupWidths));
        const std::int64_t count =
            g + 1 == n
                ? p.trueLengthOfLastGroup
                : p.referenceForGroupLengths + p.lengthIncrementForTheGroupLengths *
                                                   static_cast<std::int64_t>(length.next(
                                                       p.numberOfBitsUsedForTheScaledGroupLengths));
        if (bits < 0 || bits > kWidestField || count < 0 ||
            points + static_cast<std::uint64_t>(count) >
                static_cast<std::uint64_t>(p.numberOfValues)) {
            return "its group " + std::to_string(g + 1) + " of " + std::to_string(groups) +
                   " says it holds " + std::to_string(count) + " values of " +
                   std::to_string(bits) + " bits, which its " + std::to_string(p.numberOfValues) +
                   " values do not allow";
        }
        points += static_cast<std::uint64_t>(count);
        valueBits += static_cast<std::uint64_t>(count) * static_cast<std::uint64_t>(bits);
    }
    if (points != static_cast<std::uint64_t>(p.numberOfValues)) {
        return "its groups hold " + std::to_string(points) + " values, not the " +
               std::to_string(p.numberOfValues) + " it says it packs";
    }
    if (values + bytesOf(valueBits) > data.size()) {
        return "its groups' values need " + std::to_string(values + bytesOf(valueBits)) +
               " bytes, but its data section holds " + std::to_string(data.size());
    }
    return std::nullopt;
}

}  // namespace ensil::data
