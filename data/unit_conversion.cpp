#include "data/unit_conversion.h"

#include <udunits2.h>

#include <memory>
#include <mutex>

#include "data/ascii_case.h"

namespace ensil::data {
namespace {

std::mutex& udunitsMutex() {
    static std::mutex mutex;
    return mutex;
}

struct UnitFree {
    void operator()(ut_unit* unit) const { ut_free(unit); }
};
using Unit = std::unique_ptr<ut_unit, UnitFree>;

// The unit system from the installed database (UDUNITS2_XML_PATH, else the library's own
// path), read once; null when it cannot be read, so that every conversion says "unknown".
// Called under the lock.
const ut_system* unitSystem() {
    static const ut_system* system = [] {
        // UDUNITS-2 prints its complaints to standard error by default; ensil says what failed.
        ut_set_error_message_handler(ut_ignore);
        return static_cast<const ut_system*>(ut_read_xml(nullptr));
    }();
    return system;
}

// Called under the lock. Null for an empty or unknown unit.
Unit parse(const std::string& units) {
    const ut_system* system = unitSystem();
    // ut_parse refuses surrounding spaces.
    const std::string trimmed = asciiTrimmed(units);
    if (system == nullptr || trimmed.empty()) return nullptr;
    return Unit(ut_parse(system, trimmed.c_str(), UT_UTF8));
}

}  // namespace

std::optional<double> convertUnits(double value, const std::string& from, const std::string& to) {
    if (from == to) return value;
    const std::lock_guard lock(udunitsMutex());
    const Unit source = parse(from);
    const Unit target = parse(to);
    if (!source || !target || ut_are_convertible(source.get(), target.get()) == 0) {
        return std::nullopt;
    }
    cv_converter* converter = ut_get_converter(source.get(), target.get());
    if (converter == nullptr) return std::nullopt;
    const double converted = cv_convert_double(converter, value);
    cv_free(converter);
    return converted;
}

bool isKnownUnit(const std::string& units) {
    const std::lock_guard lock(udunitsMutex());
    return parse(units) != nullptr;
}

}  // namespace ensil::data
