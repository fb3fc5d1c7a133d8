"""Time steps are named by the date their CF time gives, in every CF calendar: ensil's dates
against python3-cftime's on 10,000 random (value, units, calendar) cases, with no disagreement
allowed."""

import random

import cftime
import pytest

from ensil import _ensil

CALENDARS = ["standard", "gregorian", "proleptic_gregorian", "julian", "noleap", "365_day",
             "all_leap", "366_day", "360_day"]
UNITS = {"seconds": 1, "minutes": 60, "hours": 3600, "days": 86400}


def cftime_text(value, units, calendar):
    d = cftime.num2date(value, units, calendar)
    return f"{d.year:04d}-{d.month:02d}-{d.day:02d}T{d.hour:02d}:{d.minute:02d}"


def test_ten_thousand_random_times_agree_with_cftime():
    rng = random.Random(20261207)
    compared = 0
    while compared < 10_000:
        calendar = rng.choice(CALENDARS)
        unit = rng.choice(list(UNITS))
        year, month, day = rng.randint(1, 3000), rng.randint(1, 12), rng.randint(1, 28)
        hour, minute = rng.randint(0, 23), rng.randint(0, 59)
        if calendar in ("standard", "gregorian") and (year, month) == (1582, 10) and 5 <= day <= 14:
            continue  # days that never were in that calendar
        units = f"{unit} since {year}-{month}-{day} {hour:02d}:{minute:02d}:00"
        # Up to some 3,000 years either way, in whole units.
        value = rng.randint(-(3000 * 365 * 86400) // UNITS[unit], (3000 * 365 * 86400) // UNITS[unit])
        expected = cftime_text(value, units, calendar)
        if not 1 <= int(expected[:-12]) <= 9999:
            assert _ensil._format_cf_time(value, units, calendar) is None
            continue
        assert _ensil._format_cf_time(value, units, calendar) == expected, (value, units, calendar)
        compared += 1


def test_a_calendar_cf_does_not_have_gives_no_date():
    assert _ensil._format_cf_time(1, "days since 2000-01-01", "none") is None
    with pytest.raises(ValueError):
        cftime.num2date(1, "days since 2000-01-01", "none")
