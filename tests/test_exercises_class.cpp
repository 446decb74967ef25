/// \file test_exercises_class.cpp The teacher's path of the classroom (scripts/exercise.sh): a release holds no solution line of any exercise, a release inside the repository is refused, and a scripted class of 30 workspaces (correct ones, planted bugs, an edited test, an endless loop, a forbidden call) is graded in one command into a TSV that is right for every row; prove answers are collected beside the teacher's sheet.
#include <doctest/doctest.h>

#include <chrono>
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

// The lines of a text inside and outside its solution regions (any exercise).
void splitRegions(const std::string& text, std::set<std::string>& inside, std::set<std::string>& outside) {
  std::istringstream in(text);
  std::string line;
  int depth = 0;
  while (std::getline(in, line)) {
    if (isMarker(line, "BEGIN")) { ++depth; continue; }
    if (isMarker(line, "END")) { --depth; continue; }
    (depth > 0 ? inside : outside).insert(trim(line));
  }
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
  for (const std::string& d : {nested + "/code", nested + "/scripts", oddBuild}) fs::create_directories(d);
  dttest::writeText(nested + "/CMakeLists.txt", "project(x)\n");
  dttest::writeText(nested + "/scripts/exercise.sh", "\n");
  dttest::writeText(nested + "/code/stats.cpp",
                    dttest::readText(std::string(DT_SOURCE_DIR) + "/code/stats.cpp"));
  dttest::writeText(oddBuild + "/CMakeCache.txt", "\n");
  dttest::writeText(oddBuild + "/star.cpp", dttest::readText(std::string(DT_SOURCE_DIR) + "/code/star.cpp"));
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
  const std::string stats = dttest::readText(root + "/code/stats.cpp");
  CHECK(contains(stats, "// BEGIN " "SOLUTION 2.3.4-1\n  throw std::logic_error(\"exercise 2.3.4-1: not implemented yet\");\n  // END " "SOLUTION 2.3.4-1"));
  CHECK(contains(stats, "exercise 2.3.2-1: not implemented yet"));  // not released, stripped too

  // Every line of every solution region of the teacher's tree (code, tests, solutions page)
  // that appears nowhere outside the regions: none of them may be in any file of the release.
  std::set<std::string> inRegions, outside;
  for (const char* dir : {"code", "tests", "book", "chapters", "cli", "exercises", "scripts"})
    for (const auto& e : fs::recursive_directory_iterator(std::string(DT_SOURCE_DIR) + "/" + dir))
      if (e.is_regular_file()) splitRegions(dttest::readText(e.path().string()), inRegions, outside);
  std::set<std::string> distinctive;
  for (const std::string& l : inRegions)
    if (l.size() >= 20 && !outside.count(l)) distinctive.insert(l);
  CHECK(distinctive.size() > 200);
  CHECK(distinctive.count("if (s.forward == t.forward)"));  // 2.3.4-1
  CHECK(distinctive.count("// four values, swapped or not, negated or not (quadrant 0 swaps, quadrant 3 swaps and negates,"));
  std::size_t files = 0, leaks = 0;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    ++files;
    std::istringstream in(dttest::readText(e.path().string()));
    std::string line;
    while (std::getline(in, line))
      if (distinctive.count(trim(line)) && leaks++ < 5)
        FAIL_CHECK("solution line in " << e.path().string() << ": " << trim(line));
  }
  CHECK(files > 100);
  CHECK(leaks == 0);
  fs::remove_all(root);
}

TEST_CASE("exercises class 30 workspaces are graded in one command into a TSV right for every row") {
  const std::string root = outsideTmp("class_30");
  freshDirectory(root);
  const Run rel = exercise({"release", "2.3.4-1", root + "/release"});
  INFO(rel.out << rel.err);
  REQUIRE(rel.status == 0);

  const std::string teacher = dttest::readText(std::string(DT_SOURCE_DIR) + "/code/stats.cpp");
  const std::string solution = region(teacher, "2.3.4-1", 0);
  const std::string released = dttest::readText(root + "/release/code/stats.cpp");
  // Planted bugs (no orientation test, null links, ...), made from the teacher's own solution.
  const std::string noOrientation = replaced(solution, "if (s.forward == t.forward)", "if (false)");
  const std::string nulls = "  for (Face* f : faces) f->F[0] = f->F[1] = f->F[2] = nullptr;\n" + solution;
  // A different correct solution: directed edges sorted, the reverse found by binary search
  // (std::unordered_set is allowed: "map" is forbidden as a word only).
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
  const std::string loop = "  volatile int spin = 0;\n  while (spin == 0) {\n  }\n";
  const std::string forbidden = "  computeAdjacencies(faces);  // the library's, with its map\n";
  struct Student {
    std::string name, body, result, passed, cols, firstHas;
    bool editTest = false;
  };
  std::vector<Student> cls;
  const std::string pass3 = "pass\tpass\tpass";
  // Under AddressSanitizer (scripts/test.sh's second build) every student's file is compiled
  // instrumented: one student of each kind there, the class of 30 in the plain build.
#if defined(__SANITIZE_ADDRESS__)
  const int many = 1, few = 1, classSize = 8;
#else
  const int many = 18, few = 3, classSize = 30;
#endif
  for (int i = 0; i < many; ++i)
    cls.push_back({"correct" + std::to_string(i), solution, "PASS", "3/3", pass3, "-"});
  cls.push_back({"sorted", sorted, "PASS", "3/3", pass3, "-"});
  cls.push_back({"sorted2", "  // a comment naming std::map is not a use of it\n" + sorted, "PASS", "3/3", pass3, "-"});
  for (int i = 0; i < few; ++i)
    cls.push_back({"no_orientation" + std::to_string(i), noOrientation, "FAIL", "2/3", "pass\tfail\tpass",
                   "test '2.3.4 exercise 2.3.4-1 an edge two faces use in the same direction is rejected'"});
  for (int i = 0; i < few; ++i)
    cls.push_back({"nullptr" + std::to_string(i), nulls, "FAIL", "2/3", "pass\tpass\tfail",
                   "(on the ball's boundary) linked to nullptr, expected a face outside the list"});
  cls.push_back({"edited_test", "", "FAIL", "0/3", "fail\tfail\tfail", "exercise 2.3.4-1: not implemented yet"});
  cls.back().editTest = true;
  cls.push_back({"endless_loop", loop, "TIMEOUT", "0/3", "timeout\ttimeout\ttimeout",
                 "test '2.3.4 exercise 2.3.4-1 the links of a 3000-point triangulation are restored' did not finish within 15 s"});
  cls.push_back({"forbidden_call", forbidden, "FORBIDDEN", "0/3", "-\t-\t-", "uses 'computeAdjacencies' in"});
  cls.push_back({"untouched", "", "FAIL", "0/3", "fail\tfail\tfail", "exercise 2.3.4-1: not implemented yet"});
  REQUIRE(cls.size() == std::size_t(classSize));

  std::vector<std::string> dirs;
  for (const Student& s : cls) {
    const std::string d = root + "/" + s.name;
    fs::copy(root + "/release", d, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    if (!s.body.empty()) dttest::writeText(d + "/code/stats.cpp", withRegion(released, "2.3.4-1", 0, s.body));
    if (s.editTest) {
      // The student's tests of the same names, made to pass on the stub: grade never uses them.
      dttest::writeText(d + "/tests/test_2_3_4_exercises.cpp",
                        "#include <doctest/doctest.h>\n"
                        "TEST_CASE(\"2.3.4 exercise 2.3.4-1 the links of a 3000-point triangulation are restored\") {}\n"
                        "TEST_CASE(\"2.3.4 exercise 2.3.4-1 an edge two faces use in the same direction is rejected\") {}\n"
                        "TEST_CASE(\"2.3.4 exercise 2.3.4-1 a link across an unmatched edge is left as it was\") {}\n");
    }
    dirs.push_back(d);
  }
  const auto t0 = std::chrono::steady_clock::now();
  dirs.insert(dirs.begin(), {"grade", "2.3.4-1"});
  const Run g = exercise(dirs, {{"DT_GRADE_NO_BUILD", "1"}, {"DT_TEST_TIMEOUT", "15"},
                                {"DT_GRADE_BUILD", buildDir()}});
  dirs.erase(dirs.begin(), dirs.begin() + 2);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  MESSAGE("graded " << classSize << " workspaces of 2.3.4-1 in " << seconds << " s");
  INFO(g.out << g.err);
  REQUIRE(g.status == 0);
  const auto rows = tsv(g.out);
  REQUIRE(rows.size() == cls.size() + 1);
  CHECK(rows[0][0] == "student");
  CHECK(rows[0][3] == "2.3.4 exercise 2.3.4-1 the links of a 3000-point triangulation are restored");
  for (std::size_t i = 0; i < cls.size(); ++i) {
    const Student& s = cls[i];
    const auto& row = rows[i + 1];
    INFO("row of " << s.name);
    REQUIRE(row.size() == 8);
    CHECK(row[0] == s.name);
    CHECK(row[1] == s.result);
    CHECK(row[2] == s.passed);
    CHECK(row[3] + "\t" + row[4] + "\t" + row[5] == s.cols);
    CHECK_MESSAGE(contains(row[6], s.firstHas), row[6]);
  }
  // The nullptr rows name the face and the edge that failed.
  for (std::size_t i = 0; i < cls.size(); ++i)
    if (cls[i].name == "nullptr0") {
      CHECK(contains(rows[i + 1][6], "face "));
      CHECK(contains(rows[i + 1][6], ", edge "));
    }
  fs::remove_all(root);
}

TEST_CASE("exercises class grade catches the planted bugs of 2.1-1 and collects prove answers beside the sheet") {
  const std::string root = outsideTmp("class_21");
  freshDirectory(root);
  const Run rel = exercise({"release", "2.1-1", "2.3.5-1", root + "/release"});
  REQUIRE(rel.status == 0);
  const std::string teacher = dttest::readText(std::string(DT_SOURCE_DIR) + "/code/star.cpp");
  const std::string kernel = region(teacher, "2.1-1", 0), open = region(teacher, "2.1-1", 1);
  const std::string released = dttest::readText(root + "/release/code/star.cpp");
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
    dttest::writeText(d + "/code/star.cpp",
                      withRegion(withRegion(released, "2.1-1", 0, s.body), "2.1-1", 1, open));
    dirs.push_back(d);
  }
  dttest::writeText(root + "/correct/answers.md",
                    dttest::readText(root + "/correct/answers.md") + "Each update swaps or negates.\n");
  dirs.insert(dirs.begin(), {"grade", "2.1-1"});
  const Run g = exercise(dirs, {{"DT_GRADE_NO_BUILD", "1"}, {"DT_TEST_TIMEOUT", "20"},
                                {"DT_GRADE_BUILD", buildDir()}});
  dirs.erase(dirs.begin(), dirs.begin() + 2);
  INFO(g.out << g.err);
  REQUIRE(g.status == 0);
  const auto rows = tsv(g.out);
  REQUIRE(rows.size() == 4);
  for (std::size_t i = 0; i < cls.size(); ++i) {
    INFO(cls[i].name);
    CHECK(rows[i + 1][0] == cls[i].name);
    CHECK(rows[i + 1][1] == cls[i].result);
    REQUIRE(rows[i + 1].size() == 9);
    CHECK_MESSAGE(contains(rows[i + 1][7], cls[i].firstHas), rows[i + 1][7]);
  }
  // The last edge never clipped: the corner test fails, naming a polygon and a starting corner.
  CHECK(contains(rows[2][7], "starting at corner"));
  // The flat kernel: the other tests pass.
  CHECK(rows[3][2] == "3/4");

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
