// The outputs besides standard output (--write-oem, --write-aem, --summary-state) never touch what
// is not ours, and every input is read and checked before the first byte of any output: the
// regressions of docs/RELIABILITY.md's audit (deleting a directory given as --summary-state,
// replacing a device, a FIFO, a link or a read-only file, a file-size limit killing the writer,
// outputs written before a bad --apply was read, two options naming one file, an edited fit read
// by half) and the properties behind them, on text::output_file itself and end to end.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "support/cli.hpp"
#include "text/output_file.hpp"

namespace fs = std::filesystem;
using conescan::text::output_file;
using conescan_test::read_file;
using conescan_test::run_sim;
using conescan_test::shell_word;

namespace {

const std::string data = CONESCAN_TEST_DATA;
const std::string fit_h1 = data + "/calibration/fit-h1.json";

// A directory of its own per test, removed at the end: what is left in it is what a run left.
struct scratch_dir {
  fs::path path;
  scratch_dir() {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("conescan_outputs_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(path);
  }
  ~scratch_dir() {
    std::error_code ignored;
    fs::permissions(path, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(path, ignored);
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  // The names in the directory, sorted.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(path)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
  bool has_temporary() const {
    for (const std::string& n : names())
      if (n.find(".tmp-") != std::string::npos) return true;
    return false;
  }
};

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string kind_of(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return "absent";
  if (S_ISLNK(st.st_mode)) return "link";
  if (S_ISDIR(st.st_mode)) return "directory";
  if (S_ISFIFO(st.st_mode)) return "fifo";
  if (S_ISCHR(st.st_mode)) return "device";
  return S_ISREG(st.st_mode) ? "file" : "other";
}

// The CSV's scene: short, so each run takes milliseconds.
const std::string scene = " --duration-s 30 --step-s 10";

}  // namespace

// --- text::output_file: one rule per kind of path ------------------------------------------------

TEST_CASE("outputs: an absent path or a regular file is replaced whole, by commit only",
          "[reliability][outputs]") {
  scratch_dir dir;
  const std::string path = dir / "out.txt";
  {
    auto f = output_file::open(path, "write-oem");
    REQUIRE(f.ok());
    CHECK_FALSE(f.value().direct());
    REQUIRE(f.value().write("first\n").ok());
    CHECK(kind_of(path) == "absent");  // nothing at the path before commit
    REQUIRE(f.value().commit().ok());
  }
  CHECK(read_file(path) == "first\n");
  ::chmod(path.c_str(), 0640);
  {
    auto f = output_file::open(path, "write-oem");
    REQUIRE(f.ok());
    REQUIRE(f.value().write("second\n").ok());
    // Destroyed without commit: the old file stays, the temporary file goes.
  }
  CHECK(read_file(path) == "first\n");
  CHECK(dir.names() == std::vector<std::string>{"out.txt"});
  {
    auto f = output_file::open(path, "write-oem");
    REQUIRE(f.value().write("third\n").ok());
    REQUIRE(f.value().commit().ok());
  }
  CHECK(read_file(path) == "third\n");
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0640);  // the replaced file's permissions are kept
}

TEST_CASE("outputs: what is not a regular file we may write is refused or written directly",
          "[reliability][outputs]") {
  scratch_dir dir;
  // A directory (the audit's first finding: it was deleted after the failed write).
  const std::string directory = dir / "d";
  fs::create_directory(directory);
  auto refused = output_file::open(directory, "summary-state");
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().text() ==
        "--summary-state: cannot write '" + directory + "': Is a directory");
  CHECK(kind_of(directory) == "directory");
  // A read-only file: refused, even for root, and left as it was.
  const std::string read_only = dir / "read-only";
  write_text(read_only, "keep\n");
  ::chmod(read_only.c_str(), 0444);
  const auto denied = output_file::open(read_only, "write-oem");
  REQUIRE_FALSE(denied.ok());
  CHECK(denied.error().message.find("Permission denied") != std::string::npos);
  CHECK(read_file(read_only) == "keep\n");
  // A link to nothing: refused (no file is created through it).
  const std::string dangling = dir / "dangling";
  fs::create_symlink(dir / "nowhere", dangling);
  CHECK_FALSE(output_file::open(dangling, "write-oem").ok());
  CHECK(kind_of(dir / "nowhere") == "absent");
  // A link to a regular file: the file is replaced, the link kept.
  const std::string target = dir / "target", link = dir / "link";
  write_text(target, "old\n");
  fs::create_symlink(target, link);
  {
    auto f = output_file::open(link, "write-oem");
    REQUIRE(f.ok());
    REQUIRE(f.value().write("new\n").ok());
    REQUIRE(f.value().commit().ok());
  }
  CHECK(kind_of(link) == "link");
  CHECK(read_file(target) == "new\n");
  // A character device: written directly, never replaced (/dev/null stays a device).
  {
    auto f = output_file::open("/dev/null", "write-oem");
    REQUIRE(f.ok());
    CHECK(f.value().direct());
    REQUIRE(f.value().write("x").ok());
    REQUIRE(f.value().commit().ok());
  }
  CHECK(kind_of("/dev/null") == "device");
  // A full device: the write error, with errno's text.
  {
    auto f = output_file::open("/dev/full", "write-aem");
    REQUIRE(f.ok());
    const auto written = f.value().write(std::string(1 << 16, 'x'));
    REQUIRE_FALSE(written.ok());
    CHECK(written.error().text() ==
          "--write-aem: cannot write '/dev/full': No space left on device");
    CHECK_FALSE(f.value().commit().ok());
  }
  CHECK(kind_of("/dev/full") == "device");
  CHECK(dir.names() == std::vector<std::string>{"d", "dangling", "link", "read-only", "target"});
}

TEST_CASE("outputs: a FIFO is written directly and stays a FIFO", "[reliability][outputs]") {
  scratch_dir dir;
  const std::string fifo = dir / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  REQUIRE(reader >= 0);
  {
    auto f = output_file::open(fifo, "write-oem");
    REQUIRE(f.ok());
    CHECK(f.value().direct());
    REQUIRE(f.value().write("through\n").ok());
    REQUIRE(f.value().commit().ok());
  }
  char buffer[16] = {};
  CHECK(::read(reader, buffer, sizeof buffer) == 8);
  ::close(reader);
  CHECK(std::string(buffer) == "through\n");
  CHECK(kind_of(fifo) == "fifo");
}

TEST_CASE("outputs: only our own temporary file is ever removed", "[reliability][outputs]") {
  scratch_dir dir;
  const std::string path = dir / "out.oem";
  // Another process's file of the temporary's form (a crashed run, or a namesake): kept.
  const std::string namesake = path + ".tmp-" + std::to_string(::getpid()) + "-0";
  write_text(namesake, "not ours\n");
  {
    auto f = output_file::open(path, "write-oem");
    REQUIRE(f.ok());
    REQUIRE(f.value().write("ours\n").ok());
  }  // abandoned
  CHECK(read_file(namesake) == "not ours\n");
  CHECK(dir.names() ==
        std::vector<std::string>{"out.oem.tmp-" + std::to_string(::getpid()) + "-0"});
}

TEST_CASE("outputs: two paths of one file are one output", "[reliability][outputs]") {
  scratch_dir dir;
  using conescan::text::same_output_file;
  CHECK(same_output_file(dir / "a", dir / "a"));
  CHECK(same_output_file(dir / "a", dir.path.string() + "/./a"));
  CHECK_FALSE(same_output_file(dir / "a", dir / "b"));
  write_text(dir / "b", "");
  fs::create_symlink(dir / "b", dir / "c");
  CHECK(same_output_file(dir / "b", dir / "c"));
}

// --- End to end: the audit's commands -----------------------------------------------------------

TEST_CASE("outputs: --summary-state on a directory fails before the CSV and deletes nothing",
          "[reliability][outputs][regression]") {
  scratch_dir dir;
  const std::string d = dir / "d";
  fs::create_directory(d);
  const auto r = run_sim("--summary --summary-state " + d + scene);
  CHECK(r.exit_status == 1);
  CHECK(r.out.empty());
  CHECK(r.err == "conescan-sim: --summary-state: cannot write '" + d + "': Is a directory\n");
  CHECK(kind_of(d) == "directory");
  // A device is written directly, never removed or replaced.
  CHECK(run_sim("--summary --summary-state /dev/null" + scene).exit_status == 0);
  CHECK(kind_of("/dev/null") == "device");
  const auto full = run_sim("--summary --summary-state /dev/full" + scene);
  CHECK(full.exit_status == 1);
  CHECK(full.err.find("No space left on device") != std::string::npos);
  CHECK(kind_of("/dev/full") == "device");
}

TEST_CASE("outputs: --write-oem and --write-aem keep devices, FIFOs, links and read-only files",
          "[reliability][outputs][regression]") {
  scratch_dir dir;
  for (const char* option : {"--write-oem", "--write-aem"}) {
    INFO(option);
    CHECK(run_sim(std::string(option) + " /dev/null" + scene).exit_status == 0);
    CHECK(kind_of("/dev/null") == "device");
    const auto full = run_sim(std::string(option) + " /dev/full" + scene);
    CHECK(full.exit_status == 1);
    CHECK(full.out.empty());
    CHECK(full.err.find("cannot write '/dev/full': No space left on device") != std::string::npos);
    const std::string read_only = dir / "read-only";
    write_text(read_only, "keep\n");
    ::chmod(read_only.c_str(), 0444);
    const auto denied = run_sim(std::string(option) + " " + read_only + scene);
    CHECK(denied.exit_status == 1);
    CHECK(read_file(read_only) == "keep\n");
    fs::remove(read_only);
  }
  const std::string target = dir / "orbit.oem", link = dir / "link.oem";
  write_text(target, "old\n");
  fs::create_symlink(target, link);
  REQUIRE(run_sim("--write-oem " + link + scene).exit_status == 0);
  CHECK(kind_of(link) == "link");
  CHECK(read_file(target).rfind("CCSDS_OEM_VERS", 0) == 0);
  CHECK_FALSE(dir.has_temporary());
}

TEST_CASE("outputs: a file-size limit ends --write-oem with exit 1, a message, no file",
          "[reliability][outputs][regression]") {
  scratch_dir dir;
  const std::string big = dir / "big.oem";
  // 86 401 lines of ~130 bytes against a limit of 4 blocks of 1 KiB.
  const auto r = run_sim("--write-oem " + big + " --duration-s 86400 --step-s 1", "ulimit -f 4;");
  CHECK(r.exit_status == 1);
  CHECK(r.out.empty());
  CHECK(r.err == "conescan-sim: --write-oem: cannot write '" + big + "': File too large\n");
  CHECK(dir.names().empty());
}

TEST_CASE("outputs: one file named by two outputs is refused before anything is written",
          "[reliability][outputs][regression]") {
  scratch_dir dir;
  const std::string x = dir / "x";
  const auto r = run_sim("--write-oem " + x + " --write-aem " + dir.path.string() + "/./x" + scene);
  CHECK(r.exit_status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("--write-aem: '") != std::string::npos);
  CHECK(r.err.find("is also the file of --write-oem") != std::string::npos);
  const auto state = run_sim("--summary --summary-state " + x + " --write-aem " + x + scene);
  CHECK(state.exit_status == 2);
  CHECK(dir.names().empty());
}

TEST_CASE("outputs: no output is written over a file the run reads",
          "[reliability][outputs][regression]") {
  // --residuals over --telemetry once replaced the telemetry with its residuals, exit 0.
  scratch_dir dir;
  const std::string telemetry = dir / "telemetry.csv";
  const std::string fit_scene = " --model scan --duration-s 300 --head beta=90 --head beta=-90";
  REQUIRE(run_sim(fit_scene.substr(1) + " > " + telemetry).exit_status == 0);
  const std::string before = read_file(telemetry);
  for (const std::string& path : {telemetry, dir.path.string() + "/./telemetry.csv"}) {
    const auto fit =
        conescan_test::run_program(CONESCAN_FIT_PATH, "--telemetry " + telemetry + fit_scene +
                                                          " --free h1.sigma --residuals " + path);
    CHECK(fit.exit_status == 2);
    CHECK(fit.err.find("--residuals: '" + path +
                       "' is the file of --telemetry, which this run "
                       "reads") != std::string::npos);
  }
  CHECK(read_file(telemetry) == before);
  // The scene's sources alike: --write-oem over the --oem it reads.
  const std::string orbit = dir / "orbit.oem";
  REQUIRE(run_sim("--duration-s 60 --write-oem " + orbit + " > /dev/null").exit_status == 0);
  const std::string orbit_before = read_file(orbit);
  const auto over = run_sim("--duration-s 60 --oem " + orbit + " --write-oem " + orbit);
  CHECK(over.exit_status == 2);
  CHECK(over.out.empty());
  CHECK(over.err.find("is the file of --oem, which this run reads") != std::string::npos);
  CHECK(read_file(orbit) == orbit_before);
}

// --- Property: every input is read and checked before the first byte of any output -------------

TEST_CASE("outputs: no output is written or replaced when any input is bad",
          "[reliability][outputs][property]") {
  scratch_dir dir;
  // Bad inputs of each kind: an option, a source file, --apply's fit (malformed; another head
  // count; an edited estimate), each refused with exit 2.
  write_text(dir / "malformed.json", "{\"kind\": \"fit\", ");
  std::string edited = read_file(fit_h1);
  edited.replace(edited.find("\"estimate\": 0.009979862851440957"), 32, "\"estimate\": -5");
  write_text(dir / "edited.json", edited);
  write_text(dir / "bad.oem", "CCSDS_OEM_VERS = 2.0\nnot an OEM\n");
  const std::vector<std::string> bad_inputs = {
      "--model scan --apply " + dir / "malformed.json",
      "--model scan --apply " + data + "/calibration/fit-h2.json",  // two heads, the scene one
      "--model scan --apply " + dir / "edited.json",
      "--oem " + dir / "bad.oem",
      "--e 2",
  };
  // Every combination of the three outputs, each over an earlier file that must stay as it was.
  std::mt19937 draw(28);
  for (const std::string& bad : bad_inputs)
    for (int mask = 1; mask < 8; ++mask) {
      std::string args = bad + scene;
      std::vector<std::string> outputs;
      const char* names[] = {"--write-oem", "--write-aem", "--summary-state"};
      for (int k = 0; k < 3; ++k)
        if (mask & (1 << k)) {
          outputs.push_back(dir / ("out" + std::to_string(k)));
          write_text(outputs.back(), "earlier " + std::to_string(draw()) + "\n");
          args += std::string(" ") + names[k] + " " + outputs.back();
        }
      std::vector<std::string> before;
      for (const std::string& o : outputs) before.push_back(read_file(o));
      const auto r = run_sim(args);
      INFO(args << "\n" << r.err);
      CHECK(r.exit_status == 2);
      CHECK(r.out.empty());
      for (std::size_t k = 0; k < outputs.size(); ++k) CHECK(read_file(outputs[k]) == before[k]);
      CHECK_FALSE(dir.has_temporary());
    }
}

TEST_CASE("outputs: an edited fit is refused by --apply, not read by half",
          "[reliability][outputs][regression]") {
  scratch_dir dir;
  const std::string original = read_file(fit_h1);
  const auto edited = [&](const std::string& from, const std::string& to) {
    std::string text = original;
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    const std::string path = dir / ("fit" + std::to_string(text.size() + to.size()) + ".json");
    write_text(path, text.replace(at, from.size(), to));
    return path;
  };
  // A parameter's estimate that the coordinates do not say (-5, 1e300): refused, naming both.
  for (const std::string value : {"-5", "1e300"}) {
    const auto r =
        run_sim("--model scan --apply " +
                edited("\"estimate\": 0.009979862851440957", "\"estimate\": " + value) + scene);
    CHECK(r.exit_status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find("coordinate h1.misalign-x") != std::string::npos);
  }
  // A coordinate of 1e300 (which made every row invalid with exit 0).
  const auto huge =
      run_sim("--model scan --apply " +
              edited("\"estimate\": [0.009404976895626608", "\"estimate\": [1e300") + scene);
  CHECK(huge.exit_status == 2);
  CHECK(huge.err.find("disagrees with the parameters' estimate") != std::string::npos);
  // A held value outside the model's domain.
  const auto domain = run_sim(
      "--model scan --apply " +
      edited("\"h1.bias-in\": {\"estimate\": 0", "\"h1.bias-in\": {\"estimate\": 50") + scene);
  CHECK(domain.exit_status == 2);
  CHECK(domain.err.find("outside the model's domain") != std::string::npos);
  CHECK(domain.err.find("bias-in = 50") != std::string::npos);
  // The fit as written still corrects.
  CHECK(run_sim("--model scan --apply " + fit_h1 + scene).exit_status == 0);
}
