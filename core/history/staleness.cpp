#include "history/staleness.h"

namespace auv {
using namespace std::chrono;

TimePoint addOneCalendarMonth(TimePoint t) {
  const auto day_start = floor<days>(t);
  const year_month_day ymd{day_start};
  const year_month next = year_month{ymd.year(), ymd.month()} + months{1};
  const day last = year_month_day_last{next.year(), month_day_last{next.month()}}.day();
  const day d = ymd.day() > last ? last : ymd.day();
  return sys_days{year_month_day{next.year(), next.month(), d}} + (t - day_start);
}

bool temperatureIsStale(TimePoint measured_at, TimePoint now) {
  if (measured_at > now) return true;
  return now > addOneCalendarMonth(measured_at);
}

}  // namespace auv
