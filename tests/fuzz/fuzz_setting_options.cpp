// Fuzzes the checked command-line value parsers (session/setting_options.h): the value
// of any setting of the table (numbers, whole numbers, choices, flags, colours), a bounded
// number and an image size. These take whatever a user or a script types after an option, so
// each must either refuse it (nullopt and a problem naming the option) or return a value that
// keeps the promise made in the header: finite, within the setting's range, whole where
// whole, sizes from 1 to kMaxImageSide. The first byte picks the parser (and the setting); the
// rest is the text, as UTF-8.
#include <QString>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "session/setting_options.h"
#include "session/setting_table.h"
#include "tests/fuzz/fuzz_support.h"

namespace {
void require(bool promise, const char* what) {
    if (!promise) ensil::fuzz::unexpected(what);
}
}  // namespace

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ensil::session;
    if (size == 0) return 0;
    const QString text = QString::fromUtf8(reinterpret_cast<const char*>(data + 1),
                                           static_cast<qsizetype>(size - 1));
    const auto table = settingTable();
    const std::size_t choice = data[0];
    QString problem;
    if (choice < table.size()) {
        const Setting& s = table[choice];
        if (const auto value = parseSettingValue(s, text, problem)) {
            require(std::isfinite(*value), "parseSettingValue returned a value that is not finite");
            require(s.problemWith(*value).empty(), "parseSettingValue returned a refused value");
            if (s.kind == SettingKind::Number || s.kind == SettingKind::Integer) {
                require(*value >= s.minimum && *value <= s.maximum,
                        "parseSettingValue returned a value out of range");
            }
        } else {
            require(!problem.isEmpty(), "parseSettingValue refused without saying why");
        }
    } else if (choice % 2 == 0) {
        const bool whole = (choice & 4) != 0;
        if (const auto value =
                parseBoundedNumber(QStringLiteral("--frames"), text, 1, 1000, whole, problem)) {
            require(std::isfinite(*value) && *value >= 1 && *value <= 1000,
                    "parseBoundedNumber returned a value out of range");
            require(!whole || *value == std::floor(*value),
                    "parseBoundedNumber returned a fraction for a whole number");
        } else {
            require(!problem.isEmpty(), "parseBoundedNumber refused without saying why");
        }
    } else {
        if (const auto image = parseImageSize(QStringLiteral("--size"), text, problem)) {
            require(image->first >= 1 && image->first <= kMaxImageSide && image->second >= 1 &&
                        image->second <= kMaxImageSide,
                    "parseImageSize returned a size out of range");
        } else {
            require(!problem.isEmpty(), "parseImageSize refused without saying why");
        }
    }
    return 0;
}
