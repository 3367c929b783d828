#pragma once
// Thesis §5.5.3 / App. B: a water temperature older than one month must not be
// reused for a ballast calculation; the operator is asked for a new one.
// "One month" is a calendar month (see docs/decisions/history-temperature-staleness.md).
#include "history/timestamp.h"

namespace auv {

// Same day-of-month and time of day one month later; a day that does not exist
// in that month is clamped to its last day (Jan 31 -> Feb 28, or Feb 29 in a
// leap year; Dec 15 -> Jan 15 of the next year).
TimePoint addOneCalendarMonth(TimePoint t);

// True when `now` is strictly later than measured_at + one calendar month
// (exactly one month old may still be reused, as App. B's comments say), and
// also when measured_at lies in the future: a clock we cannot trust gets a
// fresh temperature rather than an unknown-age one.
bool temperatureIsStale(TimePoint measured_at, TimePoint now);

}  // namespace auv
