/// \file test_book.cpp Checks of the book: its pages (book/*.md) resolve every image, table, snippet, reference and cited test, and the book build's own tools (book/book_tool.h) catch raw markup, too-wide tables, broken links and unknown values on deliberately broken pages.
//
// The checks read the sources only, so the suite does not need the book (or the chapter
// programs' outputs) to be built. An embedded figure or table must be either in the
// repository or named by a chapter program or gnuplot script, which will write it.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../book/book_tool.h"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = DT_SOURCE_DIR;

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> filesIn(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ext) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The library's folders by repository path: code/ and its rooms (code/<room>/).
std::vector<std::string> codeDirs() {
  std::vector<std::string> out{"code"};
  for (const auto& e : fs::directory_iterator(kRoot / "code"))
    if (e.is_directory()) out.push_back("code/" + e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

struct Line {
  std::string file;  // book/<name>.md
  int number;        // 1-based
  std::string text;  // with code spans and fenced code blocks blanked out
  std::string where() const { return file + ":" + std::to_string(number); }
};

// The lines of a page as Doxygen sees its commands: fenced code blocks (``` or ~~~) and inline
// code spans are blanked, since commands there are shown verbatim and are not processed.
std::vector<Line> pageLines(const fs::path& p) {
  std::vector<Line> out;
  std::istringstream in(readAll(p));
  std::string s;
  bool fenced = false;
  int n = 0;
  while (std::getline(in, s)) {
    ++n;
    const auto first = s.find_first_not_of(" \t");
    const bool fence = first != std::string::npos &&
                       (s.compare(first, 3, "```") == 0 || s.compare(first, 3, "~~~") == 0);
    if (fence) {
      fenced = !fenced;
      out.push_back({"book/" + p.filename().string(), n, ""});
      continue;
    }
    if (fenced) {
      out.push_back({"book/" + p.filename().string(), n, ""});
      continue;
    }
    std::string t;
    bool code = false;
    for (char c : s) {
      if (c == '`') {
        code = !code;
        t += ' ';
      } else {
        t += code ? ' ' : c;
      }
    }
    out.push_back({"book/" + p.filename().string(), n, t});
  }
  return out;
}

std::vector<fs::path> pages() { return filesIn(kRoot / "book", ".md"); }

// All matches of a regex over every page: the line, and the match's groups as strings.
std::vector<std::pair<Line, std::vector<std::string>>> findAll(const std::regex& re) {
  std::vector<std::pair<Line, std::vector<std::string>>> out;
  for (const fs::path& p : pages())
    for (const Line& l : pageLines(p))
      for (auto it = std::sregex_iterator(l.text.begin(), l.text.end(), re);
           it != std::sregex_iterator(); ++it) {
        std::vector<std::string> groups;
        for (std::size_t g = 0; g < it->size(); ++g) groups.push_back((*it)[g].str());
        out.push_back({l, groups});
      }
  return out;
}

// True if a chapter program or gnuplot script names this output (its stem, e.g. "fig2_7").
bool producedByAProgram(const std::string& name) {
  const std::string stem = fs::path(name).stem().string();
  std::vector<fs::path> producers = filesIn(kRoot / "chapters" / "ch2", ".cpp");
  for (const fs::path& g : filesIn(kRoot / "figures" / "ch2", ".gp")) producers.push_back(g);
  for (const fs::path& p : producers)
    if (readAll(p).find(stem) != std::string::npos) return true;
  return false;
}

// Every TEST_CASE of tests/*.cpp, as the book build reads them.
std::vector<booktool::TestCase> allTests() {
  std::vector<booktool::TestCase> out;
  for (const fs::path& p : filesIn(kRoot / "tests", ".cpp"))
    for (const auto& t : booktool::testCases(readAll(p), "tests/" + p.filename().string()))
      out.push_back(t);
  return out;
}

// Page ids and anchors defined by the pages: \page, \section, \subsection, \anchor, {#id};
// also those of the claims index that the book build generates from the tests.
std::set<std::string> bookLabels() {
  std::set<std::string> ids = {"claims"};
  const std::string claims = booktool::claimsPage(allTests(), "claims", "Claims");
  const std::regex section(R"(\{#([A-Za-z0-9_]+)\})");
  for (auto it = std::sregex_iterator(claims.begin(), claims.end(), section);
       it != std::sregex_iterator(); ++it)
    ids.insert((*it)[1]);
  const std::regex def(R"(\\(?:page|section|subsection|subsubsection|anchor)\s+([A-Za-z0-9_]+))");
  const std::regex brace(R"(\{#([A-Za-z0-9_]+)\})");
  for (const fs::path& p : pages()) {
    const std::string s = readAll(p);
    for (auto it = std::sregex_iterator(s.begin(), s.end(), def); it != std::sregex_iterator(); ++it)
      ids.insert((*it)[1]);
    for (auto it = std::sregex_iterator(s.begin(), s.end(), brace); it != std::sregex_iterator(); ++it)
      ids.insert((*it)[1]);
  }
  return ids;
}

// Text of every header and source of code/ (for symbol references such as dt::lineSearch).
const std::string& codeText() {
  static const std::string text = [] {
    std::string t;
    for (const std::string& dir : codeDirs())
      for (const char* ext : {".h", ".cpp"})
        for (const fs::path& p : filesIn(kRoot / dir, ext)) t += readAll(p);
    return t;
  }();
  return text;
}

}  // namespace

TEST_CASE("book the pages exist and each starts with \\page or \\mainpage and page ids are unique") {
  const auto ps = pages();
  REQUIRE(ps.size() >= 3);  // at least index, errata, references
  std::map<std::string, std::string> seen;
  int mainpages = 0;
  const std::regex head(R"(^\s*\\(page|mainpage)\s*([A-Za-z0-9_]*))");
  for (const fs::path& p : ps) {
    std::istringstream in(readAll(p));
    std::string first;
    while (std::getline(in, first) && first.find_first_not_of(" \t\r") == std::string::npos) {
    }
    std::smatch m;
    const bool ok = std::regex_search(first, m, head);
    CHECK_MESSAGE(ok, "book/" << p.filename().string() << ": first line must be \\page <id> <title>");
    if (!ok) continue;
    if (m[1] == "mainpage") {
      ++mainpages;
      continue;
    }
    const std::string id = m[2];
    CHECK_MESSAGE(!id.empty(), "book/" << p.filename().string() << ": \\page without an id");
    CHECK_MESSAGE(seen.count(id) == 0, "page id '" << id << "' used by book/" << seen[id]
                                                    << " and book/" << p.filename().string());
    seen[id] = p.filename().string();
  }
  CHECK(mainpages == 1);
  CHECK(seen.count("errata") == 1);
  CHECK(seen.count("references") == 1);
}

TEST_CASE("book every \\image is in the repository or written by a chapter program") {
  for (const auto& [line, m] : findAll(std::regex(R"(\\image\s+(\w+)\s+"?([^\s"]+))"))) {
    const std::string name = m[2];
    CHECK_MESSAGE(m[1] == "html", line.where() << ": only \\image html is built (got " << m[1] << ")");
    const bool found = fs::exists(kRoot / name) || producedByAProgram(name);
    CHECK_MESSAGE(found, line.where() << ": image " << name
                                      << " is in no chapter program or gnuplot script");
  }
}

TEST_CASE("book every \\htmlinclude and \\include is in the repository or written by a chapter program") {
  for (const auto& [line, m] : findAll(std::regex(R"(\\(?:htmlinclude|include|verbinclude)\s+(?:\[[^\]]*\]\s*)?"?([^\s"]+))"))) {
    const std::string name = m[1];
    const bool found = fs::exists(kRoot / name) || producedByAProgram(name);
    CHECK_MESSAGE(found, line.where() << ": " << name
                                      << " is neither in the repository nor named by a chapter program");
  }
}

TEST_CASE("book every \\snippet names an existing file and a marker that opens and closes in it") {
  for (const auto& [line, m] : findAll(std::regex(R"(\\snippet(?:\{[^}]*\})?\s+(\S+)\s+(\S+))"))) {

    const std::string file = m[1], marker = m[2];
    const fs::path p = kRoot / file;
    const bool exists = fs::is_regular_file(p);
    CHECK_MESSAGE(exists, line.where() << ": snippet file " << file << " does not exist");
    if (!exists) continue;
    // Doxygen cuts between the first two lines that contain "[marker]".
    std::istringstream in(readAll(p));
    std::string s;
    int hits = 0;
    while (std::getline(in, s))
      if (s.find("[" + marker + "]") != std::string::npos) ++hits;
    CHECK_MESSAGE(hits >= 2, line.where() << ": marker [" << marker << "] appears " << hits
                                          << " time(s) in " << file << " (needs an opening and a closing line)");
    CHECK_MESSAGE(hits % 2 == 0, line.where() << ": marker [" << marker << "] appears an odd number of times in " << file);
  }
}

TEST_CASE("book every \\ref resolves to a page or an anchor or a file or a symbol of code/") {
  const std::set<std::string> labels = bookLabels();

  for (const auto& [line, m] : findAll(std::regex(R"(\\ref\s+([A-Za-z0-9_:.#~]+[A-Za-z0-9_]))"))) {

    const std::string target = m[1];
    bool ok = labels.count(target) > 0;
    if (!ok && target.find('.') != std::string::npos) {  // a file: tests/x.cpp or code/x.h
      ok = fs::exists(kRoot / "tests" / target);
      for (const std::string& dir : codeDirs()) ok = ok || fs::exists(kRoot / dir / target);
      // A test file's page exists only if the file documents itself with \file.
      if (ok && fs::exists(kRoot / "tests" / target))
        CHECK_MESSAGE(readAll(kRoot / "tests" / target).find("\\file") != std::string::npos,
                      line.where() << ": tests/" << target << " has no \\file comment, so no page");
    }
    if (!ok) {  // a symbol, possibly qualified: dt::lineSearch, Face::inCircle
      std::string last = target.substr(target.rfind(':') == std::string::npos ? 0 : target.rfind(':') + 1);
      ok = std::regex_search(codeText(), std::regex("\\b" + last + "\\b"));
    }
    CHECK_MESSAGE(ok, line.where() << ": \\ref " << target
                                   << " is no page id, anchor, file of tests/ or code/, nor symbol of code/");
  }
}

TEST_CASE("book every formula is closed and none is where Doxygen would print it raw") {
  // Doxygen reads a paragraph as a whole (a blank line ends it; a table row is its own unit):
  // an inline formula may span lines, and so may a "quoted" string, inside which commands are
  // NOT processed, so a \f$ there is printed as source text (checked on a Doxygen 1.9 build).
  const std::regex refText(R"(\\ref\s+\S+\s+"[^"]*")");
  const std::regex bareDollar(R"((^|[^\\f])\$[^$\s][^$]*\$)");
  for (const fs::path& p : pages()) {
    bool inDisplay = false;  // inside \f[ ... \f] or \f{ ... \f}
    int displayStart = 0;
    std::string displayKind;
    bool inInline = false, inQuote = false;
    int inlineStart = 0, quoteStart = 0;
    auto endParagraph = [&](const std::string& where) {
      CHECK_MESSAGE(!inInline, where << ": inline formula opened at line " << inlineStart
                                     << " is not closed in its paragraph");
      inInline = false;
      inQuote = false;
    };
    for (const Line& l : pageLines(p)) {
      const bool blank = l.text.find_first_not_of(" \t\r") == std::string::npos;
      const bool tableRow = !blank && l.text[l.text.find_first_not_of(" \t")] == '|';
      if ((blank || tableRow) && !inDisplay) endParagraph(l.where());
      if (blank) continue;
      const std::string t = std::regex_replace(l.text, refText, " ");
      for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] == '"' && !inInline && !inDisplay) {
          inQuote = !inQuote;
          quoteStart = l.number;
          continue;
        }
        if (t.compare(i, 2, "\\f") != 0 || i + 2 >= t.size()) continue;
        const char k = t[i + 2];
        if (k != '$' && k != '[' && k != ']' && k != '{' && k != '}') continue;
        const bool opening = (k == '$' && !inInline) || k == '[' || k == '{';
        CHECK_MESSAGE(!(opening && inQuote), l.where() << ": a formula inside \"...\" (quote opened at line "
                                                       << quoteStart << ") is printed raw by Doxygen");
        if (k == '$') {
          CHECK_MESSAGE(!inDisplay, l.where() << ": \\f$ inside a display formula");
          if (!inInline) inlineStart = l.number;
          inInline = !inInline;
        } else if (k == '[' || k == '{') {
          CHECK_MESSAGE(!inDisplay, l.where() << ": display formula opened twice (first at line "
                                              << displayStart << ")");
          inDisplay = true;
          displayStart = l.number;
          displayKind = std::string("\\f") + k;
        } else {
          CHECK_MESSAGE(inDisplay, l.where() << ": \\f" << k << " closes no formula");
          if (inDisplay)
            CHECK_MESSAGE((displayKind == "\\f[") == (k == ']'),
                          l.where() << ": " << displayKind << " closed by \\f" << k);
          inDisplay = false;
        }
        i += 2;
      }
      // LaTeX delimiters that Doxygen does not know.
      if (!inDisplay && !inInline) {
        const std::string noFormulas = std::regex_replace(t, std::regex(R"(\\f\$.*?\\f\$)"), " ");
        CHECK_MESSAGE(!std::regex_search(noFormulas, bareDollar),
                      l.where() << ": $...$ is not a formula in Doxygen; use \\f$...\\f$");
        CHECK_MESSAGE(noFormulas.find("\\(") == std::string::npos,
                      l.where() << ": \\( is not a formula in Doxygen; use \\f$...\\f$");
      }
      if (tableRow && !inDisplay) endParagraph(l.where());
    }
    endParagraph("book/" + p.filename().string() + ":end");
    CHECK_MESSAGE(!inDisplay, "book/" << p.filename().string() << ":" << displayStart
                                      << ": display formula never closed");
  }
}

TEST_CASE("book every test file documents itself with \\file so that \\ref test_x.cpp has a page") {
  // "\file" takes the file's name as its argument: "/// \file Claims of ..." would document a
  // file named "Claims", which Doxygen reports as an error and the book build stops.
  const std::regex fileCmd(R"(^\s*///?\s*[\\@]file(?:\s+(\S+))?)");
  for (const fs::path& p : filesIn(kRoot / "tests", ".cpp")) {
    if (p.filename() == "main.cpp") continue;
    std::istringstream in(readAll(p));
    std::string first;
    std::getline(in, first);
    std::smatch m;
    const bool has = std::regex_search(first, m, fileCmd);
    CHECK_MESSAGE(has, "tests/" << p.filename().string() << ":1: first line must be /// \\file");
    if (has && m[1].matched)
      CHECK_MESSAGE(m[1].str() == p.filename().string(),
                    "tests/" << p.filename().string() << ":1: \\file " << m[1].str()
                             << " names another file; write \"/// \\file " << p.filename().string()
                             << " <sentence>\" or \"/// \\file\" alone");
  }
}

// ---- the book build's own tools (book/book_tool.h), on deliberately broken input -----------

namespace {

// A page as Doxygen 1.9 writes it: header, contents, footer; `body` goes into the contents.
std::string doxygenPage(const std::string& body) {
  return "<html><head><script>var x = a*b;</script></head><body><div id=\"top\">menu * here</div>"
         "<div class=\"header\"><div class=\"headertitle\"><div class=\"title\">A page</div></div></div>"
         "<div class=\"contents\"><div class=\"textblock\"><div class=\"booknav\">Next</div>" + body +
         "</div></div><!-- start footer part --><div class=\"footer\">* footer</div></body></html>";
}

std::vector<std::string> defectsOf(const std::string& body) {
  std::vector<std::string> out;
  for (const auto& d : booktool::renderedDefects(doxygenPage(body))) out.push_back(d.what + " | " + d.context);
  return out;
}

}  // namespace

TEST_CASE("book the rendered check finds every kind of raw markup a reader saw") {
  // Each body reproduces one defect a reader once saw, as Doxygen rendered it (the formula survives
  // as MathJax source, the markup around it as typed).
  const std::vector<std::pair<std::string, std::string>> broken = {
      {"bold around a formula (2.1 corollary)",
       "<p>**Corollary: \\(|\\partial\\mathscr C| = |\\mathscr C| + 2\\).** \\(U\\) is simple.</p>"},
      {"emphasis around a quote (2.1 critique)", "<li>*\\(p_3\\), which is the triangle*.</li>"},
      {"escaped bars in a table (2.3.4)", "<table class=\"markdownTable\"><tr><td>a cavity of size \\|C\\| gives</td></tr></table>"},
      {"subscript in a caption (Fig. 2.1)", "<div class=\"caption\">the cavity C(DT_n, p_{n+1})</div>"},
      {"unrendered formula", "<p>the point \\f$p\\f$ here</p>"},
      {"unprocessed snippet", "<p>\\snippet code/listings/mesh.cpp inCircle</p>"},
      {"unsubstituted value", "<p>N_search is @{s234.nsearch_ours}.</p>"},
      {"entity escaped twice (first claims index)", "<td>eq. (2.1): DT&amp;#95;n</td>"}};
  for (const auto& [what, body] : broken) {
    INFO(what);
    CHECK_FALSE(defectsOf(body).empty());
  }
  // The same content written correctly is clean: formulas, code and listings may contain any
  // of these characters, and the page's scripts and footer are not text.
  const std::string clean =
      "<p>Corollary: \\(|\\partial\\mathscr C| = |\\mathscr C| + 2\\) and \\[ x_{i+1} = a*b \\]</p>"
      "<p>Call <code>f(*p, a_{1})</code>.</p><div class=\"fragment\"><div class=\"line\">x = *p; "
      "// \\f$ a_{2} \\f$</div></div><pre>**bold** in a listing</pre>"
      "<div class=\"caption\">the cavity C(DT<sub>n</sub>, p<sub>n+1</sub>)</div>"
      "<table><tr><td>sizeof(Vertex*) = sizeof(Face*)</td></tr></table>";
  CHECK(defectsOf(clean).empty());
  const std::vector<std::string> one = defectsOf("<p>**Corollary: \\(k = m + 2\\).**</p>");
  REQUIRE(one.size() == 2);  // the opening and the closing **
  CHECK(one[0].find("**") != std::string::npos);
}

TEST_CASE("book an unknown value key or test name stops the page build naming page and line") {
  const std::map<std::string, std::pair<std::string, std::string>> values = {
      {"s234.n", {"1000", "values_x.txt"}}};
  const std::map<std::string, booktool::TestCase> tests = {
      {"2.1 a claim", {"2.1 a claim", "tests/test_2_1_kernel.cpp", 17}},
      {"2.1.3 DT_{n+1} is Delaunay", {"2.1.3 DT_{n+1} is Delaunay", "tests/test_2_1_kernel.cpp", 40}}};
  std::vector<std::string> errors;
  const std::string ok = booktool::substitute("n = @{s234.n}; see @test{2.1 a claim}.", "book/x.md",
                                              values, tests, errors);
  CHECK(errors.empty());
  CHECK(ok.find("n = 1000;") != std::string::npos);
  CHECK(ok.find("test__2__1__kernel_8cpp_source.html#l00017") != std::string::npos);
  CHECK(booktool::substitute("@test{2.1.3 DT_{n+1} is Delaunay}", "book/x.md", values, tests, errors)
            .find("#l00040") != std::string::npos);
  booktool::substitute("line one\nn = @{s234.m}\n@test{stale marks}\n@{unclosed\n", "book/x.md",
                       values, tests, errors);
  REQUIRE(errors.size() == 3);
  CHECK(errors[0] == "book/x.md:2: unknown value key 's234.m' (no chapter program wrote it)");
  CHECK(errors[1].find("book/x.md:3:") == 0);
  CHECK(errors[1].find("stale marks") != std::string::npos);
  CHECK(errors[2].find("book/x.md:4:") == 0);
  // A key written twice (by two programs) is refused too.
  std::map<std::string, std::pair<std::string, std::string>> v2;
  booktool::readValues("a 1\nb two words\n", "values_p.txt", v2);
  CHECK(v2.at("b").first == "two words");
  CHECK_THROWS(booktool::readValues("a 2\n", "values_q.txt", v2));
}

TEST_CASE("book the claims index lists every test with its source line and command") {
  const auto tests = booktool::testCases(
      "/// \\file t.cpp\nTEST_CASE(\"2.3.4 one claim\") {\n}\n  // TEST_CASE(\"not a test\")\n"
      "TEST_CASE(\"book \\\\page lines\") {}\n",
      "tests/test_2_3_4_algorithms.cpp");
  REQUIRE(tests.size() == 2);
  CHECK(tests[0].line == 2);
  CHECK(tests[1].name == "book \\page lines");
  const std::string page = booktool::claimsPage(tests, "claims", "Claims");
  CHECK(page.find("test__2__3__4__algorithms_8cpp_source.html#l00002") != std::string::npos);
  CHECK(page.find("-tc=&quot;2.3.4 one claim&quot;") != std::string::npos);
  CHECK(page.find("# Section 2.3.4") != std::string::npos);
}

TEST_CASE("book the link check finds a missing page and a missing anchor") {
  const std::string html = doxygenPage(
      "<a href=\"a.html#l00010\">ok</a><a href=\"a.html#l00099\">x</a><a href=\"gone.html\">y</a>"
      "<a href=\"https://example.org/#z\">z</a>");
  auto exists = [](const std::string& f) { return f == "a.html"; };
  auto anchors = [](const std::string&) { return std::set<std::string>{"l00010"}; };
  const auto d = booktool::brokenLinks(html, exists, anchors);
  REQUIRE(d.size() == 2);
  CHECK(d[0].context == "a.html#l00099");
  CHECK(d[1].context == "gone.html");
}

TEST_CASE("book every test a page cites by @test{name} exists") {
  std::set<std::string> names;
  for (const auto& t : allTests()) names.insert(t.name);
  std::map<std::string, std::pair<std::string, std::string>> noValues;
  std::map<std::string, booktool::TestCase> byName;
  for (const auto& t : allTests()) byName[t.name] = t;
  int cited = 0;
  for (const fs::path& p : pages()) {
    std::vector<std::string> errors;
    const std::string text = readAll(p);
    booktool::substitute(text, "book/" + p.filename().string(), noValues, byName, errors);
    for (const std::string& e : errors)
      if (e.find("unknown value key") == std::string::npos) CHECK_MESSAGE(false, e);
    for (std::size_t at = text.find("@test{"); at != std::string::npos; at = text.find("@test{", at + 1))
      ++cited;
  }
  CHECK(cited > 50);  // the claims tables and the errata cite tests
}

TEST_CASE("book every value a page cites by @{key} is written by a chapter program or named by a test") {
  // The book build stops on a key that no values file holds; this catches a misspelt key
  // without running the programs. A key is found if a chapter program names it, or names the
  // prefix it is built from (e.g. "s236.sizes_naive_fails_" + family).
  std::string sources;
  for (const fs::path& p : filesIn(kRoot / "chapters" / "ch2", ".cpp")) sources += readAll(p);
  // A bound a test compares with, named by "// book: key" on its line (booktool::testBounds).
  std::string bounds;
  for (const fs::path& p : filesIn(kRoot / "tests", ".cpp")) bounds += readAll(p) + "\n";
  const std::regex key(R"(@\{([A-Za-z0-9_.]+)\})");
  int keys = 0;
  for (const fs::path& p : pages()) {
    const std::string text = readAll(p);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), key); it != std::sregex_iterator(); ++it) {
      const std::string k = (*it)[1];
      ++keys;
      bool found = sources.find("\"" + k + "\"") != std::string::npos || bounds.find("// book: " + k + "\n") != std::string::npos;
      for (std::size_t cut = k.find_last_of("_."); !found && cut != std::string::npos;
           cut = cut == 0 ? std::string::npos : k.find_last_of("_.", cut - 1))
        found = sources.find("\"" + k.substr(0, cut + 1) + "\"") != std::string::npos;
      CHECK_MESSAGE(found, "book/" << p.filename().string() << ": @{" << k
                                   << "} is named by no chapter program");
    }
  }
  CHECK(keys > 30);
}

// ---- the two editions, the prose check, the reproduce box -----------------------------------

namespace {

// Every source file of code/ and tests/ and every page of book/, by repository path.
void readSources(std::map<std::string, std::string>& code, std::map<std::string, std::string>& pages) {
  std::vector<std::string> dirs = codeDirs();
  dirs.push_back("tests");
  for (const std::string& dir : dirs)
    for (const char* ext : {".h", ".cpp"})
      for (const fs::path& p : filesIn(kRoot / dir, ext)) code[dir + "/" + p.filename().string()] = readAll(p);
  for (const fs::path& p : filesIn(kRoot / "book", ".md")) pages["book/" + p.filename().string()] = readAll(p);
}

std::vector<std::string> exerciseIds() {
  std::vector<std::string> ids;
  std::istringstream in(readAll(kRoot / "exercises" / "exercises.txt"));
  std::string l;
  while (std::getline(in, l))
    if (l.rfind("id:", 0) == 0) ids.push_back(booktool::squeeze(l.substr(3)));
  return ids;
}

// The edition check on the sources as each edition shows them (the pages without the tables
// the programs write; the book build runs the same check on the rendered HTML as well).
std::vector<std::string> editionDefects(const std::map<std::string, std::string>& code,
                                        const std::map<std::string, std::string>& pages) {
  std::string student, teacher;
  for (const auto& [f, t] : code) {
    student += booktool::squeeze(booktool::editionCode(t, f, booktool::Edition::Student)) + "\n";
    teacher += booktool::squeeze(booktool::editionCode(t, f, booktool::Edition::Teacher)) + "\n";
  }
  // Each line squeezed on its own too: a prose line of a block is found as written.
  for (const auto& [f, t] : pages) {
    if (f == "book/solutions.md") {  // the teacher's edition only (book/order.txt)
      teacher += booktool::squeeze(booktool::editionPage(t, f, booktool::Edition::Teacher)) + "\n";
      continue;
    }
    for (const std::string& l : booktool::splitLines(booktool::editionPage(t, f, booktool::Edition::Student)))
      student += booktool::squeeze(l) + "\n";
    for (const std::string& l : booktool::splitLines(booktool::editionPage(t, f, booktool::Edition::Teacher)))
      teacher += booktool::squeeze(l) + "\n";
  }
  // The claims index lists every test name, in both editions.
  std::vector<booktool::TestCase> tests;
  for (const auto& [f, t] : code)
    if (f.rfind("tests/", 0) == 0)
      for (const auto& c : booktool::testCases(t, f)) tests.push_back(c);
  const std::string claims = booktool::squeeze(booktool::claimsPage(tests, "claims", "Claims")) + "\n";
  student += claims;
  teacher += claims;
  const auto keys = booktool::answerKeys(code, pages);
  std::vector<std::string> out = booktool::editionLeaks(keys, exerciseIds(), student, teacher);
  for (const std::string& l : booktool::snippetLeaks(keys, code)) out.push_back(l);
  return out;
}

// `text` with the marker lines of `id`'s blocks removed: the answer left unmarked.
std::string unmark(const std::string& text, const std::string& id, bool md) {
  std::string out;
  for (const std::string& l : booktool::splitLines(text)) {
    std::string got;
    bool rm = false;
    if ((booktool::solutionMarker(l, "BEGIN", md, got, rm) || booktool::solutionMarker(l, "END", md, got, rm)) && got == id)
      continue;
    out += l + "\n";
  }
  return out;
}

bool mentions(const std::vector<std::string>& v, const std::string& what) {
  for (const std::string& s : v)
    if (s.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("book the student edition shows no line or value of any answer and the teacher edition shows all") {
  std::map<std::string, std::string> code, pages;
  readSources(code, pages);
  REQUIRE(pages.count("book/sec2_2.md"));
  REQUIRE(code.count("code/listings/star.cpp"));
  // (A subcase of its own: doctest runs the lines outside the subcases once per subcase.)
  SUBCASE("the sources as they are") {
    const std::vector<std::string> ok = editionDefects(code, pages);
    for (const std::string& d : ok) CHECK_MESSAGE(false, d);
    // Every exercise has an answer key the check can look for.
    const auto keys = booktool::answerKeys(code, pages);
    for (const std::string& id : exerciseIds()) CHECK_MESSAGE(keys.count(id), id << " has no marked answer");
  }

  SUBCASE("a page block left unmarked is found") {
    auto bad = pages;
    bad["book/sec2_2.md"] = unmark(bad["book/sec2_2.md"], "2.2-2", true);
    CHECK(mentions(editionDefects(code, bad), "2.2-2: the student edition shows"));
  }
  SUBCASE("a test name that states an answer value is found in the claims index") {
    auto bad = code;
    // The value split in two literals: this file's own source page must not show it. A
    // formula spaced otherwise than the answer's is found too.
    auto spaced = pages;
    spaced["book/sec2_3_4.md"] += "\nThe mean is 4+(6 - D)" " / n here.\n";
    CHECK(mentions(editionDefects(code, spaced), "2.3.4-2: the student edition shows the answer's value"));
    bad["tests/test_planted.cpp"] = "TEST_CASE(\"2.3.3 exercise 1: a half-edge structure needs 3" "6n pointers\") {}\n";
    CHECK(mentions(editionDefects(bad, pages), "2.3.3-1: the student edition shows the answer's value '3" "6n'"));
  }
  SUBCASE("a table that answers an exercise is found where the student edition shows it") {
    auto bad = pages;
    bad["book/sec2_3_5.md"] += "\nThe table: unit circle" " (random angles) 1e3 Hilbert 3.1\n";
    CHECK(mentions(editionDefects(code, bad), "2.3.5-3: the student edition shows the answer's value 'unit circle" " (random angles)'"));
  }
  SUBCASE("a code region left unmarked is found") {
    auto bad = code;
    bad["code/listings/star.cpp"] = unmark(bad["code/listings/star.cpp"], "2.1-1", false);
    CHECK(mentions(editionDefects(bad, pages), "2.1-1: the student edition shows the answer's snippet"));
  }
  SUBCASE("an exercise whose every block is unmarked is found") {
    // Its blocks in the pages, and its region in the tests (a measure exercise's test states
    // the answer, so the release strips it too: "(remove)").
    auto badPages = pages;
    auto badCode = code;
    for (auto& [f, t] : badPages) t = unmark(t, "2.3.5-2", true);
    for (auto& [f, t] : badCode) t = unmark(t, "2.3.5-2", false);
    CHECK(mentions(editionDefects(badCode, badPages), "2.3.5-2: no marked answer"));
  }
}

TEST_CASE("book the editions drop or frame each solution block and never show a marker") {
  const std::string page =
      "\\page p P\n\nbefore\n<!-- BEGIN SOLUTION 9.9-1 -->\n<!-- values: 42q -->\nthe answer is 42q\n"
      "<!-- END SOLUTION 9.9-1 -->\nafter\n";
  const std::string s = booktool::editionPage(page, "book/p.md", booktool::Edition::Student);
  const std::string t = booktool::editionPage(page, "book/p.md", booktool::Edition::Teacher);
  CHECK(s.find("42q") == std::string::npos);
  CHECK(s.find("after") != std::string::npos);
  CHECK(t.find("the answer is 42q") != std::string::npos);
  CHECK(t.find("Answer to exercise 9.9-1") != std::string::npos);
  for (const std::string& e : {s, t}) {
    CHECK(e.find("SOLUTION") == std::string::npos);
    CHECK(e.find("values:") == std::string::npos);
  }
  // A student line: its text in the student's edition only (where a block shows the full table).
  const std::string withStudent = "x\n<!-- student: \\htmlinclude t_student.html -->\n<!-- BEGIN SOLUTION 9.9-1 -->\n"
                                  "\\htmlinclude t.html\n<!-- END SOLUTION 9.9-1 -->\n";
  const std::string ss = booktool::editionPage(withStudent, "book/p.md", booktool::Edition::Student);
  const std::string st = booktool::editionPage(withStudent, "book/p.md", booktool::Edition::Teacher);
  CHECK(ss.find("\\htmlinclude t_student.html\n") != std::string::npos);
  CHECK(ss.find("\\htmlinclude t.html") == std::string::npos);
  CHECK(st.find("t_student") == std::string::npos);
  CHECK(st.find("\\htmlinclude t.html") != std::string::npos);
  CHECK_THROWS(booktool::editionPage("<!-- BEGIN SOLUTION 9.9-1 -->\n<!-- student: x -->\n<!-- END SOLUTION 9.9-1 -->\n",
                                     "book/p.md", booktool::Edition::Student));
  // The markers are split in two literals: this file's own source page must not show one.
  const std::string src = "int f() {\n  // " "BEGIN SOLUTION 9.9-1\n  return 42;\n  // " "END SOLUTION 9.9-1\n}\n";
  const std::string cs = booktool::editionCode(src, "code/x.cpp", booktool::Edition::Student);
  const std::string ct = booktool::editionCode(src, "code/x.cpp", booktool::Edition::Teacher);
  CHECK(cs.find("return 42") == std::string::npos);
  CHECK(cs.find("throw std::logic_error(\"exercise 9.9-1: not implemented yet\");") != std::string::npos);
  CHECK(ct.find("return 42") != std::string::npos);
  CHECK(std::count(ct.begin(), ct.end(), '\n') == std::count(src.begin(), src.end(), '\n'));  // same lines
  CHECK(ct.find("SOLUTION") == std::string::npos);
  CHECK_THROWS(booktool::editionCode("// " "BEGIN SOLUTION 1-1\nx\n", "code/y.cpp", booktool::Edition::Student));
}

TEST_CASE("book prose types no number without a reason and no project jargon") {
  const auto allowed = booktool::readAllowedNumbers(readAll(kRoot / "book" / "prose_numbers.txt"),
                                                    "book/prose_numbers.txt");
  for (const fs::path& p : filesIn(kRoot / "book", ".md"))
    for (const std::string& d : booktool::proseDefects(readAll(p), "book/" + p.filename().string(), allowed))
      CHECK_MESSAGE(false, d);
  // One planted defect of each kind is found; the same numbers as a value or a formula are not.
  auto found = [&](const std::string& line) {
    return booktool::proseDefects("\\page p P\n\n" + line + "\n", "book/p.md", allowed);
  };
  CHECK(mentions(found("BRIO keeps the mean cavity at most 3.5 on the parabola."), "a number typed in prose, '3.5'"));
  CHECK(mentions(found("Since issue 19 the orders are adaptive."), "jargon 'issue N'"));
  CHECK(mentions(found("At the end of the session that wrote this page."), "jargon 'session'"));
  CHECK(mentions(found("The helper that wrote it."), "jargon 'helper'"));
  CHECK(found("at most @{s235.parabola_brio}, in \\f$3.5n\\f$ steps, `x = 3.5`, Listing 2.5.").empty());
}

TEST_CASE("book the rendered check finds an en dash in code and raw superscripts and stray backticks and jargon") {
  CHECK(mentions(defectsOf("<p>run <code>ctest &ndash;test-dir build</code></p>"), "en dash inside code"));
  CHECK(mentions(defectsOf("<p>time close to n^{3/2}</p>"), "literal ^{"));
  CHECK(mentions(defectsOf("<p>run &lsquo;build/dt_tests -sf=` file</p>"), "stray backtick"));
  CHECK(mentions(defectsOf("<p>since issue 19 the orders</p>"), "jargon 'issue N'"));
  CHECK(mentions(defectsOf("<p>the session that wrote this page</p>"), "jargon 'session'"));
  CHECK(defectsOf("<p>run <code>ctest --test-dir build</code>, \\(n^{3/2}\\)</p>").empty());
}

TEST_CASE("book the reproduce box names the commands and the time and the files and the tests") {
  booktool::ReproduceSpec spec;
  std::string error;
  REQUIRE(booktool::parseReproduce("<!-- reproduce: programs: sec9_x; tests: 9.9 *; ctest: test_9_9 -->", spec, error));
  CHECK(error.empty());
  std::map<std::string, std::pair<std::string, std::string>> values = {{"run.sec9_x.seconds", {"12.5", "values_run.txt"}}};
  const std::string page = "\\page p P\n\\image html fig9.png \"caption\"\n\\htmlinclude table9.html\n";
  const std::set<std::string> files = {"fig9.png", "table9.csv", "table9.html", "values_sec9_x.txt"};
  const std::string box = booktool::reproduceBox(spec, page, values, "../../output/ch2",
                                                 [&](const std::string& f) { return files.count(f) > 0; });
  CHECK(box.find("build/sec9&#95;x &#45;&#45;quick") != std::string::npos);  // "--" never an en dash
  CHECK(box.find("the full run of this build's main command took it 12.5 s of wall time") != std::string::npos);
  // A quick run says so: the box names the options the main command ran with.
  auto quick = values;
  quick["run.options"] = {"--quick", "values_run.txt"};
  const std::string qbox = booktool::reproduceBox(spec, page, quick, "x", [](const std::string&) { return false; });
  CHECK(qbox.find("run with <code>&#45;&#45;quick</code>, took it 12.5 s") != std::string::npos);
  CHECK(qbox.find("full run of this build") == std::string::npos);
  CHECK(box.find("href=\"../../output/ch2/table9.csv\"") != std::string::npos);
  CHECK(box.find("href=\"../../output/ch2/fig9.png\"") != std::string::npos);
  CHECK(box.find("values&#95;sec9&#95;x.txt") != std::string::npos);
  CHECK(box.find("table9.md") == std::string::npos);  // not written: no link
  CHECK(box.find("-tc=&quot;9.9 &#42;&quot;") != std::string::npos);
  values.clear();
  CHECK(booktool::reproduceBox(spec, page, values, "x", [](const std::string&) { return false; })
            .find("not timed in this build") != std::string::npos);
  booktool::ReproduceSpec bad;
  CHECK(booktool::parseReproduce("<!-- reproduce: programs: a; tests: b -->", bad, error));
  CHECK_FALSE(error.empty());
}

TEST_CASE("book a bound named in a test is the number that test compares with") {
  std::map<std::string, std::pair<std::string, std::string>> v;
  booktool::testBounds("  CHECK(a > 0.38);  // book: s.lo\n  CHECK(std::fabs(c4 - 4) < 0.08);  // book: s.tol\n",
                       "tests/t.cpp", v);
  CHECK(v.at("s.lo").first == "0.38");
  CHECK(v.at("s.tol").first == "0.08");  // the last number: not the 4 of "c4 - 4"
  CHECK_THROWS(booktool::testBounds("CHECK(ok);  // book: s.none\n", "tests/t.cpp", v));
  CHECK_THROWS(booktool::testBounds("CHECK(a > 1);  // book: s.lo\n", "tests/t.cpp", v));  // twice
}

// Each leak a reader of the student edition once found, planted again in the sources: the
// edition check (the same one the book build runs on the HTML, source views included) must
// name its exercise.
TEST_CASE("book the edition check finds each answer a student once read in a test source or a table or a comment") {
  std::map<std::string, std::string> code, pages;
  readSources(code, pages);
  REQUIRE(code.count("tests/test_2_3_4_algorithms.cpp"));
  SUBCASE("2.3.4-3 stated by the parabola test's comment and its second order") {
    auto bad = code;
    bad["tests/test_2_3_4_algorithms.cpp"] = unmark(bad["tests/test_2_3_4_algorithms.cpp"], "2.3.4-3", false);
    CHECK(mentions(editionDefects(bad, pages), "2.3.4-3: the student edition shows"));
  }
  SUBCASE("2.2-2's point set built by the super-triangle test") {
    auto bad = code;
    bad["tests/test_2_2_bowyer_watson.cpp"] = unmark(bad["tests/test_2_2_bowyer_watson.cpp"], "2.2-2", false);
    CHECK(mentions(editionDefects(bad, pages), "2.2-2: the student edition shows"));
  }
  SUBCASE("2.3.1-1's verdict in the exercise test's comment") {
    auto bad = code;
    bad["tests/test_2_3_1_predicates.cpp"] = unmark(bad["tests/test_2_3_1_predicates.cpp"], "2.3.1-1", false);
    CHECK(mentions(editionDefects(bad, pages), "2.3.1-1: the student edition shows"));
  }
  SUBCASE("2.3.1-1's table rows marked with their exercise") {
    auto bad = pages;
    // As a program's table shows them, in a paraphrase with other capitals.
    // (Split literals: this file's own source page must not show the phrase.)
    bad["book/sec2_3_1.md"] += "\n| Canonical-order" " naive O(a,b,c) (exercise 1) | 11,492 |\n";
    CHECK(mentions(editionDefects(code, bad), "2.3.1-1: the student edition shows the answer's key phrase 'canonical-order" " naive'"));
  }
  SUBCASE("2.3.5-1's claim in the comment of the Hilbert table") {
    auto bad = code;
    bad["code/orders/hilbert.cpp"] = unmark(bad["code/orders/hilbert.cpp"], "2.3.5-1", false);
    CHECK(mentions(editionDefects(bad, pages), "2.3.5-1: the student edition shows"));
  }
  SUBCASE("2.3.2-1's hull count typed in the prose of 2.3.2") {
    auto bad = pages;
    bad["book/sec2_3_2.md"] += "\nOn a grid \\f$n_h = 2(n_x" "+n_y)-4\\f$.\n";
    CHECK(mentions(editionDefects(code, bad), "2.3.2-1: the student edition shows the answer's key phrase"));
  }
}

TEST_CASE("book the student's listing of a stub is one line and a removed comment leaves no gap") {
  const std::string src = "int f() {\n  // " "BEGIN SOLUTION 9.9-1\n  int a = 1;\n  int b = 2;\n  return a + b;\n  // "
                          "END SOLUTION 9.9-1\n}\n// " "BEGIN SOLUTION 9.9-2 (remove)\n// why: 42\n// " "END SOLUTION 9.9-2\nint g();\n";
  const std::string cs = booktool::editionCode(src, "code/x.cpp", booktool::Edition::Student);
  CHECK(cs == "int f() {\n  throw std::logic_error(\"exercise 9.9-1: not implemented yet\");\n}\nint g();\n");
  CHECK(cs.find("\n\n") == std::string::npos);
}
