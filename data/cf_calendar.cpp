#include "data/cf_calendar.h"

#include <array>

#include "data/ascii_case.h"

namespace ensil::data {
namespace {

constexpr std::array<int, 12> kMonthDays{31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};

// Floor division: day numbers before the origin count down, and years with them.
std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

bool gregorianLeap(std::int64_t y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }
bool julianLeap(std::int64_t y) { return floorDiv(y, 4) * 4 == y; }

int daysIn(int month, bool leap) { return month == 2 && leap ? 29 : kMonthDays[month - 1]; }

// Julian Day Numbers by Fliegel and Van Flandern's integer formulas (Communications of the ACM
// 11, 1968), shifted so that every year from -4800 on gives non-negative intermediate values.
std::int64_t gregorianJdn(const CfDate& d) {
    const std::int64_t a = (14 - d.month) / 12;
    const std::int64_t y = d.year + 4800 - a;
    const std::int64_t m = d.month + 12 * a - 3;
    return d.day + (153 * m + 2) / 5 + 365 * y + floorDiv(y, 4) - floorDiv(y, 100) +
           floorDiv(y, 400) - 32045;
}

std::int64_t julianJdn(const CfDate& d) {
    const std::int64_t a = (14 - d.month) / 12;
    const std::int64_t y = d.year + 4800 - a;
    const std::int64_t m = d.month + 12 * a - 3;
    return d.day + (153 * m + 2) / 5 + 365 * y + floorDiv(y, 4) - 32083;
}

// The month and day of day `e` (0-based) of a March-based year, and the year's carry.
CfDate fromMarchYear(std::int64_t yearFrom4800, std::int64_t e) {
    const std::int64_t m = (5 * e + 2) / 153;
    CfDate out;
    out.day = static_cast<int>(e - (153 * m + 2) / 5 + 1);
    out.month = static_cast<int>(m + 3 - 12 * (m / 10));
    out.year = yearFrom4800 - 4800 + m / 10;
    return out;
}

CfDate gregorianFromJdn(std::int64_t j) {
    const std::int64_t a = j + 32044;
    const std::int64_t b = floorDiv(4 * a + 3, 146097);
    const std::int64_t c = a - floorDiv(146097 * b, 4);
    const std::int64_t d = floorDiv(4 * c + 3, 1461);
    const std::int64_t e = c - floorDiv(1461 * d, 4);
    return fromMarchYear(100 * b + d, e);
}

CfDate julianFromJdn(std::int64_t j) {
    const std::int64_t c = j + 32082;
    const std::int64_t d = floorDiv(4 * c + 3, 1461);
    const std::int64_t e = c - floorDiv(1461 * d, 4);
    return fromMarchYear(d, e);
}

// The first day of the Gregorian calendar in the standard calendar (1582-10-15), as a JDN.
constexpr std::int64_t kGregorianStart = 2299161;

// Fixed-length years (noleap, all_leap, 360_day): the year's days times the year plus the day
// of the year.
std::int64_t fixedDayNumber(const CfDate& d, bool leap, int yearDays) {
    std::int64_t dayOfYear = d.day - 1;
    if (yearDays == 360) {
        dayOfYear += 30 * (d.month - 1);
    } else {
        for (int m = 1; m < d.month; ++m) dayOfYear += daysIn(m, leap);
    }
    return d.year * yearDays + dayOfYear;
}

CfDate fixedDateOf(std::int64_t n, bool leap, int yearDays) {
    CfDate out;
    out.year = floorDiv(n, yearDays);
    int rest = static_cast<int>(n - out.year * yearDays);
    if (yearDays == 360) {
        out.month = rest / 30 + 1;
        out.day = rest % 30 + 1;
        return out;
    }
    out.month = 1;
    while (rest >= daysIn(out.month, leap)) rest -= daysIn(out.month++, leap);
    out.day = rest + 1;
    return out;
}

}  // namespace

std::optional<CfCalendar> cfCalendar(const std::string& name) {
    const std::string n = asciiLower(name);
    if (n.empty() || n == "standard" || n == "gregorian") return CfCalendar::Standard;
    if (n == "proleptic_gregorian") return CfCalendar::ProlepticGregorian;
    if (n == "julian") return CfCalendar::Julian;
    if (n == "noleap" || n == "365_day") return CfCalendar::NoLeap;
    if (n == "all_leap" || n == "366_day") return CfCalendar::AllLeap;
    if (n == "360_day") return CfCalendar::Day360;
    return std::nullopt;
}

std::optional<std::int64_t> cfDayNumber(CfCalendar calendar, const CfDate& date) {
    if (date.month < 1 || date.month > 12 || date.day < 1) return std::nullopt;
    switch (calendar) {
        case CfCalendar::Day360:
            if (date.day > 30) return std::nullopt;
            return fixedDayNumber(date, false, 360);
        case CfCalendar::NoLeap:
            if (date.day > daysIn(date.month, false)) return std::nullopt;
            return fixedDayNumber(date, false, 365);
        case CfCalendar::AllLeap:
            if (date.day > daysIn(date.month, true)) return std::nullopt;
            return fixedDayNumber(date, true, 366);
        case CfCalendar::ProlepticGregorian:
            if (date.day > daysIn(date.month, gregorianLeap(date.year))) return std::nullopt;
            return gregorianJdn(date);
        case CfCalendar::Julian:
            if (date.day > daysIn(date.month, julianLeap(date.year))) return std::nullopt;
            return julianJdn(date);
        case CfCalendar::Standard: {
            const bool gregorian =
                date.year > 1582 ||
                (date.year == 1582 && (date.month > 10 || (date.month == 10 && date.day >= 15)));
            const bool leap = gregorian ? gregorianLeap(date.year) : julianLeap(date.year);
            if (date.day > daysIn(date.month, leap)) return std::nullopt;
            if (gregorian) return gregorianJdn(date);
            const std::int64_t jdn = julianJdn(date);
            // 1582-10-05 to 1582-10-14 do not exist: the Julian calendar ended on the 4th.
            return jdn < kGregorianStart ? std::optional(jdn) : std::nullopt;
        }
    }
    return std::nullopt;
}

CfDate cfDateOf(CfCalendar calendar, std::int64_t dayNumber) {
    switch (calendar) {
        case CfCalendar::Day360:
            return fixedDateOf(dayNumber, false, 360);
        case CfCalendar::NoLeap:
            return fixedDateOf(dayNumber, false, 365);
        case CfCalendar::AllLeap:
            return fixedDateOf(dayNumber, true, 366);
        case CfCalendar::ProlepticGregorian:
            return gregorianFromJdn(dayNumber);
        case CfCalendar::Julian:
            return julianFromJdn(dayNumber);
        case CfCalendar::Standard:
            return dayNumber >= kGregorianStart ? gregorianFromJdn(dayNumber)
                                                : julianFromJdn(dayNumber);
    }
    return {};
}

}  // namespace ensil::data
