#include "text/json_document.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <vector>

namespace conescan::text {

namespace {

/// A refusal from inside nlohmann's parse callback (thrown through the parser, caught below).
struct structure_refusal {
  std::string path;
  std::string message;
};

/// A streaming reader's handler stopped the reading (thrown through the parser, caught below):
/// with its error, or without one when it has what it wants.
struct handler_stop {
  std::optional<diagnostic> error;
};

/// nlohmann's parse callback: follows the path to the value being read, refuses a repeated
/// member and a nesting too deep. Keeps every value (returns true), except the elements of a
/// top-level array when a handler takes them.
class structure_checker {
 public:
  explicit structure_checker(std::size_t max_depth,
                             const json_element_handler* on_element = nullptr)
      : max_depth_(max_depth), on_element_(on_element) {}

  bool operator()(int depth, nlohmann::ordered_json::parse_event_t event,
                  nlohmann::ordered_json& parsed) {
    check(event, parsed);
    using event_t = nlohmann::ordered_json::parse_event_t;
    const bool element_read =
        event == event_t::object_end || event == event_t::array_end || event == event_t::value;
    if (on_element_ == nullptr || depth != 1 || !element_read || frames_.empty() ||
        !frames_.front().array)
      return true;
    checked<bool> go_on = (*on_element_)(frames_.front().next_index - 1, parsed);
    if (!go_on.ok()) throw handler_stop{std::move(go_on).error()};
    if (!go_on.value()) throw handler_stop{};
    return false;  // dropped: the array keeps none of its elements
  }

 private:
  void check(nlohmann::ordered_json::parse_event_t event, nlohmann::ordered_json& parsed) {
    using event_t = nlohmann::ordered_json::parse_event_t;
    switch (event) {
      case event_t::object_start:
      case event_t::array_start:
        element_begins();
        if (frames_.size() >= max_depth_)
          throw structure_refusal{path(),
                                  "nesting deeper than " + std::to_string(max_depth_) + " levels"};
        frames_.push_back({event == event_t::array_start, 0, {}, {}});
        break;
      case event_t::object_end:
      case event_t::array_end:
        frames_.pop_back();
        break;
      case event_t::key: {
        frame& object = frames_.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second)
          throw structure_refusal{path(), "member given twice in one object"};
        break;
      }
      case event_t::value:
        element_begins();
        break;
    }
  }

  struct frame {
    bool array = false;
    std::size_t next_index = 0;  // arrays: the index the next element takes
    std::string key;             // objects: the member being read
    std::set<std::string> keys;  // objects: the members read so far
  };

  // An element of an array begins: it takes the next index.
  void element_begins() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().next_index;
  }

  // The path to the value being read (the last element of an array: next_index - 1).
  std::string path() const {
    std::string out;
    for (const frame& f : frames_)
      out = f.array ? json_path(out, f.next_index == 0 ? 0 : f.next_index - 1)
                    : json_path(out, f.key);
    return out;
  }

  std::size_t max_depth_;
  const json_element_handler* on_element_;
  std::vector<frame> frames_;
};

/// nlohmann's message without its "[json.exception.parse_error.101] parse error at line L,
/// column C: " prefix (the diagnostic places it), one printable line (requoted: the token it
/// quotes, "last read: '...'" or "number overflow parsing '...'", as long as the file made it,
/// and the file's raw bytes).
std::string without_prefix(const std::string& what) {
  const std::size_t column = what.find("column ");
  const std::size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
  const std::size_t bracket = what.find("] ");
  const std::string_view message =
      colon != std::string::npos     ? std::string_view(what).substr(colon + 2)
      : bracket != std::string::npos ? std::string_view(what).substr(bracket + 2)
                                     : std::string_view(what);
  return requoted(message);
}

/// A syntax error at 1-based byte `byte` of `text` (nlohmann's position of the last character
/// it read), as line and byte column.
diagnostic at_byte(const std::string& file, std::string_view text, std::size_t byte,
                   std::string message) {
  const std::size_t offset = std::min(byte == 0 ? 0 : byte - 1, text.size());
  const std::string_view before = text.substr(0, offset);
  const std::size_t line_start =
      before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
  const auto line = static_cast<std::uint64_t>(std::count(before.begin(), before.end(), '\n') + 1);
  return diagnostic::in_file(file, line, std::move(message), offset - line_start + 1);
}

}  // namespace

namespace {

checked<nlohmann::ordered_json> parse_checked(std::string_view text, const std::string& file_name,
                                              std::size_t max_depth,
                                              const json_element_handler* on_element) {
  try {
    return nlohmann::ordered_json::parse(text.begin(), text.end(),
                                         structure_checker(max_depth, on_element));
  } catch (const handler_stop& stop) {
    if (stop.error) return *stop.error;
    return nlohmann::ordered_json::array();
  } catch (const structure_refusal& refusal) {
    // The path holds the file's member names: shown with quote()'s escapes, without its quotes
    // (a DEL or a byte that is not UTF-8 in a name reached the terminal: a fuzzing finding).
    const std::string shown = quote(refusal.path.empty() ? "the top level" : refusal.path);
    return diagnostic::in_file(file_name, 0,
                               shown.substr(1, shown.size() - 2) + ": " + refusal.message);
  } catch (const nlohmann::json::parse_error& e) {
    return at_byte(file_name, text, e.byte, without_prefix(e.what()));
  } catch (const nlohmann::json::exception& e) {  // a number beyond the doubles' range
    return diagnostic::in_file(file_name, 0, without_prefix(e.what()));
  }
}

}  // namespace

checked<nlohmann::ordered_json> parse_json_document(std::string_view text,
                                                    const std::string& file_name,
                                                    std::size_t max_depth) {
  return parse_checked(text, file_name, max_depth, nullptr);
}

checked<nlohmann::ordered_json> parse_json_streaming(std::string_view text,
                                                     const std::string& file_name,
                                                     const json_element_handler& on_element,
                                                     std::size_t max_depth) {
  return parse_checked(text, file_name, max_depth, &on_element);
}

std::string json_path(const std::string& parent, std::string_view key) {
  return parent + "." + std::string(key);
}

std::string json_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string_view json_kind(const nlohmann::ordered_json& value) noexcept {
  switch (value.type()) {
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::boolean:
      return "true or false";
    case nlohmann::json::value_t::null:
      return "null";
    default:
      return "a number";
  }
}

}  // namespace conescan::text
