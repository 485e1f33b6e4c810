// CCSDS Keyword = Value Notation (KVN, CCSDS 502.0-B-3 section 7, 504.0-B-1 section 4): the line
// syntax and the vocabulary the OEM and AEM readers share (time systems, frames, interpolation).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"
#include "text/kvn_line.hpp"

namespace conescan::sources {

/// The line syntax: the ground floor's (text/kvn_line.hpp), which the OMM reader shares.
using text::classify_kvn_line;
using text::kvn_kind;
using text::kvn_line;

/// One keyword = value of a header or metadata block, with its line for messages.
struct kvn_entry {
  std::string keyword;
  std::string value;
  std::size_t line = 0;
};

/// The keyword = value lines of one header or metadata block. Refuses keywords not in the
/// block's vocabulary and keywords given twice.
class kvn_block {
 public:
  kvn_block(std::string_view name, std::span<const std::string_view> vocabulary,
            std::size_t first_line)
      : name_(name), vocabulary_(vocabulary), first_line_(first_line) {}

  checked<void> add(const kvn_line& l, std::size_t line);
  const kvn_entry* find(std::string_view keyword) const noexcept;
  /// The first of `keywords` missing, as an error at line `at` naming the block.
  checked<void> require(std::span<const std::string_view> keywords, std::size_t at) const;
  std::size_t first_line() const noexcept { return first_line_; }

 private:
  std::string_view name_;
  std::span<const std::string_view> vocabulary_;
  std::size_t first_line_;
  std::vector<kvn_entry> entries_;
};

/// The reference frames conescan tells apart (MODEL §10).
enum class frame_kind {
  inertial,         ///< EME2000, GCRF, ICRF, TEME, TOD: rotated into TOD by the scene
  earth_fixed,      ///< ITRF*: turned inertial with the Earth rotation angle
  spacecraft_body,  ///< SC_BODY_n (AEM)
  unsupported
};

/// A REF_FRAME value (any case) to its kind.
frame_kind classify_frame(std::string_view value);

/// TIME_SYSTEM (any case): UTC, TAI, TT, GPS; nullopt for the others (TDB, UT1, MET, ...).
std::optional<time_scale> parse_time_system(std::string_view value);

enum class interpolation_method { lagrange, hermite, linear };
std::string_view to_string(interpolation_method m) noexcept;
std::optional<interpolation_method> parse_interpolation_method(std::string_view value);

/// INTERPOLATION_DEGREE's range: 1 (linear) to 31 (beyond, equispaced Lagrange is unstable).
inline constexpr int max_interpolation_degree = 31;

/// A closed span of time [start, stop].
struct time_span {
  instant start{};
  instant stop{};
};

/// A segment's declared span: USEABLE_START/STOP_TIME, else START/STOP_TIME (both mandatory and
/// checked even when the USEABLE_* stand in), on the block's time scale; refused if it ends
/// before it starts.
checked<time_span> declared_span(const kvn_block& meta, time_scale scale);

struct interpolation_choice {
  interpolation_method method = interpolation_method::linear;
  int degree = 1;
};

/// The interpolation a META block asks for (`method_keyword`: OEM "INTERPOLATION", AEM
/// "INTERPOLATION_METHOD"; INTERPOLATION_DEGREE), each absent one from `defaults`; LINEAR is
/// degree 1 whatever the block says.
checked<interpolation_choice> interpolation_from(const kvn_block& meta,
                                                 std::string_view method_keyword,
                                                 interpolation_choice defaults);

/// The refusal of a line that has no place where it stands (`where`: "among the data lines"),
/// naming a keyword of the META block as misplaced rather than unknown.
diagnostic unexpected_line(const kvn_line& l, std::size_t line, const std::string& where,
                           std::span<const std::string_view> metadata_vocabulary);

/// Errors shared by the readers (messages name the value and the accepted set).
diagnostic unsupported_value(const kvn_entry& e, std::string_view accepted);

/// An epoch keyword's value on the block's time scale; the error names keyword and line.
checked<instant> entry_epoch(const kvn_entry& e, time_scale scale);

/// A positive integer keyword in [1, max]; the error names keyword and line.
checked<int> entry_integer(const kvn_entry& e, int max);

/// The first line of a KVN message: `keyword` = version, a number in [1, max_version] ("1.0",
/// "2", "3.0", ...); returns the version. `other_keyword` names the first keyword of a message
/// type the file may be instead (an AEM handed to the OEM reader), for a clearer message.
checked<double> check_version_line(const kvn_line& l, std::string_view keyword, double max_version,
                                   std::string_view other_keyword);

}  // namespace conescan::sources
