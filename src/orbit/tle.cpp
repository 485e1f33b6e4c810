// NORAD two-line element sets: the column table, the checks and the reader (tle.hpp).
#include "orbit/tle.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>

#include "orbit/catalogue.hpp"
#include "text/calendar_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::orbit {
namespace {

constexpr std::size_t tle_line_columns = 69;
constexpr std::size_t checksum_column = 69;
constexpr std::size_t longest_line = 256;  // a name line or a TLE line with trailing blanks

/// One field of a TLE line: its columns, 1-based and inclusive as the format's tables number
/// them, and its name for the messages.
struct field {
  std::size_t first, last;
  const char* name;
};

// The columns of Spacetrack Report #3 (Hoots & Roehrich 1980), §12, as CelesTrak's "NORAD
// Two-Line Element Set Format" tabulates them.
namespace line1 {
constexpr field satellite{3, 7, "satellite number"};
constexpr field classification{8, 8, "classification"};
constexpr field designator{10, 17, "international designator"};
constexpr field epoch_year{19, 20, "epoch year"};
constexpr field epoch_day{21, 32, "epoch day of the year"};
constexpr field ndot{34, 43, "first derivative of the mean motion / 2"};
constexpr field nddot{45, 52, "second derivative of the mean motion / 6"};
constexpr field bstar{54, 61, "B* drag term"};
constexpr field ephemeris_type{63, 63, "ephemeris type"};
constexpr field element_set{65, 68, "element set number"};
constexpr std::size_t blank_columns[] = {2, 9, 18, 33, 44, 53, 62, 64};
}  // namespace line1

namespace line2 {
constexpr field satellite{3, 7, "satellite number"};
constexpr field inclination{9, 16, "inclination (deg)"};
constexpr field raan{18, 25, "right ascension of the ascending node (deg)"};
constexpr field eccentricity{27, 33, "eccentricity (decimal point assumed)"};
constexpr field perigee{35, 42, "argument of perigee (deg)"};
constexpr field anomaly{44, 51, "mean anomaly (deg)"};
constexpr field motion{53, 63, "mean motion (rev/day)"};
constexpr field revolution{64, 68, "revolution number at epoch"};
constexpr std::size_t blank_columns[] = {2, 8, 17, 26, 34, 43, 52};
}  // namespace line2

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

std::string_view without_trailing_blanks(std::string_view text) {
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
    text.remove_suffix(1);
  return text;
}

/// "A line that is card `card` of a set": begins with the digit and a blank, or is the digit
/// alone (a truncated line, refused later for its length).
bool is_card(std::string_view text, char card) {
  return !text.empty() && text[0] == card && (text.size() == 1 || text[1] == ' ');
}

/// Reads the fields of one TLE line (1 or 2). The first failure is kept and every later read
/// returns 0, so a caller reads all its fields and then asks for the error once.
class field_reader {
 public:
  field_reader(std::string_view text, int card) : text_(text), card_(card) {}

  std::optional<std::string> error() const { return error_; }
  void fail(const std::string& message) {
    if (!error_) error_ = "line " + std::to_string(card_) + ", " + message;
  }
  void fail(const field& f, const std::string& message) { fail(where(f) + ": " + message); }

  std::string_view columns(const field& f) const {
    return text_.substr(f.first - 1, f.last - f.first + 1);
  }

  /// [blanks][+|-]digits[.digits] or [blanks][+|-].digits: a decimal number.
  double decimal(const field& f) {
    std::string_view s = columns(f);
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    double sign = 1;
    if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
      if (s.front() == '-') sign = -1;
      s.remove_prefix(1);
    }
    std::size_t digits = 0, points = 0, others = 0;
    for (char c : s) ++(is_digit(c) ? digits : c == '.' ? points : others);
    double value = 0;
    if (digits == 0 || points > 1 || others > 0 ||
        std::from_chars(s.data(), s.data() + s.size(), value).ptr != s.data() + s.size()) {
      fail(f, quote(columns(f)) + " is not a decimal number");
      return 0;
    }
    return sign * value;
  }

  /// [blanks]digits; all blank reads as 0 where the format allows it.
  long integer(const field& f, bool blank_is_zero) {
    std::string_view s = columns(f);
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    if (s.empty() && blank_is_zero) return 0;
    long value = 0;
    for (char c : s) {
      if (!is_digit(c)) {
        fail(f, quote(columns(f)) + " is not a whole number");
        return 0;
      }
      value = 10 * value + (c - '0');
    }
    if (s.empty()) fail(f, "is blank, a number is required");
    return value;
  }

  /// [ |+|-]ddddd(+|-)d: +-0.ddddd x 10^(+-d), the point and the 'E' assumed. Read as the
  /// reference code does, "0.ddddd" times pow(10, exponent), for bit-identical values.
  double exponential(const field& f) {
    const std::string_view s = columns(f);  // 8 columns
    const bool mantissa_ok = s[0] == ' ' || s[0] == '+' || s[0] == '-';
    bool digits_ok = true;
    for (std::size_t i = 1; i <= 5; ++i) digits_ok = digits_ok && is_digit(s[i]);
    const bool exponent_ok = (s[6] == '+' || s[6] == '-') && is_digit(s[7]);
    if (!mantissa_ok || !digits_ok || !exponent_ok) {
      fail(f, quote(s) + " is not of the form ' 12345-6' (+-0.12345 x 10^-6)");
      return 0;
    }
    const std::string text = "0." + std::string(s.substr(1, 5));
    double mantissa = 0;
    std::from_chars(text.data(), text.data() + text.size(), mantissa);
    const int exponent = (s[6] == '-' ? -1 : 1) * (s[7] - '0');
    return (s[0] == '-' ? -mantissa : mantissa) * std::pow(10.0, exponent);
  }

  /// ddddddd: 0.ddddddd, the point assumed (the eccentricity).
  double assumed_point(const field& f) {
    const std::string_view s = columns(f);
    for (char c : s) {
      if (!is_digit(c)) {
        fail(f, quote(s) + " is not " + std::to_string(s.size()) +
                    " digits (a leading decimal point is assumed)");
        return 0;
      }
    }
    const std::string text = "0." + std::string(s);
    double value = 0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
  }

  /// A decimal number in [low, high].
  double decimal_in(const field& f, double low, double high) {
    const double value = decimal(f);
    if (!(value >= low && value <= high))
      fail(f, value_text(f) + " is outside [" + number(low) + ", " + number(high) + "]");
    return value;
  }

  /// The field's text without its leading blanks, as a message quotes a value.
  std::string value_text(const field& f) const {
    std::string_view s = columns(f);
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    return std::string(s);
  }

  std::string where(const field& f) const {
    const std::string cols =
        f.first == f.last ? "column " + std::to_string(f.first)
                          : "columns " + std::to_string(f.first) + "-" + std::to_string(f.last);
    return cols + " (" + f.name + ")";
  }

 private:
  static std::string number(double x) { return std::to_string(static_cast<long>(x)); }

  std::string_view text_;
  int card_;
  std::optional<std::string> error_;
};

/// Length, characters, the blank separator columns and the first two columns of a line.
/// Returns the first violation.
template <std::size_t n>
std::optional<std::string> check_layout(std::string_view text, int card,
                                        const std::size_t (&blanks)[n]) {
  const std::string which = "line " + std::to_string(card);
  if (text.size() != tle_line_columns)
    return which + " is " + std::to_string(text.size()) + " characters long, a TLE line has " +
           std::to_string(tle_line_columns);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x20 || byte > 0x7e)
      return which + ", column " + std::to_string(i + 1) +
             " holds a control or non-ASCII character (byte " + std::to_string(byte) + ")";
  }
  if (!is_card(text, static_cast<char>('0' + card)))
    return which + " must begin with '" + std::to_string(card) + " ', it begins with " +
           quote(text.substr(0, 2));
  for (std::size_t column : blanks)
    if (text[column - 1] != ' ')
      return which + ", column " + std::to_string(column) + " must be blank, it holds " +
             quote(text.substr(column - 1, 1));
  return std::nullopt;
}

std::optional<std::string> check_checksum(std::string_view text, int card) {
  const char written = text[checksum_column - 1];
  const std::string which = "line " + std::to_string(card);
  if (!is_digit(written))
    return which + ", column 69 (checksum) holds " + quote(std::string(1, written)) +
           ", not a digit";
  const int sum = tle_checksum(text);
  if (sum != written - '0')
    return which + ": checksum is " + std::to_string(sum) + ", the line says " +
           std::string(1, written);
  return std::nullopt;
}

/// Columns 3-7: digits, or alpha-5 (a letter other than I and O, then four digits; A = 10).
long satellite_number(field_reader& r, const field& f) {
  const std::string_view s = r.columns(f);
  const char lead = s[0];
  if (lead >= 'A' && lead <= 'Z' && lead != 'I' && lead != 'O') {
    const long letter = 10 + (lead - 'A') - (lead > 'I') - (lead > 'O');
    field digits{f.first + 1, f.last, f.name};
    return letter * 10000 + r.integer(digits, false);
  }
  return r.integer(f, false);
}

/// Columns 19-32: a two-digit year (57-99 are 19xx, 00-56 are 20xx: the convention of the
/// reference code and of NORAD for 1957-2056) and the day of the year with its fraction.
tle_epoch epoch(field_reader& r) {
  tle_epoch e{0, 0, 0};
  const std::string_view yy = r.columns(line1::epoch_year);
  if (!is_digit(yy[0]) || !is_digit(yy[1])) {
    r.fail(line1::epoch_year, quote(yy) + " is not two digits");
    return e;
  }
  const int two_digits = 10 * (yy[0] - '0') + (yy[1] - '0');
  e.year = two_digits < 57 ? 2000 + two_digits : 1900 + two_digits;
  const double day = r.decimal(line1::epoch_day);
  const int days_in_year = text::is_leap_year(e.year) ? 366 : 365;
  if (!(day >= 1 && day < days_in_year + 1)) {
    r.fail(line1::epoch_day, r.value_text(line1::epoch_day) + " is outside [1, " +
                                 std::to_string(days_in_year + 1) + ") for " +
                                 std::to_string(e.year));
    return e;
  }
  // The fraction from its own digits ("0.78495062"), rounded once, not day - floor(day).
  e.day_of_year = static_cast<int>(day);
  std::string_view digits = r.columns(line1::epoch_day);
  const std::size_t point = digits.find('.');
  if (point != std::string_view::npos) {
    const std::string text = "0" + std::string(digits.substr(point));
    std::from_chars(text.data(), text.data() + text.size(), e.fraction_of_day);
  }
  return e;
}

std::optional<std::string> read_line1(std::string_view text, tle& set) {
  if (auto bad = check_layout(text, 1, line1::blank_columns)) return bad;
  field_reader r(text, 1);
  set.catalog_number = std::string(r.columns(line1::satellite));
  set.satellite_number = satellite_number(r, line1::satellite);
  const char c = text[line1::classification.first - 1];
  if (c != 'U' && c != 'C' && c != 'S' && c != ' ')
    r.fail(line1::classification, quote(std::string(1, c)) + " is not U, C, S or blank");
  set.classification = c == ' ' ? 'U' : c;
  set.international_designator = std::string(without_trailing_blanks(r.columns(line1::designator)));
  set.epoch = epoch(r);
  set.mean_motion_dot_rev_day2 = r.decimal(line1::ndot);
  set.mean_motion_ddot_rev_day3 = r.exponential(line1::nddot);
  set.bstar_per_earth_radius = r.exponential(line1::bstar);
  set.ephemeris_type = static_cast<int>(r.integer(line1::ephemeris_type, true));
  set.element_set_number = static_cast<int>(r.integer(line1::element_set, true));
  if (auto bad = r.error()) return bad;
  return check_checksum(text, 1);
}

std::optional<std::string> read_line2(std::string_view text, tle& set) {
  if (auto bad = check_layout(text, 2, line2::blank_columns)) return bad;
  field_reader r(text, 2);
  const std::string number(r.columns(line2::satellite));
  if (number != set.catalog_number)
    r.fail(r.where(line2::satellite) + ": " + quote(number) + " differs from line 1's " +
           quote(set.catalog_number));
  set.inclination_deg = r.decimal_in(line2::inclination, 0, 180);
  set.raan_deg = r.decimal_in(line2::raan, 0, 360);
  set.eccentricity = r.assumed_point(line2::eccentricity);
  set.argument_of_perigee_deg = r.decimal_in(line2::perigee, 0, 360);
  set.mean_anomaly_deg = r.decimal_in(line2::anomaly, 0, 360);
  set.mean_motion_rev_day = r.decimal(line2::motion);
  if (!r.error() && !(set.mean_motion_rev_day > 0))
    r.fail(line2::motion, r.value_text(line2::motion) + " is not positive");
  set.revolution_number = r.integer(line2::revolution, true);
  if (auto bad = r.error()) return bad;
  return check_checksum(text, 2);
}

/// Lines 1 and 2 at lines `number1`, `number2` of the source.
checked<tle> parse_lines(std::string_view text1, std::size_t number1, std::string_view text2,
                         std::size_t number2, std::string_view source) {
  tle set{};
  if (auto bad = read_line1(without_trailing_blanks(text1), set))
    return diagnostic::in_file(std::string(source), number1, *bad);
  if (auto bad = read_line2(without_trailing_blanks(text2), set))
    return diagnostic::in_file(std::string(source), number2, *bad);
  set.line_number = number1;
  return set;
}

/// Reads a source set by set: numbered lines, blank ones skipped, each at most longest_line
/// characters (checked while reading, so memory stays bounded whatever the input).
class set_reader {
 public:
  set_reader(std::istream& input, std::string_view source) : input_(input), source_(source) {}

  /// The next set, or nullopt at the end of the source or at an error (then outcome() says it).
  std::optional<tle> next();
  const checked<void>& outcome() const { return outcome_; }

 private:
  struct numbered_line {
    std::string text;
    std::size_t number = 0;
  };

  bool next_line(numbered_line& out);
  std::optional<tle> fail(std::size_t line, std::string message) {
    outcome_ = diagnostic::in_file(source_, line, std::move(message));
    return std::nullopt;
  }

  std::istream& input_;
  std::string source_;
  std::size_t line_number_ = 0;
  checked<void> outcome_;
};

/// The next non-blank line without its trailing blanks; false at the end or at an error.
bool set_reader::next_line(numbered_line& out) {
  std::streambuf* buffer = input_.rdbuf();
  for (;;) {
    std::string text;
    int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) return false;
    ++line_number_;
    for (; c != std::char_traits<char>::eof() && c != '\n'; c = buffer->sbumpc()) {
      if (text.size() == longest_line) {
        fail(line_number_, "the line is longer than " + std::to_string(longest_line) +
                               " characters: not an element set");
        return false;
      }
      text.push_back(static_cast<char>(c));
    }
    text.resize(without_trailing_blanks(text).size());
    if (line_number_ == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 BOM
    if (!text.empty()) {
      out = {std::move(text), line_number_};
      return true;
    }
  }
}

std::optional<tle> set_reader::next() {
  numbered_line first, second;
  if (!next_line(first)) return std::nullopt;
  std::string name;
  const std::size_t start = first.number;
  if (is_card(first.text, '2'))
    return fail(first.number, "line 2 of an element set without a line 1 before it");
  if (!is_card(first.text, '1')) {  // a name line
    for (char c : first.text)
      if (static_cast<unsigned char>(c) < 0x20)
        return fail(first.number, "the name line " + quote(first.text) +
                                      " holds a control character: not an element set");
    name = first.text.rfind("0 ", 0) == 0 ? first.text.substr(2) : first.text;
    if (!next_line(first)) {
      if (!outcome_.ok()) return std::nullopt;
      return fail(start, "the name line " + quote(name) + " is not followed by an element set");
    }
    if (!is_card(first.text, '1'))
      return fail(first.number, "expected line 1 of the element set named on line " +
                                    std::to_string(start) + ", found " + quote(first.text));
  }
  if (!next_line(second)) {
    if (!outcome_.ok()) return std::nullopt;
    return fail(first.number, "line 1 of an element set is not followed by its line 2");
  }
  if (!is_card(second.text, '2'))
    return fail(second.number, "expected line 2 of the element set begun on line " +
                                   std::to_string(first.number) + ", found " + quote(second.text));
  checked<tle> parsed = parse_lines(first.text, first.number, second.text, second.number, source_);
  if (!parsed.ok()) {
    outcome_ = std::move(parsed).error();
    return std::nullopt;
  }
  tle set = std::move(parsed).value();
  set.name = std::move(name);
  set.line_number = start;
  return set;
}

/// Opens `path`, or says why it cannot (text::file_error's wording).
checked<void> open(const std::filesystem::path& path, std::ifstream& file) {
  return text::open_for_reading(path.string(), file);
}

}  // namespace

int tle_checksum(std::string_view line) noexcept {
  int sum = 0;
  for (std::size_t i = 0; i < line.size() && i < checksum_column - 1; ++i) {
    if (is_digit(line[i])) sum += line[i] - '0';
    if (line[i] == '-') sum += 1;
  }
  return sum % 10;
}

std::optional<long> catalog_number_value(std::string_view columns) noexcept {
  if (columns.size() != 5) return std::nullopt;
  long digits = 0;
  for (char c : columns.substr(1)) {
    if (!is_digit(c)) return std::nullopt;
    digits = 10 * digits + (c - '0');
  }
  const char lead = columns[0];
  if (is_digit(lead)) return (lead - '0') * 10000L + digits;
  if (lead >= 'A' && lead <= 'Z' && lead != 'I' && lead != 'O')
    return (10L + (lead - 'A') - (lead > 'I') - (lead > 'O')) * 10000L + digits;
  return std::nullopt;
}

double jd_day_start(const tle_epoch& epoch) noexcept {
  // Julian day number of 1 January (Fliegel & Van Flandern 1968, Gregorian calendar), whose
  // noon it numbers: the day starts half a day earlier.
  const long y = epoch.year + 4799;  // 1 January: a = 1, y + 4800 - a, m + 12 a - 3 = 10
  const long jdn_jan1 = 1 + (153 * 10 + 2) / 5 + 365 * y + y / 4 - y / 100 + y / 400 - 32045;
  return static_cast<double>(jdn_jan1 + epoch.day_of_year - 1) - 0.5;
}

utc_calendar calendar(const tle_epoch& epoch) noexcept {
  utc_calendar c{epoch.year, 1, epoch.day_of_year, 0, 0, 0};
  for (int m = 1; m < 12; ++m) {
    const int days = text::days_in_month(epoch.year, m);
    if (c.day <= days) break;
    c.day -= days;
    ++c.month;
  }
  double seconds = epoch.fraction_of_day * 86400;
  c.hour = static_cast<int>(seconds / 3600);
  seconds -= 3600.0 * c.hour;
  c.minute = static_cast<int>(seconds / 60);
  c.second = seconds - 60.0 * c.minute;
  return c;
}

double minutes_since_epoch(const tle_epoch& epoch, double jd_whole, double jd_fraction) noexcept {
  // As Vallado's sgp4(jd, fr): the large parts cancel first, each difference exact or nearly.
  return (jd_whole - jd_day_start(epoch)) * 1440.0 + (jd_fraction - epoch.fraction_of_day) * 1440.0;
}

checked<tle> parse_tle(std::string_view line1, std::string_view line2, std::string_view source,
                       std::size_t line1_number) {
  return parse_lines(line1, line1_number, line2, line1_number + 1, source);
}

checked<std::vector<tle>> read_tle_sets(std::istream& input, std::string_view source) {
  set_reader reader(input, source);
  std::vector<tle> sets;
  while (std::optional<tle> set = reader.next()) sets.push_back(std::move(*set));
  if (!reader.outcome().ok()) return reader.outcome().error();
  if (input.bad()) return text::file_error(std::string(source), "cannot read", EIO);
  if (sets.empty()) return diagnostic::in_file(std::string(source), 0, "holds no element set");
  return sets;
}

checked<std::vector<tle>> read_tle_sets(const std::filesystem::path& path) {
  std::ifstream file;
  if (checked<void> opened = open(path, file); !opened.ok()) return opened.error();
  return read_tle_sets(file, path.string());
}

checked<tle> read_tle(std::istream& input, std::string_view source, tle_selection selection) {
  if (selection == tle_selection::only_one) return read_tle_object(input, source, "");
  set_reader reader(input, source);
  std::optional<tle> set = reader.next();
  if (!reader.outcome().ok()) return reader.outcome().error();
  if (!set) return diagnostic::in_file(std::string(source), 0, "holds no element set");
  return std::move(*set);
}

checked<tle> read_tle(const std::filesystem::path& path, tle_selection selection) {
  std::ifstream file;
  if (checked<void> opened = open(path, file); !opened.ok()) return opened.error();
  return read_tle(file, path.string(), selection);
}

checked<tle> read_tle_object(std::istream& input, std::string_view source,
                             std::string_view object) {
  set_reader reader(input, source);
  catalogue_chooser chooser(object);
  std::optional<tle> kept;
  while (std::optional<tle> set = reader.next()) {
    const std::string place = "line " + std::to_string(set->line_number);
    const catalogue_chooser::step step =
        chooser.offer(*set, place, diagnostic::in_file(std::string(source), set->line_number, ""));
    if (step == catalogue_chooser::step::keep) kept = std::move(*set);
    if (step == catalogue_chooser::step::stop) break;
  }
  if (!reader.outcome().ok()) return reader.outcome().error();
  if (input.bad()) return text::file_error(std::string(source), "cannot read", EIO);
  if (chooser.offered() == 0)
    return diagnostic::in_file(std::string(source), 0, "holds no element set");
  if (checked<void> verdict = chooser.verdict(std::string(source)); !verdict.ok())
    return verdict.error();
  return std::move(*kept);
}

checked<tle> read_tle_object(const std::filesystem::path& path, std::string_view object) {
  std::ifstream file;
  if (checked<void> opened = open(path, file); !opened.ok()) return opened.error();
  return read_tle_object(file, path.string(), object);
}

}  // namespace conescan::orbit
