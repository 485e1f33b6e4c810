#include "calendar_run.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "simulation/calendar_csv.hpp"
#include "text/output_file.hpp"

namespace conescan::cli {

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "conescan-sim: --calendar: %s\n", message.c_str());
  return 1;
}

// DIR, made when missing (its parent must exist).
bool make_directory(const std::string& dir, std::string& error) {
  if (::mkdir(dir.c_str(), 0777) == 0) return true;
  struct stat st {};
  if (errno == EEXIST && ::stat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return true;
  error =
      "cannot make the directory " + conescan::quote(dir) + ": " +
      (errno == EEXIST ? std::string("a file of that name is in the way") : std::strerror(errno));
  return false;
}

}  // namespace

int run_calendar(const scene::scene_plan& plan) {
  const std::string& dir = plan.request().calendar_dir;
  const conescan::checked<scene::blinding_calendar> calendar =
      scene::blinding_calendar_of(plan.scene(0));
  if (!calendar.ok()) return fail(calendar.error().text());
  std::string error;
  if (!make_directory(dir, error)) return fail(error);
  const std::vector<scene::calendar_file> files = scene::calendar_csv_files(calendar.value());
  std::vector<text::output_file> outputs;
  for (const scene::calendar_file& f : files) {
    conescan::checked<text::output_file> opened =
        text::output_file::open(dir + "/" + f.name, "calendar");
    if (!opened.ok()) return fail(opened.error().text());
    outputs.push_back(std::move(opened).value());
    if (const conescan::checked<void> written = outputs.back().write(f.text); !written.ok())
      return fail(written.error().text());
  }
  for (text::output_file& out : outputs)
    if (const conescan::checked<void> done = out.commit(); !done.ok())
      return fail(done.error().text());
  const scene::blinding_calendar& c = calendar.value();
  std::fprintf(stderr,
               "conescan-sim: calendar of %zu head(s) over %.6g days at %g s: %zu intervals "
               "lost, %zu on the cone, from %llu samples of the rule; wrote %s/{lost,on-cone,"
               "days,seasons}.csv\n",
               c.heads, c.span_s / 86400, c.resolution_s, c.lost.size(), c.on_cone.size(),
               static_cast<unsigned long long>(c.samples), dir.c_str());
  return 0;
}

}  // namespace conescan::cli
