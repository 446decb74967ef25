// The book's citations of tests, checked against the tests themselves (book/citations.cpp is
// the command line; tests/test_citations.cpp plants stale and missing citations):
//  - every @test{name} on a page names a TEST_CASE that exists;
//  - a cited test belongs to the claim's section: on a section's page, a test named by another
//    section is cited only where the line says which section the claim is from;
//  - every claim test (a test named by its section, not an exercise's) is cited by a page;
//  - every row of a table with a Test column (the claims tables, the errata) names its test, or
//    says how else it is settled ("compiles", a \ref to the argument, "timed by" a program); a
//    "not tested" label or an empty cell is refused: a claim is tested, corrected with a test,
//    or argued.
#pragma once

#include <algorithm>
#include <cctype>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "book_tool.h"

namespace booktool {

/// One @test{name} of a page.
struct Citation {
  std::string file;  // book/<page>.md
  int line = 0;
  std::string test;
  std::string lineText;  // the whole line it stands on
};

/// The @test{name} citations of a page's text, with the brace rule of substitute (a name may
/// hold balanced braces, DT_{n+1}); an unclosed one is skipped (substitute reports it).
inline std::vector<Citation> citationsOf(const std::string& text, const std::string& file) {
  std::vector<Citation> out;
  const std::vector<std::string> lines = splitLines(text);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::string& l = lines[n];
    for (std::size_t i = l.find("@test{"); i != std::string::npos; i = l.find("@test{", i + 1)) {
      const std::size_t open = i + 6;
      std::size_t depth = 0, close = std::string::npos;
      for (std::size_t k = open; k < l.size(); ++k) {
        if (l[k] == '{') ++depth;
        else if (l[k] == '}' && depth-- == 0) {
          close = k;
          break;
        }
      }
      if (close == std::string::npos) continue;
      out.push_back({file, int(n + 1), l.substr(open, close - open), l});
    }
  }
  return out;
}

/// One body row of a Markdown table whose header has a column named "Test".
struct TestRow {
  std::string file;
  int line = 0;
  std::string first;  // the first cell (the claim, or what is printed)
  std::string test;   // the Test cell
};

inline std::string lowerCase(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The rows of every table of a page whose header names a column "Test".
inline std::vector<TestRow> testRows(const std::string& text, const std::string& file) {
  std::vector<TestRow> out;
  const std::vector<std::string> lines = splitLines(text);
  int column = -1;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::string& l = lines[n];
    if (l.empty() || l[0] != '|') {
      column = -1;
      continue;
    }
    const std::vector<std::string> cells = tableCells(l);  // book_tool.h's splitter
    if (column < 0) {  // a header: is there a Test column?
      column = -2;
      for (std::size_t c = 0; c < cells.size(); ++c)
        if (lowerCase(cells[c]) == "test") column = int(c);
      continue;
    }
    if (column == -2 || l.compare(0, 4, "|---") == 0) continue;
    out.push_back({file, int(n + 1), cells.empty() ? "" : cells[0],
                   std::size_t(column) < cells.size() ? cells[std::size_t(column)] : ""});
  }
  return out;
}

/// The section of a page from its id ("sec2_3_4" -> "2.3.4"), "" for other pages.
inline std::string pageSection(const std::string& id) {
  if (id.rfind("sec", 0) != 0) return "";
  std::string s = id.substr(3);
  std::replace(s.begin(), s.end(), '_', '.');
  return s;
}

/// A claim test: named by its section ("2.3.4 ..."), and not an exercise's test.
inline bool isClaimTest(const TestCase& t) {
  return !sectionOf(t.name).empty() && t.name.find("exercise") == std::string::npos;
}

/// Sections a and b are the same claim's if one is the other or contains it (2.2 and 2.2.1).
inline bool sameSection(const std::string& a, const std::string& b) {
  auto within = [](const std::string& s, const std::string& outer) {
    return s == outer || (s.size() > outer.size() && s.compare(0, outer.size(), outer) == 0 &&
                          s[outer.size()] == '.');
  };
  return within(a, b) || within(b, a);
}

/// A line with its @test{...} citations cut out (a test's own name does not count as the
/// line saying where its claim is from).
inline std::string withoutCitations(const std::string& line) {
  std::string out = line;
  for (const Citation& c : citationsOf(line, "")) {
    const std::size_t at = out.find("@test{" + c.test + "}");
    if (at != std::string::npos) out.erase(at, c.test.size() + 7);
  }
  return out;
}

/// Whether `text` names section s as a number of its own ("2.3.3" in "2.3.3: a flip", not
/// in "2.3.35" nor in "12.3.3").
inline bool namesSection(const std::string& text, const std::string& s) {
  for (std::size_t i = text.find(s); i != std::string::npos; i = text.find(s, i + 1)) {
    const std::size_t e = i + s.size();
    const bool startOk = i == 0 || !(std::isdigit(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.');
    const bool endOk = e == text.size() || !(std::isdigit(static_cast<unsigned char>(text[e])) ||
                                             (text[e] == '.' && e + 1 < text.size() &&
                                              std::isdigit(static_cast<unsigned char>(text[e + 1]))));
    if (startOk && endOk) return true;
  }
  return false;
}

/// A test cell with no @test that says the claim is not tested.
inline bool untestedLabel(const std::string& cell) {
  static const std::regex label("not tested|untested|no timed test|program only|no test",
                                std::regex::icase);
  return std::regex_search(cell, label);
}

/// Every citation fault of the pages against the tests, as "<file>:<line>: ..." lines.
inline std::vector<std::string> checkCitations(const std::vector<Page>& pages,
                                               const std::vector<TestCase>& tests) {
  std::vector<std::string> errors;
  std::map<std::string, const TestCase*> byName;
  for (const TestCase& t : tests) byName.emplace(t.name, &t);
  std::set<std::string> cited;
  for (const Page& p : pages) {
    const std::string section = pageSection(p.id);
    for (const Citation& c : citationsOf(p.text, p.file)) {
      const std::string where = c.file + ":" + std::to_string(c.line) + ": ";
      auto it = byName.find(c.test);
      if (it == byName.end()) {
        errors.push_back(where + "cites the test \"" + c.test + "\", which no TEST_CASE in tests/ has");
        continue;
      }
      cited.insert(c.test);
      const std::string ts = sectionOf(c.test);
      // A claim of another section on this page: the line must name that section.
      if (!section.empty() && !ts.empty() && !sameSection(section, ts) &&
          !namesSection(withoutCitations(c.lineText), ts))
        errors.push_back(where + "cites \"" + c.test + "\", a test of section " + ts +
                         ", on the page of section " + section +
                         " without saying the claim is from " + ts);
    }
    for (const TestRow& r : testRows(p.text, p.file)) {
      if (r.test.find("@test{") != std::string::npos) continue;
      const std::string where = r.file + ":" + std::to_string(r.line) + ": ";
      if (r.test.empty())
        errors.push_back(where + "the row \"" + r.first.substr(0, 60) +
                         "\" names no test (cite it with @test{...}, or say how it is settled)");
      else if (untestedLabel(r.test))
        errors.push_back(where + "the row \"" + r.first.substr(0, 60) + "\" is labelled \"" + r.test +
                         "\": a claim is tested (cite the test), corrected with a test, or argued "
                         "(\\ref the argument); a time is 'timed by' its program");
    }
  }
  for (const TestCase& t : tests)
    if (isClaimTest(t) && !cited.count(t.name))
      errors.push_back(t.file + ":" + std::to_string(t.line) + ": the claim test \"" + t.name +
                       "\" is cited by no page (cite it where the book states its claim)");
  return errors;
}

}  // namespace booktool
