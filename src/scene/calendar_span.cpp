#include "scene/calendar_span.hpp"

#include <algorithm>
#include <optional>

namespace conescan::scene {

double calendar_year_s(const sources::instant& epoch) {
  std::optional<sources::calendar_time> c = sources::parse_calendar(sources::format_utc(epoch, 9));
  if (!c) return 365 * sources::seconds_per_day;
  c->year += 1;
  if (c->month == 2 && c->day == 29) c->day = 28;
  c->second = std::min(c->second, 59.999999999);  // a leap second's 60: the day's last second
  const checked<sources::instant> next = sources::from_calendar(*c, sources::time_scale::utc);
  return next.ok() ? sources::seconds_between(epoch, next.value()) : 365 * sources::seconds_per_day;
}

}  // namespace conescan::scene
