/// \file test_book_access.cpp Checks of the book's accessibility and print steps (book/book_access.h): the language and the search field's label on every page, figures with alt text and caption, the student's tables without exercise rows, the printed book's links, and the refusal of a number typed where a value holds it.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../book/book_access.h"

TEST_CASE("book access every page gets lang and the search field a label once") {
  const std::string page = "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\">\n<head></head>";
  const std::string once = bookaccess::withLang(page);
  CHECK(once.find("<html lang=\"en\" xmlns=") != std::string::npos);
  CHECK(bookaccess::withLang(once) == once);
  const std::string js = "'<input type=\"text\" id=\"MSearchField\" value=\"\" placeholder=\"'+search+'\" accesskey=\"S\"/>'";
  const std::string labelled = bookaccess::withSearchLabel(js);
  CHECK(labelled.find("id=\"MSearchField\" aria-label=\"Search the book\" value=") != std::string::npos);
  CHECK(bookaccess::withSearchLabel(labelled) == labelled);
}

TEST_CASE("book access a figure without its alt line stops the build and one with it becomes a figure element") {
  std::vector<std::string> errors;
  const std::string page =
      "\\page p P\n<!-- alt: the cavity: @{s.cav} triangles shaded orange -->\n"
      "\\image html a.png \"Figure 1: a\"\n\ntext\n\\image html b.png \"Figure 2: b\"\n<!-- alt: stray -->\n\ntext\n";
  const auto alts = bookaccess::figureAlts(page, "book/p.md", errors);
  CHECK(alts.at("a.png") == "the cavity: @{s.cav} triangles shaded orange");
  CHECK(alts.count("b.png") == 0);
  REQUIRE(errors.size() == 2);
  CHECK(errors[0] == "book/p.md:6: the figure b.png has no '<!-- alt: ... -->' line above it (say in words what it shows)");
  CHECK(errors[1] == "book/p.md:7: an alt text that no figure follows");

  errors.clear();
  const std::string html =
      "<div class=\"image\">\n<img src=\"a.png\" alt=\"\"/>\n<div class=\"caption\">\nFigure 1: a</div></div>\n"
      "<div class=\"image\">\n<img src=\"c.png\" alt=\"\"/>\n</div>\n";
  const std::string out = bookaccess::withFigures(html, "p.html", {{"a.png", "5 triangles \"orange\""}}, errors);
  CHECK(out.find("<figure class=\"image\" aria-labelledby=\"figcap_a_png\">\n<img src=\"a.png\" alt=\"5 triangles &quot;orange&quot;\"/>\n"
                 "<figcaption class=\"caption\" id=\"figcap_a_png\">\nFigure 1: a</figcaption></figure>") != std::string::npos);
  CHECK(out.find("<div class=\"image\">") == std::string::npos);
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] == "p.html: the figure c.png has no alt text");
}

TEST_CASE("book access the student's table leaves out the rows an exercise asks for") {
  const std::string table =
      "<table><caption>T</caption><tr><th>what</th><th>wrong</th></tr>\n<tr><td>naive O(a,b,c)</td><td>9</td></tr>\n"
      "<tr><td>canonical naive (exercise 1)</td><td>9</td></tr>\n</table>";
  const std::string s = bookaccess::studentTable(table);
  CHECK(s.find("(exercise 1)") == std::string::npos);
  CHECK(s.find("<th>what</th>") != std::string::npos);
  CHECK(s.find("naive O(a,b,c)") != std::string::npos);
  CHECK(bookaccess::studentTable(s) == s);
}

TEST_CASE("book access a number typed in prose or a formula that a value holds is refused") {
  const std::map<std::string, std::pair<std::string, std::string>> values = {
      {"s236.test_factor_lo", {"1.0001", "tests/test_2_3_6_flips.cpp:261"}},
      {"s236.test_factor_hi", {"10000.0", "tests/test_2_3_6_flips.cpp:262"}},
      {"s231.cells", {"53,980", "values_sec2_3_1_predicates.txt"}},
      {"s231.grid", {"256", "values_sec2_3_1_predicates.txt"}},
      {"s231.ratio", {"2.5", "values_sec2_3_1_predicates.txt"}},
      {"s9.small", {"3 of 7", "values_x.txt"}},
      {"s9.other", {"12.5", "values_other_program.txt"}}};
  const std::vector<std::string> programs = {"sec2_3_1_predicates"};
  // The claims row as it once was: both ends typed, in formulas.
  const std::string page =
      "\\page p P\n| recovery | exact for super-triangles \\f$1.0001\\f$ to \\f$10^4\\f$ times the box |\n"
      "The table counts 53,980 cells on a grid of 256; a triangle has 3 vertices and 7 is small; 12.5 is another page's.\n"
      "Section 2.3.4 and Listing 2.5; `1.0001` in code; @{s236.test_factor_lo} cited.\n"
      "<!-- 1.0001 in a comment -->\n";
  const auto d = bookaccess::typedValues(page, "book/p.md", values, programs);
  REQUIRE(d.size() == 3);
  CHECK(d[0].find("book/p.md:2: '1.0001' typed, a value of s236.test_factor_lo") == 0);
  CHECK(d[1].find("book/p.md:3: '53,980' typed, a value of s231.cells") == 0);
  CHECK(d[2].find("book/p.md:3: '256' typed, a value of s231.grid") == 0);
  // A round number (10^4) is a size, not a measurement; another program's value is a
  // coincidence. Other spellings of a measured number are found.
  CHECK(bookaccess::typedValues("53980 and 5.398e4 and 10^4\n", "f", values, programs).size() == 2);
  CHECK(bookaccess::typedValues("12.5\n", "f", values, programs).empty());
  // Listing 2.5 above is a name; the same number as a quantity is refused.
  CHECK(bookaccess::typedValues("a ratio of 2.5 here\n", "f", values, programs).size() == 1);
  // A name in lower case, or after the section sign, is a name too (a full run once measured
  // 2.1 where the page spoke of "the kernel of section 2.1").
  CHECK(bookaccess::typedValues("the kernel of section 2.5, figures 2.5 and \u00a7 2.5 or \u00a72.5\n", "f", values, programs).empty());
}

TEST_CASE("book access the printed book links inside itself and prints where other links go") {
  const std::string html =
      "<html><body><div class=\"header\">T</div><div class=\"contents\">"
      "<a href=\"sec2_1.html#sec2_1_claims\">claims</a> <a href=\"sec2_2.html\">2.2</a> "
      "<a href=\"test__2__3__4__algorithms_8cpp_source.html#l00199\" class=\"testlink\">t</a>"
      "<script>var x = 1;</script></div><!-- start footer part --><hr class=\"footer\"/></body></html>";
  const std::string p = bookaccess::printPage(html, {"sec2_1", "sec2_2"});
  CHECK(p.find("href=\"#sec2_1_claims\"") != std::string::npos);
  CHECK(p.find("href=\"#print_sec2_2\"") != std::string::npos);
  CHECK(p.find("data-print=\"test_2_3_4_algorithms.cpp, line 199\"") != std::string::npos);
  CHECK(p.find("<script") == std::string::npos);
  CHECK(p.find("footer") == std::string::npos);
}

TEST_CASE("book access a keyboard can skip to the text and every table of a page is named") {
  const std::string page = "<html><body>\n<div id=\"top\">menu</div><div id=\"doc-content\"><h2 class=\"groupheader\">"
                           "<a class=\"anchor\" id=\"c\"></a>Claims &amp; tests</h2>\n<table class=\"markdownTable\">\n"
                           "<tr><th>a</th></tr></table><table class=\"markdownTable\"><caption>Own</caption></table></div></body></html>";
  const std::string s = bookaccess::withSkipLink(page);
  CHECK(s.find("<body>\n<a class=\"skiplink\" href=\"#doc-content\">Skip to the text</a>") != std::string::npos);
  CHECK(bookaccess::withSkipLink(s) == s);
  const std::string t = bookaccess::withTableCaptions(page);
  CHECK(t.find("<table class=\"markdownTable\"><caption>Claims &amp; tests</caption>\n<tr>") != std::string::npos);
  CHECK(t.find("<caption>Own</caption>") != std::string::npos);
  CHECK(t.find("<caption>Claims &amp; tests</caption><caption>") == std::string::npos);
  CHECK(bookaccess::withTableCaptions(t) == t);
}

TEST_CASE("book access a listing shows no marker of a snippet nested in the quoted one") {
  const std::string html = "<div class=\"fragment\"><div class=\"line\">int a;</div>\n"
                           "<div class=\"line\"><span class=\"comment\">//! [inner]</span></div>\n"
                           "<div class=\"line\"><span class=\"comment\">// a comment</span></div>\n</div>";
  const std::string out = bookaccess::withoutNestedMarkers(html);
  CHECK(out.find("//! [inner]") == std::string::npos);
  CHECK(out.find("// a comment") != std::string::npos);
  CHECK(out.find("int a;") != std::string::npos);
}

TEST_CASE("book access a listing of the library links no name into the test suite") {
  // A suite page is known by its navigation path (the tests directory first).
  const std::string suitePage =
      "<div id=\"nav-path\" class=\"navpath\"><ul><li class=\"navelem\"><a class=\"el\" href=\"dir_1.html\">tests</a></li>"
      "<li class=\"navelem\"><a class=\"el\" href=\"test__x_8cpp.html\">test_x.cpp</a></li></ul></div>";
  const std::string libraryPage =
      "<div id=\"nav-path\" class=\"navpath\"><ul><li class=\"navelem\"><a class=\"el\" href=\"dir_2.html\">code</a></li>"
      "<li class=\"navelem\"><a class=\"el\" href=\"tests_8cpp.html\">tests.cpp</a></li></ul></div>";
  CHECK(bookaccess::isSuitePage(suitePage));
  CHECK_FALSE(bookaccess::isSuitePage(libraryPage));
  CHECK_FALSE(bookaccess::isSuitePage("<p>no navigation path</p>"));
  // Links into the suite's pages and namespaces become their text; the library's stay.
  const std::set<std::string> suite = {"test__x_8cpp.html"};
  const std::string html =
      "<div class=\"line\"><a class=\"code hl_variable\" href=\"test__x_8cpp.html#a1\">out</a>.push_back("
      "<a class=\"code hl_function\" href=\"namespacedttest_1_1detail.html#a2\">key</a>(w, k));"
      " <a class=\"code hl_struct\" href=\"namespacedt.html#a3\">Tri</a> "
      "<a class=\"code hl_function\" href=\"namespacedoctest.html#a4\">check</a>"
      " <a class=\"el\" href=\"test__x_8cpp.html\">the test</a></div>";
  const std::string out = bookaccess::withoutLinksIntoSuite(html, suite);
  INFO(out);
  CHECK(out.find("test__x_8cpp.html#a1") == std::string::npos);
  CHECK(out.find("namespacedttest_1_1detail.html") == std::string::npos);
  CHECK(out.find("namespacedoctest.html") == std::string::npos);
  CHECK(out.find(">out</a>") == std::string::npos);
  CHECK(out.find("<div class=\"line\">out.push_back(key(w, k)); ") != std::string::npos);
  CHECK(out.find("<a class=\"code hl_struct\" href=\"namespacedt.html#a3\">Tri</a>") != std::string::npos);
  // A prose link (class "el") to a test is the claim's one click: kept.
  CHECK(out.find("<a class=\"el\" href=\"test__x_8cpp.html\">the test</a>") != std::string::npos);
}
