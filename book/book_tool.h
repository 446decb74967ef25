// The book's build steps that Doxygen cannot do, as plain functions (book_tool.cpp is the
// command line; tests/test_book.cpp tests the functions on deliberately broken input):
//  - values: pages cite measured numbers as @{key}; the chapter programs write "key value"
//    lines (ch::Values, chapters/common.h) and the pages are copied with the keys replaced.
//  - test citations: @test{name} becomes a link to the source line of the TEST_CASE "name"; a
//    name that no test has stops the build, so a citation cannot rot.
//  - the claims index page, generated from the TEST_CASE lines of tests/*.cpp.
//  - reading order: previous/next links on every page, \subpage list on the main page.
//  - the rendered check: literal markup in the text a reader sees, too-wide tables, links to
//    missing files or anchors.
#pragma once

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace booktool {

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---- values -------------------------------------------------------------------------------

/// Parses "key value" lines (value: the rest of the line) of a values file into `out`; a
/// key already present (from another file) is an error naming both files.
inline void readValues(const std::string& text, const std::string& file,
                       std::map<std::string, std::pair<std::string, std::string>>& out) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const auto sp = line.find(' ');
    if (sp == std::string::npos || sp == 0)
      throw std::runtime_error(file + ":" + std::to_string(n) + ": expected 'key value', got '" +
                               line + "'");
    const std::string key = line.substr(0, sp), value = line.substr(sp + 1);
    auto it = out.find(key);
    if (it != out.end())
      throw std::runtime_error(file + ":" + std::to_string(n) + ": key '" + key +
                               "' is also written by " + it->second.second);
    out[key] = {value, file};
  }
}

// ---- tests --------------------------------------------------------------------------------

struct TestCase {
  std::string name;  // as doctest sees it (escapes undone)
  std::string file;  // tests/<name>.cpp
  int line = 0;
};

/// The TEST_CASE("...") lines of one test file's text; a name written as adjacent string
/// literals over several lines is joined, as the compiler does.
inline std::vector<TestCase> testCases(const std::string& text, const std::string& file) {
  std::vector<TestCase> out;
  std::size_t lineStart = 0;
  int n = 0;
  while (lineStart < text.size()) {
    ++n;
    std::size_t eol = text.find('\n', lineStart);
    if (eol == std::string::npos) eol = text.size();
    const std::size_t first = text.find_first_not_of(" \t", lineStart);
    if (first < eol && text.compare(first, 10, "TEST_CASE(") == 0) {
      std::string name;
      std::size_t i = first + 10;
      bool ok = false;
      while (true) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i >= text.size() || text[i] != '"') break;
        for (++i; i < text.size() && text[i] != '"'; ++i) {
          if (text[i] == '\\' && i + 1 < text.size()) ++i;
          name += text[i];
        }
        ++i;
        ok = true;
      }
      if (ok) out.push_back({name, file, n});
    }
    lineStart = eol + 1;
  }
  return out;
}

/// Doxygen's name for the source listing of a file ("tests/test_x.cpp" ->
/// "test__x_8cpp_source.html"): '_' doubled, '.' as "_8"; directories are not part of it
/// because the book's Doxyfile strips the path of inputs (STRIP_FROM_PATH).
inline std::string sourcePage(const std::string& file) {
  const std::string base = file.substr(file.rfind('/') == std::string::npos ? 0 : file.rfind('/') + 1);
  std::string out;
  for (char c : base) {
    if (c == '_') out += "__";
    else if (c == '.') out += "_8";
    else if (c == '-') out += "-";
    else out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out + "_source.html";
}

/// Doxygen's anchor of a line in a source listing: "l" and five digits.
inline std::string lineAnchor(int line) {
  std::string d = std::to_string(line);
  while (d.size() < 5) d = "0" + d;
  return "l" + d;
}

/// The section a test name starts with ("2.3.4 ..." -> "2.3.4"), or "" if none.
inline std::string sectionOf(const std::string& name) {
  std::size_t i = 0;
  while (i < name.size() && (std::isdigit(static_cast<unsigned char>(name[i])) || name[i] == '.')) ++i;
  if (i == 0 || !std::isdigit(static_cast<unsigned char>(name[0]))) return "";
  std::string s = name.substr(0, i);
  while (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

/// An anchor id for a test on the claims page (letters, digits, '_').
inline std::string claimAnchor(const std::string& name) {
  std::string out = "claim_";
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(c)) : '_';
  return out;
}

inline std::string htmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

/// HTML text for a \htmlonly block inside a Markdown table: also the characters that the
/// table splitter (|) or Markdown emphasis (*, _) would otherwise see.
inline std::string htmlText(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += "&#124;";
    else if (c == '*') out += "&#42;";
    else if (c == '_') out += "&#95;";
    else if (c == '\\') out += "&#92;";
    else if (c == '@') out += "&#64;";
    else out += htmlEscape(std::string(1, c));
  }
  return out;
}

/// The link a page puts where it cites a test: the test's name, pointing at its source line.
/// Raw HTML (\htmlonly), so that no character of the name is read as markup.
inline std::string testLink(const TestCase& t) {
  return "\\htmlonly<a href=\"" + sourcePage(t.file) + "#" + lineAnchor(t.line) +
         "\" class=\"testlink\"><span class=\"testname\">" + htmlText(t.name) +
         "</span></a>\\endhtmlonly";
}

// ---- pages --------------------------------------------------------------------------------

struct Page {
  std::string file;   // book/<name>.md
  std::string id;     // \page id, or "index" for \mainpage
  std::string title;  // the rest of the \page line
  std::string text;
};

inline Page parsePage(const std::string& text, const std::string& file) {
  Page p{file, "", "", text};
  std::istringstream in(text);
  std::string first;
  while (std::getline(in, first) && first.find_first_not_of(" \t\r") == std::string::npos) {
  }
  std::istringstream w(first);
  std::string cmd;
  w >> cmd;
  if (cmd == "\\mainpage") {
    p.id = "index";
  } else if (cmd == "\\page") {
    w >> p.id;
  } else {
    throw std::runtime_error(file + ":1: a page starts with \\page <id> <title> or \\mainpage");
  }
  std::getline(w, p.title);
  p.title.erase(0, p.title.find_first_not_of(" \t"));
  return p;
}

/// Replaces @{key} by its value and @test{name} by a link to the test; every unknown key or
/// test name is reported as "<file>:<line>: ..." in `errors`.
inline std::string substitute(const std::string& text, const std::string& file,
                              const std::map<std::string, std::pair<std::string, std::string>>& values,
                              const std::map<std::string, TestCase>& tests,
                              std::vector<std::string>& errors) {
  std::string out;
  std::size_t i = 0;
  int line = 1;
  while (i < text.size()) {
    const bool val = text.compare(i, 2, "@{") == 0;
    const bool tst = text.compare(i, 6, "@test{") == 0;
    if (!val && !tst) {
      if (text[i] == '\n') ++line;
      out += text[i++];
      continue;
    }
    const std::size_t open = i + (val ? 2 : 6);
    // The closing brace at depth 0: a test name may hold braces (DT_{n+1}).
    std::size_t close = std::string::npos;
    for (std::size_t k = open, depth = 0; k < text.size() && text[k] != '\n'; ++k) {
      if (text[k] == '{') ++depth;
      else if (text[k] == '}' && depth-- == 0) {
        close = k;
        break;
      }
    }
    const std::size_t eol = text.find('\n', open);
    if (close == std::string::npos || (eol != std::string::npos && close > eol)) {
      errors.push_back(file + ":" + std::to_string(line) + ": " + (val ? "@{" : "@test{") +
                       " is not closed on its line");
      out += text[i++];
      continue;
    }
    const std::string key = text.substr(open, close - open);
    if (val) {
      auto it = values.find(key);
      if (it == values.end()) {
        errors.push_back(file + ":" + std::to_string(line) + ": unknown value key '" + key +
                         "' (no chapter program wrote it)");
      } else {
        out += it->second.first;
      }
    } else {
      auto it = tests.find(key);
      if (it == tests.end()) {
        errors.push_back(file + ":" + std::to_string(line) + ": cites the test \"" + key +
                         "\", which no TEST_CASE in tests/ has");
      } else {
        out += testLink(it->second);
      }
    }
    i = close + 1;
  }
  return out;
}

/// The claims index page (Markdown for Doxygen): one table per section, as raw HTML.
inline std::string claimsPage(const std::vector<TestCase>& tests, const std::string& id,
                              const std::string& title) {
  std::map<std::string, std::vector<const TestCase*>> bySection;
  for (const TestCase& t : tests) {
    std::string s = sectionOf(t.name);
    bySection[s.empty() ? "~" + t.file : s].push_back(&t);
  }
  std::ostringstream o;
  o << "\\page " << id << " " << title << "\n\n"
    << "Every test of the repository, generated from the `TEST_CASE` lines of the files in `tests/` when\n"
    << "the book is built. A test's name is its section and the claim it checks. The link goes to\n"
    << "the test's source line; the command runs that test alone, from the repository's root after\n"
    << "the build (`bash scripts/main.sh`, or `cmake --build build`). `build/dt_tests -sf='*file*'`\n"
    << "runs a whole test file; `ctest --test-dir build` runs them all.\n\n"
    << "\\tableofcontents\n\n";
  for (const auto& [section, list] : bySection) {
    const bool numbered = section[0] != '~';
    const std::string heading = numbered ? "Section " + section : "Tests of " + section.substr(1);
    std::string anchor = "claims_";
    for (char c : heading) anchor += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    o << "# " << heading << " {#" << anchor << "}\n\n";
    o << "\\htmlonly[block]\n<table class=\"claims\">\n<tr><th>Claim</th><th>Test, at its source line</th>"
         "<th>Run it</th></tr>\n";
    for (const TestCase* t : list) {
      std::string claim = t->name.substr(numbered ? section.size() : 0);
      claim.erase(0, claim.find_first_not_of(" :"));
      const std::string base = t->file.substr(t->file.rfind('/') + 1);
      o << "<tr><td><a id=\"" << claimAnchor(t->name) << "\"></a><span class=\"testname\">"
        << htmlText(claim) << "</span></td><td><a href=\"" << sourcePage(t->file) << "#" << lineAnchor(t->line)
        << "\" class=\"testlink\">" << htmlText(base) << ":" << t->line
        << "</a></td><td><code>build/dt_tests -tc=&quot;" << htmlText(t->name)
        << "&quot;</code></td></tr>\n";
    }
    o << "</table>\n\\endhtmlonly\n\n";
  }
  return o.str();
}

/// Previous/next links for the page at `k` of the reading order.
inline std::string navLine(const std::vector<Page>& order, std::size_t k) {
  std::string s = "<div class=\"booknav\">";
  if (k > 0) s += "Previous: \\ref " + order[k - 1].id + " \"" + order[k - 1].title + "\"";
  if (k > 0 && k + 1 < order.size()) s += " &nbsp;&middot;&nbsp; ";
  if (k + 1 < order.size()) s += "Next: \\ref " + order[k + 1].id + " \"" + order[k + 1].title + "\"";
  return s + "</div>\n";
}

/// Inserts the navigation after a page's first line and at its end; the main page also gets
/// the list of all pages in reading order.
inline std::string withNavigation(const std::vector<Page>& order, std::size_t k) {
  const std::string& t = order[k].text;
  const auto eol = t.find('\n');
  std::string head = t.substr(0, eol + 1), body = eol == std::string::npos ? "" : t.substr(eol + 1);
  std::string out = head + "\n" + navLine(order, k) + "\n" + body;
  if (k == 0) {
    out += "\n# Contents\n\n";
    for (std::size_t j = 1; j < order.size(); ++j)
      out += "- \\ref " + order[j].id + " \"" + order[j].title + "\"\n";
  }
  return out + "\n\n" + navLine(order, k);
}

/// A page as a Doxygen comment block (.dox): Doxygen gives such a page its own id as file
/// name and no empty "File Reference" page, as it does for a .md input. Every line gets the
/// comment decoration "* ", which Doxygen strips, so a line that starts with *emphasis* keeps
/// its first star.
inline std::string asDoxComment(const std::string& page, const std::string& file) {
  for (const char* bad : {"*/", "/*"})
    if (page.find(bad) != std::string::npos)
      throw std::runtime_error(file + ": contains " + bad +
                               ", which would end or nest the page's comment block");
  std::string out = "/*!\n";
  std::istringstream in(page);
  std::string line;
  while (std::getline(in, line)) out += "* " + line + "\n";
  return out + "*/\n";
}

// ---- the rendered check -------------------------------------------------------------------

struct Defect {
  std::string what;
  std::string context;
};

inline std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The text of some HTML: tags removed; a block-level tag (paragraph, item, cell, ...)
/// becomes a space, since the reader sees a break there.
inline std::string stripTags(const std::string& s) {
  static const std::set<std::string> blocks = {"p", "li", "div", "td", "th", "tr", "br", "h1",
                                               "h2", "h3", "h4", "table", "ul", "ol", "dd", "dt",
                                               "blockquote", "caption"};
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    if (s[i] != '<') {
      out += s[i++];
      continue;
    }
    const std::size_t end = s.find('>', i);
    if (end == std::string::npos) break;
    std::size_t a = i + 1;
    if (a < end && s[a] == '/') ++a;
    std::size_t b = a;
    while (b < end && std::isalnum(static_cast<unsigned char>(s[b]))) ++b;
    if (blocks.count(lower(s.substr(a, b - a)))) out += ' ';
    i = end + 1;
  }
  return out;
}

/// Removes every element that opens with `open` (e.g. "<pre") up to its matching `close`,
/// counting nested elements of the same tag.
inline std::string dropElements(const std::string& html, const std::string& open,
                                const std::string& tag) {
  const std::string lo = lower(html);
  std::string out;
  std::size_t i = 0;
  while (true) {
    const std::size_t at = lo.find(open, i);
    if (at == std::string::npos) break;
    out += html.substr(i, at - i);
    int depth = 0;
    std::size_t j = at;
    while (j < lo.size()) {
      const std::size_t o = lo.find("<" + tag, j), c = lo.find("</" + tag, j);
      if (c == std::string::npos) {
        j = lo.size();
        break;
      }
      if (o != std::string::npos && o < c) {
        const char after = o + tag.size() + 1 < lo.size() ? lo[o + tag.size() + 1] : '>';
        if (after == '>' || after == ' ' || after == '\n' || after == '\t') ++depth;
        j = o + tag.size() + 1;
      } else {
        --depth;
        j = lo.find('>', c);
        j = j == std::string::npos ? lo.size() : j + 1;
        if (depth <= 0) break;
      }
    }
    out += " ";
    i = j;
  }
  return out + html.substr(std::min(i, html.size()));
}

inline std::string decodeEntities(const std::string& s) {
  static const std::map<std::string, std::string> named = {
      {"lt", "<"}, {"gt", ">"}, {"amp", "&"}, {"quot", "\""}, {"nbsp", " "}, {"apos", "'"},
      {"middot", "·"}, {"ndash", "–"}, {"mdash", "—"}};
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '&') {
      const std::size_t semi = s.find(';', i);
      if (semi != std::string::npos && semi - i < 10) {
        const std::string ent = s.substr(i + 1, semi - i - 1);
        if (!ent.empty() && ent[0] == '#') {
          const long v = ent.size() > 1 && (ent[1] == 'x' || ent[1] == 'X')
                             ? std::strtol(ent.c_str() + 2, nullptr, 16)
                             : std::strtol(ent.c_str() + 1, nullptr, 10);
          if (v > 0 && v < 128) {
            out += static_cast<char>(v);
          } else {
            out += ' ';  // width of one character is all the checks need
          }
          i = semi;
          continue;
        }
        auto it = named.find(ent);
        if (it != named.end()) {
          out += it->second;
          i = semi;
          continue;
        }
      }
    }
    out += s[i];
  }
  return out;
}



/// Replaces each MathJax formula's source (\(..\), \[..\], \begin{..}..\end{..}) by `with`.
inline std::string replaceMath(const std::string& s, const std::string& with) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    std::string closer;
    if (s.compare(i, 2, "\\(") == 0) closer = "\\)";
    else if (s.compare(i, 2, "\\[") == 0) closer = "\\]";
    else if (s.compare(i, 7, "\\begin{") == 0) closer = "\\end{";
    if (closer.empty()) {
      out += s[i++];
      continue;
    }
    std::size_t end = s.find(closer, i + 2);
    if (end == std::string::npos) {
      out += s[i++];
      continue;
    }
    end += closer.size();
    if (closer == "\\end{") end = s.find('}', end) + 1;
    out += with;
    i = end;
  }
  return out;
}

/// The part of a Doxygen page a reader reads: from the title to the footer.
inline std::string readableRegion(const std::string& html) {
  std::size_t from = html.find("<div class=\"header\">");
  if (from == std::string::npos) from = html.find("<div class=\"contents\">");
  if (from == std::string::npos) from = 0;
  std::size_t to = html.find("<!-- start footer part -->", from);
  if (to == std::string::npos) to = html.size();
  return html.substr(from, to - from);
}

/// True for a page of the book (book_tool gives each one its navigation bar); the API
/// reference's pages quote C++ signatures and comments, where * and _{ are code.
inline bool isBookPage(const std::string& html) {
  return html.find("<div class=\"booknav\">") != std::string::npos;
}

/// Everything on a rendered page that a reader should not see: markup Doxygen left as typed
/// (outside code and formulas) and unsubstituted @{..} or @test{..}. Whether tables and
/// figures fit the column is measured in a browser (book/layout_check.sh). On pages of the
/// API reference only unprocessed commands count.
inline std::vector<Defect> renderedDefects(const std::string& html) {
  std::vector<Defect> out;
  const bool book = isBookPage(html);
  std::string region = readableRegion(html);
  for (const char* el : {"script", "style", "pre", "code"})
    region = dropElements(region, std::string("<") + el, el);
  region = dropElements(region, "<div class=\"fragment\"", "div");
  // Test names are quoted verbatim (DT_{n+1}, \\snippet): names, not text.
  region = dropElements(region, "<span class=\"testname\"", "span");
  std::string text = replaceMath(decodeEntities(stripTags(region)), " ");
  std::string flat;
  for (char c : text) flat += (c == '\n' || c == '\t' || c == '\r') ? ' ' : c;
  static const std::vector<std::pair<std::string, std::string>> marks = {
      {"**", "literal ** (bold markup not rendered)"},
      {"*", "literal * (emphasis markup not rendered)"},
      {"_{", "literal _{ (a subscript typed outside a formula)"},
      {"\\|", "literal \\| (an escaped bar shown as typed)"},
      {"\\f$", "raw \\f$ (formula not rendered)"},
      {"\\f[", "raw \\f[ (formula not rendered)"},
      {"\\f]", "raw \\f] (formula not rendered)"},
      {"\\f{", "raw \\f{ (formula not rendered)"},
      {"\\snippet", "raw \\snippet"},
      {"\\image", "raw \\image"},
      {"\\htmlinclude", "raw \\htmlinclude"},
      {"\\ref ", "raw \\ref"},
      {"@{", "unsubstituted @{key}"},
      {"@test{", "unsubstituted @test{name}"},
      {"&#", "an HTML character reference shown as typed"},
      {"&amp;", "an escaped &amp; shown as typed"}};
  std::vector<bool> taken(flat.size(), false);
  for (const auto& [mark, what] : marks) {
    if (!book && mark[0] != '\\' && mark[0] != '@') continue;
    std::size_t at = 0;
    while ((at = flat.find(mark, at)) != std::string::npos) {
      // "Face*" in a table the programs wrote is a C++ pointer type, not emphasis: a star
      // right after a letter or digit and not before one. An emphasis pair still shows its
      // opening star, which follows a space or punctuation.
      const auto alnum = [&](std::size_t k) {
        return k < flat.size() && std::isalnum(static_cast<unsigned char>(flat[k]));
      };
      const bool pointer = mark == "*" && at > 0 && alnum(at - 1) && !alnum(at + 1);
      if (!taken[at] && !pointer) {
        for (std::size_t k = 0; k < mark.size(); ++k) taken[at + k] = true;
        const std::size_t from = at >= 50 ? at - 50 : 0;
        out.push_back({what, flat.substr(from, 110)});
      }
      at += mark.size();
    }
  }
  return out;
}

/// Local links (href="file#anchor") of a page whose file or anchor does not exist; `exists`
/// answers for a file name, `anchors` gives the ids of a file.
template <class Exists, class Anchors>
std::vector<Defect> brokenLinks(const std::string& html, Exists exists, Anchors anchors) {
  std::vector<Defect> out;
  std::size_t i = 0;
  const std::string region = readableRegion(html);
  while ((i = region.find("href=\"", i)) != std::string::npos) {
    i += 6;
    const std::size_t end = region.find('"', i);
    if (end == std::string::npos) break;
    const std::string href = region.substr(i, end - i);
    i = end;
    if (href.empty() || href.find(':') != std::string::npos || href[0] == '/') continue;
    const std::size_t hash = href.find('#');
    const std::string file = href.substr(0, hash), anchor = hash == std::string::npos ? "" : href.substr(hash + 1);
    if (!file.empty() && !exists(file)) {
      out.push_back({"link to a missing page", href});
      continue;
    }
    if (!anchor.empty() && !file.empty() && !anchors(file).count(anchor))
      out.push_back({"link to a missing anchor", href});
  }
  return out;
}

/// The id="..." and name="..." values of a page.
inline std::set<std::string> anchorsOf(const std::string& html) {
  std::set<std::string> ids;
  for (const char* attr : {" id=\"", " name=\""}) {
    std::size_t i = 0;
    const std::string a = attr;
    while ((i = html.find(a, i)) != std::string::npos) {
      i += a.size();
      const std::size_t end = html.find('"', i);
      if (end == std::string::npos) break;
      ids.insert(html.substr(i, end - i));
      i = end;
    }
  }
  return ids;
}

}  // namespace booktool
