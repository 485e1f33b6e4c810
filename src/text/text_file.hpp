// A whole file read into memory, bounded before it is spent: for the readers of formats that a
// library parses from one text (TOML scene files, XML and JSON element sets, a fit's JSON).
#pragma once

#include <cstddef>
#include <string>

#include "text/diagnostic.hpp"

namespace conescan::text {

/// The bytes of the file at `path`, at most `max_bytes` of them. Refused, naming the file: an
/// empty name, a directory, a file that cannot be opened or read, and a file longer than
/// max_bytes (found after reading max_bytes + 1 bytes, whatever the file's size: /dev/zero too).
/// `what` names what the file should be ("an OMM") in the messages.
checked<std::string> read_text_file(const std::string& path, std::size_t max_bytes,
                                    std::string_view what);

}  // namespace conescan::text
