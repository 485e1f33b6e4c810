// The line syntax of CCSDS Keyword = Value Notation (KVN: CCSDS 502.0-B-3 section 7, 504.0-B-1
// section 4), the ground floor of both KVN readers: the orbit tier's OMM (orbit/omm_formats.cpp)
// and the sources tier's OEM and AEM (sources/kvn.hpp, kvn_reader.hpp), which give the lines'
// keywords their meaning and their order.
#pragma once

#include <string_view>

namespace conescan::text {

enum class kvn_kind {
  blank,          ///< empty or blanks only
  comment,        ///< "COMMENT", alone or followed by a blank and its text
  keyword_value,  ///< "KEYWORD = value"
  marker,         ///< one upper-case word: META_START, DATA_STOP, COVARIANCE_START, ...
  data,           ///< anything starting with a digit (an epoch) or a sign (a covariance row)
  malformed       ///< none of these
};

/// One line classified; the views point into the line.
struct kvn_line {
  kvn_kind kind = kvn_kind::blank;
  std::string_view keyword;  ///< keyword_value and marker ("COMMENT" for a comment)
  std::string_view value;    ///< keyword_value: the text after the first '=', trimmed; a
                             ///< comment's text
};

/// The kind of a line (blanks around it ignored), in this order: blank, comment, a line with '='
/// (keyword and value trimmed of blanks), data, marker, malformed.
kvn_line classify_kvn_line(std::string_view line) noexcept;

}  // namespace conescan::text
