#pragma once
// History timestamps: whole seconds, UTC, stored as ISO-8601 text
// ("2014-04-04T15:28:00Z"). Fixed-width text sorts in time order, so SQL can
// ORDER BY the column directly and a human can read the database file.
#include <chrono>
#include <string>

namespace auv {

using TimePoint = std::chrono::sys_seconds;

TimePoint nowUtc();
std::string toIsoUtc(TimePoint t);  // "YYYY-MM-DDTHH:MM:SSZ", years 0000-9999
// Accepts exactly the form toIsoUtc writes; `field` names the value in errors.
TimePoint parseIsoUtc(const std::string& text, const std::string& field = "timestamp");
// Calendar-exact construction (month 1-12); throws InputError on an invalid date.
TimePoint makeUtc(int year, unsigned month, unsigned day, int hour = 0, int minute = 0,
                  int second = 0);

}  // namespace auv
