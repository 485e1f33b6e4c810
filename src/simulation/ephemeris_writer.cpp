#include "simulation/ephemeris_writer.hpp"

#include <ctime>
#include <functional>

#include "conescan/attitude.hpp"
#include "conescan/orbital_frame.hpp"
#include "simulation/truth_source.hpp"
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
  std::string oem_interpolation;  // HERMITE, or LAGRANGE for SGP4's and J2's states
};

message_parts parts_of(const loaded_scene& scene, const truth_source& truth) {
  const source_files& f = truth.files();
  const bool tle = f.tle.has_value();
  const double last_t = last_row_t_s(scene);
  const std::string id = tle ? f.tle->international_designator : "";
  return {tle && !f.tle->name.empty() ? f.tle->name : "conescan scene", id.empty() ? "NONE" : id,
          "TOD",  // the scene frame the rows are in (MODEL §10), whatever the source's
          sources::format_utc(truth.epoch(), 9),
          sources::format_utc(sources::add_seconds(truth.epoch(), last_t), 9),
          // HERMITE reads a state's velocity as its position's derivative: SGP4's states are
          // written as LAGRANGE, and so are J2's, whose velocity is the osculating ellipse's
          // (MODEL §3), some 25 m/s from the drifting position's derivative in low orbits.
          tle || scene.config.j2 ? "LAGRANGE" : "HERMITE"};
}

// A row's line after its epoch, from the truth there.
using row_text = std::function<std::string(const truth_state&)>;

// Writes `head`, the rows and `tail` to `out`, in blocks of about 64 KiB.
checked<void> write_message(text::output_file& out, const std::string& head,
                            const loaded_scene& scene, const truth_source& truth,
                            const row_text& line, const std::string& tail, const char* option) {
  constexpr std::size_t block_bytes = 1 << 16;
  std::string block = head;
  const std::uint64_t rows = row_count(scene);
  for (std::uint64_t k = 0; k < rows; ++k) {
    const double t = static_cast<double>(k) * scene.config.step_s;  // the rows' grid (MODEL §3)
    const truth_state s = truth.truth_at(t);
    if (!s.ok)
      return diagnostic{option, "cannot write " + quote(out.path()) +
                                    ": no value at t_s = " + text::shortest_text(t)};
    block += sources::format_utc(sources::add_seconds(truth.epoch(), t), 9) + line(s) + "\n";
    if (block.size() >= block_bytes) {
      if (checked<void> written = out.write(block); !written.ok()) return written;
      block.clear();
    }
  }
  return out.write(block + tail);
}

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

checked<void> write_oem(const loaded_scene& scene, text::output_file& out) {
  const checked<truth_source> made = truth_source::of(scene);
  if (!made.ok()) return made.error();
  const truth_source& truth = made.value();
  const message_parts p = parts_of(scene, truth);
  const std::string head = message_start("OEM", "2.0", p) + "REF_FRAME = " + p.inertial_frame +
                           "\nTIME_SYSTEM = UTC\nSTART_TIME = " + p.start +
                           "\nSTOP_TIME = " + p.stop + "\nINTERPOLATION = " + p.oem_interpolation +
                           "\nINTERPOLATION_DEGREE = 7\nMETA_STOP\n\n";
  return write_message(
      out, head, scene, truth,
      [](const truth_state& s) {
        const vec3<double> r = s.r_eci_m / 1000.0, v = s.v_eci_m_s / 1000.0;
        return numbers({r.x, r.y, r.z, v.x, v.y, v.z});
      },
      "", "write-oem");
}

checked<void> write_aem(const loaded_scene& scene, text::output_file& out) {
  const checked<truth_source> made = truth_source::of(scene);
  if (!made.ok()) return made.error();
  const truth_source& truth = made.value();
  const message_parts p = parts_of(scene, truth);
  const std::string head =
      message_start("AEM", "1.0", p) + "REF_FRAME_A = " + p.inertial_frame +
      "\nREF_FRAME_B = SC_BODY_1\nATTITUDE_DIR = A2B\nTIME_SYSTEM = UTC\nSTART_TIME = " + p.start +
      "\nSTOP_TIME = " + p.stop +
      "\nATTITUDE_TYPE = QUATERNION\nQUATERNION_TYPE = LAST\nINTERPOLATION_METHOD = LAGRANGE\n"
      "INTERPOLATION_DEGREE = 7\nMETA_STOP\n\nDATA_START\n";
  return write_message(
      out, head, scene, truth,
      [](const truth_state& s) {
        // body <- inertial = (body <- orbital)(orbital <- inertial); CCSDS's A2B
        // quaternion Q has A(Q) = R(conj Q) = that matrix (aem.hpp).
        const mat3<double> body_from_inertial =
            s.body_from_orbit * glm::transpose(dcm_eci_from_orbit(s.r_eci_m, s.v_eci_m_s));
        const sources::quaternion q =
            sources::conjugate(sources::quaternion_from_rotation_matrix(body_from_inertial));
        return numbers({q.x, q.y, q.z, q.w});
      },
      "DATA_STOP\n", "write-aem");
}

}  // namespace conescan::scene
