#include "book_rendered_check.h"

#include "book_editions.h"

namespace booktool {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string stripTags(const std::string& s) {
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

std::string dropElements(const std::string& html, const std::string& open,
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

std::string decodeEntities(const std::string& s) {
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

std::string replaceMath(const std::string& s, const std::string& with) {
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

std::string readableRegion(const std::string& html) {
  std::size_t from = html.find("<div class=\"header\">");
  if (from == std::string::npos) from = html.find("<div class=\"contents\">");
  if (from == std::string::npos) from = 0;
  std::size_t to = html.find("<!-- start footer part -->", from);
  if (to == std::string::npos) to = html.size();
  return html.substr(from, to - from);
}

bool isBookPage(const std::string& html) {
  return html.find("<div class=\"booknav\">") != std::string::npos;
}

std::vector<Defect> renderedDefects(const std::string& html) {
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

std::set<std::string> anchorsOf(const std::string& html) {
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
