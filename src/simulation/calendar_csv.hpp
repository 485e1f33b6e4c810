// The blinding calendar as CSV tables (conescan-sim --calendar DIR; docs/SUN_MOON.md): the text of
// each file, from blinding_calendar.hpp's intervals. Heads are named h1, h2, ... as in the rows'
// columns, bodies sun and moon; times in s from the epoch and as UTC; day K of the calendar is
// [(K - 1) 86400, K 86400) s from the epoch (the UTC date it starts on in `date`).
//
//   lost.csv      head,body,start_utc,end_utc,start_s,end_s,duration_s,day,start_orbit_deg
//                 every interval in which the head's crossings are lost to the body (its
//                 status sun or moon), by start time; start_orbit_deg the argument of latitude
//   on-cone.csv   the same columns: every interval with the body on the head's cone
//   days.csv      head,body,day,date,on_cone_s,lost_s,lost_events: every head, body and day
//                 (an interval across midnight counts in both days; events by their start day)
//   seasons.csv   head,body,on_cone_days,first_on_cone_day,last_on_cone_day,lost_days,
//                 first_lost_day,last_lost_day,lost_events,lost_s,lost_hours,shortest_event_s,
//                 longest_event_s: per head and body (days 0 and empty fields when none)
#pragma once

#include <string>
#include <vector>

#include "simulation/blinding_calendar.hpp"

namespace conescan::scene {

struct calendar_file {
  std::string name;  ///< lost.csv, on-cone.csv, days.csv, seasons.csv
  std::string text;
};

/// The four tables of `calendar`, in the order above.
std::vector<calendar_file> calendar_csv_files(const blinding_calendar& calendar);

}  // namespace conescan::scene
