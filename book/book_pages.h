// A piece of the book tool (book_tool.h lists them all):
// reading the pages, the values and the tests: a page's title, the "key value" lines of the
// chapter programs, the TEST_CASE lines of tests/*.cpp and their anchors.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cctype>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace booktool {

std::string readFile(const std::string& path);

// ---- values -------------------------------------------------------------------------------

/// Parses "key value" lines (value: the rest of the line) of a values file into `out`; a
/// key already present (from another file) is an error naming both files.
void readValues(const std::string& text, const std::string& file,
                std::map<std::string, std::pair<std::string, std::string>>& out);

// ---- tests --------------------------------------------------------------------------------

struct TestCase {
  std::string name;  // as doctest sees it (escapes undone)
  std::string file;  // tests/<name>.cpp
  int line = 0;
};

/// The TEST_CASE("...") lines of one test file's text; a name written as adjacent string
/// literals over several lines is joined, as the compiler does.
std::vector<TestCase> testCases(const std::string& text, const std::string& file);

/// Doxygen's name for the source listing of a file ("tests/test_x.cpp" ->
/// "test__x_8cpp_source.html"): '_' doubled, '.' as "_8"; directories are not part of it
/// because the book's Doxyfile strips the path of inputs (STRIP_FROM_PATH).
std::string sourcePage(const std::string& file);

/// Doxygen's anchor of a line in a source listing: "l" and five digits.
std::string lineAnchor(int line);

/// The section a test name starts with ("2.3.4 ..." -> "2.3.4"), or "" if none.
std::string sectionOf(const std::string& name);

/// An anchor id for a test on the claims page (letters, digits, '_').
std::string claimAnchor(const std::string& name);

std::string htmlEscape(const std::string& s);

/// HTML text for a \htmlonly block inside a Markdown table: also the characters that the
/// table splitter (|) or Markdown emphasis (*, _) would otherwise see.
std::string htmlText(const std::string& s);

/// The link a page puts where it cites a test: the test's name, pointing at its source line.
/// Raw HTML (\htmlonly), so that no character of the name is read as markup.
std::string testLink(const TestCase& t);

// ---- pages --------------------------------------------------------------------------------

struct Page {
  std::string file;   // book/<name>.md
  std::string id;     // \page id, or "index" for \mainpage
  std::string title;  // the rest of the \page line
  std::string text;
};

Page parsePage(const std::string& text, const std::string& file);

}  // namespace booktool
