#include "scene/ephemeris_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>

#include "conescan/attitude.hpp"
#include "conescan/orbital_frame.hpp"
#include "scene/truth_source.hpp"
#include "sources/rotation.hpp"
#include "sources/time_scales.hpp"
#include "text/number_text.hpp"

namespace conescan::scene {

namespace {

// CREATION_DATE: the wall clock's UTC, to the second.
std::string creation_date() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  return text;
}

// What both messages share: the header's creation and originator, the object, the span.
struct message_parts {
  std::string object_name, object_id, inertial_frame, start, stop;
  std::string oem_interpolation;  // HERMITE, or LAGRANGE for SGP4's states (header file)
};

message_parts parts_of(const scene_config& scene, const truth_source& truth) {
  const source_files& f = truth.files();
  const bool tle = f.tle.has_value();
  const double last_t = static_cast<double>(row_count(scene) - 1) * scene.step_s;
  const std::string id = tle ? f.tle->international_designator : "";
  return {tle && !f.tle->name.empty() ? f.tle->name : "conescan scene",
          id.empty() ? "NONE" : id,
          "TOD",  // the scene frame the rows are in (MODEL §10), whatever the source's
          sources::format_utc(truth.epoch(), 9),
          sources::format_utc(sources::add_seconds(truth.epoch(), last_t), 9),
          tle ? "LAGRANGE" : "HERMITE"};
}

// A row's line after its epoch, from the truth there.
using row_text = std::function<std::string(const truth_state&)>;

// Writes `head`, the rows and `tail` to `path`, all or nothing (top of ephemeris_writer.hpp).
class atomic_file {
 public:
  atomic_file(std::string path, const char* option)
      : path_(std::move(path)),
        temporary_(path_ + ".tmp-" + std::to_string(::getpid())),
        option_(option) {}

  checked<void> write(const std::string& head, const scene_config& scene, const truth_source& truth,
                      const row_text& line, const std::string& tail) {
    const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return failed("create " + temporary_);
    std::FILE* out = ::fdopen(fd, "w");
    if (!out) {
      ::close(fd);
      return discard(failed("fdopen"));
    }
    checked<void> written = put(out, head);
    const std::uint64_t rows = row_count(scene);
    for (std::uint64_t k = 0; k < rows && written.ok(); ++k) {
      const double t = static_cast<double>(k) * scene.step_s;  // the rows' grid (MODEL §3)
      const truth_state s = truth.truth_at(t);
      if (!s.ok)
        written =
            diagnostic{option_, quote(path_) + ": no value at t_s = " + text::shortest_text(t), {}};
      else
        written = put(
            out, sources::format_utc(sources::add_seconds(truth.epoch(), t), 9) + line(s) + "\n");
    }
    if (written.ok()) written = put(out, tail);
    if (written.ok() && std::fflush(out) != 0) written = failed("write");
    if (written.ok() && ::fsync(::fileno(out)) != 0) written = failed("fsync");
    if (std::fclose(out) != 0 && written.ok()) written = failed("close");
    if (written.ok() && std::rename(temporary_.c_str(), path_.c_str()) != 0)
      written = failed("rename to " + path_);
    return written.ok() ? written : discard(std::move(written));
  }

 private:
  diagnostic failed(const std::string& step) const {
    return diagnostic{option_, quote(path_) + ": " + step + ": " + std::strerror(errno), {}};
  }
  checked<void> put(std::FILE* out, const std::string& text) const {
    if (std::fputs(text.c_str(), out) == EOF) return failed("write");
    return success();
  }
  checked<void> discard(checked<void> error) const {
    ::unlink(temporary_.c_str());
    return error;
  }

  std::string path_, temporary_;
  const char* option_;
};

// The header and the META block's keywords that both messages begin with.
std::string message_start(const std::string& type, const char* version, const message_parts& p) {
  std::string lower = type;
  for (char& c : lower) c = static_cast<char>(c - 'A' + 'a');
  return "CCSDS_" + type + "_VERS = " + version + "\nCOMMENT written by conescan-sim --write-" +
         lower + "\nCREATION_DATE = " + creation_date() +
         "\nORIGINATOR = conescan\n\nMETA_START\nOBJECT_NAME = " + p.object_name +
         "\nOBJECT_ID = " + p.object_id + "\nCENTER_NAME = EARTH\n";
}

std::string numbers(std::initializer_list<double> values) {
  std::string text;
  for (double v : values) text += " " + text::shortest_text(v);
  return text;
}

}  // namespace

checked<void> write_oem(const scene_config& scene, const std::string& path) {
  const truth_source truth = truth_source::of(scene).value();
  const message_parts p = parts_of(scene, truth);
  const std::string head = message_start("OEM", "2.0", p) + "REF_FRAME = " + p.inertial_frame +
                           "\nTIME_SYSTEM = UTC\nSTART_TIME = " + p.start +
                           "\nSTOP_TIME = " + p.stop + "\nINTERPOLATION = " + p.oem_interpolation +
                           "\nINTERPOLATION_DEGREE = 7\nMETA_STOP\n\n";
  return atomic_file(path, "write-oem")
      .write(
          head, scene, truth,
          [](const truth_state& s) {
            const vec3<double> r = s.r_eci_m / 1000.0, v = s.v_eci_m_s / 1000.0;
            return numbers({r.x, r.y, r.z, v.x, v.y, v.z});
          },
          "");
}

checked<void> write_aem(const scene_config& scene, const std::string& path) {
  const truth_source truth = truth_source::of(scene).value();
  const message_parts p = parts_of(scene, truth);
  const std::string head =
      message_start("AEM", "1.0", p) + "REF_FRAME_A = " + p.inertial_frame +
      "\nREF_FRAME_B = SC_BODY_1\nATTITUDE_DIR = A2B\nTIME_SYSTEM = UTC\nSTART_TIME = " + p.start +
      "\nSTOP_TIME = " + p.stop +
      "\nATTITUDE_TYPE = QUATERNION\nQUATERNION_TYPE = LAST\nINTERPOLATION_METHOD = LAGRANGE\n"
      "INTERPOLATION_DEGREE = 7\nMETA_STOP\n\nDATA_START\n";
  return atomic_file(path, "write-aem")
      .write(
          head, scene, truth,
          [](const truth_state& s) {
            // body <- inertial = (body <- orbital)(orbital <- inertial); CCSDS's A2B
            // quaternion Q has A(Q) = R(conj Q) = that matrix (aem.hpp).
            const mat3<double> body_from_inertial =
                s.body_from_orbit * glm::transpose(dcm_eci_from_orbit(s.r_eci_m, s.v_eci_m_s));
            const sources::quaternion q =
                sources::conjugate(sources::quaternion_from_rotation_matrix(body_from_inertial));
            return numbers({q.x, q.y, q.z, q.w});
          },
          "DATA_STOP\n");
}

}  // namespace conescan::scene
