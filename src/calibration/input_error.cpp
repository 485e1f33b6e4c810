#include "calibration/input_error.hpp"

#include <cstdio>

namespace conescan::calibration {

std::string input_error::text() const {
  std::string out;
  if (!file.empty()) {
    out += file;
    if (line != 0) out += ':' + std::to_string(line);
    if (line != 0 && column != 0) out += ':' + std::to_string(column);
    out += ": ";
  }
  if (!option.empty()) out += "--" + option + ": ";
  return out + message;
}

std::string quote(std::string_view text) {
  constexpr std::size_t shown = 60;
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < shown; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7f) {
      out += text[i];
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", byte);
      out += hex;
    }
  }
  if (text.size() > shown) out += "...";
  return out + "'";
}

}  // namespace conescan::calibration
