/// \file test_cli.cpp End-to-end tests of the command-line triangulator delaunay2d: degenerate
/// families validated exactly from the written .ele, bad input rejected cleanly, and outputs
/// that keep their promises whatever they are (files, symlinks, pipes, devices, standard
/// output) and whatever happens (signals, concurrent runs, limits, full disks).
#include <doctest/doctest.h>

#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <sched.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

#include "support.h"
#include "fast_parallel.h"
#include "output_files.h"
#include "parallel_for.h"
// The chapter programs' plumbing (the figure check); its default output directory is unused.
#ifndef DT_OUTPUT_DIR
#define DT_OUTPUT_DIR DT_TEST_TMP
#endif
#include "../chapters/common.h"

using dt::XY;

namespace {

// Runs the CLI on p and validates out.ele exactly; every distinct point must be a vertex.
void runAndValidate(const std::string& name, const XY& p, int first = 1) {
  const std::string in = dttest::tmpPath(name + ".node"), out = dttest::tmpPath(name + "_out");
  std::remove((out + ".ele").c_str());
  dttest::writeText(in, dttest::nodeText(p, first));
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --stats");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto tri = dttest::readEle(out + ".ele", first);
  // Points equal to an earlier one are merged: they must not be used, the others must.
  std::map<std::pair<double, double>, int> firstSeen;
  std::vector<char> must(p.size() / 2, 0);
  for (std::size_t i = 0; i < p.size() / 2; ++i)
    if (firstSeen.emplace(std::make_pair(p[2 * i], p[2 * i + 1]), int(i)).second) must[i] = 1;
  int outOfRange = 0, mergedUsed = 0;
  for (const auto& t : tri)
    for (int v : t) {
      if (v < 0 || v >= int(must.size())) ++outOfRange;
      else if (!must[v]) ++mergedUsed;
    }
  REQUIRE(outOfRange == 0);
  CHECK_MESSAGE(mergedUsed == 0, "a merged duplicate is used by a triangle");
  const dt::CheckReport c = dt::checkDelaunay(p, tri, &must);
  CHECK_MESSAGE(c.ok, name << ": " << c.error);
  CHECK(r.out.find("points: " + std::to_string(p.size() / 2)) != std::string::npos);
  CHECK(r.out.find("triangles: " + std::to_string(tri.size())) != std::string::npos);
  CHECK(r.out.find("triangulation_seconds: ") != std::string::npos);
  // Of that time, the system's part: a share of it (getrusage may count a whole clock tick to
  // the system, hence the slack).
  const std::size_t at = r.out.find("triangulation_system_seconds: ");
  REQUIRE(at != std::string::npos);
  const double sys = std::stod(r.out.substr(at + 30));
  const double all = std::stod(r.out.substr(r.out.find("triangulation_seconds: ") + 23));
  CHECK(sys >= 0);
  CHECK(sys <= all + 0.05);
}

}  // namespace

TEST_CASE("cli delaunay2d writes the exact DT(S) on degenerate families") {
  runAndValidate("grid", dt::gridPoints(30, 30));
  // an integer grid rotated by an angle with rational cos and sin (3/5, 4/5)
  runAndValidate("grid_rotated", dt::rotatedGridPoints(20, 20));
  runAndValidate("circle", dt::circlePoints(400));
  XY col;
  for (int i = 0; i < 300; ++i) {
    col.push_back(i);
    col.push_back(2.0 * i);
  }
  col.insert(col.end(), {10, 0, 100, 500, 299, 0});
  runAndValidate("collinear", col, 0);
  XY dup = dt::uniformPoints(500, 9);
  for (int i = 0; i < 100; ++i) {
    dup.push_back(dup[2 * (i * 3)]);
    dup.push_back(dup[2 * (i * 3) + 1]);
  }
  runAndValidate("duplicates", dup);
  runAndValidate("big", dt::uniformPoints(3000, 2, 1e9, 1e9 + 1));
  runAndValidate("tiny", dt::uniformPoints(3000, 3, 1e-200, 2e-200));
  runAndValidate("convex", dt::circlePoints(1000, 1e6));
  XY sorted = dt::uniformPoints(5000, 4);
  std::vector<std::pair<double, double>> v;
  for (std::size_t i = 0; i < sorted.size() / 2; ++i) v.emplace_back(sorted[2 * i], sorted[2 * i + 1]);
  std::sort(v.begin(), v.end());
  for (std::size_t i = 0; i < v.size(); ++i) {
    sorted[2 * i] = v[i].first;
    sorted[2 * i + 1] = v[i].second;
  }
  runAndValidate("sorted_by_x", sorted);
}

TEST_CASE("cli delaunay2d merges duplicates into the first number and reports them") {
  const std::string in = dttest::tmpPath("dups.xy"), out = dttest::tmpPath("dups_out");
  dttest::writeText(in, "0 0\n1 0\n0 1\n1 0\n1 1\n");
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "'");
  REQUIRE(r.status == 0);
  CHECK(r.err.find("point 4 duplicates point 2") != std::string::npos);
  const std::string ele = dttest::readText(out + ".ele");
  CHECK(ele.find(" 4") == std::string::npos);  // point 4 is used by no triangle
  CHECK(ele.rfind("2 3 0", 0) == 0);            // header: two triangles
}

TEST_CASE("cli delaunay2d answers bad input with a message naming the problem and exit 2 and no output") {
  struct Bad {
    const char* name;
    const char* text;
    const char* expect;  // a piece of the message
  };
  const Bad cases[] = {
      {"malformed.node", "3 2 0 0\n1 0 0\n2 1 zero\n3 0 1\n", "malformed.node:3: y 'zero' is not a number"},
      {"count.node", "4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n", "of the 4 points announced"},
      {"nan.xy", "0 0\n1 0\nnan 1\n", "nan.xy:3: x 'nan' is NaN"},
      {"inf.xy", "0 0\n1 0\n0 1e999\n", "nan"},
      {"two.xy", "0 0\n1 1\n0 0\n", "fewer than 3 distinct points"},
      {"line.xy", "0 0\n1 1\n2 2\n3 3\n", "all points are collinear"},
  };
  for (const Bad& b : cases) {
    CAPTURE(b.name);
    const std::string in = dttest::tmpPath(b.name), out = dttest::tmpPath(std::string(b.name) + "_out");
    std::remove((out + ".ele").c_str());
    dttest::writeText(in, b.text);
    const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "'");
    CHECK(r.status == 2);
    if (std::string(b.name) == "inf.xy")
      CHECK(r.err.find("inf.xy:3: y '1e999' overflows a double") != std::string::npos);
    else
      CHECK_MESSAGE(r.err.find(b.expect) != std::string::npos, r.err);
    CHECK_FALSE(dttest::fileExists(out + ".ele"));
  }
  const dttest::CliResult r = dttest::runCli("'" + dttest::tmpPath("does_not_exist.node") + "' -o x");
  CHECK(r.status == 2);
  CHECK(r.err.find("cannot open") != std::string::npos);
}

namespace {

// The files of a directory whose name starts with `prefix` (temporaries left behind).
std::vector<std::string> filesStartingWith(const std::string& dir, const std::string& prefix) {
  std::vector<std::string> found;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.compare(0, prefix.size(), prefix) == 0) found.push_back(name);
  }
  return found;
}

// A directory of its own for each test of the outputs.
std::string freshDir(const std::string& name) {
  const std::string d = dttest::tmpPath("outputs_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

const char* kSquare = "0 0\n1 0\n0 1\n1 1\n";

}  // namespace

TEST_CASE("cli a failed run leaves every pre-existing output as it was") {
  const std::string d = freshDir("keep"), in = d + "/in.xy", out = d + "/out";
  dttest::writeText(in, kSquare);
  dttest::writeText(out + ".ele", "OLD ELE\n");
  dttest::writeText(d + "/old.svg", "OLD SVG\n");
  // The .msh cannot be created: the .ele and the SVG were written, but are not put in place.
  dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --svg '" + d +
                                       "/old.svg' --msh '" + d + "/no/such/dir.msh'");
  CHECK(r.status == 1);
  CHECK_MESSAGE(r.err.find("no/such/dir.msh: cannot open for writing: No such file or directory") !=
                    std::string::npos, r.err);
  CHECK(dttest::readText(out + ".ele") == "OLD ELE\n");
  CHECK(dttest::readText(d + "/old.svg") == "OLD SVG\n");
  CHECK(filesStartingWith(d, ".dttmp-").empty());
  // Bad input: exit 2, the old files untouched.
  dttest::writeText(d + "/bad.xy", "0 0\n1 x\n");
  r = dttest::runCli("'" + d + "/bad.xy' -o '" + out + "' --svg '" + d + "/old.svg'");
  CHECK(r.status == 2);
  CHECK(dttest::readText(out + ".ele") == "OLD ELE\n");
  CHECK(dttest::readText(d + "/old.svg") == "OLD SVG\n");
  // A target that is a directory is refused before anything is read.
  std::filesystem::create_directories(d + "/adir");
  r = dttest::runCli("'" + in + "' -o '" + out + "' --svg '" + d + "/adir'");
  CHECK(r.status == 2);
  CHECK(dttest::readText(out + ".ele") == "OLD ELE\n");
  // A successful run replaces them.
  r = dttest::runCli("'" + in + "' -o '" + out + "' --svg '" + d + "/old.svg'");
  REQUIRE(r.status == 0);
  CHECK(dttest::readText(out + ".ele").rfind("2 3 0\n", 0) == 0);
  CHECK(dttest::readText(d + "/old.svg").rfind("<svg", 0) == 0);
  CHECK(filesStartingWith(d, "out.ele.").empty());
}

TEST_CASE("cli an output that is the input file or another output is refused") {
  const std::string d = freshDir("same"), in = d + "/in.xy";
  dttest::writeText(in, kSquare);
  struct Case {
    std::string args, expect;
  };
  const std::string q = "'" + in + "'";
  const Case cases[] = {
      {q + " -o '" + d + "/o' --svg " + q, "--svg: " + in + " is the input file"},
      {q + " -o '" + d + "/o' --msh " + q, "--msh: " + in + " is the input file"},
      {q + " -o '" + d + "/o' --msh '" + d + "/o.ele'", "-o " + d + "/o and --msh name the same file"},
      {q + " -o '" + d + "/o' --svg '" + d + "/f' --msh '" + d + "/./f'", "--svg and --msh name the same file"},
      // the same file under another name: a hard link (device and inode, not names)
      {q + " -o '" + d + "/o' --svg '" + d + "/alias.svg'", "--svg: " + d + "/alias.svg is the input file"},
  };
  std::filesystem::create_hard_link(in, d + "/alias.svg");
  for (const Case& c : cases) {
    CAPTURE(c.args);
    const dttest::CliResult r = dttest::runCli(c.args);
    CHECK(r.status == 2);
    CHECK_MESSAGE(r.err.find("delaunay2d: " + c.expect) != std::string::npos, r.err);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(dttest::readText(in) == kSquare);
    CHECK_FALSE(dttest::fileExists(d + "/o.ele"));
    CHECK_FALSE(dttest::fileExists(d + "/f"));
  }
  // An "x y" file named pts.ele with -o pts.
  dttest::writeText(d + "/pts.ele", kSquare);
  const dttest::CliResult r = dttest::runCli("'" + d + "/pts.ele' -o '" + d + "/pts'");
  CHECK(r.status == 2);
  CHECK(r.err.find("is the input file; refusing to overwrite it") != std::string::npos);
  CHECK(dttest::readText(d + "/pts.ele") == kSquare);
}

TEST_CASE("cli outputs are planned once and a refusal names the option that asked") {
  const std::string d = freshDir("plan"), in = d + "/in.xy";
  dttest::writeText(in, kSquare);
  dttest::writeText(d + "/old.svg", "OLD\n");
  const dt::OutputPlan plan = dt::planOutputs({{"-o " + d + "/o", d + "/o.ele"}, {"--svg", d + "/old.svg"},
                                               {"--msh", "-"}}, in);
  REQUIRE(plan.targets.size() == 3);
  CHECK(plan.targets[0].kind == dt::OutputTarget::File);
  CHECK_FALSE(plan.targets[0].exists);
  CHECK(plan.targets[1].exists);
  CHECK(plan.targets[2].kind == dt::OutputTarget::Stream);
  CHECK(plan.toStandardOutput);
  CHECK_FALSE(dt::planOutputs({{"--svg", d + "/a.svg"}}, "-").toStandardOutput);
  // Each refusal names the option (or both options) that asked for the path.
  auto refusal = [&](const std::vector<dt::OutputRequest>& list, const std::string& input) {
    try {
      dt::planOutputs(list, input);
    } catch (const dt::OutputConflict& e) {
      return std::string("conflict: ") + e.what();
    } catch (const dt::OutputRefused& e) {
      return std::string("refused: ") + e.what();
    }
    return std::string("planned");
  };
  CHECK(refusal({{"-o x", d + "/x.ele"}, {"--svg", in}}, in) == "refused: --svg: " + in + " is the input file; refusing to overwrite it");
  CHECK(refusal({{"--svg", d + "/f"}, {"--msh", d + "/./f"}}, in) == "refused: --svg and --msh name the same file " + d + "/./f");
  CHECK(refusal({{"-o -", "-"}, {"--svg", "-"}}, in) == "conflict: -o - and --svg both write to standard output");
  CHECK(refusal({{"--svg", d}}, in).rfind("refused: --svg " + d + ": is a directory", 0) == 0);
  // The plan is what is opened: a hook passed to the commit sees every rename, in order.
  const dt::OutputPlan two = dt::planOutputs({{"--svg", d + "/a.svg"}, {"--msh", d + "/old.svg"}}, in);
  dt::OutputFiles files(two);
  files.writer(0).put("A\n");
  files.writer(1).put("B\n");
  std::vector<std::size_t> seen;
  dt::OutputHooks hooks;
  hooks.afterRename = [&](std::size_t renamed) {
    seen.push_back(renamed);
    CHECK(dttest::fileExists(d + "/a.svg"));
  };
  files.commit(dt::OutputFiles::AfterCommit::RestoreSignals, hooks);
  CHECK(seen == std::vector<std::size_t>{1, 2});
  CHECK(dttest::readText(d + "/a.svg") == "A\n");
  CHECK(dttest::readText(d + "/old.svg") == "B\n");
}

TEST_CASE("cli killed while its outputs are written it leaves no temporary and keeps the old files") {
  const std::string d = freshDir("killed"), in = d + "/in.xy", out = d + "/out";
  dttest::writeText(in, kSquare);
  dttest::writeText(out + ".ele", "OLD ELE\n");
  // --hold-outputs (the tests' driver, tests/hooks): the CLI stops once the temporaries are
  // written, says "holding", and waits; the signal comes then.
  // The paths reach the script through the environment (D, DT_CLI_HOOKED_BIN), never as code.
  const std::string script =
      "\"$DT_CLI_HOOKED_BIN\" --hold-outputs 60 \"$D/in.xy\" -o \"$D/out\" "
      "--svg \"$D/s.svg\" 2> \"$D/err\" & pid=$!; "
      "for i in $(seq 300); do grep -q holding \"$D/err\" && break; sleep 0.1; done; "
      "ls -a \"$D\" > \"$D/during\"; kill -TERM $pid; wait $pid; echo $? > \"$D/status\"";
  dttest::writeText(d + "/kill.sh", script + "\n");
  ch::ProcessIo io;
  io.stderrPath = "/dev/null";
  io.env = {{"D", d}, {"DT_CLI_HOOKED_BIN", DT_CLI_HOOKED}};
  REQUIRE(ch::runProgram({"sh", d + "/kill.sh"}, io) == 0);
  const std::string during = dttest::readText(d + "/during");
  // The signal came while both temporaries existed.
  const std::size_t first = during.find(".dttmp-");
  CHECK(first != std::string::npos);
  CHECK(during.find(".dttmp-", first + 1) != std::string::npos);
  CHECK(dttest::readText(d + "/status") == "143\n");  // 128 + SIGTERM: the signal's own status
  CHECK(filesStartingWith(d, ".dttmp-").empty());
  CHECK(filesStartingWith(d, "s.svg").empty());
  CHECK(dttest::readText(out + ".ele") == "OLD ELE\n");
}

TEST_CASE("cli the SVG of subnormal or near-overflow coordinates has finite coordinates") {
  const double tiny = 4.9406564584124654e-324, huge = 1.7976931348623157e308;
  const std::vector<std::pair<const char*, XY>> sets = {
      {"subnormal", {0, 0, 3 * tiny, 0, 0, 2 * tiny, 3 * tiny, 5 * tiny, tiny, tiny}},
      {"near_max", {-huge, -huge, huge, -huge, -huge, huge, huge, huge, 0, 1e300}},
      {"tiny_span", {1e-310, 1e-310, 1.5e-310, 1e-310, 1e-310, 1.25e-310, 1.2e-310, 1.2e-310}},
  };
  for (const auto& [name, p] : sets) {
    CAPTURE(name);
    const std::string in = dttest::tmpPath(std::string("svg_") + name + ".node");
    const std::string svg = dttest::tmpPath(std::string("svg_") + name + ".svg");
    dttest::writeText(in, dttest::nodeText(p));
    const dttest::CliResult r =
        dttest::runCli("'" + in + "' -o '" + dttest::tmpPath("svg_out") + "' --svg '" + svg + "'");
    REQUIRE_MESSAGE(r.status == 0, r.err);
    const std::string s = dttest::readText(svg);
    CHECK(s.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"800\">\n", 0) == 0);
    CHECK(s.size() > 7);
    CHECK(s.substr(s.size() - 7) == "</svg>\n");
    // Every polygon: three "x,y" pairs of finite numbers inside the 800-pixel square.
    std::istringstream lines(s);
    int polygons = 0;
    double lo = 1e9, hi = -1e9;
    for (std::string l; std::getline(lines, l);) {
      if (l.rfind("<polygon points=\"", 0) != 0) continue;
      ++polygons;
      const std::string pts = l.substr(17, l.find('"', 17) - 17);
      std::istringstream ps(pts);
      int pairs = 0;
      for (std::string xy; ps >> xy; ++pairs) {
        const std::size_t comma = xy.find(',');
        REQUIRE(comma != std::string::npos);
        const double x = std::strtod(xy.c_str(), nullptr), y = std::strtod(xy.c_str() + comma + 1, nullptr);
        CHECK(std::isfinite(x));
        CHECK(std::isfinite(y));
        CHECK((x >= 0 && x <= 800 && y >= 0 && y <= 800));
        lo = std::min({lo, x, y});
        hi = std::max({hi, x, y});
      }
      CHECK(pairs == 3);
    }
    CHECK(polygons > 0);
    CHECK(hi - lo > 700);  // the drawing fills the picture, not collapsed to a point
  }
}

TEST_CASE("cli one line per error with the error first") {
  const std::string d = freshDir("messages"), in = d + "/in.xy", out = d + "/o";
  dttest::writeText(in, kSquare);
  // A usage error: one line naming the problem and pointing to --help.
  dttest::CliResult r = dttest::runCli("'" + in + "' -o a -o b");
  CHECK(r.status == 2);
  CHECK(r.err == "delaunay2d: option -o given twice (usage: delaunay2d INPUT -o OUT [options]; "
                 "delaunay2d --help for more)\n");
  r = dttest::runCli("'" + in + "' -o '" + out + "' --order input --order brio");
  CHECK(r.status == 2);
  CHECK(r.err.find("option --order given twice") != std::string::npos);
  r = dttest::runCli("'" + in + "' -o '" + out + "' --progress --no-progress");
  CHECK(r.status == 2);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  r = dttest::runCli("");
  CHECK(r.status == 2);
  CHECK(r.err.find("no input file") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  // Duplicates and then a failure: the error line first, the notes after it.
  dttest::writeText(d + "/dups.xy", "0 0\n1 0\n0 1\n1 0\n1 1\n");
  r = dttest::runCli("'" + d + "/dups.xy' -o '" + out + "' --svg '" + d + "/no/dir.svg'");
  CHECK(r.status == 1);
  CHECK_MESSAGE(r.err.rfind("delaunay2d: error: " + d + "/no/dir.svg: cannot open for writing: ", 0) == 0, r.err);
  CHECK(r.err.find("point 4 duplicates point 2 (line 2); merged") != std::string::npos);
  // Without a triangulation, the duplicate notes are not shown: one line.
  dttest::writeText(d + "/two.xy", "0 0\n1 1\n0 0\n1 1\n1 1\n");
  for (const char* kernel : {"fast", "listings"}) {
    r = dttest::runCli("'" + d + "/two.xy' -o '" + out + "' --kernel " + kernel);
    CHECK(r.status == 2);
    CHECK_MESSAGE(r.err == "delaunay2d: " + d + "/two.xy: fewer than 3 distinct points: no "
                           "triangulation exists\n", r.err);
  }
  // An output that cannot be written gives the system's reason.
  r = dttest::runCli("'" + in + "' -o '" + d + "/none/o'");
  CHECK(r.status == 1);
  CHECK(r.err.find("none/o.ele: cannot open for writing: No such file or directory") != std::string::npos);
}

// ---- what an output is: a file, a symlink, a pipe, a device, standard output ----------

namespace {

// What lstat says a path is: 'f' regular file, 'l' symlink, 'p' named pipe, 'c' character
// device, 'b' block device, 'd' directory, 's' socket, '-' nothing.
char kindOf(const std::string& path) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0) return '-';
  if (S_ISREG(st.st_mode)) return 'f';
  if (S_ISLNK(st.st_mode)) return 'l';
  if (S_ISFIFO(st.st_mode)) return 'p';
  if (S_ISCHR(st.st_mode)) return 'c';
  if (S_ISBLK(st.st_mode)) return 'b';
  if (S_ISDIR(st.st_mode)) return 'd';
  return 's';
}

std::string linkText(const std::string& path) {
  char buf[4096];
  const ssize_t n = ::readlink(path.c_str(), buf, sizeof buf);
  return n < 0 ? std::string() : std::string(buf, std::size_t(n));
}

// Runs a shell script (written to DIR/NAME.sh) with sh; returns its exit status. The
// triangulator's path reaches the script through the environment (cli() below): a build path
// may hold a quote or a space, which no quoting pasted into the script survives.
int runScript(const std::string& dir, const std::string& name, const std::string& script) {
  dttest::writeText(dir + "/" + name + ".sh", script + "\n");
  ch::ProcessIo io;
  io.env = {{"DT_CLI_BIN", DT_CLI}, {"DT_CLI_HOOKED_BIN", DT_CLI_HOOKED}};
  const int rc = ch::runProgram({"sh", dir + "/" + name + ".sh"}, io);
  return rc >= 0 && rc < 128 ? rc : -1;
}

// The triangulator in a script of runScript: its path, expanded by the shell, never parsed.
std::string cli() { return "\"$DT_CLI_BIN\""; }

// The same program with test hooks (tests/hooks/delaunay2d_hooked.cpp), in a script of
// runScript: its options --hold-outputs and --commit-pause-ms come first.
std::string hookedCli() { return "\"$DT_CLI_HOOKED_BIN\""; }

// Every name in `dir` containing ".dttmp-": temporaries (or their backups) left behind.
std::vector<std::string> temporariesIn(const std::string& dir) {
  std::vector<std::string> found;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d))
      if (std::string(e->d_name).find(".dttmp-") != std::string::npos) found.push_back(e->d_name);
    ::closedir(d);
  }
  return found;
}

// A 300-point input and the .ele, SVG and .msh a plain run writes of it (to compare with).
struct Reference {
  std::string in, ele, svg, msh;
};
Reference reference(const std::string& d) {
  Reference r;
  r.in = d + "/in.node";
  dttest::writeText(r.in, dttest::nodeText(dt::uniformPoints(300, 17)));
  const dttest::CliResult c = dttest::runCli("'" + r.in + "' -o '" + d + "/ref' --svg '" + d +
                                             "/ref.svg' --msh '" + d + "/ref.msh'");
  REQUIRE_MESSAGE(c.status == 0, c.err);
  r.ele = dttest::readText(d + "/ref.ele");
  r.svg = dttest::readText(d + "/ref.svg");
  r.msh = dttest::readText(d + "/ref.msh");
  REQUIRE(r.ele.rfind("5", 0) == 0);  // some 580 triangles
  return r;
}

}  // namespace

TEST_CASE("cli an output that is a symlink is written to the file it points to and stays a link") {
  const std::string d = freshDir("symlink");
  const Reference ref = reference(d);
  std::filesystem::create_directories(d + "/real");
  dttest::writeText(d + "/real/target.svg", "OLD SVG\n");
  ::chmod((d + "/real/target.svg").c_str(), 0640);
  REQUIRE(::symlink("real/target.svg", (d + "/link.svg").c_str()) == 0);
  REQUIRE(::symlink("real/made.msh", (d + "/dangling.msh").c_str()) == 0);
  REQUIRE(::symlink("real/out.ele", (d + "/o.ele").c_str()) == 0);
  const dttest::CliResult r = dttest::runCli("'" + ref.in + "' -o '" + d + "/o' --svg '" + d +
                                             "/link.svg' --msh '" + d + "/dangling.msh'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  // The links stay links to the same names; the files they point to got the outputs.
  CHECK(kindOf(d + "/link.svg") == 'l');
  CHECK(linkText(d + "/link.svg") == "real/target.svg");
  CHECK(kindOf(d + "/o.ele") == 'l');
  CHECK(kindOf(d + "/dangling.msh") == 'l');  // a dangling link: its target is created
  CHECK(dttest::readText(d + "/real/target.svg") == ref.svg);
  CHECK(dttest::readText(d + "/real/out.ele") == ref.ele);
  CHECK(dttest::readText(d + "/real/made.msh") == ref.msh);
  struct stat st;
  REQUIRE(::stat((d + "/real/target.svg").c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0640);  // the replaced file keeps its mode
  CHECK(temporariesIn(d).empty());
  CHECK(temporariesIn(d + "/real").empty());
  // A dangling link into a missing directory: one line with the system's reason, exit 1, the
  // other outputs not replaced.
  REQUIRE(::symlink("nowhere/x.svg", (d + "/lost.svg").c_str()) == 0);
  dttest::writeText(d + "/real/out.ele", "OLD ELE\n");
  const dttest::CliResult lost =
      dttest::runCli("'" + ref.in + "' -o '" + d + "/o' --svg '" + d + "/lost.svg'");
  CHECK(lost.status == 1);
  CHECK_MESSAGE(lost.err == "delaunay2d: error: " + d + "/lost.svg: cannot open for writing: No "
                            "such file or directory\n", lost.err);
  CHECK(kindOf(d + "/lost.svg") == 'l');
  CHECK(dttest::readText(d + "/real/out.ele") == "OLD ELE\n");
  CHECK(temporariesIn(d + "/real").empty());
}

TEST_CASE("cli a named pipe output with a reader gets every byte and stays a pipe") {
  const std::string d = freshDir("fifo");
  const Reference ref = reference(d);
  REQUIRE(::mkfifo((d + "/p.svg").c_str(), 0644) == 0);
  REQUIRE(::mkfifo((d + "/p.ele").c_str(), 0644) == 0);
  // Two readers wait; the run writes into both pipes, and its status is saved. (A run that
  // replaced a pipe would leave its reader waiting on the unnamed pipe: timeout ends it.)
  const int rc = runScript(d, "fifo",
      "timeout 30 cat '" + d + "/p.svg' > '" + d + "/got.svg' & a=$!\n"
      "timeout 30 cat '" + d + "/p.ele' > '" + d + "/got.ele' & b=$!\n" +
      cli() + " '" + ref.in + "' -o '" + d + "/p' --svg '" + d + "/p.svg' --msh '" + d +
      "/m.msh' 2> '" + d + "/err'; s=$?\nwait $a $b\nexit $s");
  CHECK_MESSAGE(rc == 0, dttest::readText(d + "/err"));
  CHECK(dttest::readText(d + "/got.svg") == ref.svg);
  CHECK(dttest::readText(d + "/got.ele") == ref.ele);
  CHECK(dttest::readText(d + "/m.msh") == ref.msh);
  CHECK(kindOf(d + "/p.svg") == 'p');
  CHECK(kindOf(d + "/p.ele") == 'p');
  CHECK(temporariesIn(d).empty());
}

TEST_CASE("cli a reader that leaves a pipe halfway fails the run with a partial write and no file replaced") {
  const std::string d = freshDir("fifo_half"), in = d + "/in.node";
  dttest::writeText(in, dttest::nodeText(dt::uniformPoints(20000, 3)));  // an SVG of about 3 MB
  dttest::writeText(d + "/o.ele", "OLD ELE\n");
  REQUIRE(::mkfifo((d + "/p.svg").c_str(), 0644) == 0);
  const int rc = runScript(d, "half",
      "timeout 30 head -c 1000 '" + d + "/p.svg' > '" + d + "/got' & a=$!\n" +
      cli() + " '" + in + "' -o '" + d + "/o' --svg '" + d + "/p.svg' 2> '" + d +
      "/err'; s=$?\nwait $a\nexit $s");
  const std::string err = dttest::readText(d + "/err");
  CHECK(rc == 1);
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  CHECK_MESSAGE(err.find(d + "/p.svg: cannot write: Broken pipe (a stream: it got a partial write of ") !=
                    std::string::npos, err);
  CHECK(dttest::readText(d + "/got").size() == 1000);
  CHECK(dttest::readText(d + "/o.ele") == "OLD ELE\n");  // nothing else was put in place
  CHECK(kindOf(d + "/p.svg") == 'p');
  CHECK(temporariesIn(d).empty());
}

TEST_CASE("cli character devices are written into and stay devices") {
  const std::string d = freshDir("devices");
  const Reference ref = reference(d);
  // A device node of our own first (root only): if the code under test replaced it, the real
  // /dev/null and /dev/full below must not be tried (a rename would replace them for everyone).
  if (::geteuid() == 0) {
    REQUIRE(::mknod((d + "/null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0);
    const dttest::CliResult r =
        dttest::runCli("'" + ref.in + "' -o '" + d + "/o' --svg '" + d + "/null'");
    CHECK(r.status == 0);
    REQUIRE_MESSAGE(kindOf(d + "/null") == 'c', "the CLI replaced a device node: not trying /dev");
  }
  REQUIRE(kindOf("/dev/null") == 'c');
  REQUIRE(kindOf("/dev/full") == 'c');
  // /dev/full: every write fails with ENOSPC. One line with the system's reason; the .ele,
  // written beside its target, is not renamed into place.
  dttest::writeText(d + "/o.ele", "OLD ELE\n");
  dttest::CliResult r =
      dttest::runCli("'" + ref.in + "' -o '" + d + "/o' --svg /dev/null --msh /dev/full");
  CHECK(r.status == 1);
  CHECK_MESSAGE(r.err == "delaunay2d: error: /dev/full: cannot write: No space left on device (a "
                         "stream: it got a partial write of 0 bytes)\n", r.err);
  CHECK(dttest::readText(d + "/o.ele") == "OLD ELE\n");
  CHECK(temporariesIn(d).empty());
  r = dttest::runCli("'" + ref.in + "' -o '" + d + "/o' --svg /dev/null");
  CHECK(r.status == 0);
  CHECK(dttest::readText(d + "/o.ele") == ref.ele);
  CHECK(kindOf("/dev/null") == 'c');
  CHECK(kindOf("/dev/full") == 'c');
}

TEST_CASE("cli a directory or a socket or a block device output is refused with exit 2 and nothing written") {
  const std::string d = freshDir("refused"), in = d + "/in.xy", q = "'" + in + "' -o '" + d + "/o'";
  dttest::writeText(in, kSquare);
  std::filesystem::create_directories(d + "/adir");
  REQUIRE(::symlink("adir", (d + "/dirlink").c_str()) == 0);
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  REQUIRE(sock >= 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string sockPath = d + "/s.svg";
  REQUIRE(sockPath.size() < sizeof addr.sun_path);
  std::memcpy(addr.sun_path, sockPath.c_str(), sockPath.size() + 1);
  REQUIRE(::bind(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
  const std::string tail = "; an output must be a regular file, a named pipe or a character device\n";
  struct Case {
    std::string args, err;
  };
  std::vector<Case> cases = {
      {q + " --svg '" + d + "/adir'", "delaunay2d: --svg " + d + "/adir: is a directory" + tail},
      {q + " --msh '" + d + "/dirlink'", "delaunay2d: --msh " + d + "/dirlink: is a directory (the "
                                         "symlink points to " + d + "/adir)" + tail},
      {q + " --svg '" + sockPath + "'", "delaunay2d: --svg " + sockPath + ": is a socket" + tail},
      {q + " --svg '" + d + "/new/'", "delaunay2d: --svg " + d + "/new/: ends in '/', so it names "
                                      "a directory, not a file\n"},
      {"'" + in + "' -o '" + d + "/adir'", "delaunay2d: -o " + d + "/adir names a directory; -o "
       "takes a base name (-o " + d + "/adir/mesh writes " + d + "/adir/mesh.ele) (usage: "
       "delaunay2d INPUT -o OUT [options]; delaunay2d --help for more)\n"},
      {"'" + in + "' -o '" + d + "/x/'", "delaunay2d: -o " + d + "/x/ names a directory; -o "
       "takes a base name (-o " + d + "/x/mesh writes " + d + "/x/mesh.ele) (usage: "
       "delaunay2d INPUT -o OUT [options]; delaunay2d --help for more)\n"},
  };
  if (::geteuid() == 0) {
    REQUIRE(::mknod((d + "/blk").c_str(), S_IFBLK | 0600, makedev(7, 200)) == 0);
    cases.push_back({q + " --svg '" + d + "/blk'", "delaunay2d: --svg " + d + "/blk: is a block "
                                                   "device" + tail});
  }
  for (const Case& c : cases) {
    CAPTURE(c.args);
    const dttest::CliResult r = dttest::runCli(c.args);
    CHECK(r.status == 2);
    CHECK(r.err == c.err);
    CHECK(r.out.empty());
    CHECK(kindOf(d + "/o.ele") == '-');
    CHECK(kindOf(d + "/adir/.ele") == '-');
  }
  CHECK(kindOf(d + "/adir") == 'd');
  CHECK(kindOf(d + "/dirlink") == 'l');
  CHECK(kindOf(sockPath) == 's');
  if (::geteuid() == 0) CHECK(kindOf(d + "/blk") == 'b');
  CHECK(temporariesIn(d).empty());
  ::close(sock);
}

TEST_CASE("cli '-' reads standard input and writes one output to standard output through real pipes") {
  const std::string d = freshDir("dash");
  const Reference ref = reference(d);
  // .node on standard input, the .ele on standard output, --stats and progress on stderr.
  int rc = runScript(d, "both",
      "cat '" + ref.in + "' | { " + cli() + " - -o - --stats --progress 2> '" + d +
      "/err'; echo $? > '" + d + "/status'; } | cat > '" + d + "/got.ele'");
  CHECK(rc == 0);
  CHECK(dttest::readText(d + "/status") == "0\n");
  CHECK(dttest::readText(d + "/got.ele") == ref.ele);  // data only
  const std::string err = dttest::readText(d + "/err");
  CHECK(err.find("points: 300\n") != std::string::npos);
  CHECK(err.find("peak_memory_mb: ") != std::string::npos);
  // The SVG on standard output (by '-' and by /dev/stdout, which stays a symlink), 'x y' lines
  // on standard input.
  std::string xy;
  for (std::size_t i = 0; i < 300; ++i) {
    const dt::XY p = dt::uniformPoints(300, 17);
    char buf[80];
    std::snprintf(buf, sizeof buf, "%.17g %.17g\n", p[2 * i], p[2 * i + 1]);
    xy += buf;
  }
  dttest::writeText(d + "/in.xy", xy);
  for (const std::string svg : {"-", "/dev/stdout"}) {
    CAPTURE(svg);
    std::remove((d + "/x.ele").c_str());
    rc = runScript(d, "svg",
        "cat '" + d + "/in.xy' | " + cli() + " - -o '" + d + "/x' --svg " + svg + " --stats | cat > '" +
        d + "/got.svg'");
    CHECK(rc == 0);
    CHECK(dttest::readText(d + "/got.svg") == ref.svg);
    CHECK(dttest::readText(d + "/x.ele") == ref.ele);
  }
  CHECK(kindOf("/dev/stdout") == 'l');
  // Bad input on standard input is named "stdin", with its line.
  rc = runScript(d, "bad", "printf '0 0\\n1 x\\n' | " + cli() + " - -o '" + d + "/bad' 2> '" + d + "/err'");
  CHECK(rc == 2);
  CHECK(dttest::readText(d + "/err") == "delaunay2d: stdin:2: y 'x' is not a number\n");
  // Two outputs on standard output are refused, by '-' and by another name of it.
  dttest::CliResult r = dttest::runCli("'" + ref.in + "' -o - --svg -");
  CHECK(r.status == 2);
  CHECK(r.err.rfind("delaunay2d: -o - and --svg both write to standard output", 0) == 0);
  CHECK(r.out.empty());
  r = dttest::runCli("'" + ref.in + "' -o - --msh /dev/stdout");
  CHECK(r.status == 2);
  CHECK(r.err == "delaunay2d: -o - and --msh name the same file /dev/stdout\n");
}

TEST_CASE("cli outputs that reach one file through symlinks are refused") {
  const std::string d = freshDir("same_links"), in = d + "/in.xy", q = "'" + in + "' -o '" + d + "/o'";
  dttest::writeText(in, kSquare);
  dttest::writeText(d + "/f.svg", "OLD\n");
  REQUIRE(::symlink("f.svg", (d + "/l1").c_str()) == 0);
  REQUIRE(::symlink(d.c_str(), (d + "/dirl").c_str()) == 0);
  REQUIRE(::symlink("missing.svg", (d + "/d1").c_str()) == 0);
  REQUIRE(::symlink("dirl/missing.svg", (d + "/d2").c_str()) == 0);
  REQUIRE(::symlink("in.xy", (d + "/toinput").c_str()) == 0);
  struct Case {
    std::string args, err;
  };
  const Case cases[] = {
      {q + " --svg '" + d + "/l1' --msh '" + d + "/f.svg'", "--svg and --msh name the same file"},
      // two dangling links whose targets would be one new file
      {q + " --svg '" + d + "/d1' --msh '" + d + "/d2'", "--svg and --msh name the same file"},
      {q + " --svg '" + d + "/toinput'", "--svg: " + d + "/toinput is the input file"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.args);
    const dttest::CliResult r = dttest::runCli(c.args);
    CHECK(r.status == 2);
    CHECK_MESSAGE(r.err.find("delaunay2d: " + c.err) == 0, r.err);
    CHECK(dttest::readText(d + "/f.svg") == "OLD\n");
    CHECK(kindOf(d + "/missing.svg") == '-');
    CHECK(kindOf(d + "/o.ele") == '-');
  }
  CHECK(dttest::readText(in) == kSquare);
}

// ---- signals, concurrent runs, limits, leftovers, permissions -------------------------------

TEST_CASE("cli a signal after the first rename leaves the new outputs and exit status 0 and --stats") {
  const std::string d = freshDir("final");
  const Reference ref = reference(d);
  // --commit-pause-ms: the CLI pauses after each rename and says "committing N";
  // the signal comes during the pause after the first one, when the commit is under way, or
  // during the pause after the commit ("committed"), before --stats is printed. (Not SIGINT: a
  // shell starts a background job with SIGINT ignored.)
  const std::pair<const char*, const char*> cases[] = {
      {"committing 1", "TERM"}, {"committing 1", "HUP"}, {"committed", "TERM"}, {"committed", "HUP"}};
  for (const auto& [when, sig] : cases) {
    CAPTURE(sig);
    CAPTURE(when);
    for (const char* f : {"/o.ele", "/o.svg", "/o.msh"}) dttest::writeText(d + f, "OLD\n");
    // Emptied first: the script's first grep may run before the background job truncates err,
    // and the last case's err holds the same words (it sent the signal at once: seen in CI).
    for (const char* f : {"/err", "/out"}) dttest::writeText(d + f, "");
    const int rc = runScript(d, "final",
        hookedCli() + " --commit-pause-ms 800 '" + ref.in + "' -o '" + d +
        "/o' --svg '" + d + "/o.svg' --msh '" + d + "/o.msh' --stats > '" + d + "/out' 2> '" + d +
        "/err' & pid=$!\n"
        "for i in $(seq 300); do grep -q '" + std::string(when) + "' '" + d + "/err' && break; "
        "sleep 0.05; done\nkill -" + std::string(sig) + " $pid; wait $pid; echo $? > '" + d +
        "/status'");
    CHECK(rc == 0);
    CHECK(dttest::readText(d + "/err").find(when) != std::string::npos);
    CHECK(dttest::readText(d + "/status") == "0\n");
    CHECK(dttest::readText(d + "/out").find("points: 300\n") != std::string::npos);
    CHECK(dttest::readText(d + "/o.ele") == ref.ele);
    CHECK(dttest::readText(d + "/o.svg") == ref.svg);
    CHECK(dttest::readText(d + "/o.msh") == ref.msh);
    CHECK(temporariesIn(d).empty());
  }
}

TEST_CASE("cli signals at every 10 ms of a run give the old set or the new one with a status that says which") {
  const std::string d = freshDir("signals_sweep"), in = d + "/in.node";
  dttest::writeText(in, dttest::nodeText(dt::uniformPoints(20000, 8)));
  // The run pauses 30 ms after each rename, so the delays below fall before, inside and after
  // the commit; they go on past 400 ms until some runs have finished (a loaded machine).
  int oldSets = 0, newSets = 0;
  std::string newEle;
  for (int ms = 0; ms <= 400 || (newSets < 3 && ms <= 3000); ms += 10) {
    CAPTURE(ms);
    for (const char* f : {"/o.ele", "/o.svg", "/o.msh"}) dttest::writeText(d + f, "OLD\n");
    const int rc = runScript(d, "sweep",
        hookedCli() + " --commit-pause-ms 30 '" + in + "' -o '" + d + "/o' --svg '" +
        d + "/o.svg' --msh '" + d + "/o.msh' 2> /dev/null & pid=$!\n"
        "sleep " + std::to_string(ms / 1000.0) + "; kill -TERM $pid; wait $pid; echo $? > '" + d +
        "/status'");
    REQUIRE(rc == 0);
    const std::string status = dttest::readText(d + "/status");
    const std::string ele = dttest::readText(d + "/o.ele"), svg = dttest::readText(d + "/o.svg"),
                      msh = dttest::readText(d + "/o.msh");
    CHECK(temporariesIn(d).empty());
    if (status == "143\n") {
      ++oldSets;
      CHECK(ele == "OLD\n");
      CHECK(svg == "OLD\n");
      CHECK(msh == "OLD\n");
    } else {
      REQUIRE(status == "0\n");
      ++newSets;
      CHECK(ele.rfind("OLD", 0) != 0);
      CHECK(svg.rfind("<svg", 0) == 0);
      CHECK(msh.rfind("$MeshFormat", 0) == 0);
      if (newEle.empty()) newEle = ele;
      CHECK(ele == newEle);
    }
  }
  MESSAGE(oldSets << " runs ended by the signal with the old set, " << newSets << " with the new");
  CHECK(oldSets > 0);
}

namespace {

// The script of the concurrent-runs tests: `pairs` times, a run on IN/a.node and one on
// IN/b.node (inputs with different triangle counts) write OUT/o.ele, o.svg and o.msh at once,
// then the three counts of the set left go as one line into OUT/sets. One of the two (a in odd
// rounds, b in even ones) pauses 40 ms after each of its renames, the other does not: without
// a lock, the quick one's three renames fall inside the slow one's commit, which then puts its
// last two files over them.
std::string pairsScript(const std::string& in, const std::string& out, int pairs) {
  const std::string args = " -o '" + out + "/o' --svg '" + out + "/o.svg' --msh '" + out + "/o.msh'";
  return "for i in $(seq " + std::to_string(pairs) + "); do\n"
         "pa=$((i % 2 * 40)); pb=$((40 - pa))\n" +
         hookedCli() + " --commit-pause-ms $pa '" + in + "/a.node'" + args +
         " 2> /dev/null & a=$!\n" +
         hookedCli() + " --commit-pause-ms $pb '" + in + "/b.node'" + args +
         " 2> /dev/null & b=$!\n"
         "wait $a || exit 1; wait $b || exit 1\n"
         "{ head -1 '" + out + "/o.ele'; grep -c '<polygon' '" + out + "/o.svg'; sed -n '/^\\$Elements/{n;p;}' '" +
         out + "/o.msh'; } | tr '\\n' ' ' >> '" + out + "/sets'; echo >> '" + out + "/sets'\n"
         "done";
}

// Writes the two inputs of pairsScript into `dir`, readable by all.
void writePairInputs(const std::string& dir) {
  dttest::writeText(dir + "/a.node", dttest::nodeText(dt::uniformPoints(200, 1)));
  dttest::writeText(dir + "/b.node", dttest::nodeText(dt::uniformPoints(260, 2)));
  for (const char* f : {"/a.node", "/b.node"}) ::chmod((dir + f).c_str(), 0644);
}

// Checks the sets pairsScript left in OUT/sets: `pairs` lines, each one run's (counts agree).
void checkNoMixedSet(const std::string& out, int pairs) {
  std::istringstream sets(dttest::readText(out + "/sets"));
  int n = 0, mixed = 0;
  for (long ele, three, zero, svg, msh; sets >> ele >> three >> zero >> svg >> msh; ++n)
    mixed += !(ele == svg && svg == msh);
  CHECK(n == pairs);
  CHECK_MESSAGE(mixed == 0, mixed << " of " << n << " pairs left a mixed set");
  CHECK(temporariesIn(out).empty());
}

}  // namespace

TEST_CASE("cli two runs on the same outputs started together never mix their files") {
  const std::string d = freshDir("concurrent");
  writePairInputs(d);
  REQUIRE(runScript(d, "pairs", pairsScript(d, d, 40)) == 0);
  checkNoMixedSet(d, 40);
}

TEST_CASE("cli a file size limit fails the run with one line and no temporary and the old files kept") {
  const std::string d = freshDir("fsize");
  const Reference ref = reference(d);
  dttest::writeText(d + "/o.ele", "OLD ELE\n");
  dttest::writeText(d + "/o.svg", "OLD SVG\n");
  // 30 blocks of 512 bytes (dash) or 1 KiB (bash): the .ele (10 kB) fits, the SVG (36 kB) does
  // not. Without SIGXFSZ ignored, the kernel kills the run (status 153) and leaves temporaries.
  REQUIRE(ref.ele.size() < 15000);
  REQUIRE(ref.svg.size() > 31000);
  const int rc = runScript(d, "fsize",
      "ulimit -f 30; " + cli() + " '" + ref.in + "' -o '" + d + "/o' --svg '" + d + "/o.svg' 2> '" +
      d + "/err'");
  CHECK(rc == 1);
  CHECK(dttest::readText(d + "/err") == "delaunay2d: error: " + d + "/o.svg: cannot write: File too large\n");
  CHECK(dttest::readText(d + "/o.ele") == "OLD ELE\n");
  CHECK(dttest::readText(d + "/o.svg") == "OLD SVG\n");
  CHECK(temporariesIn(d).empty());
}

TEST_CASE("cli a run removes the temporaries no live run holds whatever their pid says") {
  const std::string d = freshDir("stale"), in = d + "/in.xy";
  dttest::writeText(in, kSquare);
  // A pid that has just ended: a child that exits at once. A run in another PID namespace can
  // have such a pid here while it lives; only the flock it holds on its temporary tells.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  const std::string dead = std::to_string(child);
  const std::string held = ".dttmp-" + dead + "-0", left = ".dttmp-" + dead + "-1",
                    leftOld = ".dttmp-" + dead + "-2-old";
  for (const std::string& name : {held, left, leftOld}) dttest::writeText(d + "/" + name, "LEFT\n");
  const int fd = ::open((d + "/" + held).c_str(), O_RDONLY | O_CLOEXEC);
  REQUIRE(fd >= 0);
  REQUIRE(::flock(fd, LOCK_EX) == 0);  // as a live run holds its temporary
  dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + d + "/o' --svg '" + d + "/o.svg'");
  REQUIRE(r.status == 0);
  CHECK(temporariesIn(d) == std::vector<std::string>{held});
  CHECK(dttest::readText(d + "/" + held) == "LEFT\n");
  ::close(fd);  // its run has ended: the next run removes it
  r = dttest::runCli("'" + in + "' -o '" + d + "/o'");
  REQUIRE(r.status == 0);
  CHECK(temporariesIn(d).empty());
}

namespace {

// In a forked child: becomes the triangulator with these arguments (status 122 if it cannot).
[[noreturn]] void execCli(const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>(DT_CLI)};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(DT_CLI, argv.data());
  ::_exit(122);
}

// Runs the CLI as user and group 65534 (nobody) with the given arguments; returns its exit
// status and stderr.
dttest::CliResult runCliAsNobody(const std::vector<std::string>& args, const std::string& errFile) {
  dttest::CliResult r;
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (fd < 0 || ::dup2(fd, 2) < 0) ::_exit(120);
    if (::setgroups(0, nullptr) != 0 || ::setresgid(65534, 65534, 65534) != 0 ||
        ::setresuid(65534, 65534, 65534) != 0)
      ::_exit(121);
    execCli(args);
  }
  int st = 0;
  ::waitpid(pid, &st, 0);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  r.err = dttest::readText(errFile);
  return r;
}

}  // namespace

TEST_CASE("cli replacing an output keeps its mode and refuses one the user could not write in place") {
  const std::string d = freshDir("perm"), in = d + "/in.xy";
  dttest::writeText(in, kSquare);
  dttest::writeText(d + "/o.ele", "OLD\n");
  ::chmod((d + "/o.ele").c_str(), 0604);
  dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + d + "/o'");
  REQUIRE(r.status == 0);
  struct stat st;
  REQUIRE(::stat((d + "/o.ele").c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0604);
  if (::geteuid() != 0) return;  // the rest needs a second user
  // A world-writable directory (rename allowed to anyone) holding root's read-only-for-others
  // file: nobody's run must not replace it (its owner and mode would change).
  const std::string w = freshDir("perm_shared");
  ::chmod(w.c_str(), 0777);
  ::chmod(d.c_str(), 0755);
  ::chmod(in.c_str(), 0644);
  dttest::writeText(w + "/o.ele", "ROOT'S\n");
  ::chmod((w + "/o.ele").c_str(), 0644);
  // Every directory above must let nobody reach the binary and the input.
  r = runCliAsNobody({in, "-o", w + "/o"}, w + "/err");
  if (r.status >= 120) {
    MESSAGE("cannot run as nobody here (status " << r.status << "): part skipped");
    return;
  }
  CHECK(r.status == 1);
  CHECK_MESSAGE(r.err == "delaunay2d: error: " + w + "/o.ele: refusing to replace it: it could "
                         "not be written in place (Permission denied)\n", r.err);
  CHECK(dttest::readText(w + "/o.ele") == "ROOT'S\n");
  REQUIRE(::stat((w + "/o.ele").c_str(), &st) == 0);
  CHECK(st.st_uid == 0);
  CHECK(temporariesIn(w).empty());
  // A file nobody may write is replaced by nobody's run, and keeps its mode.
  ::chown((w + "/o.ele").c_str(), 65534, 65534);
  ::chmod((w + "/o.ele").c_str(), 0640);
  r = runCliAsNobody({in, "-o", w + "/o"}, w + "/err");
  CHECK_MESSAGE(r.status == 0, r.err);
  REQUIRE(::stat((w + "/o.ele").c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0640);
  CHECK(dttest::readText(w + "/o.ele").rfind("2 3 0\n", 0) == 0);
}

TEST_CASE("cli out of memory is one line naming the input and the phase") {
#if defined(__SANITIZE_ADDRESS__)
  return;  // AddressSanitizer reserves terabytes of address space: no ulimit -v lets it start
#endif
  const std::string d = freshDir("oom"), in = d + "/in.node";
  dttest::writeText(in, dttest::nodeText(dt::uniformPoints(400000, 6)));
  dttest::writeText(d + "/o.ele", "OLD\n");
  // 40 MB of address space: enough to start and read, not for 400000 points' triangulation
  // (which takes about 60 MB).
  const int rc = runScript(d, "oom",
      "ulimit -v 40000; " + cli() + " '" + in + "' -o '" + d + "/o' 2> '" + d + "/err'");
  const std::string err = dttest::readText(d + "/err");
  CHECK(rc == 1);
  // The phase: the file is read within the limit, the triangulation is not.
  CHECK_MESSAGE(err.rfind("delaunay2d: " + in + ": out of memory while triangulating", 0) == 0, err);
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  CHECK(dttest::readText(d + "/o.ele") == "OLD\n");
  CHECK(temporariesIn(d).empty());
}

// ---- the edges of the outputs: long names, rollback, locks, exits ----------------------------

namespace {

// Runs `script` with sh as user and group 65534 (nobody) through setpriv; its exit status, or
// -1 if it cannot run so (not root, setpriv missing).
int runScriptAsNobody(const std::string& dir, const std::string& name, const std::string& script) {
  if (::geteuid() != 0) return -1;
  dttest::writeText(dir + "/" + name + ".sh", script + "\n");
  ::chmod((dir + "/" + name + ".sh").c_str(), 0644);
  ch::ProcessIo io;
  io.env = {{"DT_CLI_BIN", DT_CLI}, {"DT_CLI_HOOKED_BIN", DT_CLI_HOOKED}};
  const int rc = ch::runProgram({"setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", "sh",
                                 dir + "/" + name + ".sh"}, io);
  return rc >= 0 && rc < 127 ? rc : -1;
}

// Whether nobody can run the triangulator here (every directory above the build searchable).
bool nobodyCanRun(const std::string& dir) {
  return runScriptAsNobody(dir, "probe", cli() + " --help > /dev/null") == 0;
}

// Runs the triangulator with `args`, stdout and stderr as given by the caller's descriptors
// (-1: /dev/null), SIGPIPE at its default action as a shell leaves it; returns its wait status.
int runWithFds(const std::vector<std::string>& args, int out, int err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(out >= 0 ? out : null, 1);
    ::dup2(err >= 0 ? err : null, 2);
    ::signal(SIGPIPE, SIG_DFL);
    execCli(args);
  }
  int st = 0;
  ::waitpid(pid, &st, 0);
  return st;
}

}  // namespace

TEST_CASE("cli base names of 234 to 251 bytes are written and a failed commit puts the old file back byte for byte") {
  const std::string d = freshDir("longnames");
  dttest::writeText(d + "/in.xy", kSquare);
  for (const int len : {234, 237, 245, 251}) {
    CAPTURE(len);
    const std::string base(std::size_t(len), 'K');
    // Every name the shell's > can write (base.ele: up to 255 bytes), a run writes and replaces.
    for (int round = 0; round < 2; ++round) {
      const dttest::CliResult r = dttest::runCli("'" + d + "/in.xy' -o '" + d + "/" + base + "'");
      CHECK_MESSAGE(r.status == 0, r.err);
      CHECK(dttest::readText(d + "/" + base + ".ele").rfind("2 3 0\n", 0) == 0);
    }
    // The data-loss case: an existing .ele, and a second output that turns into a directory
    // after the .ele is in place (--commit-pause-ms pauses after each rename: long
    // enough for the script's rm and mkdir on a loaded machine).
    const std::string precious = "precious\n\x01\xff bytes " + std::to_string(len) + "\n";
    dttest::writeText(d + "/" + base + ".ele", precious);
    std::filesystem::remove_all(d + "/app.svg");
    dttest::writeText(d + "/app.svg", "OLD SVG\n");
    dttest::writeText(d + "/err", "");
    const int rc = runScript(d, "turn",
        hookedCli() + " --commit-pause-ms 1500 '" + d + "/in.xy' -o '" + d + "/" + base +
        "' --svg '" + d + "/app.svg' 2> '" + d + "/err' & pid=$!\n"
        "for i in $(seq 300); do grep -q 'committing 1' '" + d + "/err' && break; sleep 0.02; done\n"
        "rm '" + d + "/app.svg'; mkdir '" + d + "/app.svg'\n"
        "wait $pid; echo $? > '" + d + "/status'");
    CHECK(rc == 0);
    const std::string err = dttest::readText(d + "/err");
    CHECK_MESSAGE(dttest::readText(d + "/status") == "1\n", err);
    CHECK_MESSAGE(err.find("app.svg: cannot replace it: it is now a directory") != std::string::npos, err);
    CHECK(dttest::readText(d + "/" + base + ".ele") == precious);
    CHECK(kindOf(d + "/app.svg") == 'd');
    CHECK(temporariesIn(d).empty());
    std::filesystem::remove(d + "/" + base + ".ele");
  }
}

TEST_CASE("cli replacing a file keeps its set-group-ID bit") {
  const std::string d = freshDir("setgid"), in = d + "/in.xy";
  dttest::writeText(in, kSquare);
  dttest::writeText(d + "/o.ele", "OLD\n");
  // The file's group is the caller's own: the bit may be set by whoever owns the file.
  REQUIRE(::chmod((d + "/o.ele").c_str(), 02754) == 0);
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + d + "/o'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  struct stat st;
  REQUIRE(::stat((d + "/o.ele").c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 02754);
  CHECK(dttest::readText(d + "/o.ele").rfind("2 3 0\n", 0) == 0);
}

TEST_CASE("cli in a sticky directory another user's file is refused with what to do and nothing left behind") {
  const std::string d = freshDir("sticky");
  dttest::writeText(d + "/in.xy", kSquare);
  ::chmod((d + "/in.xy").c_str(), 0644);
  if (!nobodyCanRun(d)) {
    MESSAGE("cannot run as nobody here: skipped");
    return;
  }
  const std::string w = freshDir("sticky_shared");
  ::chmod(w.c_str(), 01777);
  // Root's file, writable by all: writable in place, yet not replaceable by nobody here.
  dttest::writeText(w + "/o.ele", "ROOT'S\n");
  ::chmod((w + "/o.ele").c_str(), 0666);
  const int rc = runScriptAsNobody(w, "run", cli() + " '" + d + "/in.xy' -o '" + w + "/o' 2> '" +
                                                 w + "/err'; echo $? > '" + w + "/status'");
  REQUIRE(rc == 0);
  const std::string err = dttest::readText(w + "/err");
  CHECK(dttest::readText(w + "/status") == "1\n");
  CHECK_MESSAGE(err.find("is a sticky directory and the file belongs to user 0") != std::string::npos, err);
  CHECK(err.find("ask them to remove it, or write to another name") != std::string::npos);
  CHECK(dttest::readText(w + "/o.ele") == "ROOT'S\n");
  CHECK(temporariesIn(w).empty());
}

TEST_CASE("cli two runs into a directory they may write but not read never mix their sets") {
  const std::string d = freshDir("unreadable");
  writePairInputs(d);
  if (!nobodyCanRun(d)) {
    MESSAGE("cannot run as nobody here: skipped");
    return;
  }
  // Write and search for others, no read: nobody cannot open the directory to lock it.
  const std::string w = freshDir("unreadable_out");
  ::chmod(w.c_str(), 0733);
  REQUIRE(runScriptAsNobody(w, "pairs", pairsScript(d, w, 20)) == 0);
  checkNoMixedSet(w, 20);
}

TEST_CASE("cli a thread that cannot start is one line and exit 1 and more threads than CPUs are capped") {
  const std::string d = freshDir("threads");
  dttest::writeText(d + "/in.node", dttest::nodeText(dt::uniformPoints(20000, 3)));
  ::chmod((d + "/in.node").c_str(), 0644);
  cpu_set_t cpus;
  REQUIRE(::sched_getaffinity(0, sizeof cpus, &cpus) == 0);
  const int usable = CPU_COUNT(&cpus);
  dttest::CliResult r = dttest::runCli("'" + d + "/in.node' -o '" + d + "/o' --threads 1024");
  CHECK_MESSAGE(r.status == 0, r.err);
  CHECK(r.err == "delaunay2d: note: --threads 1024 capped to " + std::to_string(usable) +
                     ", the CPUs this process may run on\n");
  r = dttest::runCli("'" + d + "/in.node' -o '" + d + "/o' --threads ' 2'");
  CHECK(r.status == 2);
  CHECK(r.err.find("--threads must be 'auto' or an integer from 1 to 1024, not ' 2'") != std::string::npos);
  if (usable < 2 || !nobodyCanRun(d)) {
    MESSAGE("one CPU, or cannot run as nobody here: the thread limit part skipped");
    return;
  }
  // One process for the user: no thread can start (root is not held by RLIMIT_NPROC, nobody is).
  // The input is large enough that the cost model asks for the second thread.
  dttest::writeText(d + "/big.node",
                    dttest::nodeText(dt::uniformPoints(2 * dt::ParallelModel::minPointsPerThread + 10000, 5)));
  ::chmod((d + "/big.node").c_str(), 0644);
  const std::string w = freshDir("threads_out");
  ::chmod(w.c_str(), 0777);
  // LeakSanitizer's check at exit starts a thread of its own, which one process cannot: an
  // instrumented build leaves leaks to the other tests here.
  const int rc = runScriptAsNobody(w, "nproc", "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" "
                                               "prlimit --nproc=1 " + cli() + " '" + d +
                                                   "/big.node' -o '" + w + "/o' --threads 2 2> '" + w +
                                                   "/err'; echo $? > '" + w + "/status'");
  REQUIRE(rc == 0);
  CHECK(dttest::readText(w + "/status") == "1\n");
  CHECK(dttest::readText(w + "/err") ==
        "delaunay2d: error: cannot start 2 threads: Resource temporarily unavailable\n");
  CHECK(!dttest::fileExists(w + "/o.ele"));
  CHECK(temporariesIn(w).empty());
}

TEST_CASE("cli parallelFor joins the threads that started when one cannot start") {
  // The third start fails as std::thread does when the system has no thread left for us.
  struct FailThird : dt::ThreadStarter {
    int started = 0;
    std::thread start(std::function<void()> run) override {
      if (++started == 3) throw std::system_error(EAGAIN, std::generic_category());
      return std::thread(std::move(run));
    }
  } starter;
  std::atomic<int> ran{0};
  std::string what;
  try {
    dt::parallelFor(5, 100, [&](int, std::size_t, std::size_t) { ++ran; }, &starter);
  } catch (const dt::ThreadStartError& e) {
    what = e.what();
  }
  CHECK(what == "cannot start 5 threads: Resource temporarily unavailable");
  CHECK(ran == 2);  // the two started pieces ran and were joined; the rest never began
  // With no failure, every piece runs.
  ran = 0;
  dt::parallelFor(5, 100, [&](int, std::size_t, std::size_t) { ++ran; });
  CHECK(ran == 5);
}

TEST_CASE("cli exit status after the commit: SIGPIPE on notes is 0 and lost --stats are 1") {
  const std::string d = freshDir("pipes");
  // A duplicate point: a note on stderr after the commit.
  dttest::writeText(d + "/in.xy", "0 0\n1 0\n0 1\n1 1\n1 1\n");
  const std::string in = d + "/in.xy", o = d + "/o";
  int p[2];
  // stderr a pipe nobody reads any more: the note is lost, the run has succeeded.
  REQUIRE(::pipe(p) == 0);
  ::close(p[0]);
  int st = runWithFds({in, "-o", o}, -1, p[1]);
  ::close(p[1]);
  CHECK(WIFEXITED(st));
  CHECK(WEXITSTATUS(st) == 0);
  // --stats into a closed pipe, /dev/full, a closed stdout: status 1, saying so, outputs written.
  const int errFd = ::open((d + "/err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  REQUIRE(::pipe(p) == 0);
  ::close(p[0]);
  std::remove((o + ".ele").c_str());
  st = runWithFds({in, "-o", o, "--stats"}, p[1], errFd);
  ::close(p[1]);
  CHECK(WIFEXITED(st));
  CHECK(WEXITSTATUS(st) == 1);
  CHECK(dttest::fileExists(o + ".ele"));
  const int full = ::open("/dev/full", O_WRONLY);
  REQUIRE(full >= 0);
  st = runWithFds({in, "-o", o, "--stats"}, full, errFd);
  ::close(full);
  CHECK(WIFEXITED(st));
  CHECK(WEXITSTATUS(st) == 1);
  ::close(errFd);
  const std::string err = dttest::readText(d + "/err");
  CHECK_MESSAGE(err.find("delaunay2d: --stats: cannot write to standard output: Broken pipe (the "
                         "outputs are written)\n") != std::string::npos, err);
  CHECK(err.find("delaunay2d: --stats: cannot write to standard output: No space left on device")
        != std::string::npos);
  const int rc = runScript(d, "closed", cli() + " '" + in + "' -o '" + o + "' --stats >&- 2> '" + d +
                                            "/err2'; echo $? > '" + d + "/status'");
  CHECK(rc == 0);
  CHECK(dttest::readText(d + "/status") == "1\n");
  CHECK(dttest::readText(d + "/err2").find("--stats: cannot write to standard output: Bad file "
                                           "descriptor") != std::string::npos);
  // '-o -' into a closed stdout is refused before anything is read.
  const int rc2 = runScript(d, "closed2", cli() + " '" + in + "' -o - >&- 2> '" + d +
                                              "/err3'; echo $? > '" + d + "/status'");
  CHECK(rc2 == 0);
  CHECK(dttest::readText(d + "/status") == "1\n");
  CHECK(dttest::readText(d + "/err3") ==
        "delaunay2d: -o -: cannot write to descriptor 1: Bad file descriptor\n");
}

TEST_CASE("cli control characters in a path are escaped and the message stays one line") {
  const std::string d = freshDir("newline");
  dttest::writeText(d + "/in.xy", kSquare);
  const std::string odd = d + "/a\nb\x1b[31m";
  dttest::CliResult r = dttest::runCli("'" + odd + ".xy' -o '" + d + "/o'");
  CHECK(r.status == 2);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_MESSAGE(r.err.find(d + "/a\\nb\\x1b[31m.xy") != std::string::npos, r.err);
  // An output in a directory that does not exist, named with a newline.
  r = dttest::runCli("'" + d + "/in.xy' -o '" + d + "/no\ndir/o'");
  CHECK(r.status == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_MESSAGE(r.err.find("/no\\ndir/o.ele") != std::string::npos, r.err);
}

TEST_CASE("cli -o /dev/null discards the .ele and creates nothing in /dev") {
  const std::string d = freshDir("devnull");
  dttest::writeText(d + "/in.xy", kSquare);
  ::unlink("/dev/null.ele");  // what an earlier version left there, if any
  const dttest::CliResult r = dttest::runCli("'" + d + "/in.xy' -o /dev/null --svg '" + d + "/o.svg'");
  CHECK_MESSAGE(r.status == 0, r.err);
  CHECK(kindOf("/dev/null") == 'c');
  CHECK(kindOf("/dev/null.ele") == '-');
  CHECK(dttest::readText(d + "/o.svg").rfind("<svg", 0) == 0);
}

TEST_CASE("cli --order brio with the listings warns that shuffled collinear points and an apex are quadratic") {
  // Points on a line, shuffled, and one apex: every new point's walk crosses the fan of
  // triangles to the apex built so far; the default order does not help the listings.
  const int n = 120000;
  dt::XY p;
  for (int i = 0; i < n; ++i) p.insert(p.end(), {double(i), 0.0});
  dttest::shuffle(p, 7);
  p.insert(p.end(), {n / 2.0, 1.0});
  const std::string d = freshDir("brio_quadratic");
  dttest::writeText(d + "/in.node", dttest::nodeText(p));
  const dttest::CliResult r = dttest::runCli("'" + d + "/in.node' -o '" + d + "/o' --kernel listings --stats");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  CHECK_MESSAGE(r.err.rfind("delaunay2d: warning: walks average ", 0) == 0, r.err);
  CHECK(r.err.find("--order brio on this input (sorted, along a curve, or cocircular) takes "
                   "quadratic time") != std::string::npos);
  CHECK(r.err.find("; --kernel fast may avoid it\n") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

TEST_CASE("cli a program run by runProgram is ended and reaped with its parent's SIGTERM") {
  const std::string d = freshDir("reap");
  const std::string pidFile = d + "/child_pid";
  const pid_t parent = ::fork();
  if (parent == 0) {
    // A chapter program running gnuplot: here a shell that says its pid and sleeps. (The
    // test runner's own handlers are not a chapter program's.)
    ::signal(SIGTERM, SIG_DFL);
    const int rc = ch::runProgram({"sh", "-c", "echo $$ > \"$1.tmp\"; mv \"$1.tmp\" \"$1\"; exec sleep 30",
                                   "sh", pidFile});
    ::_exit(rc == 0 ? 0 : 3);
  }
  for (int i = 0; i < 500 && !dttest::fileExists(pidFile); ++i) ::usleep(10000);
  REQUIRE(dttest::fileExists(pidFile));
  const pid_t sleeper = pid_t(std::atol(dttest::readText(pidFile).c_str()));
  REQUIRE(sleeper > 0);
  REQUIRE(::kill(parent, SIGTERM) == 0);
  int st = 0;
  ::waitpid(parent, &st, 0);
  CHECK(WIFSIGNALED(st));
  CHECK(WTERMSIG(st) == SIGTERM);
  // The child is gone, not reparented and still running.
  const bool gone = ::kill(sleeper, 0) != 0 && errno == ESRCH;
  CHECK(gone);
  if (!gone) ::kill(sleeper, SIGKILL);
}

TEST_CASE("cli a PNG or SVG figure cut short is told from a whole one") {
  const std::string d = freshDir("figures_cut");
  const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + std::string(20, 'x') +
                          std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  dttest::writeText(d + "/whole.png", png);
  dttest::writeText(d + "/cut.png", png.substr(0, png.size() - 5));
  dttest::writeText(d + "/whole.svg", "<svg>\n</svg>\n");
  dttest::writeText(d + "/cut.svg", "<svg>\n<path d='M 0");
  CHECK(ch::figureTruncated(d + "/whole.png").empty());
  CHECK(ch::figureTruncated(d + "/cut.png") == "no IEND chunk at its end");
  CHECK(ch::figureTruncated(d + "/whole.svg").empty());
  CHECK(ch::figureTruncated(d + "/cut.svg") == "no closing </svg>");
}

TEST_CASE("cli a bad option of bench_parallel creates no output directory and out of memory names the phase") {
  const std::string d = freshDir("bench_args");
  const std::string bench = dttest::buildDir() + "/bench_parallel";
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"--threads", "abc"}, std::vector<std::string>{"--cache-dir", d + "/none"}}) {
    std::vector<std::string> argv{bench, "--quick", "--no-plot", "--out", d + "/new"};
    argv.insert(argv.end(), bad.begin(), bad.end());
    const dttest::RunResult r = dttest::runCaptured(argv);
    CHECK(r.status == 2);
    CHECK_MESSAGE(r.err.rfind("bench_parallel: " + bad[0], 0) == 0, r.err);
    CHECK(!std::filesystem::exists(d + "/new"));
  }
#if !defined(__SANITIZE_ADDRESS__)
  // 25 MB of address space: enough to start, not for the footprint of 10^6 points' structures.
  dttest::writeText(d + "/oom.sh", "ulimit -v 25000; exec \"$1\" --quick --no-plot --out \"$2\"\n");
  const dttest::RunResult r = dttest::runCaptured(
      {"sh", d + "/oom.sh", dttest::buildDir() + "/sec2_3_3_datastructures", d + "/oom"});
  CHECK(r.status == 1);
  CHECK_MESSAGE(r.err == "sec2_3_3_datastructures: out of memory while computing\n", r.err);
#endif
}
