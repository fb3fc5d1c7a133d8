#include "geo/natural_earth.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <string_view>
#include <utility>

namespace ensil::geo {
namespace embedded {
extern const unsigned char kNaturalEarthLines[];
extern const std::size_t kNaturalEarthLinesSize;
}  // namespace embedded

namespace {

// The file's layout is described in resources/tools/natural_earth_lines.mjs, which writes it.
constexpr std::string_view kMagic = "ENSILNE1";
constexpr double kDegreesPerUnit = 180.0 / 32767.0;

class ByteReader {
public:
    ByteReader(const unsigned char* data, std::size_t size) : m_data(data), m_size(size) {}
    [[nodiscard]] bool has(std::size_t bytes) const { return m_size - m_offset >= bytes; }
    template <typename T>
    T take() {
        T value{};
        std::memcpy(&value, m_data + m_offset, sizeof(T));  // little-endian, as written
        m_offset += sizeof(T);
        return value;
    }
    void skip(std::size_t bytes) { m_offset += bytes; }

private:
    const unsigned char* m_data;
    std::size_t m_size;
    std::size_t m_offset = 0;
};

using Layers = std::map<std::pair<MapFeature, MapScale>, std::vector<LonLatLine>>;

Layers readLayers() {
    Layers layers;
    ByteReader in(embedded::kNaturalEarthLines, embedded::kNaturalEarthLinesSize);
    if (!in.has(kMagic.size() + 4)) return layers;
    std::array<char, kMagic.size()> magic{};
    for (char& c : magic) c = in.take<char>();
    if (std::string_view(magic.data(), magic.size()) != kMagic) return layers;
    const auto layerCount = in.take<std::uint32_t>();
    for (std::uint32_t l = 0; l < layerCount && in.has(8); ++l) {
        const auto feature = in.take<std::uint8_t>();
        const auto scale = in.take<std::uint8_t>();
        in.skip(2);
        const auto lineCount = in.take<std::uint32_t>();
        const std::pair key{feature == 0 ? MapFeature::Coastlines : MapFeature::Borders,
                            scale == 110 ? MapScale::Small110m : MapScale::Medium50m};
        std::vector<LonLatLine>& lines = layers[key];
        for (std::uint32_t i = 0; i < lineCount && in.has(4); ++i) {
            const auto points = in.take<std::uint32_t>();
            if (!in.has(std::size_t{points} * 4)) return layers;
            LonLatLine line(points);
            for (glm::dvec2& p : line) {
                p.x = in.take<std::int16_t>() * kDegreesPerUnit;
                p.y = in.take<std::int16_t>() * kDegreesPerUnit;
            }
            lines.push_back(std::move(line));
        }
    }
    return layers;
}

}  // namespace

const std::vector<LonLatLine>& naturalEarthLines(MapFeature feature, MapScale scale) {
    static const Layers layers = readLayers();
    static const std::vector<LonLatLine> none;
    const auto found = layers.find({feature, scale});
    return found == layers.end() ? none : found->second;
}

MapScale scaleForExtent(double extentDegrees) {
    return extentDegrees > kRegionalExtentDegrees ? MapScale::Small110m : MapScale::Medium50m;
}

}  // namespace ensil::geo
