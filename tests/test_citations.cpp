/// \file test_citations.cpp The book's citations of tests (book/citations.h): the check passes on the real pages and tests, and fails, naming file and line, on a planted stale citation, a missing one, a test of another section, and a "not tested" label.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../book/citations.h"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = DT_SOURCE_DIR;

struct Book {
  std::vector<booktool::Page> pages;
  std::vector<booktool::TestCase> tests;
};

Book realBook() {
  Book b;
  for (const auto& e : fs::directory_iterator(kRoot / "book"))
    if (e.path().extension() == ".md")
      b.pages.push_back(booktool::parsePage(booktool::readFile(e.path().string()),
                                            "book/" + e.path().filename().string()));
  for (const auto& e : fs::directory_iterator(kRoot / "tests"))
    if (e.path().extension() == ".cpp")
      for (const auto& t : booktool::testCases(booktool::readFile(e.path().string()),
                                               "tests/" + e.path().filename().string()))
        b.tests.push_back(t);
  return b;
}

bool anyContains(const std::vector<std::string>& errors, const std::string& part) {
  for (const std::string& e : errors)
    if (e.find(part) != std::string::npos) return true;
  return false;
}

const std::string kPage =
    "\\page sec2_3_4 Section 2.3.4\n"
    "\n"
    "## Claims and their tests {#sec2_3_4_claims}\n"
    "| Claim | Verdict | Test |\n"
    "|---|---|---|\n"
    "| map operations | 3 per triangle | @test{2.3.4 the map makes 3 operations per triangle} |\n";

}  // namespace

TEST_CASE("citations the book's pages cite every claim test and only tests that exist") {
  const Book b = realBook();
  REQUIRE(b.pages.size() > 10);
  REQUIRE(b.tests.size() > 100);
  const std::vector<std::string> errors = booktool::checkCitations(b.pages, b.tests);
  for (const std::string& e : errors) MESSAGE(e);
  CHECK(errors.empty());
}

TEST_CASE("citations a stale citation and a missing one fail naming file and line") {
  const std::vector<booktool::TestCase> tests = {
      {"2.3.4 the map makes 3 operations per triangle", "tests/t.cpp", 10},
      {"2.3.4 the walk visits sqrt(n) faces", "tests/t.cpp", 20},
      {"2.3.4 exercise 1: an exercise's test needs no page", "tests/t.cpp", 30}};
  Book b{{booktool::parsePage(kPage, "book/sec2_3_4.md")}, tests};
  // The walk's test is cited by no page: missing. The exercise's test is not a claim test.
  std::vector<std::string> errors = booktool::checkCitations(b.pages, b.tests);
  CHECK(errors.size() == 1);
  CHECK(anyContains(errors, "tests/t.cpp:20: the claim test \"2.3.4 the walk visits sqrt(n) faces\" is cited by no page"));
  // Cite it, and the check passes.
  b.pages[0].text += "The walk (@test{2.3.4 the walk visits sqrt(n) faces}).\n";
  CHECK(booktool::checkCitations(b.pages, b.tests).empty());
  // The test renamed, the page not: stale (the page's line named), and missing again.
  b.tests[1].name = "2.3.4 the walk visits about sqrt(n) faces";
  errors = booktool::checkCitations(b.pages, b.tests);
  CHECK(anyContains(errors, "book/sec2_3_4.md:7: cites the test \"2.3.4 the walk visits sqrt(n) faces\", which no TEST_CASE"));
  CHECK(anyContains(errors, "tests/t.cpp:20: the claim test \"2.3.4 the walk visits about sqrt(n) faces\" is cited by no page"));
}

TEST_CASE("citations a test of another section is refused unless the line names that section") {
  const std::vector<booktool::TestCase> tests = {
      {"2.3.4 the map makes 3 operations per triangle", "tests/t.cpp", 10},
      {"2.2.1 super-triangles of any factor fail on some input", "tests/t.cpp", 40}};
  Book b{{booktool::parsePage(kPage + "| the bound | holds | @test{2.2.1 super-triangles of any factor fail on some input} |\n",
                              "book/sec2_3_4.md")},
         tests};
  std::vector<std::string> errors = booktool::checkCitations(b.pages, b.tests);
  CHECK(anyContains(errors, "book/sec2_3_4.md:7: cites \"2.2.1 super-triangles of any factor fail on some input\", a test of section 2.2.1, on the page of section 2.3.4"));
  // Saying where the claim is from settles it (and "2.2.11" would not).
  b.pages[0].text = kPage + "| 2.2.11: the bound | holds | @test{2.2.1 super-triangles of any factor fail on some input} |\n";
  CHECK(!booktool::checkCitations(b.pages, b.tests).empty());
  b.pages[0].text = kPage + "| 2.2.1: the bound | holds | @test{2.2.1 super-triangles of any factor fail on some input} |\n";
  CHECK(booktool::checkCitations(b.pages, b.tests).empty());
}

TEST_CASE("citations a not-tested label and an empty test cell are refused") {
  const std::vector<booktool::TestCase> tests = {
      {"2.3.4 the map makes 3 operations per triangle", "tests/t.cpp", 10}};
  for (const char* cell : {"program only (no timed test)", "measured, not tested", ""}) {
    CAPTURE(cell);
    Book b{{booktool::parsePage(kPage + "| the time | n^{3/2} | " + cell + " |\n", "book/sec2_3_4.md")}, tests};
    const std::vector<std::string> errors = booktool::checkCitations(b.pages, b.tests);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].rfind("book/sec2_3_4.md:7: the row \"the time\"", 0) == 0);
  }
  // How a row is settled without a test: compiled, argued, or a time read from a program.
  for (const char* cell : {"compiles", "argued: \\ref sec2_1_proof", "timed by `sec2_3_5_hilbert` in this run"}) {
    CAPTURE(cell);
    Book b{{booktool::parsePage(kPage + "| the time | n^{3/2} | " + cell + " |\n", "book/sec2_3_4.md")}, tests};
    CHECK(booktool::checkCitations(b.pages, b.tests).empty());
  }
  // A table without a Test column is not a claims table.
  Book b{{booktool::parsePage(kPage + "\n| n | time |\n|---|---|\n| 10 | not tested |\n", "book/sec2_3_4.md")}, tests};
  CHECK(booktool::checkCitations(b.pages, b.tests).empty());
}
