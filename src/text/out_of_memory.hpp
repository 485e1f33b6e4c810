// Memory that runs out while a user's file is read (a table of millions of rows under a small
// `ulimit -v`): the programs' message names the option and the file, not only "out of memory"
// (cli/guarded_main.hpp prints it; exit 1 as for any memory that runs out).
#pragma once

#include <new>
#include <string>
#include <string_view>
#include <utility>

namespace conescan::text {

/// std::bad_alloc that says what was being read: "--oem: x.oem".
class out_of_memory_reading : public std::bad_alloc {
 public:
  explicit out_of_memory_reading(std::string what) noexcept : what_(std::move(what)) {}
  const char* what() const noexcept override { return what_.c_str(); }

 private:
  std::string what_;
};

/// read(), a std::bad_alloc it throws named "--OPTION: PATH".
template <class Read>
auto naming_input(std::string_view option, const std::string& path, Read&& read)
    -> decltype(read()) {
  try {
    return read();
  } catch (const out_of_memory_reading&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw out_of_memory_reading("--" + std::string(option) + ": " + path);
  }
}

}  // namespace conescan::text
