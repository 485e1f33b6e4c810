// The four OMM formats read into records (omm_record.hpp): CCSDS KVN and XML, CelesTrak's CSV
// and JSON. Each reader checks its format's syntax, keywords, units and repeats; what the
// values mean is checked once, for every format, in omm.cpp.
#include <algorithm>
#include <array>
#include <optional>
#include <pugixml.hpp>
#include <set>

#include "orbit/omm_record.hpp"
#include "orbit/xml_outline.hpp"
#include "text/json_document.hpp"
#include "text/kvn_line.hpp"
#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::orbit::omm_detail {

namespace {

// --- Keywords (CCSDS 502.0-B-3, the OMM's sections) ------------------------------------------

constexpr std::array<std::string_view, 5> header_keywords = {
    "CCSDS_OMM_VERS", "CREATION_DATE", "ORIGINATOR", "MESSAGE_ID", "CLASSIFICATION"};
constexpr std::array<std::string_view, 7> metadata_keywords = {
    "OBJECT_NAME", "OBJECT_ID",       "CENTER_NAME",        "REF_FRAME",
    "TIME_SYSTEM", "REF_FRAME_EPOCH", "MEAN_ELEMENT_THEORY"};
constexpr std::array<std::string_view, 9> mean_element_keywords = {
    "EPOCH",       "SEMI_MAJOR_AXIS", "MEAN_MOTION",       "ECCENTRICITY",
    "INCLINATION", "RA_OF_ASC_NODE",  "ARG_OF_PERICENTER", "MEAN_ANOMALY",
    "GM"};
constexpr std::array<std::string_view, 5> spacecraft_keywords = {
    "MASS", "SOLAR_RAD_AREA", "SOLAR_RAD_COEFF", "DRAG_AREA", "DRAG_COEFF"};
constexpr std::array<std::string_view, 10> tle_keywords = {"EPHEMERIS_TYPE",
                                                           "CLASSIFICATION_TYPE",
                                                           "NORAD_CAT_ID",
                                                           "ELEMENT_SET_NO",
                                                           "REV_AT_EPOCH",
                                                           "BSTAR",
                                                           "BTERM",
                                                           "MEAN_MOTION_DOT",
                                                           "MEAN_MOTION_DDOT",
                                                           "AGOM"};
constexpr std::array<std::string_view, 22> covariance_keywords = {
    "COV_REF_FRAME", "CX_X",         "CY_X",         "CY_Y",         "CZ_X",         "CZ_Y",
    "CZ_Z",          "CX_DOT_X",     "CX_DOT_Y",     "CX_DOT_Z",     "CX_DOT_X_DOT", "CY_DOT_X",
    "CY_DOT_Y",      "CY_DOT_Z",     "CY_DOT_X_DOT", "CY_DOT_Y_DOT", "CZ_DOT_X",     "CZ_DOT_Y",
    "CZ_DOT_Z",      "CZ_DOT_X_DOT", "CZ_DOT_Y_DOT", "CZ_DOT_Z_DOT"};

template <std::size_t n>
bool one_of(const std::array<std::string_view, n>& words, std::string_view word) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

bool is_omm_keyword(std::string_view k) {
  return one_of(header_keywords, k) || one_of(metadata_keywords, k) ||
         one_of(mean_element_keywords, k) || one_of(spacecraft_keywords, k) ||
         one_of(tle_keywords, k) || one_of(covariance_keywords, k) ||
         k.rfind("USER_DEFINED_", 0) == 0;
}

/// The unit a field is written in (CCSDS 502.0-B-3's tables), "" when there is none to check.
std::string_view expected_units(std::string_view keyword) {
  if (keyword == "MEAN_MOTION") return "rev/day";
  if (keyword == "INCLINATION" || keyword == "RA_OF_ASC_NODE" || keyword == "ARG_OF_PERICENTER" ||
      keyword == "MEAN_ANOMALY")
    return "deg";
  if (keyword == "BSTAR") return "1/ER";
  if (keyword == "MEAN_MOTION_DOT") return "rev/day**2";
  if (keyword == "MEAN_MOTION_DDOT") return "rev/day**3";
  if (keyword == "SEMI_MAJOR_AXIS") return "km";
  if (keyword == "GM") return "km**3/s**2";
  return "";
}

/// Units as written must be the field's own (any case); none given is fine.
checked<void> check_units(const std::string& source, const field_value& f, std::string_view key,
                          std::string_view units) {
  const std::string_view expected = expected_units(key);
  if (units.empty() || expected.empty() || text::to_upper(units) == text::to_upper(expected))
    return success();
  return field_error(
      source, f,
      "units " + quote(units) + ": " + std::string(key) + " is in " + std::string(expected));
}

/// A repeated field: refused, naming where it was first given.
diagnostic repeated(const std::string& source, const field_value& again, const field_value& first) {
  return field_error(source, again,
                     "given twice in one element set (first " +
                         (first.line ? "on line " + std::to_string(first.line) : first.label) +
                         ")");
}

checked<void> add_field(const std::string& source, record& set, const std::string& key,
                        field_value value) {
  if (const auto it = set.fields.find(key); it != set.fields.end())
    return repeated(source, value, it->second);
  set.fields.emplace(key, std::move(value));
  return success();
}

/// Byte offsets where each line of a text begins: line and column of any offset in log time.
class line_index {
 public:
  explicit line_index(std::string_view text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }
  /// 1-based line and column of a 0-based byte offset.
  std::pair<std::uint64_t, std::uint64_t> at(std::size_t offset) const {
    const auto after = std::upper_bound(starts_.begin(), starts_.end(), offset);
    const auto line = static_cast<std::uint64_t>(after - starts_.begin());
    return {line, offset - *(after - 1) + 1};
  }

 private:
  std::vector<std::size_t> starts_;
};

/// The text's lines (without "\n" or "\r\n"), numbered from 1, while on_line says true.
template <class F>
checked<void> for_each_text_line(std::string_view text, F&& on_line) {
  std::uint64_t number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    checked<bool> go_on = on_line(line, ++number);
    if (!go_on.ok()) return std::move(go_on).error();
    if (!go_on.value() || end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return success();
}

/// A name or member from the file as a message shows it: quote()'s escapes, without its quotes
/// (an XML element's name or a JSON member's may hold any byte: a fuzzing finding).
std::string shown(std::string_view name) {
  const std::string quoted = quote(name);
  return quoted.substr(1, quoted.size() - 2);
}

std::string_view without_bom(std::string_view text) {
  return text.substr(0, 3) == "\xEF\xBB\xBF" ? text.substr(3) : text;
}

// --- KVN -------------------------------------------------------------------------------------

/// `value [units]` split into the value and its units.
std::pair<std::string_view, std::string_view> value_and_units(std::string_view value) {
  if (value.empty() || value.back() != ']') return {value, {}};
  const std::size_t open = value.rfind('[');
  if (open == std::string_view::npos) return {value, {}};
  return {text::trim_blanks(value.substr(0, open)),
          text::trim_blanks(value.substr(open + 1, value.size() - open - 2))};
}

class kvn_reader {
 public:
  kvn_reader(const std::string& source, const record_handler& on_set)
      : source_(source), on_set_(on_set) {}

  checked<bool> line(std::string_view text, std::uint64_t number) {
    const text::kvn_line l = text::classify_kvn_line(text);
    if (l.kind == text::kvn_kind::blank || l.kind == text::kvn_kind::comment) return true;
    const std::string_view trimmed = text::trim_blanks(text);
    if (l.kind != text::kvn_kind::keyword_value)
      return diagnostic::in_file(source_, number,
                                 "expected KEYWORD = value, not " + quote(trimmed));
    const std::size_t equals = trimmed.find('=');
    const std::string key(l.keyword);
    const std::string_view after = trimmed.substr(equals + 1);
    const auto [value, units] = value_and_units(text::trim_blanks(after));
    const auto column = static_cast<std::uint64_t>(
        (value.empty() ? after.data() + after.size() : value.data()) - text.data() + 1);
    field_value f{std::string(value), number, column, key};
    if (!is_omm_keyword(key))
      return diagnostic::in_file(source_, number,
                                 "unknown keyword " + quote(key) + ": not an OMM keyword",
                                 static_cast<std::uint64_t>(trimmed.data() - text.data() + 1));
    if (key == "CCSDS_OMM_VERS") {
      // A message begins: the one before it is complete.
      if (set_) {
        checked<bool> go_on = on_set_(std::move(*set_));
        if (!go_on.ok() || !go_on.value()) return go_on;
      }
      set_ = record{{}, number, 1, "line " + std::to_string(number), "", true};
    } else if (!set_) {
      return diagnostic::in_file(source_, number,
                                 "an OMM in KVN begins with CCSDS_OMM_VERS, not " + quote(key));
    }
    if (checked<void> u = check_units(source_, f, key, units); !u.ok()) return u.error();
    if (checked<void> a = add_field(source_, *set_, key, std::move(f)); !a.ok()) return a.error();
    return true;
  }

  /// The text has ended: its last message is complete.
  checked<void> finish() {
    if (!set_) return success();
    checked<bool> last = on_set_(std::move(*set_));
    if (!last.ok()) return std::move(last).error();
    return success();
  }

 private:
  const std::string& source_;
  const record_handler& on_set_;
  std::optional<record> set_;  // the message being read
};

// --- CSV ---------------------------------------------------------------------------------------

struct csv_field {
  std::string text;
  std::uint64_t column;
};

/// RFC 4180 fields of one line: "a ""quoted"" field" may hold commas; blanks around fields kept
/// out. An unterminated quote or text after a closing quote is an error (message only).
checked<std::vector<csv_field>> split_csv(std::string_view line) {
  std::vector<csv_field> fields;
  std::size_t at = 0;
  for (;;) {
    csv_field f{{}, at + 1};
    if (at < line.size() && line[at] == '"') {
      std::size_t i = at + 1;
      for (;; ++i) {
        if (i >= line.size())
          return diagnostic{{},
                            "unterminated quote in the field at column " + std::to_string(at + 1)};
        if (line[i] != '"') {
          f.text += line[i];
        } else if (i + 1 < line.size() && line[i + 1] == '"') {
          f.text += '"';
          ++i;
        } else {
          break;
        }
      }
      at = i + 1;
      if (at < line.size() && line[at] != ',')
        return diagnostic{{}, "text after the closing quote at column " + std::to_string(at + 1)};
    } else {
      const std::size_t comma = std::min(line.find(',', at), line.size());
      f.text = std::string(text::trim_blanks(line.substr(at, comma - at)));
      at = comma;
    }
    fields.push_back(std::move(f));
    if (at >= line.size()) return fields;
    ++at;  // the comma
  }
}

class csv_reader {
 public:
  csv_reader(const std::string& source, const record_handler& on_set)
      : source_(source), on_set_(on_set) {}

  checked<bool> line(std::string_view text, std::uint64_t number) {
    if (text::trim_blanks(text).empty()) return true;
    checked<std::vector<csv_field>> fields = split_csv(text);
    if (!fields.ok())
      return diagnostic::in_file(source_, number, std::move(fields).error().message);
    if (names_.empty()) {
      if (checked<void> h = header(fields.value(), number); !h.ok()) return h.error();
      return true;
    }
    if (fields.value().size() != names_.size())
      return diagnostic::in_file(source_, number,
                                 std::to_string(fields.value().size()) +
                                     " fields, the header has " + std::to_string(names_.size()));
    record set{{}, number, 1, "line " + std::to_string(number), "", false};
    for (std::size_t i = 0; i < names_.size(); ++i) {
      csv_field& f = fields.value()[i];
      if (f.text.empty()) continue;  // an empty field is an absent one
      set.fields.emplace(names_[i], field_value{std::move(f.text), number, f.column, names_[i]});
    }
    return on_set_(std::move(set));
  }

  checked<void> finish() { return success(); }

 private:
  checked<void> header(const std::vector<csv_field>& fields, std::uint64_t number) {
    for (const csv_field& f : fields) {
      if (std::find(names_.begin(), names_.end(), f.text) != names_.end())
        return diagnostic::in_file(
            source_, number, "column " + quote(f.text) + " appears twice in the header", f.column);
      names_.push_back(f.text);
    }
    return success();
  }

  const std::string& source_;
  const record_handler& on_set_;
  std::vector<std::string> names_;
};

// --- JSON --------------------------------------------------------------------------------------

/// One member's value as text: strings as written, numbers in their shortest round-trip form
/// (integers exactly), null as absent (nullopt); anything else refused.
checked<std::optional<std::string>> member_text(const nlohmann::ordered_json& value) {
  using kind = nlohmann::ordered_json::value_t;
  switch (value.type()) {
    case kind::string:
      return std::optional<std::string>(text::trim_blanks(value.get_ref<const std::string&>()));
    case kind::number_integer:
      return std::optional<std::string>(std::to_string(value.get<std::int64_t>()));
    case kind::number_unsigned:
      return std::optional<std::string>(std::to_string(value.get<std::uint64_t>()));
    case kind::number_float:
      return std::optional<std::string>(text::shortest_text(value.get<double>()));
    case kind::null:
      return std::optional<std::string>();
    default:
      return diagnostic{
          {}, "expected a number or a string, found " + std::string(text::json_kind(value))};
  }
}

checked<record> json_record(const nlohmann::ordered_json& object, const std::string& path,
                            const std::string& source) {
  if (!object.is_object())
    return diagnostic::in_file(source, 0,
                               (path.empty() ? "the top level" : path) +
                                   ": expected an object of OMM fields, found " +
                                   std::string(text::json_kind(object)));
  record set{{}, 0, 0, path.empty() ? "the object" : path, path, false};
  for (const auto& [key, value] : object.items()) {
    const std::string member = text::json_path(path, key);
    checked<std::optional<std::string>> t = member_text(value);
    if (!t.ok()) return diagnostic::in_file(source, 0, shown(member) + ": " + t.error().message);
    if (t.value()) set.fields.emplace(key, field_value{std::move(*t.value()), 0, 0, member});
  }
  return set;
}

// --- XML ---------------------------------------------------------------------------------------

/// The text of a value element: all of its character data, CDATA sections included, with the
/// comments and processing instructions inside it left out, as XML defines an element's text
/// (`15.56<!-- x -->387291` is 15.56387291, as python-sgp4's ElementTree reads it); nullopt when
/// it holds an element.
std::optional<std::string> element_text(const pugi::xml_node& element) {
  std::string text;
  for (const pugi::xml_node& part : element.children()) {
    if (part.type() == pugi::node_element) return std::nullopt;
    if (part.type() == pugi::node_pcdata || part.type() == pugi::node_cdata) text += part.value();
  }
  return std::string(text::trim_blanks(text));
}

/// Reads one <omm> element (the text of one set, found by the document's outline) into a
/// record, with each element's path and its line and column in the whole file.
class xml_reader {
 public:
  xml_reader(std::string_view part, const xml_extent& where, const std::string& source)
      : lines_(part), where_(where), source_(source) {}

  checked<record> omm(const pugi::xml_node& node, const std::string& path) {
    record set{{}, 0, 0, path, path, true};
    std::tie(set.line, set.column) = place(node);
    // CCSDS_OMM_VERS is the <omm> element's version attribute in XML.
    const pugi::xml_attribute version = node.attribute("version");
    if (!version)
      return record_error(source_, set, "missing the version attribute (CCSDS_OMM_VERS)");
    set.fields.emplace("CCSDS_OMM_VERS",
                       field_value{std::string(text::trim_blanks(version.value())), set.line,
                                   set.column, path + "/@version"});
    if (checked<void> h = section(set, node.child("header"), path + "/header", header_keywords);
        !h.ok())
      return h.error();
    checked<pugi::xml_node> segment = only_child(set, node, "body", path);
    if (!segment.ok()) return segment.error();
    const std::string body = path + "/body";
    segment = only_child(set, segment.value(), "segment", body);
    if (!segment.ok()) return segment.error();
    const std::string seg = body + "/segment";
    if (checked<void> m =
            section(set, segment.value().child("metadata"), seg + "/metadata", metadata_keywords);
        !m.ok())
      return m.error();
    if (checked<void> d = data(set, segment.value().child("data"), seg + "/data"); !d.ok())
      return d.error();
    return set;
  }

  /// Line and column in the file of a 0-based offset into the part.
  std::pair<std::uint64_t, std::uint64_t> at(std::size_t offset) const {
    const auto [line, column] = lines_.at(offset);
    return {where_.line + line - 1, line == 1 ? where_.column + column - 1 : column};
  }

  std::pair<std::uint64_t, std::uint64_t> place(const pugi::xml_node& node) const {
    // pugixml places an element at its name, one past the '<' a reader looks for.
    const std::ptrdiff_t offset = node.offset_debug();
    if (offset < 1) return {where_.line, where_.column};
    return at(static_cast<std::size_t>(offset - 1));
  }

 private:
  diagnostic error_at(const pugi::xml_node& node, const std::string& path, std::string message) {
    const auto [line, column] = place(node);
    return diagnostic::in_file(source_, line, path + ": " + std::move(message), column);
  }

  /// The one child element `name` of `node` (the message names what is missing or repeated).
  checked<pugi::xml_node> only_child(const record& set, const pugi::xml_node& node,
                                     const char* name, const std::string& path) {
    const pugi::xml_node child = node.child(name);
    if (!child) return record_error(source_, set, "missing <" + std::string(name) + "> in " + path);
    if (child.next_sibling(name))
      return error_at(child.next_sibling(name), path + "/" + name,
                      "a second <" + std::string(name) + ">: an OMM has one");
    return child;
  }

  template <std::size_t n>
  checked<void> section(record& set, const pugi::xml_node& node, const std::string& path,
                        const std::array<std::string_view, n>& keywords) {
    for (const pugi::xml_node& child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string name = child.name();
      const std::string child_path = path + "/" + shown(name);
      if (name == "COMMENT") continue;
      if (!one_of(keywords, name))
        return error_at(child, child_path,
                        "unknown element: not an OMM field of <" + shown(node.name()) + ">");
      std::optional<std::string> value = element_text(child);
      if (!value) return error_at(child, child_path, "holds elements: expected a value");
      auto [line, column] = place(child);
      field_value f{std::move(*value), line, column, child_path};
      if (checked<void> u = check_units(source_, f, name, child.attribute("units").value());
          !u.ok())
        return u;
      if (checked<void> added = add_field(source_, set, name, std::move(f)); !added.ok())
        return added;
    }
    return success();
  }

  checked<void> data(record& set, const pugi::xml_node& node, const std::string& path) {
    if (!node) return record_error(source_, set, "missing <data> in its segment");
    for (const pugi::xml_node& child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string name = child.name();
      checked<void> read = success();
      if (name == "meanElements")
        read = section(set, child, path + "/" + shown(name), mean_element_keywords);
      else if (name == "tleParameters")
        read = section(set, child, path + "/" + shown(name), tle_keywords);
      else if (name != "COMMENT" && name != "spacecraftParameters" && name != "covarianceMatrix" &&
               name != "userDefinedParameters")
        return error_at(child, path + "/" + shown(name),
                        "unknown element: not a part of an OMM's data");
      if (!read.ok()) return read;
    }
    return success();
  }

  line_index lines_;
  const xml_extent& where_;
  const std::string& source_;
};

/// The record of one <omm> element, parsed alone (pugixml's tree of one set, at most
/// omm_xml_max_set_bytes of text).
checked<record> xml_set(std::string_view text, const xml_extent& omm, const std::string& path,
                        const std::string& source) {
  const std::size_t bytes = omm.end - omm.begin;
  if (bytes > omm_xml_max_set_bytes)
    return diagnostic::in_file(source, omm.line,
                               path + ": an element set of " + std::to_string(bytes) +
                                   " bytes, more than " + std::to_string(omm_xml_max_set_bytes) +
                                   ": not an OMM's",
                               omm.column);
  const std::string_view part = text.substr(omm.begin, bytes);
  pugi::xml_document document;
  const pugi::xml_parse_result parsed =
      document.load_buffer(part.data(), part.size(), pugi::parse_default, pugi::encoding_utf8);
  xml_reader reader(part, omm, source);
  if (!parsed) {
    const auto [line, column] = reader.at(static_cast<std::size_t>(parsed.offset));
    return diagnostic::in_file(source, line,
                               std::string("not well-formed XML: ") + parsed.description(), column);
  }
  return reader.omm(document.document_element(), path);
}

}  // namespace

diagnostic field_error(const std::string& source, const field_value& field, std::string message) {
  return diagnostic::in_file(source, field.line, field.label + ": " + std::move(message),
                             field.column);
}

diagnostic record_error(const std::string& source, const record& set, std::string message) {
  return diagnostic::in_file(source, set.line,
                             (set.label.empty() ? "" : set.label + ": ") + std::move(message),
                             set.column);
}

// The records of a line-based format, read by `Reader` (kvn_reader, csv_reader) line by line.
template <class Reader>
checked<void> line_records(std::string_view text, const std::string& source,
                           const record_handler& on_set) {
  Reader reader(source, on_set);
  bool stopped = false;
  if (checked<void> r = for_each_text_line(without_bom(text),
                                           [&](std::string_view l, std::uint64_t n) {
                                             checked<bool> go_on = reader.line(l, n);
                                             stopped = go_on.ok() && !go_on.value();
                                             return go_on;
                                           });
      !r.ok())
    return r;
  return stopped ? success() : reader.finish();
}

checked<void> kvn_records(std::string_view text, const std::string& source,
                          const record_handler& on_set) {
  return line_records<kvn_reader>(text, source, on_set);
}

checked<void> csv_records(std::string_view text, const std::string& source,
                          const record_handler& on_set) {
  return line_records<csv_reader>(text, source, on_set);
}

checked<void> json_records(std::string_view text, const std::string& source,
                           const record_handler& on_set) {
  // The elements of a top-level array one at a time (a catalogue is held as text, and one set).
  checked<nlohmann::ordered_json> root = text::parse_json_streaming(
      without_bom(text), source,
      [&](std::size_t index, const nlohmann::ordered_json& element) -> checked<bool> {
        checked<record> set = json_record(element, text::json_path("", index), source);
        if (!set.ok()) return std::move(set).error();
        return on_set(std::move(set).value());
      });
  if (!root.ok()) return std::move(root).error();
  if (root.value().is_array()) return success();
  checked<record> one = json_record(root.value(), "", source);
  if (!one.ok()) return std::move(one).error();
  checked<bool> taken = on_set(std::move(one).value());
  if (!taken.ok()) return std::move(taken).error();
  return success();
}

checked<void> xml_records(std::string_view text, const std::string& source,
                          const record_handler& on_set) {
  // The document's outline first, then each <omm> parsed alone as the outline passes its end:
  // an <omm> root whole, or each <omm> of an <ndm> (other messages of an NDM are not read).
  std::size_t count = 0;
  return walk_xml_outline(
      text, source, omm_xml_max_depth, [&](const xml_extent& element) -> checked<bool> {
        const bool root = element.parent.empty();
        if (root && element.name != "omm" && element.name != "ndm")
          return diagnostic::in_file(
              source, element.line,
              "root element <" + shown(element.name) + ">: an OMM's is <omm> or <ndm>",
              element.column);
        const bool set =
            root ? element.name == "omm" : element.parent == "ndm" && element.name == "omm";
        if (!set) return true;
        checked<record> read = xml_set(
            text, element, root ? "omm" : "ndm/omm[" + std::to_string(++count) + "]", source);
        if (!read.ok()) return std::move(read).error();
        return on_set(std::move(read).value());
      });
}

}  // namespace conescan::orbit::omm_detail
