/// \file test_names.cpp The naming rule of the test suite, checked over every registered test case: "<section> <claim>" or "<topic> <claim>", unique, no commas.
//
// The rule. A test file `test_<a>_<b>[_<c>...]_<words>.cpp` holds the claims of section a.b[.c]:
// each of its test names starts with that section number followed by a space, or with a
// subsection of it ("2.2.1 ..." in the 2.2 file). Any other file `test_<words>.cpp` holds tests
// of a topic: each name starts with the file's words, underscores read as spaces and runs of
// digits joined by dots, compared without case ("fast kernel ..." in test_fast_kernel.cpp,
// "exercises 2.3.1 ..." in test_exercises_2_3_1.cpp). No name contains a comma: doctest's -tc
// reads a comma as a separator, so a pasted name would find nothing. Names are unique, so that
// -tc="<name>" runs exactly one test.
#include <doctest/doctest.h>

#include <cctype>
#include <map>
#include <set>
#include <string>
#include <vector>

// doctest keeps its registry in the implementation part of the header (compiled in main.cpp);
// the declaration below is the one doctest itself uses (external linkage, namespace detail).
namespace doctest {
namespace detail {
std::set<TestCase>& getRegisteredTests();
}  // namespace detail
}  // namespace doctest

namespace {

std::string baseName(const std::string& path) {
  const std::size_t s = path.find_last_of("/\\");
  return s == std::string::npos ? path : path.substr(s + 1);
}

bool isNumber(const std::string& t) {
  if (t.empty()) return false;
  for (char c : t)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

struct FileRule {
  bool section = false;  // a section file: the prefix is a section number
  std::string prefix;    // "2.3.1" or "fast kernel"
};

// The rule a file's name declares (see the file comment). Empty prefix: not a test file name.
FileRule ruleOf(const std::string& file) {
  FileRule r;
  const std::string stem = baseName(file);
  if (stem.rfind("test_", 0) != 0 || stem.size() < 9 || stem.substr(stem.size() - 4) != ".cpp")
    return r;
  std::vector<std::string> tok;
  std::string cur;
  for (char c : stem.substr(5, stem.size() - 9)) {
    if (c == '_') {
      tok.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  tok.push_back(cur);
  std::size_t k = 0;
  while (k < tok.size() && isNumber(tok[k])) ++k;
  if (k >= 2) {  // at least "a_b": a section number
    r.section = true;
    for (std::size_t i = 0; i < k; ++i) r.prefix += (i ? "." : "") + tok[i];
    return r;
  }
  for (std::size_t i = 0; i < tok.size(); ++i) {
    if (i > 0) r.prefix += (isNumber(tok[i]) && isNumber(tok[i - 1])) ? "." : " ";
    r.prefix += tok[i];
  }
  return r;
}

// Empty if `name` follows the rule of `file`, else the reason.
std::string violation(const std::string& name, const FileRule& rule) {
  if (rule.prefix.empty()) return "the file name is not test_<section or topic>.cpp";
  if (name.find(',') != std::string::npos) return "contains a comma";
  if (rule.section) {
    // "<section> " or "<section>.<digits>... " (a subsection).
    if (name.rfind(rule.prefix, 0) != 0) return "does not start with section " + rule.prefix;
    std::size_t i = rule.prefix.size();
    while (i + 1 < name.size() && name[i] == '.' && std::isdigit(static_cast<unsigned char>(name[i + 1]))) {
      ++i;
      while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i;
    }
    if (i >= name.size() || name[i] != ' ') return "section " + rule.prefix + " is not followed by a space";
  } else {
    const std::string p = rule.prefix + " ";
    if (lower(name).rfind(lower(p), 0) != 0) return "does not start with the topic '" + rule.prefix + " '";
  }
  if (name.size() <= rule.prefix.size() + 1) return "has no claim after its prefix";
  return "";
}

}  // namespace

TEST_CASE("names the rule accepts and rejects what it says") {
  const FileRule s = ruleOf("/x/tests/test_2_3_1_predicates.cpp");
  CHECK(s.section);
  CHECK(s.prefix == "2.3.1");
  CHECK(violation("2.3.1 robust orient2d is exact", s) == "");
  CHECK(violation("2.3.1.2 a subsection", s) == "");
  CHECK(violation("2.3.1: a colon", s) != "");
  CHECK(violation("2.3.10 another section", s) != "");
  CHECK(violation("2.3 the parent section", s) != "");
  CHECK(violation("2.3.1 one, two", s) != "");
  CHECK(violation("2.3.1 ", s) != "");
  const FileRule t = ruleOf("test_fast_kernel.cpp");
  CHECK_FALSE(t.section);
  CHECK(t.prefix == "fast kernel");
  CHECK(violation("Fast kernel merges duplicates", t) == "");
  CHECK(violation("fast kernel: merges duplicates", t) != "");
  CHECK(violation("fast kernels merge", t) != "");
  CHECK(ruleOf("test_exercises_2_3_1.cpp").prefix == "exercises 2.3.1");
  CHECK(ruleOf("test_2_2_bowyer_watson.cpp").prefix == "2.2");
  CHECK(ruleOf("support.h").prefix.empty());
}

TEST_CASE("names every test case is <section or topic> <claim> without commas and unique") {
  const std::set<doctest::detail::TestCase>& all = doctest::detail::getRegisteredTests();
  std::map<std::string, std::string> seen;  // name -> file
  std::size_t files = 0;
  std::set<std::string> fileNames;
  for (const doctest::detail::TestCase& tc : all) {
    const std::string file = baseName(tc.m_file.c_str());
    const std::string name = tc.m_name;
    fileNames.insert(file);
    CAPTURE(file);
    CAPTURE(name);
    CHECK(violation(name, ruleOf(file)) == "");
    const auto [it, fresh] = seen.emplace(name, file);
    CHECK_MESSAGE(fresh, "also in " << it->second);
  }
  files = fileNames.size();
  MESSAGE(all.size() << " test cases in " << files << " files checked");
  // The registry is the whole suite, not just this file's tests.
  CHECK(files > 10);
  CHECK(all.size() > 100);
}
