// The book's pages made readable by everyone (WCAG 2.1 AA), as plain functions run on
// Doxygen's output by `book_tool access` (tests/test_book_access.cpp tests them on broken
// input; book/axe_check.sh measures the result in a browser):
//  - the language of every page (`lang` on <html>), which a screen reader needs to speak it;
//  - the search box labelled (Doxygen's menu script writes it without a label);
//  - every figure a <figure> with its <figcaption> and a real alt text: what the figure shows,
//    written with the page ("<!-- alt: ... -->" above each \image, values cited by @{key});
//  - the student's copy of a table without the rows an exercise asks for ("(exercise N)");
//  - a number typed in a page (prose or formula) that a program or a test's bound also holds
//    is refused: the page must cite it by @{key}, so it cannot drift from what was measured.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <cstdlib>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "book_tool.h"

namespace bookaccess {

/// `<html ...>` with lang="en" (unchanged if it has a lang already).
inline std::string withLang(const std::string& html) {
  const std::size_t at = html.find("<html");
  if (at == std::string::npos) return html;
  const std::size_t end = html.find('>', at);
  if (end == std::string::npos) return html;
  if (html.substr(at, end - at).find(" lang=") != std::string::npos) return html;
  return html.substr(0, at + 5) + " lang=\"en\"" + html.substr(at + 5);
}

/// The search field (in a page or in the menu script that writes it) with an accessible name.
inline std::string withSearchLabel(const std::string& text) {
  const std::string field = "id=\"MSearchField\"";
  std::string out;
  std::size_t i = 0;
  for (std::size_t at = text.find(field); at != std::string::npos; at = text.find(field, i)) {
    out += text.substr(i, at + field.size() - i);
    i = at + field.size();
    const std::size_t close = text.find('>', i);
    if (text.substr(i, close == std::string::npos ? std::string::npos : close - i).find("aria-label") ==
        std::string::npos)
      out += " aria-label=\"Search the book\"";
  }
  return out + text.substr(i);
}

/// The alt text of each figure of a page source: a line "<!-- alt: TEXT -->" directly above
/// (blank lines allowed) an "\image html FILE ..." line. A figure without one, or an alt line
/// that no figure follows, is an error naming the file and line.
inline std::map<std::string, std::string> figureAlts(const std::string& page, const std::string& file,
                                                     std::vector<std::string>& errors) {
  std::map<std::string, std::string> out;
  std::string pending;
  int pendingLine = 0, n = 0;
  for (const std::string& raw : booktool::splitLines(page)) {
    ++n;
    const std::string line = booktool::squeeze(raw);
    if (line.rfind("<!-- alt:", 0) == 0) {
      if (!pending.empty())
        errors.push_back(file + ":" + std::to_string(pendingLine) + ": an alt text that no figure follows");
      const std::size_t close = line.rfind("-->");
      pending = booktool::squeeze(line.substr(9, close == std::string::npos || close < 9 ? std::string::npos : close - 9));
      pendingLine = n;
      if (pending.empty()) errors.push_back(file + ":" + std::to_string(n) + ": an empty alt text");
      continue;
    }
    if (line.rfind("\\image html ", 0) == 0) {
      std::string name = line.substr(12);
      name = name.substr(0, name.find(' '));
      if (!name.empty() && name.front() == '"') name = name.substr(1, name.find('"', 1) - 1);
      if (pending.empty())
        errors.push_back(file + ":" + std::to_string(n) + ": the figure " + name +
                         " has no '<!-- alt: ... -->' line above it (say in words what it shows)");
      else
        out[name] = pending;
      pending.clear();
      continue;
    }
    if (!line.empty() && !pending.empty()) {
      errors.push_back(file + ":" + std::to_string(pendingLine) + ": an alt text that no figure follows");
      pending.clear();
    }
  }
  if (!pending.empty())
    errors.push_back(file + ":" + std::to_string(pendingLine) + ": an alt text that no figure follows");
  return out;
}

/// Doxygen's figure markup (<div class="image"><img .../><div class="caption">..</div></div>)
/// as <figure> with the alt text of `alts` and a <figcaption>. An image of a book page with no
/// alt text is an error naming the page and the file.
inline std::string withFigures(const std::string& html, const std::string& page,
                               const std::map<std::string, std::string>& alts,
                               std::vector<std::string>& errors) {
  static const std::regex fig(
      "<div class=\"image\">\\s*<img src=\"([^\"]*)\"([^>]*?)/?>\\s*(?:<div class=\"caption\">([\\s\\S]*?)</div>)?\\s*</div>");
  static const std::regex altAttr(" alt=\"[^\"]*\"");
  std::string out;
  auto begin = std::sregex_iterator(html.begin(), html.end(), fig);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out += html.substr(last, m.position(0) - last);
    last = m.position(0) + m.length(0);
    const std::string src = m[1].str();
    auto a = alts.find(src);
    std::string alt;
    if (a == alts.end()) errors.push_back(page + ": the figure " + src + " has no alt text");
    else alt = a->second;
    const std::string rest = std::regex_replace(m[2].str(), altAttr, "");
    // The caption names the figure for a screen reader (aria-labelledby: Chromium does not
    // take a figcaption as the name by itself).
    std::string cap = "figcap_";
    for (char c : src) cap += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    out += std::string("<figure class=\"image\"") + (m[3].matched ? " aria-labelledby=\"" + cap + "\"" : "") +
           ">\n<img src=\"" + src + "\" alt=\"" + booktool::htmlEscape(alt) + "\"" + rest + "/>\n";
    if (m[3].matched) out += "<figcaption class=\"caption\" id=\"" + cap + "\">" + m[3].str() + "</figcaption>";
    out += "</figure>";
  }
  return out + html.substr(last);
}

/// True for a page of the test suite: a source or file page whose path starts with the tests
/// directory (Doxygen's navigation path, "tests" first).
inline bool isSuitePage(const std::string& html) {
  const std::string item = "<li class=\"navelem\">";
  const std::size_t at = html.find(item);
  if (at == std::string::npos) return false;
  const std::size_t close = html.find("</li>", at);
  const std::string first = html.substr(at, close == std::string::npos ? std::string::npos : close - at);
  return first.find(">tests</a>") != std::string::npos;
}

/// Doxygen links every name in a listing to a symbol of that name wherever it finds one, and the
/// suite's helpers share short names with the library's locals (a variable `out`, a function
/// `key`): a listing of the library then linked them into the tests, a wrong target and, in
/// the student's edition, a page of tests. In a page that is not the suite's, a listing's link to
/// a page of `suite` (isSuitePage), or of the namespaces dttest and doctest, becomes its text.
inline std::string withoutLinksIntoSuite(const std::string& html, const std::set<std::string>& suite) {
  const std::string open = "<a class=\"code";
  std::string out;
  std::size_t i = 0;
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, i)) {
    const std::size_t gt = html.find('>', at), end = html.find("</a>", at);
    if (gt == std::string::npos || end == std::string::npos || end < gt) break;
    const std::string tag = html.substr(at, gt - at);
    const std::size_t h = tag.find("href=\"");
    std::string page = h == std::string::npos ? "" : tag.substr(h + 6, tag.find('"', h + 6) - h - 6);
    page = page.substr(0, page.find('#'));
    bool intoSuite = suite.count(page) > 0;
    for (const char* ns : {"namespacedttest", "structdttest", "classdttest", "namespacedoctest",
                           "structdoctest", "classdoctest"})
      intoSuite = intoSuite || page.rfind(ns, 0) == 0;
    out += html.substr(i, at - i);
    out += intoSuite ? html.substr(gt + 1, end - gt - 1) : html.substr(at, end + 4 - at);
    i = end + 4;
  }
  return out + html.substr(i);
}

/// A link first in the page, shown when focused, to the text: a keyboard reaches the page's
/// text without passing every link of the menu and the navigation tree (WCAG 2.4.1).
inline std::string withSkipLink(const std::string& html) {
  const std::size_t body = html.find("<body>");
  if (body == std::string::npos || html.find("class=\"skiplink\"") != std::string::npos) return html;
  const std::string target = html.find("id=\"doc-content\"") != std::string::npos ? "doc-content" : "";
  if (target.empty()) return html;
  return html.substr(0, body + 6) + "\n<a class=\"skiplink\" href=\"#" + target + "\">Skip to the text</a>" +
         html.substr(body + 6);
}

/// Each Markdown table (class="markdownTable") without a caption gets one: the heading it
/// stands under ("Claims and their tests"), so a screen reader names the table.
inline std::string withTableCaptions(const std::string& html) {
  static const std::regex heading("<h[1-6][^>]*>([\\s\\S]*?)</h[1-6]>");
  const std::string open = "<table class=\"markdownTable\">";
  std::string out;
  std::size_t last = 0;
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
    const std::size_t after = at + open.size();
    const std::size_t next = html.find_first_not_of(" \n\t", after);
    if (next != std::string::npos && html.compare(next, 8, "<caption") == 0) continue;
    std::string title;
    const std::string before = html.substr(0, at);
    for (auto it = std::sregex_iterator(before.begin(), before.end(), heading); it != std::sregex_iterator(); ++it)
      title = booktool::squeeze(booktool::decodeEntities(booktool::stripTags((*it)[1].str())));
    if (title.empty()) continue;
    out += html.substr(last, after - last) + "<caption>" + booktool::htmlEscape(title) + "</caption>";
    last = after;
  }
  return out + html.substr(last);
}

/// A listing of a book page without the marker lines of a snippet nested in the one it quotes
/// (Doxygen drops only the quoted snippet's own "//! [name]" lines).
inline std::string withoutNestedMarkers(const std::string& html) {
  static const std::regex marker("<div class=\"line\">(?:<a [^>]*></a>)?\\s*<span class=\"comment\">//! \\[[A-Za-z0-9_]+\\]</span></div>\n?");
  return std::regex_replace(html, marker, "");
}

/// The student's copy of a table written by a chapter program: every row whose text names an
/// exercise ("... (exercise 1)") is the exercise's answer and is left out.
inline std::string studentTable(const std::string& html) {
  static const std::regex row("<tr[ >][\\s\\S]*?</tr>\\s*");
  std::string out;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), row); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out += html.substr(last, m.position(0) - last);
    last = m.position(0) + m.length(0);
    const std::string text = booktool::decodeEntities(booktool::stripTags(m.str()));
    if (!std::regex_search(text, std::regex("\\(exercises? [0-9]"))) out += m.str();
  }
  return out + html.substr(last);
}

/// The numbers of a text as values ("53,980" -> 53980, "1e4", "10^4", "10^{4}" and "10⁴" ->
/// 10000, "2⁻⁵³" is left alone), each with its spelling and its offset.
struct TypedNumber {
  double value;
  std::string text;
  std::size_t at;
};
inline std::vector<TypedNumber> numbersIn(const std::string& s) {
  static const std::regex num(
      "(?:10\\^\\{?([0-9]+)\\}?)|(?:10((?:⁰|¹|²|³|⁴|⁵|⁶|⁷|⁸|⁹)+))|([0-9]+(?:,[0-9]{3})*(?:\\.[0-9]+)?(?:[eE][+-]?[0-9]+)?)");
  static const std::vector<std::string> sup = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::vector<TypedNumber> out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), num); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const std::size_t at = m.position(0);
    // Part of a word or of a longer number ("x86", "2.3.4", "v3"): not a number of its own.
    auto wordy = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; };
    if (at > 0 && wordy(s[at - 1])) continue;
    const std::size_t end = at + m.length(0);
    if (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '_' ||
                           (s[end] == '.' && end + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[end + 1])))))
      continue;
    double v = 0;
    if (m[1].matched) {
      v = std::pow(10.0, std::stod(m[1].str()));
    } else if (m[2].matched) {
      std::string d, e = m[2].str();
      for (std::size_t i = 0; i < e.size();)
        for (std::size_t k = 0; k < sup.size(); ++k)
          if (e.compare(i, sup[k].size(), sup[k]) == 0) { d += char('0' + k); i += sup[k].size(); break; }
      v = std::pow(10.0, std::stod(d));
    } else {
      std::string t = m[3].str();
      t.erase(std::remove(t.begin(), t.end(), ','), t.end());
      v = std::stod(t);
    }
    out.push_back({v, m.str(), at});
  }
  return out;
}

/// A number worth citing: one with a fractional part, an exponent, or at least three digits
/// (a one- or two-digit count is the mathematics' own: 3 vertices, 12 points of a figure).
inline bool distinctive(const TypedNumber& n) {
  if (n.text.find_first_of(".eE^") != std::string::npos || n.text.rfind("10", 0) == 0) return n.value >= 10 || n.value != std::floor(n.value);
  return n.value >= 100;
}

/// A value that is one number and not a round one (two significant digits or more, or a
/// fraction): "1.0001", "53,980", "12.5"; not "10000.0", "3 of 7" or a sentence.
inline bool measuredNumber(const std::string& value, double& v) {
  const auto ns = numbersIn(value);
  if (ns.size() != 1 || booktool::squeeze(value) != ns[0].text) return false;
  v = ns[0].value;
  if (v != std::floor(v)) return true;
  double m = std::fabs(v);
  while (m >= 10 && std::fmod(m, 10) == 0) m /= 10;
  return m >= 10 && v >= 100;
}

/// The page source's numbers (prose and formulas; code, comments, @{..}, file arguments and
/// quotations left out) that a value of the page's own programs (`programs`: their values
/// files are values_<program>.txt) or a bound named in a test holds as its one number:
/// "file:line: '1.0001' typed, a value of key (where): cite @{key}". `values`: key -> (value,
/// where). A number of another program's values is a coincidence (an input size of one page
/// is the bit count of another), not a copy.
inline std::vector<std::string> typedValues(const std::string& page, const std::string& file,
                                            const std::map<std::string, std::pair<std::string, std::string>>& values,
                                            const std::vector<std::string>& programs = {}) {
  std::map<double, std::string> held;
  for (const auto& [key, v] : values) {
    bool mine = v.second.rfind("tests/", 0) == 0;
    for (const std::string& p : programs) mine = mine || v.second == "values_" + p + ".txt";
    double x = 0;
    if (mine && measuredNumber(v.first, x)) held.emplace(x, key);
  }
  // The prose check's blanking, formulas kept: blank only what proseOnly blanks besides them.
  std::string text = page;
  for (const char* open : {"\\f$", "\\f[", "\\f{"}) {
    std::size_t i = 0;
    const std::string o = open;
    while ((i = text.find(o, i)) != std::string::npos) text.replace(i, o.size(), std::string(o.size(), '\x01')), i += o.size();
  }
  for (const char* close : {"\\f]", "\\f}"}) {
    std::size_t i = 0;
    const std::string c = close;
    while ((i = text.find(c, i)) != std::string::npos) text.replace(i, c.size(), std::string(c.size(), '\x01')), i += c.size();
  }
  const std::string prose = booktool::proseOnly(text);
  std::vector<std::string> out;
  const std::vector<std::string> lines = booktool::splitLines(prose);
  for (std::size_t k = 0; k < lines.size(); ++k)
    for (const TypedNumber& n : numbersIn(lines[k])) {
      if (!distinctive(n)) continue;
      // A name, not a quantity: "Listing 2.4", "section 2.1", "§ 2.3" are the notes' numbering
      // whatever a run measured (in either case: a sentence says "the kernel of section 2.1").
      static const std::regex named(
          "(?:(?:Listings?|Figures?|Fig\\.|Tables?|Propert(?:y|ies)|Propositions?|Sections?|Lemma|"
          "Theorem|Algorithm|Exercises?|Chapter|Definition|Corollary|Remark|Errat(?:um|a))\\s+|\u00a7\\s*)$",
          std::regex::ECMAScript | std::regex::icase);
      if (std::regex_search(lines[k].substr(0, n.at), named)) continue;
      auto it = held.end();
      for (auto h = held.begin(); h != held.end(); ++h)
        if (std::fabs(h->first - n.value) <= 1e-12 * std::fabs(n.value)) { it = h; break; }
      if (it == held.end()) continue;
      out.push_back(file + ":" + std::to_string(k + 1) + ": '" + n.text + "' typed, a value of " + it->second +
                    " (" + values.at(it->second).second + "): cite @{" + it->second + "} or a formula of it");
    }
  return out;
}

/// A book page as a section of the printed book: the part a reader reads (title to footer),
/// without scripts; a link to a page of the book (`ids`) becomes a link inside the file
/// ("sec2_1.html#x" -> "#x", "sec2_1.html" -> "#print_sec2_1"); a link to a source view gets
/// the printed target data-print="test_x.cpp, line 12".
inline std::string printPage(const std::string& html, const std::set<std::string>& ids) {
  std::string region = booktool::readableRegion(html);
  static const std::regex script("<script[^>]*>[\\s\\S]*?</script>");
  region = std::regex_replace(region, script, "");
  static const std::regex href("href=\"([A-Za-z0-9_.-]+)\\.html(#[^\"]*)?\"");
  std::string out;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(region.begin(), region.end(), href); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out += region.substr(last, m.position(0) - last);
    last = m.position(0) + m.length(0);
    const std::string page = m[1].str(), anchor = m[2].matched ? m[2].str() : "";
    if (ids.count(page)) {
      out += "href=\"" + (anchor.empty() ? "#print_" + page : anchor) + "\"";
      continue;
    }
    // Doxygen's file names: "_8" is '.', "__" is '_'; a source view ends in "_source". Only
    // those get a printed target (a test's line); a link of code to the API stays as it is.
    std::string name = page, label;
    const bool source = name.size() > 7 && name.compare(name.size() - 7, 7, "_source") == 0;
    if (!source) { out += m.str(); continue; }
    name.erase(name.size() - 7);
    for (std::size_t i = 0; i < name.size(); ++i) {
      if (name.compare(i, 2, "__") == 0) { label += '_'; ++i; }
      else if (name.compare(i, 2, "_8") == 0) { label += '.'; ++i; }
      else label += name[i];
    }
    if (anchor.size() > 2 && anchor[1] == 'l')
      label += ", line " + std::to_string(std::atoi(anchor.c_str() + 2));
    out += m.str() + " data-print=\"" + booktool::htmlEscape(label) + "\"";
  }
  return out + region.substr(last);
}

}  // namespace bookaccess
