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
  // Fast path: only the stubbed files are compiled, then linked before this build's library; the
  // restored solution is this build's own dt_tests (scripts/exercise.sh selftest).
  const Run r = exercise({"selftest", buildDir()});
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK_FALSE(contains(r.out, "FAIL"));
  CHECK(contains(r.out, "ok   2.3.6-1: the stub compiles and its check fails"));
  CHECK(contains(r.out, "ok   2.1-1: the restored solution passes"));
  // The judges of grade: each tells the stub from the solution (the library, the solution itself,
  // gives the reference; the class test grades solutions by that reference).
  for (const char* id : {"2.1-1", "2.1-2", "2.2-1", "2.2-3", "2.2.2-1", "2.3.1-1", "2.3.1-2", "2.3.1-3", "2.3.2-1",
                         "2.3.2-2", "2.3.3-1", "2.3.3-2", "2.3.4-1", "2.3.4-2", "2.3.5-5", "2.3.6-1"}) {
    CHECK(contains(r.out, std::string("ok   ") + id + ": the judge tells the stub from the solution"));
  }
}

TEST_CASE("exercises release check hint and watch end to end in a temporary directory") {
  // One exercise through the student's path: a released workspace, a full build that fails the
  // check with the stub's message and the hint, hints one level at a time, then the solution put
  // back passes under watch. The workspace lies outside the repository (inside is refused).
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("dt_exercise_e2e_" + std::to_string(::getpid()))).string();
  std::filesystem::remove_all(dir);
  const Run s = exercise({"release", "--variant", "5", "2.3.2-1", dir});
  INFO(s.out);
  REQUIRE(s.status == 0);
  CHECK(contains(s.out, "(variant 5)"));
  CHECK(contains(dttest::readText(dir + "/.exercise"), "\nvariant: 5\n"));
  const std::string stats = dttest::readText(dir + "/code/checks/stats.cpp");
  // (The marker is spelled in two literals so that the book's source pages never show it.)
  CHECK(contains(stats, "  // BEGIN " "SOLUTION 2.3.2-1\n  throw std::logic_error(\"exercise 2.3.2-1: not implemented yet\");\n"));
  CHECK_FALSE(contains(stats, "2 * (nx + ny) - 4"));  // the solution's hull count
  CHECK(contains(stats, "exercise 2.3.2-2: not implemented yet"));  // every exercise is stripped
  CHECK_FALSE(dttest::fileExists(dir + "/.git/HEAD"));
  CHECK_FALSE(dttest::fileExists(dir + "/exercises/judge_2_3.h"));  // the judges compute the answers
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
  CHECK(contains(fail.out, "variant 5: your tests draw their own random inputs"));
  // Only the test file of 2.3.2-1 is compiled into the workspace's dt_tests, not the suite.
  CHECK(contains(fail.out, "(target dt_tests, from tests/test_2_3_2_adjacencies.cpp) ..."));
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

TEST_CASE("exercises release gives each student of a roster a workspace with the roster's seed as its variant") {
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("dt_exercise_roster_" + std::to_string(::getpid()))).string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  dttest::writeText(dir + "/roster.tsv", "# workspace\tseed\tname\nada\t11\tAda L.\n\nbob\t42\tBob K.\n");
  const Run r = exercise({"release", "--roster", dir + "/roster.tsv", "2.3.3-2", dir + "/class"});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(contains(dttest::readText(dir + "/class/ada/.exercise"), "\nvariant: 11\n"));
  CHECK(contains(dttest::readText(dir + "/class/bob/.exercise"), "\nvariant: 42\n"));
  CHECK(contains(dttest::readText(dir + "/class/bob/code/checks/stats.cpp"), "exercise 2.3.3-2: not implemented yet"));
  // A seed that is not a number names the file, the line and the value; nothing is released.
  dttest::writeText(dir + "/bad.tsv", "ada\t11\nbob\tx7\n");
  const Run bad = exercise({"release", "--roster", dir + "/bad.tsv", "2.3.3-2", dir + "/bad"});
  CHECK(bad.status == 2);
  CHECK(contains(bad.out, "bad.tsv, line 2: the seed of bob is 'x7', not a number"));
  CHECK_FALSE(std::filesystem::exists(dir + "/bad"));
  const Run both = exercise({"release", "--variant", "3", "--roster", dir + "/roster.tsv", "2.3.3-2", dir + "/x"});
  CHECK(both.status == 2);
  CHECK(contains(both.out, "exclude each other"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("exercises a workspace's variant changes the seeds of the exercises' random inputs") {
  // tests/support.h: DT_VARIANT (set by check from the workspace) mixes into each seed.
  ::unsetenv("DT_VARIANT");
  CHECK(dttest::variant(21) == 21u);
  ::setenv("DT_VARIANT", "0", 1);
  CHECK(dttest::variant(21) == 21u);
  ::setenv("DT_VARIANT", "5", 1);
  const unsigned five = dttest::variant(21);
  CHECK(five != 21u);
  CHECK(dttest::variant(22) != five);
  CHECK(dt::uniformPoints(10, dttest::variant(21)) != dt::uniformPoints(10, 21));
  ::setenv("DT_VARIANT", "6", 1);
  CHECK(dttest::variant(21) != five);
  ::setenv("DT_VARIANT", "5x", 1);
  CHECK_THROWS_WITH(dttest::variant(21), "DT_VARIANT='5x' is not a variant number");
  ::unsetenv("DT_VARIANT");
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

TEST_CASE("exercises the judges of grade catch one planted bug in each exercise on the default seed") {
  // One wrong line in each teacher's solution: the judge linked with it must print other lines
  // than with the library, first in a line of the test whose claim the bug breaks. (grade
  // compares exactly these outputs; the sandbox around them is the class test's.)
  struct Plant {
    std::string id, file, from, to;
    int test;
  };
  const std::vector<Plant> plants = {
      // A face whose circle does not hold p is accepted.
      {"2.1-2", "listings/star.cpp", "    if (!f->inCircle(p)) fail(\"p is not strictly inside the circle of a cavity face\");\n", "", 1},
      // The closed disk: cocircular points join the cavity.
      {"2.2-1", "listings/bowyer_watson.cpp", "Y(t[2]), px, py) > 0)\n      cavity.push_back(t);", "Y(t[2]), px, py) >= 0)\n      cavity.push_back(t);", 1},
      // Collinear hull points dropped: a grid's hull edges are not split.
      {"2.2-3", "listings/bowyer_watson.cpp", "Y(hull.back()), X(p), Y(p)) < 0)", "Y(hull.back()), X(p), Y(p)) <= 0)", 1},
      // Parallel neighbouring edges counted as meeting.
      {"2.2.2-1", "exercises/ex_hull_regions.cpp", "return crossSign(a, b, c, d) > 0;", "return crossSign(a, b, c, d) >= 0;", 1},
      // One swap that forgets to negate the sign.
      {"2.3.1-1", "predicates/robustness.cpp", "if (p[2] < p[1]) std::swap(p[1], p[2]), parity = -parity;", "if (p[2] < p[1]) std::swap(p[1], p[2]);", 1},
      // Four bits short for incircle.
      {"2.3.1-2", "predicates/predicates_demo.cpp", "return 4 * scaledBits(in, 8) + 8;", "return 4 * scaledBits(in, 8) + 4;", 1},
      // The last endpoint is never tested on the other segment.
      {"2.3.1-3", "predicates/robustness.cpp", "  if (o4 == 0 && onSegment(rx, ry, sx, sy, qx, qy)) return true;\n", "", 1},
      // An off-by-one in the hull count.
      {"2.3.2-1", "checks/stats.cpp", "nh = 2 * (nx + ny) - 4;", "nh = 2 * (nx + ny) - 3;", 1},
      // An unused vertex (a skipped duplicate) returned.
      {"2.3.2-2", "checks/stats.cpp", "if (c.vf[v] > 0 && c.ve[v] <= 5) return int(v);", "if (c.ve[v] <= 5) return int(v);", 1},
      // Four links per half-edge counted as three.
      {"2.3.3-1", "checks/stats.cpp", "return (2 * ne * (1 + 4) +", "return (2 * ne * (1 + 3) +", 1},
      // A hull vertex's fan not started after the ghost faces.
      {"2.3.3-2", "checks/stats.cpp", "      std::rotate(star.begin(), star.begin() + long(k % star.size()), star.end());\n", "", 1},
      // Vertex 0 counted as a super vertex.
      {"2.3.4-2", "checks/stats.cpp", "(v->id < 0 ? D : sum) += 1;", "(v->id <= 0 ? D : sum) += 1;", 1},
      // Super-triangles 500 times larger: the flat triangle's circle no longer reaches them.
      {"2.3.6-1", "exercises/ex_flips.cpp", "return StuckRecovery{{0, 0, 1, 0, 0.5, -d}, 2.0};", "return StuckRecovery{{0, 0, 1, 0, 0.5, -d}, 1000.0};", 1},
  };
  // A directory of the build tree without the pid, and the compiles of this teacher's code
  // through ccache when the build found it: the next run of the suite, from any clone, takes the
  // same planted objects from the cache (the paths, below the source directory, are relative).
  const std::string work = dttest::tmpPath("judge_planted");
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  const std::string src = DT_SOURCE_DIR, lib = buildDir() + "/libdt.a";
  // The headers are found in their rooms (code/rooms.txt), as the library's build finds them.
  std::vector<std::string> cxx = {"g++", "-std=c++17", "-O1", "-ffp-contract=off", "-I" + src + "/code"};
  const std::string ccache = DT_CCACHE;
  if (!ccache.empty()) cxx.insert(cxx.begin(), ccache);
  for (const auto& room : std::filesystem::directory_iterator(src + "/code"))
    if (room.is_directory()) cxx.push_back("-I" + room.path().string());
  cxx.push_back("-c");
  auto compile = [&](const std::string& from, const std::string& to) {
    std::vector<std::string> argv = cxx;
    argv.insert(argv.end(), {from, "-o", to});
    const Run r = dttest::runCaptured(argv, {{"CCACHE_BASEDIR", src}}, true);
    INFO(r.out);
    REQUIRE(r.status == 0);
  };
  auto link = [&](const std::vector<std::string>& objs, const std::string& to) {
    std::vector<std::string> argv = {"g++", "-o", to};
    argv.insert(argv.end(), objs.begin(), objs.end());
    argv.insert(argv.end(), {lib, "-lmpfr", "-lgmp", "-pthread"});
    const Run r = dttest::runCaptured(argv, {}, true);
    INFO(r.out);
    REQUIRE(r.status == 0);
  };
  compile(src + "/exercises/judge.cpp", work + "/judge.o");
  link({work + "/judge.o"}, work + "/judge_ref");
  for (const Plant& p : plants) {
    INFO("exercise " << p.id << ", planted in code/" << p.file);
    std::string text = dttest::readText(src + "/code/" + p.file);
    const auto at = text.find(p.from);
    REQUIRE_MESSAGE(at != std::string::npos, "the teacher's solution no longer holds: " << p.from);
    REQUIRE(text.find(p.from, at + 1) == std::string::npos);
    text.replace(at, p.from.size(), p.to);
    const std::string planted = work + "/" + std::filesystem::path(p.file).filename().string(), obj = work + "/planted.o";
    dttest::writeText(planted, text);
    compile(planted, obj);
    link({obj, work + "/judge.o"}, work + "/j");
    const Run ref = dttest::runCaptured({work + "/judge_ref", p.id, "1"});
    const Run got = dttest::runCaptured({work + "/j", p.id, "1"});
    REQUIRE(ref.status == 0);
    CHECK(contains(ref.out, "\nend " + p.id + "\n"));
    CHECK(got.out != ref.out);
    // The first line that differs belongs to the test the bug breaks.
    std::size_t i = 0;
    while (i < ref.out.size() && i < got.out.size() && ref.out[i] == got.out[i]) ++i;
    const std::size_t line = ref.out.rfind('\n', i == 0 ? 0 : i - 1);
    const std::string first = ref.out.substr(line == std::string::npos ? 0 : line + 1, 120);
    INFO("first differing line of the reference: " << first);
    CHECK(first.rfind("t" + std::to_string(p.test) + " ", 0) == 0);
    std::filesystem::remove(planted);
  }
  std::filesystem::remove_all(work);
}
