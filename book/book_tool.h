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

inline std::string squeeze(const std::string& s);  // below, with the editions

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
         "\" class=\"testlink\"><code class=\"testname\">" + htmlText(t.name) +
         "</code></a>\\endhtmlonly";
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
    std::string key = text.substr(open, close - open);
    // "@{key|fallback}": the fallback text where no program wrote the key (the run summary's
    // timings exist only after the main command has run).
    std::string fallback;
    bool hasFallback = false;
    if (val && key.find('|') != std::string::npos) {
      fallback = key.substr(key.find('|') + 1);
      key = key.substr(0, key.find('|'));
      hasFallback = true;
    }
    if (val) {
      auto it = values.find(key);
      if (it == values.end() && hasFallback) {
        out += fallback;
      } else if (it == values.end()) {
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
    // Commands as raw HTML: Markdown would read the stars of a pattern as emphasis and
    // Doxygen turns "--" into an en dash, and a pasted command must work.
    << "the build (\\htmlonly<code>bash scripts/main.sh</code>\\endhtmlonly, or "
       "\\htmlonly<code>cmake &#45;&#45;build build</code>\\endhtmlonly). "
       "\\htmlonly<code>build/dt_tests -sf=&quot;&#42;test_2_3_4&#42;&quot;</code>\\endhtmlonly\n"
    << "runs the tests of the files whose name matches the pattern; "
       "\\htmlonly<code>ctest &#45;&#45;test-dir build</code>\\endhtmlonly runs them all, one entry per file.\n\n"
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
  // Code a reader may paste: an en dash there (Doxygen's "--") breaks the command.
  if (book) {
    for (const char* el : {"code", "pre"}) {
      const std::string lo = lower(region);
      std::size_t i = 0;
      const std::string open = std::string("<") + el;
      while ((i = lo.find(open, i)) != std::string::npos) {
        const char after = i + open.size() < lo.size() ? lo[i + open.size()] : ' ';
        const std::size_t end = lo.find(std::string("</") + el, i);
        if (end == std::string::npos) break;
        if (after == '>' || after == ' ') {
          const std::string inner = decodeEntities(stripTags(region.substr(i, end - i)));
          if (inner.find("\xE2\x80\x93") != std::string::npos)
            out.push_back({"an en dash inside code (a pasted command fails; write -- as &#45;&#45;)",
                           squeeze(inner).substr(0, 110)});
        }
        i = end + 1;
      }
    }
  }
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
      {"^{", "literal ^{ (a superscript typed outside a formula)"},
      {"`", "a stray backtick (inline code not closed, or a backtick inside a code span)"},
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
  // The project's own workflow words, which a reader cannot follow.
  if (book) {
    const std::string lo = lower(flat);
    for (std::size_t at = lo.find("issue "); at != std::string::npos; at = lo.find("issue ", at + 1))
      if (at + 6 < lo.size() && std::isdigit(static_cast<unsigned char>(lo[at + 6])))
        out.push_back({"project jargon 'issue N'", flat.substr(at >= 50 ? at - 50 : 0, 110)});
    for (const char* word : {"session", "helper"})
      for (std::size_t at = lo.find(word); at != std::string::npos; at = lo.find(word, at + 1))
        out.push_back({std::string("project jargon '") + word + "'", flat.substr(at >= 50 ? at - 50 : 0, 110)});
  }
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

// ---- editions -------------------------------------------------------------------------------
// One source, two books. A solution is marked once: in C++ between the comment lines
// "// BEGIN SOLUTION <id>" and "// END SOLUTION <id>" ("(remove)" after the id: a helper the
// student's stub does not need), in a page between the lines "<!-- BEGIN SOLUTION <id> -->"
// and "<!-- END SOLUTION <id> -->" (scripts/exercise.sh reads the same markers). The student
// edition drops every marked block (C++: the stub scripts/exercise.sh gives a student), the
// teacher edition keeps it and labels it as an answer; the markers themselves are never shown.

enum class Edition { Student, Teacher };

inline Edition editionNamed(const std::string& s) {
  if (s == "student") return Edition::Student;
  if (s == "teacher") return Edition::Teacher;
  throw std::runtime_error("unknown edition '" + s + "' (student or teacher)");
}

/// A marker line: `word` is "BEGIN" or "END"; `md` selects the page form (an HTML comment)
/// instead of the C++ comment. Sets the exercise id and whether the region is "(remove)".
inline bool solutionMarker(const std::string& line, const std::string& word, bool md,
                           std::string& id, bool& remove) {
  std::size_t a = line.find_first_not_of(" \t");
  if (a == std::string::npos) return false;
  const std::string lead = (md ? "<!-- " : "// ") + word + " SOLUTION ";
  if (line.compare(a, lead.size(), lead) != 0) return false;
  std::string rest = line.substr(a + lead.size());
  while (!rest.empty() && (rest.back() == '\r' || rest.back() == ' ')) rest.pop_back();
  if (md) {
    if (rest.size() < 3 || rest.compare(rest.size() - 3, 3, "-->") != 0) return false;
    rest.erase(rest.size() - 3);
    while (!rest.empty() && rest.back() == ' ') rest.pop_back();
  }
  const std::size_t sp = rest.find(' ');
  id = rest.substr(0, sp);
  remove = sp != std::string::npos && rest.find("(remove)", sp) != std::string::npos;
  return !id.empty();
}

/// One marked solution block of a file: its exercise, first line (of the BEGIN marker) and
/// the lines between the markers.
struct SolutionBlock {
  std::string id, file;
  int line = 0;
  bool md = false;
  std::vector<std::string> lines;
};

inline std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string s;
  while (std::getline(in, s)) out.push_back(s);
  return out;
}

/// The solution blocks of a file (a page if `md`); an END without its BEGIN, a block left
/// open or a nested block is an error naming the file and line.
inline std::vector<SolutionBlock> solutionBlocks(const std::string& text, const std::string& file,
                                                 bool md) {
  std::vector<SolutionBlock> out;
  const std::vector<std::string> lines = splitLines(text);
  SolutionBlock* open = nullptr;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::string id;
    bool rm = false;
    const std::string where = file + ":" + std::to_string(k + 1) + ": ";
    if (solutionMarker(lines[k], "BEGIN", md, id, rm)) {
      if (open) throw std::runtime_error(where + "BEGIN SOLUTION " + id + " inside the block of " + open->id);
      out.push_back({id, file, int(k + 1), md, {}});
      open = &out.back();
    } else if (solutionMarker(lines[k], "END", md, id, rm)) {
      if (!open || open->id != id) throw std::runtime_error(where + "END SOLUTION " + id + " without its BEGIN");
      open = nullptr;
    } else if (open) {
      open->lines.push_back(lines[k]);
    }
  }
  if (open) throw std::runtime_error(file + ":" + std::to_string(open->line) + ": BEGIN SOLUTION " +
                                     open->id + " is never closed");
  return out;
}

/// A source file as an edition shows it. Student: a block becomes the one line the student's
/// stub has (scripts/exercise.sh start), a "(remove)" block nothing at all, so a listing shows
/// no gap where an answer was (the student edition's claims index reads these copies, so its
/// line links stay right). Teacher: the lines stay, the markers become comments that say
/// "answer", so line numbers match the repository.
inline std::string editionCode(const std::string& text, const std::string& file, Edition ed) {
  solutionBlocks(text, file, false);  // balanced, or an error
  std::string out;
  bool inside = false;
  for (const std::string& line : splitLines(text)) {
    std::string id;
    bool rm = false;
    const std::string indent = line.substr(0, line.find_first_not_of(" \t"));
    if (solutionMarker(line, "BEGIN", false, id, rm)) {
      inside = true;
      if (ed == Edition::Teacher)
        out += indent + "// Answer to exercise " + id + " (teacher's edition) from here" + (rm ? ": a helper" : "") + "\n";
      else if (!rm)
        out += indent + "throw std::logic_error(\"exercise " + id + ": not implemented yet\");\n";
      continue;
    }
    if (solutionMarker(line, "END", false, id, rm)) {
      inside = false;
      if (ed == Edition::Teacher) out += indent + "// End of the answer to exercise " + id + "\n";
      continue;
    }
    if (!inside || ed == Edition::Teacher) out += line + "\n";
  }
  return out;
}

/// A page as an edition shows it. Student: blocks dropped. Teacher: each block framed as the
/// answer to its exercise. Lines "<!-- values: a | b -->" inside a block (the answer's
/// distinctive values, for the edition check) are dropped in both. A line
/// "<!-- student: TEXT -->" outside the blocks is TEXT in the student's edition and nothing in
/// the teacher's: where a block shows a full table, the student's edition shows the version
/// without the answer (e.g. "\htmlinclude table_brio_student.html").
inline std::string editionPage(const std::string& text, const std::string& file, Edition ed) {
  solutionBlocks(text, file, true);
  std::string out;
  bool inside = false;
  for (const std::string& line : splitLines(text)) {
    std::string id;
    bool rm = false;
    const std::string studentLead = "<!-- student:";
    const std::size_t lead = line.find_first_not_of(" \t");
    if (lead != std::string::npos && line.compare(lead, studentLead.size(), studentLead) == 0) {
      const std::size_t close = line.rfind("-->");
      if (inside || close == std::string::npos || close < lead + studentLead.size())
        throw std::runtime_error(file + ": a '<!-- student: ... -->' line inside a solution block or not closed on its line");
      if (ed == Edition::Student) {
        std::string t = line.substr(lead + studentLead.size(), close - lead - studentLead.size());
        t.erase(0, t.find_first_not_of(' '));
        t.erase(t.find_last_not_of(' ') + 1);
        out += t + "\n";
      }
      continue;
    }
    if (solutionMarker(line, "BEGIN", true, id, rm)) {
      inside = true;
      if (ed == Edition::Teacher)
        out += "\\htmlonly[block]<div class=\"answer\"><div class=\"answerhead\">Answer to exercise " + id +
               " (teacher's edition only)</div>\\endhtmlonly\n";
      else
        out += "\n";  // keeps the paragraphs around the block apart
      continue;
    }
    if (solutionMarker(line, "END", true, id, rm)) {
      inside = false;
      if (ed == Edition::Teacher) out += "\\htmlonly[block]</div>\\endhtmlonly\n";
      continue;
    }
    if (inside && (line.find("<!-- values:") != std::string::npos || line.find("<!-- phrases:") != std::string::npos)) continue;
    if (!inside || ed == Edition::Teacher) out += line + "\n";
  }
  return out;
}

/// The student edition's text for a link to the solutions page, which it does not have:
/// `\ref solutions "the solutions page"` becomes "the solutions page (teacher's edition)".
inline std::string studentLinks(const std::string& page) {
  std::string out = page;
  const std::string ref = "\\ref solutions \"";
  std::size_t at = 0;
  while ((at = out.find(ref, at)) != std::string::npos) {
    const std::size_t close = out.find('"', at + ref.size());
    if (close == std::string::npos) break;
    const std::string label = out.substr(at + ref.size(), close - at - ref.size());
    out.replace(at, close + 1 - at, label + " (teacher's edition)");
    at += label.size();
  }
  return out;
}

/// The distinctive values an answer block lists ("<!-- values: 36n | 16n -->"), or with
/// `what` = "phrases", its key phrases ("<!-- phrases: away from the apex -->"): the words a
/// paraphrase of the answer would keep.
inline std::vector<std::string> blockValues(const SolutionBlock& b, const std::string& what = "values") {
  std::vector<std::string> out;
  const std::string lead = "<!-- " + what + ":";
  for (const std::string& l : b.lines) {
    const std::size_t at = l.find(lead);
    if (at == std::string::npos) continue;
    std::string v = l.substr(at + lead.size(), l.find("-->", at) - at - lead.size());
    std::size_t s = 0;
    while (s <= v.size()) {
      std::size_t bar = v.find('|', s);
      if (bar == std::string::npos) bar = v.size();
      std::string item = v.substr(s, bar - s);
      item.erase(0, item.find_first_not_of(" \t"));
      item.erase(item.find_last_not_of(" \t") + 1);
      if (!item.empty()) out.push_back(item);
      s = bar + 1;
    }
  }
  return out;
}

/// Whitespace runs as one space, ends trimmed: how text is compared across HTML and sources.
inline std::string squeeze(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

/// The lines between "//! [name]" markers of a source text (empty if the snippet is absent).
inline std::vector<std::string> snippetLines(const std::string& text, const std::string& name) {
  std::vector<std::string> out;
  bool inside = false;
  const std::string mark = "//! [" + name + "]";
  for (const std::string& l : splitLines(text)) {
    if (l.find(mark) != std::string::npos) {
      if (inside) return out;
      inside = true;
      continue;
    }
    if (inside) out.push_back(l);
  }
  return {};
}

/// What an exercise's answer consists of, for the edition check: its source lines (of its
/// code regions, and of the .cpp snippets its page blocks quote) that appear nowhere else in
/// the sources, the plain prose lines of its page blocks, and the values they list.
struct AnswerKey {
  std::set<std::string> lines;   // squeezed
  std::set<std::string> values;
  std::set<std::string> phrases;  // lower case, looked for case-insensitively
  std::set<std::pair<std::string, std::string>> snippets;  // (file, name) its blocks quote
};

/// True for a line of prose with no markup at all, long enough to be the answer's own words.
inline bool plainProse(const std::string& s) {
  std::string t = squeeze(s);
  if (t.rfind("- ", 0) == 0) t.erase(0, 2);  // a list item's marker is not shown as typed
  if (t.size() < 30) return false;
  for (char c : t)
    if (std::string("\\`*_{}[]<>|#@$&\"").find(c) != std::string::npos) return false;
  return true;
}

/// The answer keys of every exercise, from the sources (`code`: file -> text of code/ and
/// tests/; `pages`: file -> text of book/*.md).
inline std::map<std::string, AnswerKey> answerKeys(const std::map<std::string, std::string>& code,
                                                   const std::map<std::string, std::string>& pages) {
  std::map<std::string, AnswerKey> keys;
  // Spans: per file, the line numbers that belong to an answer.
  std::map<std::string, std::set<std::size_t>> span;
  std::map<std::string, std::vector<std::string>> linesOf;
  for (const auto& [f, t] : code) linesOf[f] = splitLines(t);
  std::map<std::string, std::vector<std::pair<std::string, std::size_t>>> candidates;  // id -> (file, line)
  for (const auto& [f, t] : code) {
    const auto& L = linesOf[f];
    std::string open;
    for (std::size_t k = 0; k < L.size(); ++k) {
      std::string id;
      bool rm = false;
      if (solutionMarker(L[k], "BEGIN", false, id, rm)) { open = id; span[f].insert(k); continue; }
      if (solutionMarker(L[k], "END", false, id, rm)) { open.clear(); span[f].insert(k); continue; }
      if (!open.empty()) {
        span[f].insert(k);
        candidates[open].push_back({f, k});
      }
    }
  }
  for (const auto& [pf, pt] : pages)
    for (const SolutionBlock& b : solutionBlocks(pt, pf, true)) {
      AnswerKey& key = keys[b.id];
      for (const std::string& v : blockValues(b)) key.values.insert(v);
      for (const std::string& v : blockValues(b, "phrases")) key.phrases.insert(lower(squeeze(v)));
      for (const std::string& l : b.lines) {
        if (plainProse(l)) {
          std::string t = squeeze(l);
          if (t.rfind("- ", 0) == 0) t.erase(0, 2);
          key.lines.insert(t);
        }
        // "\snippet code/x.cpp name": the quoted definition is the answer too.
        std::istringstream w(l);
        std::string cmd, file, name;
        w >> cmd >> file >> name;
        if (cmd != "\\snippet" || file.size() < 4 || file.compare(file.size() - 4, 4, ".cpp") != 0) continue;
        key.snippets.insert({file, name});
      }
    }
  // A line is distinctive if it is long and occurs nowhere outside the answers' spans.
  // "Nowhere else" also means: not part of a longer line elsewhere ("for (...)" of "for (...) {").
  std::string elsewhereText;
  for (const auto& [f, L] : linesOf)
    for (std::size_t k = 0; k < L.size(); ++k)
      if (!span[f].count(k)) elsewhereText += squeeze(L[k]) + "\n";
  struct Elsewhere {
    const std::string& text;
    std::size_t count(const std::string& line) const { return text.find(line) != std::string::npos; }
  } elsewhere{elsewhereText};
  for (const auto& [id, where] : candidates)
    for (const auto& [f, k] : where) {
      const std::string s = squeeze(linesOf[f][k]);
      std::string marker;
      bool rm = false;
      if (s.size() >= 25 && !elsewhere.count(s) && !solutionMarker(s, "BEGIN", false, marker, rm) &&
          !solutionMarker(s, "END", false, marker, rm))
        keys[id].lines.insert(s);
    }
  return keys;
}

/// The .cpp snippets that answer blocks quote must differ between the editions: a snippet
/// the student's sources show exactly as the teacher's holds an unmarked answer.
inline std::vector<std::string> snippetLeaks(const std::map<std::string, AnswerKey>& keys,
                                             const std::map<std::string, std::string>& code) {
  std::vector<std::string> out;
  for (const auto& [id, k] : keys)
    for (const auto& [file, name] : k.snippets) {
      auto it = code.find(file);
      if (it == code.end()) continue;
      const auto student = snippetLines(editionCode(it->second, file, Edition::Student), name);
      const auto teacher = snippetLines(editionCode(it->second, file, Edition::Teacher), name);
      if (!teacher.empty() && student == teacher)
        out.push_back(id + ": the student edition shows the answer's snippet " + file + " [" + name +
                      "] as the teacher's does (its solution region is not marked)");
    }
  return out;
}

/// The edition check: for every exercise, none of its answer's lines and values in the
/// student text, all of them in the teacher text (both squeezed, all pages joined), and an
/// answer for every exercise of `ids`. Returns one message per defect.
inline std::vector<std::string> editionLeaks(const std::map<std::string, AnswerKey>& keys,
                                             const std::vector<std::string>& ids,
                                             const std::string& student, const std::string& teacher) {
  std::vector<std::string> out;
  // Values are looked for with white space squeezed and none next to a sign or bracket: a
  // formula or a test name may space "4 + (6-D)/n" differently from the answer's
  // "4 + (6 - D)/n". Between two letters or digits a space stays ("16 namespace" is not 16n).
  auto bare = [](const std::string& s) {
    const std::string q = squeeze(s);
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
    std::string o;
    for (std::size_t i = 0; i < q.size(); ++i)
      if (q[i] != ' ' || (i > 0 && i + 1 < q.size() && word(q[i - 1]) && word(q[i + 1]))) o += q[i];
    return o;
  };
  const std::string studentBare = bare(student), teacherBare = bare(teacher);
  const std::string studentLower = lower(student), teacherLower = lower(teacher);
  // A value is found as a whole: not inside a longer word ("16n" is not in "16namespace", the
  // line number 16 of a source listing before its code).
  auto contains = [](const std::string& text, const std::string& v) {
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
    for (std::size_t at = text.find(v); at != std::string::npos; at = text.find(v, at + 1)) {
      const bool before = at > 0 && word(text[at - 1]) && word(v.front());
      const bool after = at + v.size() < text.size() && word(text[at + v.size()]) && word(v.back());
      if (!before && !after) return true;
    }
    return false;
  };
  for (const std::string& id : ids) {
    auto it = keys.find(id);
    if (it == keys.end() || (it->second.lines.empty() && it->second.values.empty())) {
      out.push_back(id + ": no marked answer (no solution block with a distinctive line or value)");
      continue;
    }
    auto look = [&](const std::string& item, const std::string& needle, const std::string& s,
                    const std::string& t, const char* kind) {
      const bool value = std::string(kind) == "value";  // a line is looked for as it is
      if (value ? contains(s, needle) : s.find(needle) != std::string::npos)
        out.push_back(id + ": the student edition shows the answer's " + kind + " '" + item + "'");
      if (value ? !contains(t, needle) : t.find(needle) == std::string::npos)
        out.push_back(id + ": the teacher edition lacks the answer's " + kind + " '" + item + "'");
    };
    for (const std::string& l : it->second.lines) look(l, l, student, teacher, "line");
    for (const std::string& p : it->second.phrases) look(p, p, studentLower, teacherLower, "key phrase");
    for (const std::string& v : it->second.values) look(v, bare(v), studentBare, teacherBare, "value");
  }
  return out;
}

// ---- the prose check (on the page sources) ------------------------------------------------
// A number a reader meets in prose must come from a program (@{key}) or be a formula, code,
// or a number of an allow-list entry (book/prose_numbers.txt: a section number, a
// mathematical constant, ...), each with its reason. Project jargon fails too.

/// One allowed form of a number in prose: a regular expression that the whole word (or the
/// word with the one before or after it: "Listing 2.5", "15 cm") must match, and why such a
/// number may be typed.
struct AllowedNumber {
  std::string pattern, reason;
};

/// Parses book/prose_numbers.txt: "regex | reason" lines, '#' comments; an entry without a
/// reason is an error.
inline std::vector<AllowedNumber> readAllowedNumbers(const std::string& text, const std::string& file) {
  std::vector<AllowedNumber> out;
  int n = 0;
  for (const std::string& raw : splitLines(text)) {
    ++n;
    std::string l = raw;
    if (!l.empty() && l.back() == '\r') l.pop_back();
    if (l.find_first_not_of(" \t") == std::string::npos || l[l.find_first_not_of(" \t")] == '#') continue;
    const std::size_t bar = l.find(" | ");
    if (bar == std::string::npos || squeeze(l.substr(bar + 3)).empty())
      throw std::runtime_error(file + ":" + std::to_string(n) + ": expected 'regex | reason'");
    out.push_back({squeeze(l.substr(0, bar)), squeeze(l.substr(bar + 3))});
  }
  return out;
}

/// The prose of a page source: code (fenced and inline), formulas, @{..}/@test{..}, commands
/// with file or anchor arguments, HTML tags and comments are blanked (newlines kept, so line
/// numbers stay right).
inline std::string proseOnly(const std::string& page) {
  std::string s = page;
  auto blank = [&](std::size_t a, std::size_t b) {
    for (std::size_t k = a; k < b && k < s.size(); ++k)
      if (s[k] != '\n') s[k] = ' ';
  };
  auto blankBetween = [&](const std::string& open, const std::string& close, bool nestBraces) {
    std::size_t i = 0;
    while ((i = s.find(open, i)) != std::string::npos) {
      std::size_t end;
      if (nestBraces) {
        int depth = 0;
        end = std::string::npos;
        for (std::size_t k = i + open.size() - 1; k < s.size(); ++k) {
          if (s[k] == '{') ++depth;
          else if (s[k] == '}' && --depth == 0) { end = k + 1; break; }
        }
      } else {
        end = s.find(close, i + open.size());
        if (end != std::string::npos) end += close.size();
      }
      if (end == std::string::npos) end = s.size();
      blank(i, end);
      i = end;
    }
  };
  // Fenced code blocks.
  {
    std::size_t i = 0;
    bool fenced = false;
    std::size_t start = 0;
    while (i < s.size()) {
      std::size_t eol = s.find('\n', i);
      if (eol == std::string::npos) eol = s.size();
      const std::size_t first = s.find_first_not_of(" \t", i);
      const bool fence = first < eol && (s.compare(first, 3, "```") == 0 || s.compare(first, 3, "~~~") == 0);
      if (fence) {
        if (!fenced) start = i;
        else blank(start, eol);
        fenced = !fenced;
      }
      i = eol + 1;
    }
  }
  blankBetween("<!--", "-->", false);
  blankBetween("\\htmlonly", "\\endhtmlonly", false);
  blankBetween("\\f$", "\\f$", false);
  blankBetween("\\f[", "\\f]", false);
  blankBetween("\\f{", "\\f}", false);
  blankBetween("@test{", "", true);
  blankBetween("@{", "", true);
  blankBetween("{#", "}", false);
  // Quotations (of the notes, mostly) are quoted as printed, numbers included.
  blankBetween("“", "”", false);
  {
    std::size_t i = 0;
    while ((i = s.find('"', i)) != std::string::npos) {
      const std::size_t end = s.find('"', i + 1);
      if (end == std::string::npos || s.find('\n', i) < end) { ++i; continue; }
      blank(i, end + 1);
      i = end + 1;
    }
  }
  // Inline code spans.
  {
    std::size_t i = 0;
    while ((i = s.find('`', i)) != std::string::npos) {
      const std::size_t end = s.find('`', i + 1);
      if (end == std::string::npos) break;
      blank(i, end + 1);
      i = end + 1;
    }
  }
  // HTML tags (their attributes hold file names and sizes).
  {
    std::size_t i = 0;
    while ((i = s.find('<', i)) != std::string::npos) {
      const std::size_t end = s.find('>', i);
      if (end == std::string::npos || s.find('\n', i) < end) { ++i; continue; }
      if (end > i + 1 && (std::isalpha(static_cast<unsigned char>(s[i + 1])) || s[i + 1] == '/')) blank(i, end + 1);
      i = end + 1;
    }
  }
  // Commands whose arguments are names, not prose: the whole line, or the argument.
  for (const char* cmd : {"\\snippet", "\\image", "\\htmlinclude", "\\include", "\\anchor", "\\ref", "\\subpage", "\\page"}) {
    std::size_t i = 0;
    const std::string c = cmd;
    while ((i = s.find(c, i)) != std::string::npos) {
      std::size_t end = i + c.size();
      const bool wholeLine = c == "\\snippet" || c == "\\image" || c == "\\htmlinclude" || c == "\\include";
      if (wholeLine) {
        end = s.find('\n', i);
        if (end == std::string::npos) end = s.size();
      } else {
        while (end < s.size() && s[end] == ' ') ++end;
        while (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end]))) ++end;
      }
      blank(i, end);
      i = end;
    }
  }
  // Addresses.
  for (const char* scheme : {"http://", "https://"}) {
    std::size_t i = 0;
    while ((i = s.find(scheme, i)) != std::string::npos) {
      std::size_t end = i;
      while (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end])) && s[end] != ')') ++end;
      blank(i, end);
      i = end;
    }
  }
  return s;
}

/// Defects of a page's prose: a word holding a digit that no allow-list entry admits, and the
/// project's jargon ("issue N", "session", "helper"), each as "file:line: what".
inline std::vector<std::string> proseDefects(const std::string& page, const std::string& file,
                                             const std::vector<AllowedNumber>& allowed) {
  std::vector<std::regex> res;
  for (const AllowedNumber& a : allowed) res.emplace_back(a.pattern);
  std::vector<std::string> out;
  const std::vector<std::string> lines = splitLines(proseOnly(page));
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::string where = file + ":" + std::to_string(k + 1) + ": ";
    const std::string lo = lower(lines[k]);
    // Jargon of the project's own workflow, which a reader cannot follow.
    for (std::size_t at = lo.find("issue "); at != std::string::npos; at = lo.find("issue ", at + 1))
      if (at + 6 < lo.size() && std::isdigit(static_cast<unsigned char>(lo[at + 6])))
        out.push_back(where + "project jargon 'issue N': " + squeeze(lines[k]));
    for (const char* word : {"session", "helper"})
      if (lo.find(word) != std::string::npos)
        out.push_back(where + "project jargon '" + word + "': " + squeeze(lines[k]));
    // Words with a digit.
    std::vector<std::string> words;
    {
      std::istringstream w(lines[k]);
      std::string x;
      while (w >> x) words.push_back(x);
    }
    std::string prev;
    for (std::size_t wi = 0; wi < words.size(); ++wi) {
      std::string t = words[wi];
      // Punctuation around the word: ASCII, and the typographic quotes (UTF-8, whole).
      const std::string punct = ".,;:()[]\"'!?*";
      const auto trim = [&] {
        bool again = true;
        while (again && !t.empty()) {
          again = false;
          if (punct.find(t.back()) != std::string::npos) { t.pop_back(); again = true; }
          else if (punct.find(t.front()) != std::string::npos) { t.erase(0, 1); again = true; }
          for (const char* q : {"“", "”", "‘", "’", "'s", "’s"}) {
            const std::string qs = q;
            if (t.size() >= qs.size() && t.compare(t.size() - qs.size(), qs.size(), qs) == 0) { t.erase(t.size() - qs.size()); again = true; }
            else if (qs[0] != '\'' && t.compare(0, qs.size(), qs) == 0 && qs != "’s") { t.erase(0, qs.size()); again = true; }
          }
        }
      };
      trim();
      bool digit = false;
      for (char c : t) digit = digit || std::isdigit(static_cast<unsigned char>(c));
      // Superscript digits (10⁸) count as digits too.
      for (const char* sup : {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"}) digit = digit || t.find(sup) != std::string::npos;
      if (digit) {
        bool ok = false;
        // The word alone, with the word before it ("Listing 2.5") or after it ("15 cm").
        const std::string pair = prev + " " + t;
        const std::string next = wi + 1 < words.size() ? t + " " + words[wi + 1] : t;
        for (const std::regex& r : res)
          ok = ok || std::regex_match(t, r) || std::regex_match(pair, r) || std::regex_match(next, r);
        if (!ok) out.push_back(where + "a number typed in prose, '" + t + "' (cite a program's @{key}, write it as a formula, or add it to book/prose_numbers.txt with its reason)");
      }
      prev = t;
    }
  }
  return out;
}

// ---- "Reproduce this page" ----------------------------------------------------------------
// A section page names its program(s) and tests in one line,
//   <!-- reproduce: programs: sec2_3_4_algorithms; tests: 2.3.4 *; ctest: test_2_3_4 -->
// and book_tool puts in its place a box: the commands (full and --quick), the wall time of the
// program in this build's run of the main command (value run.<program>.seconds, written by
// scripts/main.sh), the files of the page as links, and the commands that run its tests.

/// Percent-encodes what a relative URL path cannot hold as typed (spaces, quotes, '%', '#').
inline std::string urlPath(const std::string& p) {
  std::string out;
  for (unsigned char c : p) {
    if (std::isalnum(c) || std::string("/._-~").find(char(c)) != std::string::npos) {
      out += char(c);
    } else {
      char b[4];
      std::snprintf(b, sizeof b, "%%%02X", c);
      out += b;
    }
  }
  return out;
}

struct ReproduceSpec {
  std::vector<std::string> programs;
  std::string tests, ctest;
};

/// Reads a "<!-- reproduce: ... -->" line; false if the line is not one.
inline bool parseReproduce(const std::string& line, ReproduceSpec& spec, std::string& error) {
  const std::string lead = "<!-- reproduce:";
  const std::size_t a = line.find(lead);
  if (a == std::string::npos) return false;
  const std::size_t end = line.find("-->", a);
  if (end == std::string::npos) {
    error = "a reproduce line must end with -->";
    return true;
  }
  std::string body = line.substr(a + lead.size(), end - a - lead.size());
  std::size_t s = 0;
  while (s < body.size()) {
    std::size_t semi = body.find(';', s);
    if (semi == std::string::npos) semi = body.size();
    const std::string part = body.substr(s, semi - s);
    const std::size_t colon = part.find(':');
    const std::string key = squeeze(part.substr(0, colon)), val = colon == std::string::npos ? "" : squeeze(part.substr(colon + 1));
    if (key == "programs") {
      std::istringstream w(val);
      std::string p;
      while (w >> p) spec.programs.push_back(p);
    } else if (key == "tests") {
      spec.tests = val;
    } else if (key == "ctest") {
      spec.ctest = val;
    } else if (!key.empty()) {
      error = "unknown field '" + key + "' in a reproduce line (programs, tests, ctest)";
    }
    s = semi + 1;
  }
  if (spec.programs.empty() || spec.tests.empty() || spec.ctest.empty())
    error = "a reproduce line needs programs, tests and ctest";
  return true;
}

/// The box (raw HTML for Doxygen). `page` is the page's text (for the files it embeds),
/// `values` the measured values, `outputUrl` the output directory relative to the pages,
/// `exists` answers whether a file of the output directory exists.
template <class Exists>
std::string reproduceBox(const ReproduceSpec& spec, const std::string& page,
                         const std::map<std::string, std::pair<std::string, std::string>>& values,
                         const std::string& outputUrl, Exists exists) {
  auto code = [](const std::string& s) {
    std::string e = htmlText(s);
    std::string out;
    for (std::size_t i = 0; i < e.size(); ++i)  // "--" must not become an en dash
      out += (e[i] == '-' && ((i + 1 < e.size() && e[i + 1] == '-') || (i > 0 && e[i - 1] == '-')))
                 ? std::string("&#45;")
                 : std::string(1, e[i]);
    return "<code>" + out + "</code>";
  };
  std::ostringstream o;
  o << "\\htmlonly[block]<div class=\"reproduce\"><b>Reproduce this page</b> (from the repository's root, "
       "once <code>bash scripts/main.sh</code> has built everything):<ul>\n";
  for (const std::string& p : spec.programs) {
    o << "<li>" << code("build/" + p) << " (the full run) or " << code("build/" + p + " --quick")
      << " (small sizes); ";
    auto it = values.find("run." + p + ".seconds");
    // Which run timed it: the main command's options (values_run.txt), "none" for the full run.
    auto opts = values.find("run.options");
    const bool full = opts == values.end() || opts->second.first == "none";
    if (it != values.end() && full)
      o << "the full run of this build's main command took it " << htmlText(it->second.first) << " s of wall time.";
    else if (it != values.end())
      o << "this build's main command, run with " << code(opts->second.first) << ", took it "
        << htmlText(it->second.first) << " s of wall time.";
    else
      o << "not timed in this build (the main command, <code>bash scripts/main.sh</code>, times every program).";
    o << "</li>\n";
  }
  // The files this page shows, from the output directory.
  std::vector<std::string> files;
  for (const std::string& l : splitLines(page)) {
    std::istringstream w(l);
    std::string cmd, a, b;
    w >> cmd >> a >> b;
    std::string name = cmd == "\\image" ? b : cmd == "\\htmlinclude" ? a : "";
    if (name.empty()) continue;
    if (!name.empty() && name.front() == '"') name = name.substr(1, name.find('"', 1) - 1);
    const std::string stem = name.substr(0, name.rfind('.'));
    if (cmd == "\\htmlinclude") {
      for (const char* ext : {".csv", ".md", ".html"})
        if (exists(stem + ext)) files.push_back(stem + ext);
    } else if (exists(name)) {
      files.push_back(name);
    }
  }
  for (const std::string& p : spec.programs)
    if (exists("values_" + p + ".txt")) files.push_back("values_" + p + ".txt");
  if (!files.empty()) {
    o << "<li>What it writes that this page shows, in <code>build/output/ch2/</code>: ";
    for (std::size_t k = 0; k < files.size(); ++k)
      o << (k ? ", " : "") << "<a href=\"" << htmlEscape(urlPath(outputUrl + "/" + files[k])) << "\">"
        << htmlText(files[k]) << "</a>";
    o << ".</li>\n";
  }
  // No full stop after the command: a narrow page wrapped it onto a line of its own.
  o << "<li>The page's tests: " << code("build/dt_tests -tc=\"" + spec.tests + "\"") << ", or "
    << code("ctest --test-dir build -R \"" + spec.ctest + "\"") << "</li>\n";
  o << "</ul></div>\\endhtmlonly\n";
  return o.str();
}

// ---- the summary at the top of a section page ----------------------------------------------

/// The cells of a Markdown table row; a '|' inside a formula, a code span or @test{..} (test
/// names hold |C|) does not split.
inline std::vector<std::string> tableCells(const std::string& row) {
  std::vector<std::string> cells;
  std::string cur;
  bool math = false, code = false;
  int test = 0;
  std::size_t i = row.find('|');
  if (i == std::string::npos) return cells;
  for (++i; i < row.size(); ++i) {
    if (row.compare(i, 3, "\\f$") == 0) { math = !math; cur += "\\f$"; i += 2; continue; }
    if (row.compare(i, 6, "@test{") == 0) { ++test; cur += "@test{"; i += 5; continue; }
    const char c = row[i];
    if (test && c == '{') ++test;
    if (test && c == '}') --test;
    if (c == '`') code = !code;
    if (c == '|' && !math && !code && !test) {
      cells.push_back(squeeze(cur));
      cur.clear();
      continue;
    }
    cur += c;
  }
  if (!squeeze(cur).empty()) cells.push_back(squeeze(cur));
  return cells;
}

/// A short summary for the top of a page, from its claims table (the first table after a
/// heading that starts with "Claims", whose heading carries the anchor {#id}): each claim of
/// the notes with its verdict (measured values cited by @{key} are substituted later, with the
/// rest of the page). Empty if the page has no claims table.
inline std::string claimsSummary(const std::string& page) {
  const std::vector<std::string> lines = splitLines(page);
  std::size_t k = 0;
  std::string anchor;
  for (; k < lines.size(); ++k) {
    const std::string& l = lines[k];
    const std::size_t h = l.find_first_not_of('#');
    if (!l.empty() && l[0] == '#' && h != std::string::npos && l.compare(h, 7, " Claims") == 0) {
      const std::size_t a = l.find("{#");
      if (a != std::string::npos) anchor = l.substr(a + 2, l.find('}', a) - a - 2);
      break;
    }
  }
  if (k == lines.size()) return "";
  std::vector<std::pair<std::string, std::string>> rows;
  int seen = 0;
  for (++k; k < lines.size(); ++k) {
    const std::string t = squeeze(lines[k]);
    if (t.empty() && seen == 0) continue;
    if (t.empty() || t[0] != '|') break;
    if (++seen <= 2) continue;  // header and separator
    const std::vector<std::string> c = tableCells(t);
    if (c.size() >= 2) rows.push_back({c[0], c[1]});
  }
  if (rows.empty()) return "";
  std::string out = "\\htmlonly[block]<div class=\"ataglance\">\\endhtmlonly\n";
  out += "**At a glance.** The claims of the notes that this page checks, and the verdict";
  out += anchor.empty() ? "" : " (tests and details: \\ref " + anchor + " \"the claims table\")";
  out += ":\n\n";
  for (const auto& [claim, verdict] : rows) out += "- " + claim + ": " + verdict + "\n";
  out += "\n\\htmlonly[block]</div>\\endhtmlonly\n";
  return out;
}

// ---- listing captions -----------------------------------------------------------------------

/// The first and last line (1-based) of the code between the "//! [name]" markers of a source
/// text, as \snippet shows it; {0, 0} if the snippet is not there.
inline std::pair<int, int> snippetRange(const std::string& text, const std::string& name) {
  const std::string mark = "//! [" + name + "]";
  int n = 0, open = 0;
  for (const std::string& l : splitLines(text)) {
    ++n;
    if (l.find(mark) == std::string::npos) continue;
    if (open) return {open + 1, n - 1};
    open = n;
  }
  return {0, 0};
}

/// Puts above each "\snippet file name" line of a page a caption naming the file and the
/// line range, linked to that line of the source browser. `source` reads a file of the
/// edition's sources ("" if absent).
template <class Source>
std::string withListingCaptions(const std::string& page, Source source) {
  std::string out;
  for (const std::string& l : splitLines(page)) {
    std::istringstream w(l);
    std::string cmd, file, name;
    w >> cmd >> file >> name;
    if (cmd == "\\snippet" && !name.empty()) {
      const auto [a, b] = snippetRange(source(file), name);
      if (a > 0) {
        char range[64];
        std::snprintf(range, sizeof range, "lines %d&ndash;%d", a, b);
        out += "\\htmlonly[block]<div class=\"listingcaption\"><a href=\"" + sourcePage(file) + "#" +
               lineAnchor(a) + "\"><code>" + htmlText(file) + "</code>, " + range + "</a></div>\\endhtmlonly\n";
      }
    }
    out += l + "\n";
  }
  return out;
}

// ---- bounds named in the tests --------------------------------------------------------------

/// The bounds a test compares with, named for the book: a line of a test file that ends with
/// "// book: <key>" gives <key> the last number literal before the comment ("CHECK(a > 0.38);
/// // book: s234.bound_exp_lo" -> 0.38). The prose cites @{<key>}: the bound it states is then
/// the very number the test compares with. A key without a number is an error.
inline void testBounds(const std::string& text, const std::string& file,
                       std::map<std::string, std::pair<std::string, std::string>>& out) {
  int n = 0;
  for (const std::string& l : splitLines(text)) {
    ++n;
    const std::size_t at = l.find("// book: ");
    if (at == std::string::npos) continue;
    const std::string key = squeeze(l.substr(at + 9));
    // Only "key" alone to the end of the line (letters, digits, '_' and '.') is a name; the
    // same text inside a string literal, as in test_book.cpp, is not.
    bool name = !key.empty();
    for (char c : key) name = name && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.');
    if (!name) continue;
    const std::string code = l.substr(0, at);
    std::string last;
    for (std::size_t i = 0; i < code.size(); ++i) {
      const bool start = std::isdigit(static_cast<unsigned char>(code[i])) &&
                         (i == 0 || !(std::isalnum(static_cast<unsigned char>(code[i - 1])) || code[i - 1] == '_' || code[i - 1] == '.'));
      if (!start) continue;
      std::size_t j = i;
      while (j < code.size() && (std::isdigit(static_cast<unsigned char>(code[j])) || code[j] == '.')) ++j;
      last = code.substr(i, j - i);
      i = j;
    }
    const std::string where = file + ":" + std::to_string(n) + ": ";
    if (key.empty() || last.empty()) throw std::runtime_error(where + "'// book:' needs a key and a number on its line");
    if (out.count(key)) throw std::runtime_error(where + "key '" + key + "' is also written by " + out[key].second);
    out[key] = {last, file + ":" + std::to_string(n)};
  }
}

}  // namespace booktool
