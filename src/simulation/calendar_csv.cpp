#include "simulation/calendar_csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace conescan::scene {

namespace {

constexpr double day_s = sources::seconds_per_day;

std::string printed(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

std::string head_name(std::size_t head) {
  return "h" + std::to_string(head + 1);
}

std::string utc_at(const blinding_calendar& c, double t_s) {
  return sources::format_utc(sources::add_seconds(c.epoch, t_s), 3);
}

// The calendar's day (1-based) that holds t_s; the span's end belongs to its last day.
std::size_t day_of(double t_s, std::size_t days) {
  const auto day = static_cast<std::size_t>(std::floor(t_s / day_s)) + 1;
  return std::min(day, days);
}

std::size_t day_count(const blinding_calendar& c) {
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(c.span_s / day_s)));
}

std::string intervals_csv(const blinding_calendar& c,
                          const std::vector<calendar_interval>& intervals) {
  std::string out = "head,body,start_utc,end_utc,start_s,end_s,duration_s,day,start_orbit_deg\n";
  const std::size_t days = day_count(c);
  for (const calendar_interval& i : intervals)
    out += head_name(i.head) + "," + calendar_body_name(i.body) + "," + utc_at(c, i.start_s) + "," +
           utc_at(c, i.end_s) + "," + printed("%.3f", i.start_s) + "," + printed("%.3f", i.end_s) +
           "," + printed("%.3f", i.end_s - i.start_s) + "," +
           std::to_string(day_of(i.start_s, days)) + "," + printed("%.2f", i.start_orbit_deg) +
           "\n";
  return out;
}

// Per head, body and day: seconds on the cone, seconds lost, events lost (by start day).
struct day_totals {
  double on_cone_s = 0, lost_s = 0;
  std::size_t lost_events = 0;
};

class day_table {
 public:
  explicit day_table(const blinding_calendar& c)
      : days_(day_count(c)), totals_(c.heads * calendar_bodies * days_) {
    for (const calendar_interval& i : c.on_cone)
      spread(i, [](day_totals& d, double s) { d.on_cone_s += s; });
    for (const calendar_interval& i : c.lost) {
      spread(i, [](day_totals& d, double s) { d.lost_s += s; });
      ++at(i.head, i.body, day_of(i.start_s, days_)).lost_events;
    }
  }
  std::size_t days() const noexcept { return days_; }
  const day_totals& at(std::size_t head, std::size_t body, std::size_t day) const {
    return totals_[(head * calendar_bodies + body) * days_ + day - 1];
  }

 private:
  day_totals& at(std::size_t head, std::size_t body, std::size_t day) {
    return totals_[(head * calendar_bodies + body) * days_ + day - 1];
  }
  // Adds the interval's seconds in each day it covers.
  template <class Add>
  void spread(const calendar_interval& i, Add add) {
    for (std::size_t day = day_of(i.start_s, days_); day <= day_of(i.end_s, days_); ++day) {
      const double from = std::max(i.start_s, static_cast<double>(day - 1) * day_s);
      const double to =
          day == days_ ? i.end_s : std::min(i.end_s, static_cast<double>(day) * day_s);
      if (to > from) add(at(i.head, i.body, day), to - from);
    }
  }
  std::size_t days_;
  std::vector<day_totals> totals_;
};

std::string days_csv(const blinding_calendar& c, const day_table& table) {
  std::string out = "head,body,day,date,on_cone_s,lost_s,lost_events\n";
  for (std::size_t h = 0; h < c.heads; ++h)
    for (std::size_t b = 0; b < calendar_bodies; ++b)
      for (std::size_t day = 1; day <= table.days(); ++day) {
        const day_totals& d = table.at(h, b, day);
        out += head_name(h) + "," + calendar_body_name(b) + "," + std::to_string(day) + "," +
               utc_at(c, static_cast<double>(day - 1) * day_s).substr(0, 10) + "," +
               printed("%.3f", d.on_cone_s) + "," + printed("%.3f", d.lost_s) + "," +
               std::to_string(d.lost_events) + "\n";
      }
  return out;
}

// Days with any time of one kind: their count, the first and the last ("" when none).
struct day_span {
  std::size_t count = 0, first = 0, last = 0;
  void add(std::size_t day) {
    if (count++ == 0) first = day;
    last = day;
  }
  std::string text() const {
    const std::string none;
    return std::to_string(count) + "," + (count ? std::to_string(first) : none) + "," +
           (count ? std::to_string(last) : none);
  }
};

std::string seasons_csv(const blinding_calendar& c, const day_table& table) {
  std::string out =
      "head,body,on_cone_days,first_on_cone_day,last_on_cone_day,lost_days,first_lost_day,"
      "last_lost_day,lost_events,lost_s,lost_hours,shortest_event_s,longest_event_s\n";
  for (std::size_t h = 0; h < c.heads; ++h)
    for (std::size_t b = 0; b < calendar_bodies; ++b) {
      day_span on, lost;
      for (std::size_t day = 1; day <= table.days(); ++day) {
        if (table.at(h, b, day).on_cone_s > 0) on.add(day);
        if (table.at(h, b, day).lost_s > 0) lost.add(day);
      }
      std::size_t events = 0;
      double total = 0, shortest = INFINITY, longest = 0;
      for (const calendar_interval& i : c.lost) {
        if (i.head != h || i.body != b) continue;
        ++events;
        total += i.end_s - i.start_s;
        shortest = std::min(shortest, i.end_s - i.start_s);
        longest = std::max(longest, i.end_s - i.start_s);
      }
      out += head_name(h) + "," + calendar_body_name(b) + "," + on.text() + "," + lost.text() +
             "," + std::to_string(events) + "," + printed("%.3f", total) + "," +
             printed("%.4f", total / 3600) + "," +
             (events ? printed("%.3f", shortest) + "," + printed("%.3f", longest) : ",") + "\n";
    }
  return out;
}

}  // namespace

std::vector<calendar_file> calendar_csv_files(const blinding_calendar& calendar) {
  const day_table table(calendar);
  return {{"lost.csv", intervals_csv(calendar, calendar.lost)},
          {"on-cone.csv", intervals_csv(calendar, calendar.on_cone)},
          {"days.csv", days_csv(calendar, table)},
          {"seasons.csv", seasons_csv(calendar, table)}};
}

}  // namespace conescan::scene
