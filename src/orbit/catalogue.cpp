// Choosing one element set from a catalogue (catalogue.hpp).
#include "orbit/catalogue.hpp"

#include <algorithm>
#include <utility>

#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::orbit {

namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_letter(char c) {
  return c >= 'A' && c <= 'Z';
}
bool all_of(std::string_view text, bool (*test)(char)) {
  return !text.empty() && std::all_of(text.begin(), text.end(), test);
}

/// A designator's piece: 1 to 3 letters.
bool is_piece(std::string_view text) {
  return text.size() <= 3 && all_of(text, is_letter);
}

/// The catalogue number VALUE names: 1 to 9 digits (as NORAD_CAT_ID), or alpha-5.
std::optional<long> number_named(std::string_view upper) {
  if (upper.size() <= 9 && all_of(upper, is_digit)) {
    long value = 0;
    for (char c : upper) value = 10 * value + (c - '0');
    return value;
  }
  return catalog_number_value(upper);
}

/// Levenshtein distance of the first `cap` bytes of each text: how near a key is to a selector
/// that matched none (a bounded cost per set, whatever a name's length).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  constexpr std::size_t cap = 64;
  a = a.substr(0, cap);
  b = b.substr(0, cap);
  std::size_t row[cap + 1];
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({above + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// How near `key` (upper case) is to the selector: a key holding it ranks before any other
/// (by its extra length, its edit distance to the selector), the others by edit distance.
std::size_t key_nearness(std::string_view key, std::string_view selector) {
  constexpr std::size_t apart = 1000;
  if (key.empty()) return 2 * apart;
  if (key.find(selector) != std::string_view::npos) return key.size() - selector.size();
  return apart + edit_distance(key, selector);
}

/// "line 4 'ISS (ZARYA)' (NORAD 25544, 1998-067A)": a set as a message lists it.
std::string described(const tle& set, std::string_view place) {
  std::string out(place);
  if (!set.name.empty()) out += " " + quote(set.name);
  out += " (NORAD " + (set.catalog_number.empty() ? std::string("none") : set.catalog_number);
  // A designator of another form (OMM's OBJECT_ID as written) is shown as any text from a file.
  const std::string& d = set.international_designator;
  if (!d.empty()) out += ", " + (tle_form_designator(d) ? cospar_designator(d) : quote(d));
  return out + ")";
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : "; ") + item;
  return out;
}

constexpr const char* keys_named =
    "its NORAD catalogue number, international designator (1998-067A) or name";

}  // namespace

std::optional<std::string> tle_form_designator(std::string_view text) {
  const std::string upper = text::to_upper(text::trim_blanks(text));
  const std::string_view d = upper;
  // COSPAR: YYYY-NNNP[PP]
  if (d.size() >= 9 && d[4] == '-' && all_of(d.substr(0, 4), is_digit) &&
      all_of(d.substr(5, 3), is_digit) && is_piece(d.substr(8)))
    return std::string(d.substr(2, 2)) + std::string(d.substr(5));
  // The TLE's columns 10-17: YYNNNP[PP]
  if (d.size() >= 6 && all_of(d.substr(0, 5), is_digit) && is_piece(d.substr(5))) return upper;
  return std::nullopt;
}

std::string cospar_designator(std::string_view designator) {
  if (!(designator.size() >= 6 && all_of(designator.substr(0, 5), is_digit) &&
        is_piece(designator.substr(5))))
    return std::string(designator);
  const int yy = (designator[0] - '0') * 10 + (designator[1] - '0');
  return std::to_string(yy >= 57 ? 1900 + yy : 2000 + yy) + "-" + std::string(designator.substr(2));
}

catalogue_chooser::catalogue_chooser(std::string_view object)
    : object_(text::trim_blanks(object)), upper_(text::to_upper(object_)) {
  if (!object_.empty()) {
    number_ = number_named(upper_);
    designator_ = tle_form_designator(upper_);
  }
}

bool catalogue_chooser::matches(const tle& set) const {
  if (number_ && !set.catalog_number.empty() && set.satellite_number == *number_) return true;
  if (designator_ && tle_form_designator(set.international_designator) == designator_) return true;
  return !set.name.empty() && text::to_upper(text::trim_blanks(set.name)) == upper_;
}

std::size_t catalogue_chooser::nearness(const tle& set) const {
  const std::string designator = text::to_upper(cospar_designator(set.international_designator));
  return std::min({key_nearness(text::to_upper(set.name), upper_),
                   key_nearness(set.catalog_number, upper_), key_nearness(designator, upper_),
                   key_nearness(text::to_upper(set.international_designator), upper_)});
}

void catalogue_chooser::note_nearest(const tle& set, std::string_view place) {
  const std::size_t score = nearness(set);
  if (nearest_.size() == max_listed && score >= nearest_.back().score) return;
  // After the last of equal score: the file's order among equals.
  const auto at = std::upper_bound(nearest_.begin(), nearest_.end(), score,
                                   [](std::size_t s, const listed& l) { return s < l.score; });
  nearest_.insert(at, listed{described(set, place), score});
  if (nearest_.size() > max_listed) nearest_.pop_back();
}

catalogue_chooser::step catalogue_chooser::offer(const tle& set, std::string_view place,
                                                 const diagnostic& at) {
  ++offered_;
  if (!selecting()) {
    if (offered_ == 2) second_ = at;
    listed_.push_back({described(set, place)});
    if (offered_ == 1) return step::keep;
    return offered_ == max_listed ? step::stop : step::skip;
  }
  if (!matches(set)) {
    if (matched_ == 0) note_nearest(set, place);
    return step::skip;
  }
  ++matched_;
  if (matched_ == 1) first_number_ = set.satellite_number;
  one_object_ = one_object_ && set.satellite_number == first_number_;
  if (listed_.size() < max_listed) listed_.push_back({described(set, place)});
  return matched_ == 1 ? step::keep : step::skip;
}

checked<void> catalogue_chooser::verdict(const std::string& source) const {
  std::vector<std::string> items;
  for (const listed& l : listed_) items.push_back(l.text);
  if (!selecting()) {
    if (offered_ <= 1) return success();
    diagnostic e = *second_;
    e.message +=
        "a second element set begins here: the file is a catalogue of several; choose "
        "one with --object and " +
        std::string(keys_named) + ": " + joined(items) + (offered_ == max_listed ? "; ..." : "");
    return e;
  }
  if (matched_ == 1) return success();
  diagnostic e{"object", "", origin::file_line(source, 0)};
  if (matched_ == 0) {
    std::vector<std::string> near;
    for (const listed& l : nearest_) near.push_back(l.text);
    e.message = quote(object_) +
                " is no element set's NORAD catalogue number, international "
                "designator or name (" +
                std::to_string(offered_) + (offered_ == 1 ? " set" : " sets") +
                " read); the nearest: " + joined(near);
    return e;
  }
  e.message =
      quote(object_) + " matches " + std::to_string(matched_) + " element sets: " + joined(items) +
      (matched_ > items.size() ? "; and " + std::to_string(matched_ - items.size()) + " more"
                               : "") +
      (one_object_ ? "; they are one object's sets (a history of epochs?): keep the one meant in "
                     "a file of its own"
                   : "; give a key only one of them has (its NORAD catalogue number)");
  return e;
}

}  // namespace conescan::orbit
