// Writes small GRIB files for the GRIB reader's tests with ecCodes itself: a message starts from
// one of ecCodes's samples, takes keys in the order given, and its values come from a function
// of each point's latitude and longitude as ecCodes's own geo-iterator places them (so the
// expected field does not depend on the reader's scanning logic).
#pragma once

#include <eccodes.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace ensil::test {

using GribKey = std::pair<std::string, std::variant<long, double, std::string>>;

struct GribField {
    std::string sample = "regular_ll_pl_grib2";
    std::vector<GribKey> keys;
    // The value at a point; NaN makes the point missing (a bitmap).
    std::function<double(double lat, double lon)> value;
    // A packing set once the values are (ecCodes cannot switch an empty field to a complex
    // packing); empty: the keys' packing.
    std::string packingOfValues;
};

// An 8 x 5 latitude-longitude grid, 0..70 E and 40..0 N in steps of 10 degrees, scanned in the
// mode given, IEEE-packed (values keep float precision), in an ensemble forecast template.
inline std::vector<GribKey> smallGrid(bool iNegative = false, bool jPositive = false,
                                      bool jConsecutive = false) {
    return {{"packingType", std::string("grid_ieee")},
            {"productDefinitionTemplateNumber", 1L},
            {"numberOfForecastsInEnsemble", 10L},
            {"Ni", 8L},
            {"Nj", 5L},
            {"iScansNegatively", iNegative ? 1L : 0L},
            {"jScansPositively", jPositive ? 1L : 0L},
            {"jPointsAreConsecutive", jConsecutive ? 1L : 0L},
            {"longitudeOfFirstGridPointInDegrees", iNegative ? 70.0 : 0.0},
            {"longitudeOfLastGridPointInDegrees", iNegative ? 0.0 : 70.0},
            {"latitudeOfFirstGridPointInDegrees", jPositive ? 0.0 : 40.0},
            {"latitudeOfLastGridPointInDegrees", jPositive ? 40.0 : 0.0},
            {"iDirectionIncrementInDegrees", 10.0},
            {"jDirectionIncrementInDegrees", 10.0}};
}

inline bool setKey(codes_handle* h, const GribKey& key) {
    const char* name = key.first.c_str();
    if (const auto* l = std::get_if<long>(&key.second)) return codes_set_long(h, name, *l) == 0;
    if (const auto* d = std::get_if<double>(&key.second)) return codes_set_double(h, name, *d) == 0;
    const std::string& s = std::get<std::string>(key.second);
    std::size_t length = s.size();
    return codes_set_string(h, name, s.c_str(), &length) == 0;
}

// The bytes of one message.
inline std::string encodeGrib(const GribField& field) {
    codes_handle* h = codes_grib_handle_new_from_samples(nullptr, field.sample.c_str());
    EXPECT_NE(h, nullptr) << field.sample;
    if (h == nullptr) return {};
    for (const GribKey& key : field.keys) EXPECT_TRUE(setKey(h, key)) << key.first;
    if (field.value) {
        // As many values as the grid now has points: ecCodes counts the points anew only once
        // values of the new size are set, and its geo-iterator follows that count.
        long ni = 0, nj = 0;
        EXPECT_EQ(codes_get_long(h, "Ni", &ni), 0);
        EXPECT_EQ(codes_get_long(h, "Nj", &nj), 0);
        const auto n = static_cast<std::size_t>(ni * nj);
        std::vector<double> lats(n), lons(n), values(n, 0.0);
        EXPECT_EQ(codes_set_double_array(h, "values", values.data(), n), 0);
        std::size_t got = n;
        EXPECT_EQ(codes_get_double_array(h, "latitudes", lats.data(), &got), 0);
        got = n;
        EXPECT_EQ(codes_get_double_array(h, "longitudes", lons.data(), &got), 0);
        bool missing = false;
        for (std::size_t i = 0; i < n; ++i) {
            values[i] = field.value(lats[i], lons[i]);
            missing = missing || values[i] != values[i];
            if (values[i] != values[i]) values[i] = 9999.0;
        }
        if (missing) {
            EXPECT_EQ(codes_set_double(h, "missingValue", 9999.0), 0);
            EXPECT_EQ(codes_set_long(h, "bitmapPresent", 1), 0);
        }
        EXPECT_EQ(codes_set_double_array(h, "values", values.data(), n), 0);
        if (!field.packingOfValues.empty()) {
            EXPECT_TRUE(setKey(h, {"packingType", field.packingOfValues}));
            EXPECT_EQ(codes_set_double_array(h, "values", values.data(), n), 0);
        }
    }
    const void* bytes = nullptr;
    std::size_t size = 0;
    EXPECT_EQ(codes_get_message(h, &bytes, &size), 0);
    std::string message(static_cast<const char*>(bytes), size);
    codes_handle_delete(h);
    return message;
}

inline void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace ensil::test
