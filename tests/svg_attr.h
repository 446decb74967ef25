/// \file svg_attr.h An attribute and a colour of an SVG tag, for the figure tests that read gnuplot's SVGs.
#pragma once

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace dttest {

/// The value of attribute `name` in the text of one tag ("" if absent). By hand, not with
/// std::regex: a path's d attribute can hold 100 000 characters over many lines, and
/// libstdc++'s regex recurses per character.
inline std::string svgAttr(const std::string& tag, const std::string& name) {
  for (std::size_t at = tag.find(name); at != std::string::npos; at = tag.find(name, at + 1)) {
    if (at == 0 || !std::isspace(static_cast<unsigned char>(tag[at - 1]))) continue;
    std::size_t k = at + name.size();
    while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
    if (k >= tag.size() || tag[k] != '=') continue;
    ++k;
    while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
    if (k >= tag.size() || (tag[k] != '"' && tag[k] != '\'')) continue;
    const std::size_t close = tag.find(tag[k], k + 1);
    return close == std::string::npos ? "" : tag.substr(k + 1, close - k - 1);
  }
  return "";
}

/// "#rrggbb" for a colour as gnuplot writes it: "rgb( 60,  60,  60)", "rgb(60,60,60)",
/// "#3c3c3c" (any case), "black", "white".
inline std::string svgHexColour(const std::string& c) {
  int r, g, b;
  if (std::sscanf(c.c_str(), " rgb( %d, %d, %d)", &r, &g, &b) == 3) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r, g, b);
    return buf;
  }
  if (c == "black") return "#000000";
  if (c == "white") return "#ffffff";
  std::string l = c;
  for (char& ch : l) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return l;
}

/// gnuplot's svg terminal opens each plot as `<g id="gnuplot_plot_N">`, N from 1 again in each
/// multiplot panel: true for such a tag, with `plot` set to N and `panel` counted on.
inline bool svgPlotStart(const std::string& tag, int& panel, int& plot) {
  const std::string id = svgAttr(tag, "id");
  if (id.compare(0, 13, "gnuplot_plot_") != 0) return false;
  const int n = std::atoi(id.c_str() + 13);
  if (n == 1 || n <= plot) ++panel;
  plot = n;
  return true;
}

/// Calls f(tag, begin, end) for each tag of an SVG's body (after its `</defs>`), in order: `tag` is the
/// text from '<' to '>', `begin` and `end` the offsets of the two. f returns the offset the next tag is
/// looked for from: end + 1, or past what it read itself (a text up to its `</text>`).
template <class F>
void forEachSvgTag(const std::string& s, F f) {
  const std::size_t body = s.find("</defs>");
  std::size_t i = body == std::string::npos ? 0 : body;
  while ((i = s.find('<', i)) != std::string::npos) {
    const std::size_t end = s.find('>', i);
    if (end == std::string::npos) break;
    i = f(s.substr(i, end - i + 1), i, end);
  }
}

}  // namespace dttest
