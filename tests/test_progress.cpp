/// \file test_progress.cpp delaunay2d reports progress on stderr (points inserted, rate, time left) when stderr is a terminal, and is silent otherwise.
#include <doctest/doctest.h>

#include <cstdlib>

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
  REQUIRE_MESSAGE(std::system("command -v script > /dev/null") == 0, "script (util-linux) is needed");
  const std::string log = dttest::tmpPath("progress_tty.log");
  const std::string cmd = std::string(DT_CLI) + " '" + slowInput() + "' -o '" +
                          dttest::tmpPath("progress_tty") + "'" + kSlow;
  const int rc = std::system(("script -qec \"" + cmd + "\" /dev/null > '" + log + "' 2>&1").c_str());
  REQUIRE(rc == 0);
  const std::string t = dttest::readText(log);
  CHECK(t.find("\rdelaunay2d: ") != std::string::npos);
  CHECK(t.find(" of 60000 points inserted (") != std::string::npos);
  CHECK(t.find(" s left\033[K") != std::string::npos);  // rewritten, not a new line
  CHECK(t.find("\r\033[Kdelaunay2d: 60000 points triangulated in ") != std::string::npos);
}
