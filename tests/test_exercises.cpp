/// \file test_exercises.cpp The classroom machinery (exercises/exercises.txt, scripts/exercise.sh): the list agrees with the tests, pages and solutions; every implement exercise's stub compiles and fails its check while the solution passes; release, check, hint and watch work end to end.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support.h"

namespace {

using Run = dttest::RunResult;
using dttest::buildDir;
using dttest::contains;

// scripts/exercise.sh ARGS with the environment variables ENV; stdout and stderr together.
Run exercise(const std::vector<std::string>& args,
             const std::vector<std::pair<std::string, std::string>>& env = {}) {
  return dttest::runExerciseScript(args, env, true);
}

}  // namespace

TEST_CASE("exercises the list agrees with the test names the pages and the solutions page") {
  const Run r = exercise({"lint", buildDir()});
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK(contains(r.out, "26 exercises consistent"));
  const Run l = exercise({"list"});
  CHECK(l.status == 0);
  CHECK(contains(l.out, "2.3.5-4   prove      sec2_3_5"));
}

TEST_CASE("exercises every implement exercise fails on its stub and passes with its solution restored") {
  // Fast path: only the files holding the solution are recompiled, then linked before this
  // build's library (scripts/exercise.sh selftest).
  const Run r = exercise({"selftest", buildDir()});
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK_FALSE(contains(r.out, "FAIL"));
  CHECK(contains(r.out, "ok   2.3.6-1: the stub compiles and its check fails"));
  CHECK(contains(r.out, "ok   2.1-1: the restored solution passes"));
  // The judges of grade: each tells the stub from the solution and agrees with the library.
  for (const char* id : {"2.1-1", "2.3.4-1", "2.3.5-5"}) {
    CHECK(contains(r.out, std::string("ok   ") + id + ": the judge tells the stub from the solution"));
    CHECK(contains(r.out, std::string("ok   ") + id + ": the judge prints the library's output on the restored solution"));
  }
}

TEST_CASE("exercises release check hint and watch end to end in a temporary directory") {
  // One exercise through the student's path: a released workspace, a full build that fails the
  // check with the stub's message and the hint, hints one level at a time, then the solution put
  // back passes under watch. The workspace lies outside the repository (inside is refused).
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("dt_exercise_e2e_" + std::to_string(::getpid()))).string();
  std::filesystem::remove_all(dir);
  const Run s = exercise({"release", "2.3.2-1", dir});
  INFO(s.out);
  REQUIRE(s.status == 0);
  const std::string stats = dttest::readText(dir + "/code/checks/stats.cpp");
  // (The marker is spelled in two literals so that the book's source pages never show it.)
  CHECK(contains(stats, "  // BEGIN " "SOLUTION 2.3.2-1\n  throw std::logic_error(\"exercise 2.3.2-1: not implemented yet\");\n"));
  CHECK_FALSE(contains(stats, "2 * (nx + ny) - 4"));  // the solution's hull count
  CHECK(contains(stats, "exercise 2.3.2-2: not implemented yet"));  // every exercise is stripped
  CHECK_FALSE(dttest::fileExists(dir + "/.git/HEAD"));
  const std::string solutions = dttest::readText(dir + "/book/solutions.md");
  CHECK_FALSE(contains(solutions, "sol_2_3_2_1"));
  CHECK_FALSE(contains(solutions, "sol_2_3_2_2"));
  // No page quotes the stripped code or links to the removed solution.
  CHECK(ch::runProgram({"grep", "-rqE", "snippet code/checks/stats.cpp gridCounts|ref sol_2_3_2_1", dir + "/book"}) == 1);
  CHECK(contains(dttest::readText(dir + "/book/sec2_3_2.md"), "<!-- EXERCISE 2.3.2-1 -->"));

  // No exercise named: the workspace's own (.exercise).
  const Run fail = exercise({"check", dir});
  INFO(fail.out);
  CHECK(fail.status == 1);
  CHECK(contains(fail.out, "FAIL 2.3.2-1"));
  CHECK(contains(fail.out, "exercise 2.3.2-1: not implemented yet"));
  CHECK(contains(fail.out, "hint: gridCounts(nx, ny) must return"));

  const Run h1 = exercise({"hint", dir});
  CHECK(contains(h1.out, "hint 1 of 2 for 2.3.2-1: which vertices of a grid are on the hull?"));
  const Run h2 = exercise({"hint", dir});
  CHECK(contains(h2.out, "hint 2 of 2 for 2.3.2-1: gridCounts(nx, ny) must return"));
  const Run h3 = exercise({"hint", dir});
  CHECK(contains(h3.out, "no more hints for 2.3.2-1"));

  dttest::writeText(dir + "/code/checks/stats.cpp",
                    dttest::readText(std::string(DT_SOURCE_DIR) + "/code/checks/stats.cpp"));
  const Run pass = exercise({"watch", dir}, {{"DT_WATCH_ROUNDS", "1"}});
  INFO(pass.out);
  CHECK(pass.status == 0);
  CHECK(contains(pass.out, "PASS 2.3.2-1"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("exercises a handout is self-contained and stops on a missing figure") {
  const std::string out = dttest::tmpPath("handout_" + std::to_string(::getpid()));
  const std::string figs = out + "_figures";
  std::filesystem::remove_all(out);
  std::filesystem::remove_all(figs);
  std::filesystem::create_directories(figs);
  // No figure: the handout stops and says how to make it; nothing is written.
  const Run missing = exercise({"handout", "2.3.4", out}, {{"DT_HANDOUT_FIGURES", figs}});
  CHECK(missing.status == 2);
  CHECK(contains(missing.out, "fig_parabola_cavity.png of exercise 2.3.4-3 is missing"));
  CHECK(contains(missing.out, "cmake --build build --target sec2_3_4_algorithms"));
  CHECK_FALSE(dttest::fileExists(out + "/exercises_2.3.4.md"));

  dttest::writeText(figs + "/fig_parabola_cavity.png", "placeholder");
  const Run r = exercise({"handout", "2.3.4", out}, {{"DT_HANDOUT_FIGURES", figs}});
  INFO(r.out);
  REQUIRE(r.status == 0);
  const std::string sheet = dttest::readText(out + "/exercises_2.3.4.md");
  INFO(sheet);
  // The file, the signature and contract from the header, what a pass looks like.
  CHECK(contains(sheet, "`// BEGIN " "SOLUTION 2.3.4-1` and `// END " "SOLUTION 2.3.4-1` of `code/checks/stats.cpp`"));
  CHECK(contains(sheet, "**Signature and contract** (`code/checks/stats.h`):"));
  CHECK(contains(sheet, "// borders a face outside the list). Throws std::logic_error if an edge is shared by more than"));
  CHECK(contains(sheet, "void computeAdjacenciesSorted(std::vector<Face*>& faces);"));
  CHECK(contains(sheet, "then `PASS 2.3.4-1`"));
  CHECK(contains(sheet, "- `2.3.4 exercise 2.3.4-1 a link across an unmatched edge is left as it was`"));
  CHECK(contains(sheet, "**Not allowed:** `std::map`, `map`, `computeAdjacencies`"));
  // A measure exercise: its build line; its answer goes to answers.md, not PASS.
  CHECK(contains(sheet, "cmake --build build --target sec2_3_4_algorithms && build/sec2_3_4_algorithms"));
  CHECK(contains(sheet, "under `## Exercise 2.3.4-3` in `answers.md`"));
  CHECK(contains(sheet, "![fig_parabola_cavity.png](fig_parabola_cavity.png)"));
  CHECK_FALSE(contains(sheet, "not built yet"));
  CHECK_FALSE(contains(sheet, "if (s.forward == t.forward)"));  // no solution on the sheet
  CHECK(contains(dttest::readText(out + "/solutions_2.3.4.md"), "if (s.forward == t.forward)"));
  std::filesystem::remove_all(out);
  std::filesystem::remove_all(figs);
}
