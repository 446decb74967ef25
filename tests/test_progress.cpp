/// \file test_progress.cpp delaunay2d reports progress on stderr (points inserted, rate, time left) when stderr is a terminal, and is silent otherwise.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "fast_delaunay.h"
#include "support.h"

namespace {

// A run whose insertions take well over the half second before the first count: the listings
// kernel on 60000 random points in file order (walks of O(sqrt n) steps).
const char* kSlow = " --kernel listings --order input";
std::string slowInput() {
  static const std::string in = [] {
    const std::string path = dttest::tmpPath("progress_input.node");
    dttest::writeText(path, dttest::nodeText(dttest::uniformPoints(60000, 77)));
    return path;
  }();
  return in;
}

}  // namespace

TEST_CASE("progress is not reported when stderr is not a terminal") {
  const std::string in = slowInput(), out = dttest::tmpPath("progress_quiet");
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "'" + kSlow);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.empty());
}

TEST_CASE("progress is reported with --progress on any stderr and never with --no-progress") {
  const std::string in = dttest::tmpPath("progress_small.xy"), out = dttest::tmpPath("progress_small");
  dttest::writeText(in, "0 0\n1 0\n0 1\n1 1\n");
  dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --progress");
  REQUIRE(r.status == 0);
  // A short run reports its phases and its end.
  CHECK(r.err.find("delaunay2d: triangulating 4 points (fast kernel)\n") != std::string::npos);
  CHECK(r.err.find("delaunay2d: checking the result with exact predicates\n") != std::string::npos);
  CHECK(r.err.find("delaunay2d: 4 points triangulated in ") != std::string::npos);
  r = dttest::runCli("'" + slowInput() + "' -o '" + out + "' --progress" + kSlow);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("delaunay2d: inserting 60000 points (listings)\n") != std::string::npos);
  CHECK(r.err.find(" of 60000 points inserted (") != std::string::npos);
  CHECK(r.err.find(" points/s, about ") != std::string::npos);
  CHECK(r.err.find(" s left\n") != std::string::npos);
  CHECK(r.err.find("delaunay2d: 60000 points triangulated in ") != std::string::npos);
  CHECK(r.err.find('\r') == std::string::npos);  // not a terminal: whole lines, no rewriting
  r = dttest::runCli("'" + in + "' -o '" + out + "' --no-progress");
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
}

TEST_CASE("progress on a terminal is rewritten in place") {
  // script(1) runs the command on a pseudo-terminal and copies what it writes.
  // script -c takes a shell command: the paths reach it through the environment, never as code.
  const std::string log = dttest::tmpPath("progress_tty.log");
  ch::ProcessIo io;
  io.stdoutPath = log;
  io.stderrPath = "&1";
  io.env = {{"DT_CLI_BIN", DT_CLI}, {"DT_IN", slowInput()}, {"DT_OUT", dttest::tmpPath("progress_tty")}};
  const int rc = ch::runProgram(
      {"script", "-qec", std::string("\"$DT_CLI_BIN\" \"$DT_IN\" -o \"$DT_OUT\"") + kSlow, "/dev/null"}, io);
  REQUIRE_MESSAGE(rc != 127, "script (util-linux) is needed");
  REQUIRE(rc == 0);
  const std::string t = dttest::readText(log);
  CHECK(t.find("\rdelaunay2d: ") != std::string::npos);
  CHECK(t.find(" of 60000 points inserted (") != std::string::npos);
  CHECK(t.find(" s left\033[K") != std::string::npos);  // rewritten, not a new line
  CHECK(t.find("\r\033[Kdelaunay2d: 60000 points triangulated in ") != std::string::npos);
}

TEST_CASE("progress --order input on points sorted along a curve warns once that it is quadratic") {
  // A parabola in x order: from its vertex on, every new point's cavity (and the walk to it)
  // holds all the points of the right half inserted before it.
  dttest::XY p;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const double x = -1 + 2.0 * i / n;
    p.insert(p.end(), {x, x * x});
  }
  const std::string in = dttest::tmpPath("sorted_parabola.node"), out = dttest::tmpPath("sorted_parabola");
  dttest::writeText(in, dttest::nodeText(p));
  for (const char* kernel : {"fast", "listings"}) {
    CAPTURE(kernel);
    dttest::CliResult r =
        dttest::runCli("'" + in + "' -o '" + out + "' --order input --kernel " + std::string(kernel));
    REQUIRE(r.status == 0);
    const std::string w = "delaunay2d: warning: ";
    CHECK_MESSAGE(r.err.rfind(w, 0) == 0, r.err);
    CHECK(r.err.find(w, 1) == std::string::npos);  // once
    CHECK(r.err.find("--order input on this input (sorted, along a curve, or cocircular) takes "
                     "quadratic time") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    // The default order on the same file: no warning.
    r = dttest::runCli("'" + in + "' -o '" + out + "' --kernel " + std::string(kernel));
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
  }
}

TEST_CASE("progress the fast kernel hook sees every k-th point and the numbering options agree") {
  const dttest::XY p = dttest::uniformPoints(10000, 91);
  dt::FastOptions o;
  o.progressEvery = 1000;
  std::vector<std::size_t> seen;
  std::uint64_t lastInsertions = 0;
  o.progress = [&](std::size_t done, std::size_t total, const dt::FastStats& st) {
    seen.push_back(done);
    CHECK(total == 10000);
    CHECK(st.insertions >= lastInsertions);
    CHECK(st.insertions <= done + 2);
    lastInsertions = st.insertions;
  };
  const dt::FastResult a = dt::fastDelaunay(p, o);
  CHECK(seen == std::vector<std::size_t>{1000, 2000, 3000, 4000, 5000, 6000, 7000, 8000, 9000});
  // Insertion numbering: the same triangles, indexing the points in insertion order.
  o.progress = nullptr;
  o.insertionNumbering = true;
  const dt::FastResult b = dt::fastDelaunay(p, o);
  REQUIRE(b.tri.size() == a.tri.size());
  REQUIRE(b.points.size() == p.size());
  REQUIRE(b.inserted.size() == p.size() / 2);
  CHECK(dt::checkDelaunay(b.points, b.tri).ok);
  bool same = true;
  for (std::size_t t = 0; t < a.tri.size(); ++t)
    for (int k = 0; k < 3; ++k) same = same && a.tri[t][k] == b.inserted[std::size_t(b.tri[t][k])];
  CHECK(same);
  bool pointsMatch = true;
  for (std::size_t i = 0; i < b.inserted.size(); ++i)
    pointsMatch = pointsMatch && b.points[2 * i] == p[2 * std::size_t(b.inserted[i])] &&
                  b.points[2 * i + 1] == p[2 * std::size_t(b.inserted[i]) + 1];
  CHECK(pointsMatch);
}
