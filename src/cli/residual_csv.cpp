#include "cli/residual_csv.hpp"

#include <limits>
#include <utility>

namespace conescan::cli {

checked<residual_csv> residual_csv::open(const std::string& path) {
  checked<text::output_file> file = text::output_file::open(path, "residuals");
  if (!file.ok()) return std::move(file).error();
  residual_csv out(std::move(file).value());
  out.sink_.append(
      "t_s,row,head,lat_deg,chord_residual_deg,phase_residual_deg,normalised,fitted\n");
  return out;
}

residual_csv::residual_csv(text::output_file file) : file_(std::move(file)) {}

void residual_csv::pass_on() noexcept {
  if (written_.ok()) written_ = file_.write(sink_.buffered());
  sink_.discard();
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
  if (sink_.size() >= sink_.flush_threshold()) pass_on();
}

checked<void> residual_csv::finish() {
  pass_on();
  if (!written_.ok()) return written_;
  return file_.commit();
}

}  // namespace conescan::cli
