#include "calibration/json.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace conescan::calibration {

const json_value* json_value::find(std::string_view key) const {
  for (const auto& [name, value] : members)
    if (name == key) return &value;
  return nullptr;
}

namespace {

class json_parser {
 public:
  json_parser(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  checked<json_value> document() {
    skip_space();
    json_value value;
    if (!parse_value(value, 0)) return error_;
    skip_space();
    if (at_ < text_.size()) return fail("unexpected text after the JSON value");
    return value;
  }

 private:
  std::string_view text_;
  const std::string& file_;
  std::size_t at_ = 0;
  std::uint64_t line_ = 1;
  std::size_t line_start_ = 0;
  diagnostic error_;

  std::uint64_t column() const { return at_ - line_start_ + 1; }

  diagnostic fail(std::string message) {
    error_ = {"", std::move(message), origin::file_line(file_, line_, column())};
    return error_;
  }
  bool failed(std::string message) {
    fail(std::move(message));
    return false;
  }

  void skip_space() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        ++line_;
        line_start_ = at_ + 1;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        return;
      }
      ++at_;
    }
  }

  bool literal(std::string_view word) {
    if (text_.substr(at_, word.size()) != word) return failed("expected a JSON value");
    at_ += word.size();
    return true;
  }

  bool parse_value(json_value& value, int depth) {
    if (depth > json_max_depth) return failed("nesting deeper than 64 levels");
    value.line = line_;
    value.column = column();
    if (at_ >= text_.size()) return failed("unexpected end of the text: expected a JSON value");
    switch (text_[at_]) {
      case '{':
        value.kind = json_value::type::object;
        return parse_object(value, depth);
      case '[':
        value.kind = json_value::type::array;
        return parse_array(value, depth);
      case '"':
        value.kind = json_value::type::string;
        return parse_string(value.text);
      case 't':
        value.kind = json_value::type::boolean;
        value.boolean = true;
        return literal("true");
      case 'f':
        value.kind = json_value::type::boolean;
        return literal("false");
      case 'n':
        value.kind = json_value::type::null;
        return literal("null");
      default:
        value.kind = json_value::type::number;
        return parse_number(value.number);
    }
  }

  bool expect(char c, const char* what) {
    skip_space();
    if (at_ >= text_.size() || text_[at_] != c) return failed(std::string("expected ") + what);
    ++at_;
    return true;
  }

  bool parse_object(json_value& value, int depth) {
    ++at_;
    skip_space();
    if (at_ < text_.size() && text_[at_] == '}') return ++at_, true;
    for (;;) {
      skip_space();
      if (at_ >= text_.size() || text_[at_] != '"')
        return failed("expected a member name in quotes");
      const std::uint64_t key_line = line_, key_column = column();
      std::string key;
      if (!parse_string(key)) return false;
      if (value.find(key) != nullptr) {
        const std::string shown = quote(key);  // escaped: no raw byte of the file on a terminal
        error_ = {"", "member \"" + shown.substr(1, shown.size() - 2) + "\" given twice",
                  origin::file_line(file_, key_line, key_column)};
        return false;
      }
      if (!expect(':', "':' after the member name")) return false;
      skip_space();
      json_value member;
      if (!parse_value(member, depth + 1)) return false;
      value.members.push_back({std::move(key), std::move(member)});
      skip_space();
      if (at_ < text_.size() && text_[at_] == ',') {
        ++at_;
        continue;
      }
      return expect('}', "',' or '}' in the object");
    }
  }

  bool parse_array(json_value& value, int depth) {
    ++at_;
    skip_space();
    if (at_ < text_.size() && text_[at_] == ']') return ++at_, true;
    for (;;) {
      skip_space();
      json_value item;
      if (!parse_value(item, depth + 1)) return false;
      value.items.push_back(std::move(item));
      skip_space();
      if (at_ < text_.size() && text_[at_] == ',') {
        ++at_;
        continue;
      }
      return expect(']', "',' or ']' in the array");
    }
  }

  /// RFC 8259's number grammar, checked before from_chars (which would accept "1." or "01").
  bool parse_number(double& number) {
    const std::size_t start = at_;
    auto digits = [&] {
      const std::size_t from = at_;
      while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9') ++at_;
      return at_ - from;
    };
    if (at_ < text_.size() && text_[at_] == '-') ++at_;
    const std::size_t int_start = at_;
    const std::size_t int_digits = digits();
    if (int_digits == 0) return at_ = start, failed("expected a JSON value");
    if (int_digits > 1 && text_[int_start] == '0')
      return at_ = start, failed("a number may not start with 0");
    if (at_ < text_.size() && text_[at_] == '.') {
      ++at_;
      if (digits() == 0) return failed("expected digits after the decimal point");
    }
    if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
      ++at_;
      if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
      if (digits() == 0) return failed("expected digits in the exponent");
    }
    const auto [end, ec] = std::from_chars(text_.data() + start, text_.data() + at_, number);
    if (ec != std::errc() || end != text_.data() + at_ || !std::isfinite(number)) {
      at_ = start;
      return failed("the number " + std::string(text_.substr(start, end - text_.data() - start)) +
                    " is beyond the range of a double");
    }
    return true;
  }

  bool hex4(unsigned& code) {
    if (at_ + 4 > text_.size()) return failed("expected four hex digits after \\u");
    code = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = text_[at_++];
      code <<= 4;
      if (c >= '0' && c <= '9')
        code |= static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f')
        code |= static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F')
        code |= static_cast<unsigned>(c - 'A' + 10);
      else
        return --at_, failed("expected four hex digits after \\u");
    }
    return true;
  }

  static void append_utf8(std::string& out, unsigned code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  bool parse_escape(std::string& out) {
    if (at_ >= text_.size()) return failed("unterminated string");
    const char c = text_[at_++];
    switch (c) {
      case '"':
      case '\\':
      case '/':
        out += c;
        return true;
      case 'b':
        out += '\b';
        return true;
      case 'f':
        out += '\f';
        return true;
      case 'n':
        out += '\n';
        return true;
      case 'r':
        out += '\r';
        return true;
      case 't':
        out += '\t';
        return true;
      case 'u':
        break;
      default:
        return --at_, failed("unknown escape " + quote("\\" + std::string(1, c)));
    }
    unsigned code = 0;
    if (!hex4(code)) return false;
    if (code >= 0xDC00 && code <= 0xDFFF) return failed("a lone low surrogate in \\u escapes");
    if (code >= 0xD800 && code <= 0xDBFF) {
      unsigned low = 0;
      if (text_.substr(at_, 2) != "\\u") return failed("a high surrogate without its low half");
      at_ += 2;
      if (!hex4(low)) return false;
      if (low < 0xDC00 || low > 0xDFFF) return failed("a high surrogate without its low half");
      code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
    }
    append_utf8(out, code);
    return true;
  }

  bool parse_string(std::string& out) {
    ++at_;  // the opening quote
    for (;;) {
      if (at_ >= text_.size()) return failed("unterminated string");
      const char c = text_[at_];
      if (c == '"') return ++at_, true;
      if (static_cast<unsigned char>(c) < 0x20)
        return failed("a control character inside a string (write it as an escape)");
      ++at_;
      if (c == '\\') {
        if (!parse_escape(out)) return false;
      } else {
        out += c;
      }
    }
  }
};

}  // namespace

checked<json_value> parse_json(std::string_view text, const std::string& file_name) {
  if (text.size() > json_max_bytes)
    return diagnostic{"", "larger than 64 MiB: not a fit's JSON", origin::file_line(file_name, 0)};
  return json_parser(text, file_name).document();
}

std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
          out += escape;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string json_number(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace conescan::calibration
