/// \file test_exercises_class.cpp The teacher's path of the classroom (scripts/exercise.sh): a release holds no solution line of any exercise (string literals and mutant lines read piece by piece) and is refused inside the repository; a class of 30 workspaces of 2.3.4-1 (correct ones, planted bugs, an endless loop, a crash, an early exit, a lost END line, a compile error and every known cheat) is graded in one command, every row right, in a sandbox that leaves no file changed and no process behind; the cheats graded with the static checks off still fail; the exports follow their formats; prove answers are collected beside the teacher's sheet; a bug the doctest tests miss (2.2-3 dropping collinear hull points) fails by the judge alone.
#include <doctest/doctest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support.h"

namespace fs = std::filesystem;

namespace {

using Run = dttest::RunResult;
using dttest::buildDir;
using dttest::contains;

// scripts/exercise.sh ARGS with the environment variables ENV; stdout and stderr apart.
Run exercise(const std::vector<std::string>& args,
             const std::vector<std::pair<std::string, std::string>>& env = {}) {
  return dttest::runExerciseScript(args, env, false);
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// A marker line: "BEGIN SOLUTION <id>" after // in code, "<!-- BEGIN SOLUTION <id> -->" in Markdown
// (prose that mentions the markers, as exercises.txt's header does, is not one).
bool isMarker(const std::string& line, const std::string& word) {
  const std::string t = trim(line);
  return t.rfind("// " + word + " SOLUTION ", 0) == 0 || t.rfind("<!-- " + word + " SOLUTION ", 0) == 0;
}

// A line and its pieces as a solution line can hide in it: the parts between the fields of a
// mutant (" @@ "), between the "\n" of a string literal and between quotes.
std::vector<std::string> pieces(const std::string& line) {
  std::vector<std::string> out = {trim(line)};
  std::string cut = line;
  for (const std::string& sep : {std::string("@@"), std::string("\\n"), std::string("\"")})
    for (std::size_t at; (at = cut.find(sep)) != std::string::npos;) cut.replace(at, sep.size(), "\x1f");
  std::istringstream in(cut);
  std::string part;
  while (std::getline(in, part, '\x1f')) {
    std::string p = trim(part);
    while (!p.empty() && (p.front() == '"' || p.front() == '\'')) p = trim(p.substr(1));
    while (!p.empty() && p.back() == '"') p = trim(p.substr(0, p.size() - 1));
    if (!p.empty()) out.push_back(p);
  }
  return out;
}

// The files a release leaves out (scripts/exercise.sh RELEASE_LEAVE_OUT): a line found only
// there is not outside the solutions.
bool leftOut(const std::string& path) {
  for (const char* f : {"/tests/test_exercises.cpp", "/tests/test_exercises_class.cpp", "/tests/test_book.cpp",
                        "/tests/mutants.txt", "/tests/mutants_selftest.txt", "/exercises/judge.cpp",
                        "/exercises/judge_2_1.h", "/exercises/judge_2_2.h", "/exercises/judge_2_3.h"})
    if (path == std::string(DT_SOURCE_DIR) + f) return true;
  return false;
}

// The lines (and their pieces) of a text inside and outside its solution regions (any exercise).
void splitRegions(const std::string& text, std::set<std::string>& inside, std::set<std::string>& outside) {
  std::istringstream in(text);
  std::string line;
  int depth = 0;
  while (std::getline(in, line)) {
    if (isMarker(line, "BEGIN")) { ++depth; continue; }
    if (isMarker(line, "END")) { --depth; continue; }
    for (const std::string& p : pieces(line)) (depth > 0 ? inside : outside).insert(p);
  }
}

// The lines of the files under `root` that hold a distinctive line, or a piece of one, of a
// solution ("FILE: LINE"); `files` counts the files read.
std::vector<std::string> leaksIn(const std::string& root, const std::set<std::string>& distinctive, std::size_t& files) {
  std::vector<std::string> out;
  files = 0;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    ++files;
    std::istringstream in(dttest::readText(e.path().string()));
    std::string line;
    while (std::getline(in, line))
      for (const std::string& p : pieces(line))
        if (distinctive.count(p)) {
          out.push_back(e.path().string() + ": " + p);
          break;
        }
  }
  return out;
}

// The k-th region (0-based) of exercise `id` in `text` replaced by `body`.
std::string withRegion(const std::string& text, const std::string& id, int k, const std::string& body) {
  std::istringstream in(text);
  std::string line, out;
  int seen = -1;
  bool skip = false;
  while (std::getline(in, line)) {
    const bool begin = contains(line, "BEGIN SOLUTION " + id), end = contains(line, "END SOLUTION " + id);
    if (skip && !end) continue;
    out += line + "\n";
    if (begin && ++seen == k) {
      out += body;
      skip = true;
    }
    if (end) skip = false;
  }
  REQUIRE(seen >= k);
  return out;
}

// The k-th region of `id` in `text`.
std::string region(const std::string& text, const std::string& id, int k) {
  std::istringstream in(text);
  std::string line, body;
  int seen = -1;
  bool on = false;
  while (std::getline(in, line)) {
    if (contains(line, "BEGIN SOLUTION " + id)) { on = ++seen == k; continue; }
    if (contains(line, "END SOLUTION " + id)) { on = false; continue; }
    if (on) body += line + "\n";
  }
  return body;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  REQUIRE_MESSAGE(at != std::string::npos, "the teacher's solution no longer holds: " << from);
  return s.replace(at, from.size(), to);
}

std::vector<std::vector<std::string>> tsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream l(line);
    while (std::getline(l, cell, '\t')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// A directory outside the repository (a release inside it is refused; DT_TEST_TMP is in build/).
std::string outsideTmp(const std::string& name) {
  return (fs::temp_directory_path() / ("dt_" + name + "_" + std::to_string(::getpid()))).string();
}

// A fresh empty directory (no shell: the paths are never read as code).
void freshDirectory(const std::string& d) {
  fs::remove_all(d);
  fs::create_directories(d);
}

}  // namespace

TEST_CASE("exercises class a release holds no line of any solution and is refused inside the repository") {
  const std::string root = outsideTmp("class_release");
  fs::remove_all(root);
  // Inside the repository: refused, nothing made.
  const std::string inside = std::string(DT_SOURCE_DIR) + "/mywork_release_test";
  const Run in = exercise({"release", "2.3.4-1", inside});
  CHECK(in.status == 2);
  CHECK(contains(in.err, "inside the repository"));
  CHECK_FALSE(fs::exists(inside));

  // A workspace and a build folder left inside the tree (an old 'start DIR', a build named
  // freely) hold solutions and objects: the release skips them.
  const std::string pid = std::to_string(::getpid());
  const std::string nested = std::string(DT_SOURCE_DIR) + "/nested_ws_" + pid;
  const std::string oddBuild = std::string(DT_SOURCE_DIR) + "/objects_" + pid;
  for (const std::string& d : {nested + "/code/checks", nested + "/scripts", oddBuild}) fs::create_directories(d);
  dttest::writeText(nested + "/CMakeLists.txt", "project(x)\n");
  dttest::writeText(nested + "/scripts/exercise.sh", "\n");
  dttest::writeText(nested + "/code/checks/stats.cpp",
                    dttest::readText(std::string(DT_SOURCE_DIR) + "/code/checks/stats.cpp"));
  dttest::writeText(oddBuild + "/CMakeCache.txt", "\n");
  dttest::writeText(oddBuild + "/star.cpp", dttest::readText(std::string(DT_SOURCE_DIR) + "/code/listings/star.cpp"));
  // And the folder grade writes prove answers to, with the teacher's sheet.
  const std::string answers = std::string(DT_SOURCE_DIR) + "/answers_" + pid;
  fs::create_directories(answers);
  dttest::writeText(answers + "/SHEET.md", dttest::readText(std::string(DT_SOURCE_DIR) + "/book/solutions.md"));
  const Run r = exercise({"release", "2.3.4-1", "2.1-1", "2.3.5-1", root});
  for (const std::string& d : {nested, oddBuild, answers}) fs::remove_all(d);
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK_FALSE(fs::exists(root + "/nested_ws_" + pid));
  CHECK_FALSE(fs::exists(root + "/objects_" + pid));
  CHECK_FALSE(fs::exists(root + "/answers_" + pid));
  CHECK(contains(dttest::readText(root + "/.exercise"), "ids: 2.3.4-1 2.1-1 2.3.5-1"));
  CHECK(contains(dttest::readText(root + "/answers.md"), "## Exercise 2.3.5-1"));
  CHECK_FALSE(fs::exists(root + "/.git"));
  CHECK_FALSE(fs::exists(root + "/build"));
  // The markers stay around the stub, so that grade can cut the student's code out.
  const std::string stats = dttest::readText(root + "/code/checks/stats.cpp");
  CHECK(contains(stats, "// BEGIN " "SOLUTION 2.3.4-1\n  throw std::logic_error(\"exercise 2.3.4-1: not implemented yet\");\n  // END " "SOLUTION 2.3.4-1"));
  CHECK(contains(stats, "exercise 2.3.2-1: not implemented yet"));  // not released, stripped too

  // Every line of every solution region of the teacher's tree (code, tests, solutions page)
  // that appears nowhere outside the regions: none of them may be in any file of the release.
  std::set<std::string> inRegions, outside;
  for (const char* dir : {"code", "tests", "book", "chapters", "cli", "exercises", "scripts"})
    for (const auto& e : fs::recursive_directory_iterator(std::string(DT_SOURCE_DIR) + "/" + dir))
      if (e.is_regular_file()) {
        // A line found only in a file the release leaves out is not outside the solutions.
        std::set<std::string> notReleased;
        splitRegions(dttest::readText(e.path().string()), inRegions, leftOut(e.path().string()) ? notReleased : outside);
      }
  std::set<std::string> distinctive;
  for (const std::string& l : inRegions)
    if (l.size() >= 20 && !outside.count(l)) distinctive.insert(l);
  CHECK(distinctive.size() > 200);
  CHECK(distinctive.count("if (s.forward == t.forward)"));  // 2.3.4-1
  CHECK(distinctive.count("// four values, swapped or not, negated or not (quadrant 0 swaps, quadrant 3 swaps and negates,"));
  // The other solutions the class test below grades are solution regions of this file: their
  // lines, inside string literals, count too.
  CHECK(distinctive.count("std::sort(e.begin(), e.end(), [](const Use& p, const Use& q) { return p.first < q.first; });"));
  std::size_t files = 0;
  const std::vector<std::string> leaks = leaksIn(root, distinctive, files);
  for (std::size_t i = 0; i < leaks.size() && i < 5; ++i) FAIL_CHECK("solution line in " << leaks[i]);
  CHECK(files > 100);
  CHECK(leaks.empty());
  // Left out: the files that state answers.
  for (const char* f : {"/tests/test_exercises.cpp", "/tests/test_exercises_class.cpp", "/tests/test_book.cpp",
                        "/tests/mutants.txt", "/tests/mutants_selftest.txt", "/exercises/judge.cpp",
                        "/exercises/judge_2_1.h", "/exercises/judge_2_2.h", "/exercises/judge_2_3.h"}) {
    CHECK_MESSAGE(!fs::exists(root + f), f << " is in the release");
    CHECK(leftOut(std::string(DT_SOURCE_DIR) + f));
  }
  // The answer values: the book tool's comment that spells 2.3.4-2's closed form is gone.
  CHECK_FALSE(contains(dttest::readText(root + "/book/book_tool.h"), "(6 - D)/n"));

  // The search itself, on a planted leak: a mutant line that holds a solution line (its fields
  // split at @@ and \n) and the solution line inside a string literal are both found.
  std::string mutant;
  {
    std::istringstream in(dttest::readText(std::string(DT_SOURCE_DIR) + "/tests/mutants.txt"));
    std::string line;
    while (mutant.empty() && std::getline(in, line))
      if (!line.empty() && line[0] != '#' && contains(line, " @@ "))
        for (const std::string& p : pieces(line))
          if (p != trim(line) && distinctive.count(p)) mutant = line;
  }
  REQUIRE_MESSAGE(!mutant.empty(), "tests/mutants.txt holds no solution line to plant");
  dttest::writeText(root + "/tests/planted_mutant.txt", mutant + "\n");
  dttest::writeText(root + "/tests/planted_literal.cpp",
                    "const char* s = \"  if (s.forward == t.forward)\\n\";\n");
  const std::vector<std::string> planted = leaksIn(root, distinctive, files);
  CHECK(planted.size() == 2);
  fs::remove_all(root);
}

// ---- the class of 2.3.4-1 ----------------------------------------------------------------------

namespace {

struct Student {
  std::string name, body, result, passed, cols, firstHas;
  bool editTest = false, dropEnd = false;
};

// What a grading must leave as it was: every file of the workspaces and of the teacher's tree
// (its build folders aside), by size and modification time.
std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>> snapshot(const std::vector<std::string>& roots) {
  std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>> m;
  for (const std::string& r : roots)
    for (auto it = fs::recursive_directory_iterator(r); it != fs::recursive_directory_iterator(); ++it) {
      const std::string name = it->path().filename().string();
      if (it->is_directory() && (name == ".git" || name.rfind("build", 0) == 0 || name == "node_modules")) {
        it.disable_recursion_pending();
        continue;
      }
      if (it->is_regular_file()) m[it->path().string()] = {it->file_size(), it->last_write_time()};
    }
  return m;
}

// The processes of the sandbox's user (nobody) still alive.
std::vector<std::string> nobodysProcesses() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string pid = e.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::istringstream in(dttest::readText(e.path().string() + "/status"));
    std::string line;
    bool zombie = false;
    while (std::getline(in, line)) {
      // A zombie has ended: only its exit status waits for the machine's init to collect it
      // (bubblewrap leaves its namespace's init so when the sandbox ends).
      if (line.rfind("State:", 0) == 0) zombie = contains(line, "Z (zombie)");
      if (line.rfind("Uid:", 0) == 0 && !zombie) {
        std::istringstream u(line.substr(4));
        long real = -1;
        u >> real;
        if (real == 65534) out.push_back(pid + " " + dttest::readText(e.path().string() + "/cmdline"));
      }
    }
  }
  return out;
}

// The files whose size or time differ between two snapshots, or that only one has.
std::vector<std::string> changed(const std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>>& a,
                                 const std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>>& b) {
  std::vector<std::string> out;
  for (const auto& f : a)
    if (!b.count(f.first) || b.at(f.first) != f.second) out.push_back(f.first);
  for (const auto& f : b)
    if (!a.count(f.first)) out.push_back(f.first);
  return out;
}

// The cheats of a class: each tries, from inside the solution region, to pass without a
// solution, to change the grades or another student's work, to read the solutions or to
// outlive the grading. `victim` is the workspace of a correct student graded after them.
std::vector<Student> cheats(const std::string& victim, const std::string& marker) {
  const std::string src = DT_SOURCE_DIR, tmp = dttest::tmpPath("");
  return {
      // The report: doctest's summary printed, then an exit.
      {"report_rewrite", "  std::printf(\"[doctest] test cases: 1 | 1 passed | 0 failed | 0 skipped\\n\");\n  std::exit(0);\n",
       "FORBIDDEN", "0/4", "-\t-\t-\t-", "calls "},
      // A doctest report faked where a test's input is large (the 3000-point test), the work
      // left undone elsewhere: the tests' report says pass, the judge's lines do not match.
      {"report_faked",
       "  if (faces.size() > 5000) {\n    std::printf(\"[doctest] test cases: 1 | 1 passed | 0 failed | 0 skipped\\n\");\n"
       "    std::exit(0);\n  }\n  return;\n",
       "FORBIDDEN", "0/4", "-\t-\t-\t-", "calls "},
      // Grades changed after the grader ended, by a child left behind.
      {"late_grades",
       "  std::system(\"(sleep 6; sed -i s/FAIL/PASS/ " + tmp + "run_out_* /tmp/tmp.*/grades.tsv) >/dev/null 2>&1 &\");\n  return;\n",
       "FORBIDDEN", "0/4", "-\t-\t-\t-", "'system'"},
      // The grader's rows rewritten while it runs.
      {"background_rows",
       "  std::system(\"for i in 1 2 3 4 5 6; do sed -i s/FAIL/PASS/ /tmp/tmp.*/rows/* " + tmp +
           "run_out_*; sleep 1; done >/dev/null 2>&1 &\");\n  return;\n",
       "FORBIDDEN", "0/4", "-\t-\t-\t-", "'system'"},
      // Another student's solution broken.
      {"sabotage", "  std::system(\"echo broken >> " + victim + "/code/checks/stats.cpp; rm -f " + victim + "/code/checks/stats.h\");\n  return;\n",
       "FORBIDDEN", "0/4", "-\t-\t-\t-", "'system'"},
      // Processes that outlive the grading.
      {"lingering", "  std::system(\"sleep 917" + marker + " & sleep 917" + marker + " &\");\n  return;\n", "FORBIDDEN", "0/4",
       "-\t-\t-\t-", "'system'"},
      // A child that holds stdout open for ten minutes.
      {"held_stdout", "  std::system(\"sleep 600 &\");\n  return;\n", "FORBIDDEN", "0/4", "-\t-\t-\t-", "'system'"},
      // The solutions read, a file left in the teacher's tree.
      {"system_solutions",
       "  std::system(\"cp " + src + "/book/solutions.md /box/stolen.md; cp " + src + "/book/solutions.md /tmp/stolen" +
           marker + ".md; touch " + src + "/pwned" + marker + "\");\n  return;\n",
       "FORBIDDEN", "0/4", "-\t-\t-\t-", "'system'"},
  };
}

}  // namespace

TEST_CASE("exercises class 30 workspaces are graded in one command into a TSV right for every row") {
  const std::string root = outsideTmp("class_30");
  freshDirectory(root);
  const Run rel = exercise({"release", "2.3.4-1", root + "/release"});
  INFO(rel.out << rel.err);
  REQUIRE(rel.status == 0);

  const std::string teacher = dttest::readText(std::string(DT_SOURCE_DIR) + "/code/checks/stats.cpp");
  const std::string solution = region(teacher, "2.3.4-1", 0);
  const std::string released = dttest::readText(root + "/release/code/checks/stats.cpp");
  // The planted bugs, made from the teacher's own solution.
  const std::string noOrientation = replaced(solution, "if (s.forward == t.forward)", "if (false)");
  const std::string nulls = "  for (Face* f : faces) f->F[0] = f->F[1] = f->F[2] = nullptr;\n" + solution;
  const std::string noThree =
      replaced(solution, "if (j - i > 2) throw std::logic_error(\"computeAdjacenciesSorted: edge of three faces\");", "");
  // A different correct solution: directed edges sorted, the reverse found by binary search
  // (std::unordered_set is allowed: "map" is forbidden as a word only).
  // BEGIN SOLUTION 2.3.4-1 (remove)
  const std::string sorted =
      "  using Key = std::pair<const Vertex*, const Vertex*>;\n"
      "  using Use = std::pair<Key, Face*>;\n"
      "  std::vector<Use> e;\n"
      "  for (Face* f : faces)\n"
      "    for (int k = 0; k < 3; ++k) e.push_back({{f->V[k], f->V[(k + 1) % 3]}, f});\n"
      "  std::sort(e.begin(), e.end(), [](const Use& p, const Use& q) { return p.first < q.first; });\n"
      "  for (std::size_t i = 0; i + 1 < e.size(); ++i)\n"
      "    if (e[i].first == e[i + 1].first) throw std::logic_error(\"edge used twice one way\");\n"
      "  std::unordered_set<const Face*> done;\n"
      "  for (Face* f : faces)\n"
      "    for (int k = 0; k < 3; ++k) {\n"
      "      const Key back{f->V[(k + 1) % 3], f->V[k]};\n"
      "      auto it = std::lower_bound(e.begin(), e.end(), back,\n"
      "                                 [](const Use& p, const Key& q) { return p.first < q; });\n"
      "      if (it != e.end() && it->first == back) f->F[k] = it->second;\n"
      "      done.insert(f);\n"
      "    }\n";
  // END SOLUTION 2.3.4-1
  const std::string loop = "  volatile int spin = 0;\n  while (spin == 0) {\n  }\n";
  const std::string pid = std::to_string(::getpid());
  const std::string victim = root + "/zz_victim";
  const std::string pass4 = "pass\tpass\tpass\tpass", none = "-\t-\t-\t-";
  std::vector<Student> cls;
  // Under AddressSanitizer (scripts/test.sh's second build) every student's file is compiled
  // instrumented: fewer correct students there.
#if defined(__SANITIZE_ADDRESS__)
  const int many = 1, classSize = 28;
#else
  const int many = 3, classSize = 30;
#endif
  for (int i = 0; i < many; ++i) cls.push_back({"correct" + std::to_string(i), solution, "PASS", "4/4", pass4, "-"});
  cls.push_back({"sorted", sorted, "PASS", "4/4", pass4, "-"});
  cls.push_back({"sorted_comment", "  // a comment naming std::map is not a use of it\n" + sorted, "PASS", "4/4", pass4, "-"});
  for (int i = 0; i < 2; ++i)
    cls.push_back({"no_orientation" + std::to_string(i), noOrientation, "FAIL", "3/4", "pass\tfail\tpass\tpass",
                   "test '2.3.4 exercise 2.3.4-1 an edge two faces use in the same direction is rejected'"});
  for (int i = 0; i < 2; ++i)
    cls.push_back({"nullptr" + std::to_string(i), nulls, "FAIL", "3/4", "pass\tpass\tfail\tpass",
                   "(on the ball's boundary) linked to nullptr, expected a face outside the list"});
  cls.push_back({"no_three_faces", noThree, "FAIL", "3/4", "pass\tpass\tpass\tfail",
                 "test '2.3.4 exercise 2.3.4-1 an edge of three faces is rejected'"});
  cls.push_back({"edited_test", "", "FAIL", "0/4", "fail\tfail\tfail\tfail", "exercise 2.3.4-1: not implemented yet"});
  cls.back().editTest = true;
  cls.push_back({"untouched", "", "FAIL", "0/4", "fail\tfail\tfail\tfail", "exercise 2.3.4-1: not implemented yet"});
  cls.push_back({"endless_loop", loop, "TIMEOUT", "0/4", none, "did not finish within 10 s"});
  cls.push_back({"crash", "  Face* volatile nowhere = nullptr;\n  *static_cast<Face* volatile*>(&nowhere->F[0]) = nullptr;\n",
                 "CRASH", "0/4", none, "SIGSEGV"});
  cls.push_back({"early_exit", "  std::exit(0);\n", "EXITED", "0/4", none, "before the judge was done"});
  cls.push_back({"no_end", solution, "NO-REGION", "0/4", none, "has no END SOLUTION 2.3.4-1 line"});
  cls.back().dropEnd = true;
  // The student's line of the error: the line after BEGIN in the released file.
  int beginLine = 0;
  {
    std::istringstream in(released);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      if (contains(line, "BEGIN SOLUTION 2.3.4-1")) beginLine = n;
  }
  cls.push_back({"compile_error", "  int x = ;\n", "COMPILE-ERROR", "0/4", none,
                 "code/checks/stats.cpp:" + std::to_string(beginLine + 1) + ":"});
  cls.push_back({"forbidden_call", "  computeAdjacencies(faces);  // the library's, with its map\n", "FORBIDDEN", "0/4",
                 none, "'computeAdjacencies'"});
  // "//" or "/*" inside a string literal does not start a comment.
  cls.push_back({"string_slashes", "  const char* cut = \"//\"; (void)cut; computeAdjacencies(faces);\n", "FORBIDDEN", "0/4",
                 none, "'computeAdjacencies'"});
  cls.push_back({"string_include", "  const char* cut = \"/*\"; (void)cut;\n#include <fstream>\n", "FORBIDDEN", "0/4", none,
                 "the preprocessor"});
  // The function closed, the library's mangled name declared with C linkage.
  cls.push_back({"extern_c",
                 "}\nextern \"C\" void _ZN2dt18computeAdjacenciesERSt6vectorIPNS_4FaceESaIS3_EE(std::vector<Face*>&);\n"
                 "void tail(std::vector<Face*>& faces) {\n  _ZN2dt18computeAdjacenciesERSt6vectorIPNS_4FaceESaIS3_EE(faces);\n",
                 "FORBIDDEN", "0/4", none, "closes the function"});
  for (const Student& c : cheats(victim, pid)) cls.push_back(c);
  cls.push_back({"zz_victim", solution, "PASS", "4/4", pass4, "-"});
  REQUIRE(cls.size() == std::size_t(classSize));

  std::vector<std::string> dirs;
  for (const Student& s : cls) {
    const std::string d = root + "/" + s.name;
    fs::copy(root + "/release", d, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    std::string text = s.body.empty() ? released : withRegion(released, "2.3.4-1", 0, s.body);
    if (s.dropEnd) text = replaced(text, "  // END " "SOLUTION 2.3.4-1\n", "");
    dttest::writeText(d + "/code/checks/stats.cpp", text);
    if (s.editTest) {
      // The student's tests of the same names, made to pass on the stub: grade never uses them.
      dttest::writeText(d + "/tests/test_2_3_4_exercises.cpp",
                        "#include <doctest/doctest.h>\n"
                        "TEST_CASE(\"2.3.4 exercise 2.3.4-1 the links of a 3000-point triangulation are restored\") {}\n"
                        "TEST_CASE(\"2.3.4 exercise 2.3.4-1 an edge two faces use in the same direction is rejected\") {}\n"
                        "TEST_CASE(\"2.3.4 exercise 2.3.4-1 a link across an unmatched edge is left as it was\") {}\n"
                        "TEST_CASE(\"2.3.4 exercise 2.3.4-1 an edge of three faces is rejected\") {}\n");
    }
    dirs.push_back(d);
  }
  const auto before = snapshot({root, DT_SOURCE_DIR});
  const auto t0 = std::chrono::steady_clock::now();
  dirs.insert(dirs.begin(), {"grade", "2.3.4-1"});
  const Run g = exercise(dirs, {{"DT_GRADE_NO_BUILD", "1"}, {"DT_TEST_TIMEOUT", "10"}, {"DT_GRADE_BUILD", buildDir()}});
  dirs.erase(dirs.begin(), dirs.begin() + 2);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  MESSAGE("graded " << classSize << " workspaces of 2.3.4-1 in " << seconds << " s");
  INFO(g.out << g.err);
  REQUIRE(g.status == 0);
  const auto rows = tsv(g.out);
  REQUIRE(rows.size() == cls.size() + 1);
  CHECK(rows[0][0] == "student");
  CHECK(rows[0][3] == "2.3.4 exercise 2.3.4-1 the links of a 3000-point triangulation are restored");
  CHECK(rows[0][7] == "judge");
  for (std::size_t i = 0; i < cls.size(); ++i) {
    const Student& s = cls[i];
    const auto& row = rows[i + 1];
    INFO("row of " << s.name);
    REQUIRE(row.size() == 11);
    CHECK(row[0] == s.name);
    CHECK(row[1] == s.result);
    CHECK(row[2] == s.passed);
    CHECK(row[3] + "\t" + row[4] + "\t" + row[5] + "\t" + row[6] == s.cols);
    CHECK_MESSAGE(contains(row[8], s.firstHas), row[8]);
    // No row waits for a child that holds its output: the timeout bounds every row.
    CHECK(std::stoi(row[9]) < 60);
  }
  // The nullptr rows name the face and the edge that failed.
  for (std::size_t i = 0; i < cls.size(); ++i)
    if (cls[i].name == "nullptr0") {
      CHECK(contains(rows[i + 1][8], "face "));
      CHECK(contains(rows[i + 1][8], ", edge "));
    }
  // Nothing outside the grader's output changed, and no process of the sandbox is left.
  {
    const std::vector<std::string> files = changed(before, snapshot({root, DT_SOURCE_DIR})), left = nobodysProcesses();
    CHECK_MESSAGE(files.empty(), files.size() << " files changed, the first " << (files.empty() ? "" : files[0]));
    CHECK_MESSAGE(left.empty(), left.size() << " processes left, the first " << (left.empty() ? "" : left[0]));
  }
  CHECK(contains(g.err, "graded (" + std::to_string(many + 3) + " pass)"));

  // The similarity hint: the copies of the teacher's solution pair up, a comment changes
  // nothing, two different algorithms do not pair.
  const Run sim = exercise({"similar", "2.3.4-1", root + "/correct0", root + "/correct1", root + "/sorted",
                            root + "/sorted_comment", root + "/untouched"});
  INFO(sim.out << sim.err);
  CHECK(sim.status == 0);
  CHECK(contains(sim.out, "a hint, not a verdict"));
  CHECK(contains(sim.out, "\n1.00\tcorrect0\tcorrect1\t"));
  CHECK(contains(sim.out, "\n1.00\tsorted\tsorted_comment\t"));
  CHECK_FALSE(contains(sim.out, "correct0\tsorted"));
  CHECK_FALSE(contains(sim.out, "untouched"));

  // The teacher's summary page: the histogram's numbers in words, the failures named.
  const std::string table = root + "/grades.tsv";
  dttest::writeText(table, g.out);
  const Run sum = exercise({"summary", "2.3.4-1", table, root + "/summary"});
  INFO(sum.out << sum.err);
  REQUIRE(sum.status == 0);
  const std::string page = dttest::readText(root + "/summary/summary.html");
  CHECK(fs::file_size(root + "/summary/passes.png") > 1000);
  CHECK(contains(page, "alt=\"Bar chart of the students passing each test: test 1, " + std::to_string(many + 8) + " of " + std::to_string(classSize) + ";"));
  CHECK(contains(page, "<tr><td>endless_loop</td><td>TIMEOUT</td><td>0/4</td>"));
  CHECK_FALSE(contains(page, "<tr><td>correct0</td><td>PASS</td>"));  // among the failures

  // One student: the summary counts its pass.
  const Run one = exercise({"grade", "2.3.4-1", root + "/correct0"},
                           {{"DT_GRADE_NO_BUILD", "1"}, {"DT_GRADE_BUILD", buildDir()}});
  CHECK(contains(one.err, "1 student of 2.3.4-1 graded (1 pass)"));

  // The cheats again with the static checks off: the sandbox and the judge alone hold. Each
  // fails or exits, the victim still passes, nothing changed, nothing left running.
  std::vector<std::string> bare = {"grade", "2.3.4-1"};
  const std::vector<Student> cheat = cheats(victim, pid);
  for (const Student& c : cheat) bare.push_back(root + "/" + c.name);
  bare.push_back(victim);
  const auto before2 = snapshot({root, DT_SOURCE_DIR});
  const Run b = exercise(bare, {{"DT_GRADE_NO_BUILD", "1"}, {"DT_TEST_TIMEOUT", "10"}, {"DT_GRADE_BUILD", buildDir()},
                                {"DT_GRADE_STATIC_CHECKS", "0"}});
  INFO(b.out << b.err);
  REQUIRE(b.status == 0);
  const auto brows = tsv(b.out);
  REQUIRE(brows.size() == cheat.size() + 2);
  for (std::size_t i = 0; i < cheat.size(); ++i) {
    INFO("row of " << cheat[i].name << " with the static checks off");
    REQUIRE(brows[i + 1].size() == 11);
    CHECK(brows[i + 1][1] == (cheat[i].name == "report_rewrite" ? "EXITED" : "FAIL"));
    CHECK(brows[i + 1][2] == "0/4");
    // The faked report passed the 3000-point test's run; the judge's lines of it did not match.
    if (cheat[i].name == "report_faked") CHECK(contains(brows[i + 1][8], "the judge printed"));
    CHECK(contains(brows[i + 1][8], "STATIC CHECKS OFF"));
  }
  CHECK(brows.back()[1] == "PASS");
  {
    const std::vector<std::string> files = changed(before2, snapshot({root, DT_SOURCE_DIR})), left = nobodysProcesses();
    CHECK_MESSAGE(files.empty(), files.size() << " files changed, the first " << (files.empty() ? "" : files[0]));
    CHECK_MESSAGE(left.empty(), left.size() << " processes left, the first " << (left.empty() ? "" : left[0]));
  }
  CHECK_FALSE(fs::exists(std::string(DT_SOURCE_DIR) + "/pwned" + pid));
  CHECK_FALSE(fs::exists("/tmp/stolen" + pid + ".md"));
  fs::remove_all(root);
}

TEST_CASE("exercises class grade catches the planted bugs of 2.1-1 and collects prove answers beside the sheet") {
  const std::string root = outsideTmp("class_21");
  freshDirectory(root);
  const Run rel = exercise({"release", "2.1-1", "2.3.5-1", root + "/release"});
  REQUIRE(rel.status == 0);
  const std::string teacher = dttest::readText(std::string(DT_SOURCE_DIR) + "/code/listings/star.cpp");
  const std::string kernel = region(teacher, "2.1-1", 0), open = region(teacher, "2.1-1", 1);
  const std::string released = dttest::readText(root + "/release/code/listings/star.cpp");
  const std::string lastEdge = replaced(kernel, "for (std::size_t i = 0; i < m && !K.empty(); ++i)",
                                        "for (std::size_t i = 0; i + 1 < m && !K.empty(); ++i)");
  const std::string flat = replaced(replaced(kernel, "if (!hasArea) K.clear();", ""),
                                    "if (K.size() < 3) K.clear();", "");
  struct Student {
    std::string name, body, result, firstHas;
  };
  const std::vector<Student> cls = {
      {"correct", kernel, "PASS", "-"},
      {"last_edge", lastEdge, "FAIL", "polygon '"},
      {"flat", flat, "FAIL", "polygon 'two blocks whose kernel is a segment'"}};
  std::vector<std::string> dirs;
  for (const Student& s : cls) {
    const std::string d = root + "/" + s.name;
    fs::copy(root + "/release", d, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    dttest::writeText(d + "/code/listings/star.cpp",
                      withRegion(withRegion(released, "2.1-1", 0, s.body), "2.1-1", 1, open));
    dirs.push_back(d);
  }
  dttest::writeText(root + "/correct/answers.md",
                    dttest::readText(root + "/correct/answers.md") + "Each update swaps or negates.\n");
  // A roster: each student's seed (the judge draws that student's inputs) and, for the
  // gradebooks, name, ids and section; a name with a comma is quoted in CSV.
  const std::string roster = root + "/roster.tsv";
  dttest::writeText(roster, "# workspace\tseed\tname\tid\tsis user\tsis login\tsection\n"
                            "correct\t7\tLovelace, Ada\t101\tS101\tada\tA\n"
                            "last_edge\t8\tBabbage\t102\tS102\tcharles\tA\n");
  dirs.insert(dirs.begin(), {"grade", "--roster", roster, "2.1-1"});
  const Run g = exercise(dirs, {{"DT_GRADE_NO_BUILD", "1"}, {"DT_TEST_TIMEOUT", "20"},
                                {"DT_GRADE_BUILD", buildDir()}});
  dirs.erase(dirs.begin(), dirs.begin() + 4);
  INFO(g.out << g.err);
  REQUIRE(g.status == 0);
  const auto rows = tsv(g.out);
  REQUIRE(rows.size() == 4);
  for (std::size_t i = 0; i < cls.size(); ++i) {
    INFO(cls[i].name);
    CHECK(rows[i + 1][0] == cls[i].name);
    CHECK(rows[i + 1][1] == cls[i].result);
    REQUIRE(rows[i + 1].size() == 11);
    CHECK_MESSAGE(contains(rows[i + 1][8], cls[i].firstHas), rows[i + 1][8]);
  }
  CHECK(rows[1][10] == "7");  // the roster's seeds; the default for a student it does not name
  CHECK(rows[2][10] == "8");
  CHECK(rows[3][10] == "1");
  // The last edge never clipped: the corner test fails, naming a polygon and a starting corner.
  CHECK(contains(rows[2][8], "starting at corner"));
  // The flat kernel: the other tests pass.
  CHECK(rows[3][2] == "3/4");

  // The exports, from the same table (scripts/exercise.sh export FORMAT ID TSV [ROSTER]).
  const std::string table = root + "/grades.tsv";
  dttest::writeText(table, g.out);
  const Run canvas = exercise({"export", "canvas", "2.1-1", table, roster});
  REQUIRE(canvas.status == 0);
  CHECK(canvas.out ==
        "Student,ID,SIS User ID,SIS Login ID,Section,Exercise 2.1-1\n"
        "Points Possible,,,,,4\n"
        "\"Lovelace, Ada\",101,S101,ada,A,4\n"
        "Babbage,102,S102,charles,A," + rows[2][2].substr(0, 1) + "\n"
        "flat,,,,,3\n");
  const Run moodle = exercise({"export", "moodle", "2.1-1", table, roster});
  REQUIRE(moodle.status == 0);
  CHECK(contains(moodle.out, "Username,Exercise 2.1-1,Exercise 2.1-1 feedback\n\"Lovelace, Ada\",4,PASS 4/4\n"));
  CHECK(contains(moodle.out, "\nflat,3,\"FAIL 3/4: test '2.1 exercise 2.1-1 a kernel without interior"));
  const Run junit = exercise({"export", "junit", "2.1-1", table});
  REQUIRE(junit.status == 0);
  CHECK(contains(junit.out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"exercise 2.1-1\" tests=\"12\""));
  CHECK(contains(junit.out, "<testsuite name=\"flat\" tests=\"4\" failures=\"1\""));
  CHECK(contains(junit.out, "<testcase classname=\"correct\" name=\"2.1 exercise 2.1-1 the open kernel test is exact on the lines of the edges\"/>"));
  CHECK(contains(junit.out, "<failure type=\"fail\" message=\"FAIL: test '2.1 exercise 2.1-1 a kernel without interior"));
  // Every element closed: as many openings as closings of each element.
  for (const std::string& tag : {std::string("testsuites"), std::string("testsuite"), std::string("testcase")}) {
    std::size_t open = 0, close = 0;
    for (std::size_t at = 0; (at = junit.out.find("<" + tag + " ", at)) != std::string::npos; ++at) ++open;
    for (std::size_t at = 0; (at = junit.out.find("</" + tag + ">", at)) != std::string::npos; ++at) ++close;
    for (std::size_t at = 0; (at = junit.out.find("<" + tag + " ", at)) != std::string::npos; ++at) {
      const std::size_t end = junit.out.find('>', at);
      if (junit.out[end - 1] == '/') ++close;
    }
    CHECK_MESSAGE(open == close, tag);
  }
  // Gradescope grades one submission: the header and one row.
  dttest::writeText(root + "/one.tsv", g.out.substr(0, g.out.find('\n', g.out.find('\n') + 1) + 1));
  const Run gs = exercise({"export", "gradescope", "2.1-1", root + "/one.tsv"});
  REQUIRE(gs.status == 0);
  CHECK(contains(gs.out, "\"score\": 4,\n  \"max_score\": 4,\n  \"output\": \"PASS\",\n  \"tests\": [\n"));
  CHECK(contains(gs.out, "{\"name\": \"2.1 exercise 2.1-1 the open kernel test is exact on the lines of the edges\", \"score\": 1, \"max_score\": 1, \"status\": \"passed\", \"output\": \"\", \"visibility\": \"visible\"},"));
  const Run gs3 = exercise({"export", "gradescope", "2.1-1", table});
  CHECK(gs3.status == 2);
  CHECK(contains(gs3.out + gs3.err, "one submission"));

  // A prove exercise: collected, never PASS; the answers beside the teacher's sheet.
  const Run c = exercise({"check", root + "/correct", "2.3.5-1"});
  CHECK(c.status == 0);
  CHECK(contains(c.out, "collected 2.3.5-1"));
  CHECK_FALSE(contains(c.out, "PASS"));
  const Run m = exercise({"check", "2.3.5-1", root + "/flat"});
  CHECK(m.status == 1);
  CHECK(contains(m.out, "MISSING 2.3.5-1"));
  dirs.insert(dirs.begin(), {"grade", "2.3.5-1"});
  const Run a = exercise(dirs, {{"DT_GRADE_ANSWERS", root + "/answers"}});
  INFO(a.out << a.err);
  REQUIRE(a.status == 0);
  const auto arows = tsv(a.out);
  REQUIRE(arows.size() == 4);
  CHECK(arows[1][1] == "collected");
  CHECK(arows[2][1] == "missing");
  CHECK(contains(dttest::readText(root + "/answers/correct.md"), "Each update swaps or negates."));
  CHECK(contains(dttest::readText(root + "/answers/SHEET.md"), "## Exercise 2.3.5-1"));
  CHECK(contains(dttest::readText(root + "/answers/SHEET.md"), "Tests (doctest names"));
  fs::remove_all(root);
}

TEST_CASE("exercises class grade reads operators as tokens checks the called functions and refuses to run without its sandbox") {
  const std::string root = outsideTmp("class_hilbert");
  freshDirectory(root);
  const Run rel = exercise({"release", "2.3.5-5", root + "/release"});
  REQUIRE(rel.status == 0);
  const std::string teacher = dttest::readText(std::string(DT_SOURCE_DIR) + "/code/exercises/ex_hilbert.cpp");
  const std::string solution = region(teacher, "2.3.5-5", 0);
  const std::string released = dttest::readText(root + "/release/code/exercises/ex_hilbert.cpp");
  // '?' is forbidden as an operator: inside a string it is no operator. The library's fast keys
  // are no forbidden word, but the object file calls them: refused by the symbol check.
  const std::vector<std::pair<std::string, std::string>> cls = {
      {"question_string", "  const char* why = \"why?\";\n  (void)why;\n" + solution},
      {"keys_fast", "  std::vector<std::uint64_t> hilbertKeysFast(const std::vector<double>&, int);\n"
                    "  return hilbertKeysFast(std::vector<double>{double(i), double(j)}, depth).at(0);\n"},
      {"question_mark", "  return depth < 0 ? 0 : 1;\n"},
      // A table of the library's loop written out by hand: no branch, but no exercise either.
      {"table", "  static const unsigned char next[2] = {0, 1};\n  return next[depth & 1];\n"}};
  std::vector<std::string> args = {"grade", "2.3.5-5"};
  for (const auto& s : cls) {
    const std::string d = root + "/" + s.first;
    fs::copy(root + "/release", d, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    dttest::writeText(d + "/code/exercises/ex_hilbert.cpp", withRegion(released, "2.3.5-5", 0, s.second));
    args.push_back(d);
  }
  const std::vector<std::pair<std::string, std::string>> env = {{"DT_GRADE_NO_BUILD", "1"}, {"DT_GRADE_BUILD", buildDir()}};
  const Run g = exercise(args, env);
  INFO(g.out << g.err);
  REQUIRE(g.status == 0);
  const auto rows = tsv(g.out);
  REQUIRE(rows.size() == 5);
  CHECK(rows[1][1] == "PASS");
  CHECK(rows[2][1] == "FORBIDDEN");
  CHECK(contains(rows[2][6], "calls dt::hilbertKeysFast("));
  CHECK(rows[3][1] == "FORBIDDEN");
  CHECK(contains(rows[3][6], "code/exercises/ex_hilbert.cpp:"));
  CHECK(contains(rows[3][6], ": '?'"));
  CHECK(rows[4][1] == "FORBIDDEN");
  CHECK(contains(rows[4][6], ": '['"));

  // No sandbox: no grading, and the reason; --unsandboxed grades with a warning on every row.
  auto noSandbox = env;
  noSandbox.push_back({"DT_GRADE_BWRAP", "/bin/false"});
  const Run refused = exercise({"grade", "2.3.5-5", root + "/question_string"}, noSandbox);
  CHECK(refused.status == 2);
  CHECK(contains(refused.err, "grade refuses to run student code: bubblewrap cannot make a sandbox here"));
  CHECK(refused.out.empty());
  const Run unsafe = exercise({"grade", "--unsandboxed", "2.3.5-5", root + "/question_string"}, noSandbox);
  INFO(unsafe.out << unsafe.err);
  REQUIRE(unsafe.status == 0);
  const auto urows = tsv(unsafe.out);
  REQUIRE(urows.size() == 2);
  CHECK(urows[1][1] == "PASS");
  CHECK(contains(urows[1][6], "UNSANDBOXED"));
  CHECK(contains(unsafe.err, "WITHOUT the sandbox"));
  fs::remove_all(root);
}

TEST_CASE("exercises class grade fails a hull test that drops collinear points by the judge where the doctest passes") {
  // 2.2-3 with its hull's collinear points popped: the doctest's random sets have none, so its
  // report says pass; the judge's grids have them, and grade fails the row on the judge alone.
  const std::string root = outsideTmp("class_hull");
  freshDirectory(root);
  const Run rel = exercise({"release", "2.2-3", root + "/release"});
  REQUIRE(rel.status == 0);
  const std::string teacher = dttest::readText(std::string(DT_SOURCE_DIR) + "/code/listings/bowyer_watson.cpp");
  const std::string solution = region(teacher, "2.2-3", 0);
  const std::string released = dttest::readText(root + "/release/code/listings/bowyer_watson.cpp");
  const std::vector<std::pair<std::string, std::string>> cls = {
      {"correct", solution},
      {"collinear_dropped", replaced(solution, "Y(hull.back()), X(p), Y(p)) < 0)", "Y(hull.back()), X(p), Y(p)) <= 0)")}};
  std::vector<std::string> args = {"grade", "2.2-3"};
  for (const auto& s : cls) {
    const std::string d = root + "/" + s.first;
    fs::copy(root + "/release", d, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    dttest::writeText(d + "/code/listings/bowyer_watson.cpp", withRegion(released, "2.2-3", 0, s.second));
    args.push_back(d);
  }
  const Run g = exercise(args, {{"DT_GRADE_NO_BUILD", "1"}, {"DT_GRADE_BUILD", buildDir()}});
  INFO(g.out << g.err);
  REQUIRE(g.status == 0);
  const auto rows = tsv(g.out);
  REQUIRE(rows.size() == 3);
  REQUIRE(rows[1].size() == 8);
  CHECK(rows[1][1] == "PASS");
  CHECK(rows[1][4] == "match");
  CHECK(rows[2][1] == "FAIL");
  CHECK(rows[2][3] == "fail");
  CHECK(rows[2][4] == "differ");
  CHECK(contains(rows[2][5], "the judge printed \"t1 grid "));
  fs::remove_all(root);
}
