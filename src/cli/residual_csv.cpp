#include "cli/residual_csv.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <utility>

namespace conescan::cli {

checked<residual_csv> residual_csv::open(const std::string& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return diagnostic{"residuals", "cannot open " + quote(path) + " for writing"};
  residual_csv out(fd, path);
  out.sink_.append(
      "t_s,row,head,lat_deg,chord_residual_deg,phase_residual_deg,normalised,fitted\n");
  out.sink_.end_row();
  return out;
}

residual_csv::residual_csv(int fd, std::string path) : fd_(fd), path_(std::move(path)), sink_(fd) {}

residual_csv::residual_csv(residual_csv&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      path_(std::move(other.path_)),
      sink_(std::move(other.sink_)) {}

residual_csv::~residual_csv() {
  if (fd_ >= 0) ::close(fd_);
}

void residual_csv::write(const calibration::residual_row& r, double latitude_deg) noexcept {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  sink_.append_number(r.measured->sample.t_s);
  sink_.append(',');
  sink_.append_count(r.measured->sample.row);
  sink_.append(',');
  sink_.append_count(r.measured->sample.head + 1);
  sink_.append(',');
  sink_.append_number(latitude_deg);
  sink_.append(',');
  sink_.append_number(r.predicted ? r.chord_deg : nan);
  sink_.append(',');
  sink_.append_number(r.predicted ? r.phase_deg : nan);
  sink_.append(',');
  sink_.append_number(r.predicted ? r.normalised : nan);
  sink_.append(r.fitted ? ",1\n" : ",0\n");
  sink_.end_row();
}

checked<void> residual_csv::finish() {
  const bool written = sink_.flush();
  const bool closed = ::close(std::exchange(fd_, -1)) == 0;
  if (!written || !closed) return diagnostic{"residuals", "error writing " + quote(path_)};
  return success();
}

}  // namespace conescan::cli
