/// \file test_exercises.cpp The classroom machinery (exercises/exercises.txt, scripts/exercise.sh): the list agrees with the tests, pages and solutions; every implement exercise's stub compiles and fails its check while the solution passes; start and check work end to end.
#include <doctest/doctest.h>

#include <string>

#include "support.h"

namespace {

struct Run {
  int status = -1;
  std::string out;
};

// Runs scripts/exercise.sh with `args` (already quoted), stdout and stderr together.
Run exercise(const std::string& args) {
  const std::string log = dttest::tmpPath("exercise_" + std::to_string(::getpid()) + ".log");
  ch::ProcessIo io;  // the script's path reaches sh through the environment, never as code
  io.stdoutPath = log;
  io.stderrPath = "&1";
  io.env = {{"DT_EXERCISE_SH", std::string(DT_SOURCE_DIR) + "/scripts/exercise.sh"}};
  const int rc = ch::runProgram({"sh", "-c", "bash \"$DT_EXERCISE_SH\" " + args}, io);
  Run r;
  r.status = rc >= 0 && rc < 128 ? rc : -1;
  r.out = dttest::readText(log);
  return r;
}

// The build directory of this test binary (DT_TEST_TMP is <build>/test_tmp).
std::string buildDir() {
  const std::string t = DT_TEST_TMP;
  return t.substr(0, t.rfind('/'));
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("exercises the list agrees with the test names the pages and the solutions page") {
  const Run r = exercise("lint '" + buildDir() + "'");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK(contains(r.out, "25 exercises consistent"));
  const Run l = exercise("list");
  CHECK(l.status == 0);
  CHECK(contains(l.out, "2.3.5-4   prove      sec2_3_5"));
}

TEST_CASE("exercises every implement exercise fails on its stub and passes with its solution restored") {
  // Fast path: only the files holding the solution are recompiled, then linked before this
  // build's library (scripts/exercise.sh selftest).
  const Run r = exercise("selftest '" + buildDir() + "'");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK_FALSE(contains(r.out, "FAIL"));
  CHECK(contains(r.out, "ok   2.3.6-1: the stub compiles and its check fails"));
  CHECK(contains(r.out, "ok   2.1-1: the restored solution passes"));
}

TEST_CASE("exercises start and check end to end in a temporary directory") {
  // One exercise through the student's path: a copy without the solution, a full build that
  // fails the check with the stub's message and the hint, then the solution put back passes.
  const std::string dir = dttest::tmpPath("exercise_e2e");
  std::filesystem::remove_all(dir);
  const Run s = exercise("start 2.3.2-1 '" + dir + "'");
  INFO(s.out);
  REQUIRE(s.status == 0);
  const std::string stats = dttest::readText(dir + "/code/stats.cpp");
  CHECK(contains(stats, "throw std::logic_error(\"exercise 2.3.2-1: not implemented yet\");"));
  CHECK_FALSE(contains(stats, "SOLUTION 2.3.2-1"));
  CHECK_FALSE(contains(stats, "2 * (nx + ny) - 4"));  // the solution's hull count
  CHECK(contains(stats, "BEGIN SOLUTION 2.3.2-2"));    // the other exercises are untouched
  CHECK_FALSE(dttest::fileExists(dir + "/.git/HEAD"));
  const std::string solutions = dttest::readText(dir + "/book/solutions.md");
  CHECK_FALSE(contains(solutions, "sol_2_3_2_1"));
  CHECK(contains(solutions, "sol_2_3_2_2"));
  // No page quotes the stripped code or links to the removed solution.
  CHECK(ch::runProgram({"grep", "-rqE", "snippet code/stats.cpp gridCounts|ref sol_2_3_2_1", dir + "/book"}) == 1);
  CHECK(contains(dttest::readText(dir + "/book/sec2_3_2.md"), "<!-- EXERCISE 2.3.2-1 -->"));

  const Run fail = exercise("check 2.3.2-1 '" + dir + "'");
  INFO(fail.out);
  CHECK(fail.status == 1);
  CHECK(contains(fail.out, "FAIL 2.3.2-1"));
  CHECK(contains(fail.out, "exercise 2.3.2-1: not implemented yet"));
  CHECK(contains(fail.out, "hint: gridCounts(nx, ny) must return"));

  dttest::writeText(dir + "/code/stats.cpp",
                    dttest::readText(std::string(DT_SOURCE_DIR) + "/code/stats.cpp"));
  const Run pass = exercise("check 2.3.2-1 '" + dir + "'");
  INFO(pass.out);
  CHECK(pass.status == 0);
  CHECK(contains(pass.out, "PASS 2.3.2-1"));
  std::filesystem::remove_all(dir);
}
