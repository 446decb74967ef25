#include "book_navigation.h"

namespace booktool {

std::string navLine(const std::vector<Page>& order, std::size_t k) {
  std::string s = "<div class=\"booknav\">";
  if (k > 0) s += "Previous: \\ref " + order[k - 1].id + " \"" + order[k - 1].title + "\"";
  if (k > 0 && k + 1 < order.size()) s += " &nbsp;&middot;&nbsp; ";
  if (k + 1 < order.size()) s += "Next: \\ref " + order[k + 1].id + " \"" + order[k + 1].title + "\"";
  return s + "</div>\n";
}

std::string withNavigation(const std::vector<Page>& order, std::size_t k) {
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

std::string asDoxComment(const std::string& page, const std::string& file) {
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

std::vector<std::string> tableCells(const std::string& row) {
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

std::string claimsSummary(const std::string& page) {
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

std::pair<int, int> snippetRange(const std::string& text, const std::string& name) {
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

}  // namespace booktool
