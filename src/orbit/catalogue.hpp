// Choosing one element set from a file of many: a catalogue, as CelesTrak serves its GP data (a
// three-line TLE file, OMM JSON, CSV, XML or KVN of every active satellite), read one set at a
// time (MODEL §10: one orbit source, one set).
//
// The object selector (--object VALUE) names a set by any of three keys, compared exactly:
//  - its NORAD catalogue number: VALUE of 1 to 9 digits (leading zeros ignored: 5 = 00005) or
//    an alpha-5 number (A1234 = 101234), equal to the set's number;
//  - its international designator (COSPAR id): 1998-067A or the TLE's 98067A, any case, equal to
//    the set's designator in either form;
//  - its name: VALUE equal to the set's name (TLE line 0, OMM OBJECT_NAME), blanks around it and
//    case ignored.
// A set matches when any key does. Exactly one set of the file must match; every set is read and
// checked (a malformed set is refused wherever it is, before or after the match: its name cannot
// be trusted, and it may be the one meant), so that a second match is found. Without a selector
// the file must hold one set, as before catalogues were read: a second set is refused where it
// begins, naming the first few sets and saying to choose with --object.
//
// Memory: the chooser keeps the kept set's index, at most max_listed matches and max_listed
// nearest names for the message, whatever the catalogue's length.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/tle.hpp"
#include "text/diagnostic.hpp"

namespace conescan::orbit {

/// The TLE form (YYNNNPPP) of a designator written as COSPAR's YYYY-NNNPPP or as the TLE's
/// YYNNNPPP (piece: 1 to 3 letters; any case; blanks around it ignored), or nullopt for other text.
std::optional<std::string> tle_form_designator(std::string_view text);

/// A set's designator as a message shows it: COSPAR's 1998-067A for a TLE form 98067A (years
/// 57-99 are 19xx), else as held.
std::string cospar_designator(std::string_view designator);

/// The sets of a file offered one at a time, in order; which one to keep, and the verdict.
class catalogue_chooser {
 public:
  /// Matches and nearest names listed in a message at most.
  static constexpr std::size_t max_listed = 5;

  /// `object` "": the file must hold one set; else the selector (blanks around it ignored).
  explicit catalogue_chooser(std::string_view object);

  enum class step {
    keep,  ///< the set to take (the first match, or the first set without a selector): keep it
    skip,  ///< read on
    stop   ///< the verdict is known (a second set without a selector): stop reading
  };

  /// The file's next set; `place` says where it is in messages ("line 4", "[2]", "ndm/omm[3]")
  /// and `at` is an error at its place without a message (its file, line and column).
  step offer(const tle& set, std::string_view place, const diagnostic& at);

  /// After the last set offered (or a stop): success when the kept set is the one, else the
  /// refusal (a file of no set is the readers' own error). `source` names the file.
  checked<void> verdict(const std::string& source) const;

  bool selecting() const noexcept { return !object_.empty(); }
  std::size_t offered() const noexcept { return offered_; }

 private:
  struct listed {
    std::string text;       ///< "line 4 'ISS (ZARYA)' (25544, 1998-067A)"
    std::size_t score = 0;  ///< the nearness of its keys to the selector (0: nearest)
  };
  bool matches(const tle& set) const;
  std::size_t nearness(const tle& set) const;
  void note_nearest(const tle& set, std::string_view place);

  std::string object_;  ///< as given, blanks around it removed
  std::string upper_;   ///< the same in upper case (names and designators ignore case)
  std::optional<long> number_;
  std::optional<std::string> designator_;
  std::size_t offered_ = 0;
  std::size_t matched_ = 0;
  long first_number_ = 0;        ///< the first match's catalogue number
  bool one_object_ = true;       ///< every match has it (one object's sets: epochs of a history)
  std::vector<listed> listed_;   ///< matches; without a selector, the first sets
  std::vector<listed> nearest_;  ///< by score, then order (only while nothing matched)
  std::optional<diagnostic> second_;
};

}  // namespace conescan::orbit
