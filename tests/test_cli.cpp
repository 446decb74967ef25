/// \file test_cli.cpp End-to-end tests of the command-line triangulator delaunay2d: degenerate
/// families validated exactly from the written .ele, and bad input rejected cleanly.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "support.h"

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
  CHECK(filesStartingWith(d, "out.ele.tmp").empty());
  CHECK(filesStartingWith(d, "old.svg.tmp").empty());
  // Bad input: exit 2, the old files untouched.
  dttest::writeText(d + "/bad.xy", "0 0\n1 x\n");
  r = dttest::runCli("'" + d + "/bad.xy' -o '" + out + "' --svg '" + d + "/old.svg'");
  CHECK(r.status == 2);
  CHECK(dttest::readText(out + ".ele") == "OLD ELE\n");
  CHECK(dttest::readText(d + "/old.svg") == "OLD SVG\n");
  // A target that is a directory is refused before anything is renamed.
  std::filesystem::create_directories(d + "/adir");
  r = dttest::runCli("'" + in + "' -o '" + out + "' --svg '" + d + "/adir'");
  CHECK(r.status == 1);
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

TEST_CASE("cli killed while its outputs are written it leaves no temporary and keeps the old files") {
  const std::string d = freshDir("killed"), in = d + "/in.xy", out = d + "/out";
  dttest::writeText(in, kSquare);
  dttest::writeText(out + ".ele", "OLD ELE\n");
  // DELAUNAY2D_TEST_HOLD_OUTPUTS: the CLI stops once the temporaries are written, says
  // "holding", and waits; the signal comes then.
  // The paths reach the script through the environment (D, DT_CLI_BIN), never as code.
  const std::string script =
      "DELAUNAY2D_TEST_HOLD_OUTPUTS=60 \"$DT_CLI_BIN\" \"$D/in.xy\" -o \"$D/out\" "
      "--svg \"$D/s.svg\" 2> \"$D/err\" & pid=$!; "
      "for i in $(seq 300); do grep -q holding \"$D/err\" && break; sleep 0.1; done; "
      "ls \"$D\" > \"$D/during\"; kill -TERM $pid; wait $pid; echo $? > \"$D/status\"";
  dttest::writeText(d + "/kill.sh", script + "\n");
  ch::ProcessIo io;
  io.stderrPath = "/dev/null";
  io.env = {{"D", d}, {"DT_CLI_BIN", DT_CLI}};
  REQUIRE(ch::runProgram({"sh", d + "/kill.sh"}, io) == 0);
  const std::string during = dttest::readText(d + "/during");
  CHECK(during.find("out.ele.tmp") != std::string::npos);  // the signal came while they existed
  CHECK(during.find("s.svg.tmp") != std::string::npos);
  CHECK(dttest::readText(d + "/status") == "143\n");  // 128 + SIGTERM: the signal's own status
  CHECK(filesStartingWith(d, "out.ele.").empty());
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
