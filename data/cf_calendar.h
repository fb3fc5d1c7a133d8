// Dates in the calendars of the CF conventions (section 4.4.1): standard (= gregorian: the
// Julian calendar up to 1582-10-04, the Gregorian from the next day, 1582-10-15), proleptic
// gregorian, julian, noleap (= 365_day), all_leap (= 366_day) and 360_day, as cftime counts
// them. A date becomes a day number and back, so that "N units since an epoch" is the epoch's
// day number plus N units, and the date of that. Written here because the C++ standard library
// knows only the proleptic Gregorian calendar. Pure; any thread.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace ensil::data {

enum class CfCalendar { Standard, ProlepticGregorian, Julian, NoLeap, AllLeap, Day360 };

// The calendar of a CF `calendar` attribute, any case (empty: standard); nullopt for one that
// is not CF's ("none", a misspelling).
std::optional<CfCalendar> cfCalendar(const std::string& name);

struct CfDate {
    std::int64_t year = 0;
    int month = 1;
    int day = 1;
    bool operator==(const CfDate&) const = default;
};

// Days from a fixed origin of the calendar; nullopt for a date the calendar does not have
// (2001-02-29 anywhere but all_leap and 360_day; 1900-02-29 in proleptic_gregorian but not in
// julian; 1582-10-10 in standard; day 31 in 360_day, whose months all have 30).
std::optional<std::int64_t> cfDayNumber(CfCalendar calendar, const CfDate& date);
CfDate cfDateOf(CfCalendar calendar, std::int64_t dayNumber);

}  // namespace ensil::data
