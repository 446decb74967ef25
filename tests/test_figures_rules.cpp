/// \file test_figures_rules.cpp A textbook editor's rules for the figures, as tests:
/// colour (the pairs a reader must tell apart stay apart under protanopia, deuteranopia and
/// tritanopia, or carry a second cue; one colour per meaning, all from style.gp's table),
/// notation (no figure shows an ASCII or upright form of the notes' symbols) and caption truth
/// (what each caption promises is drawn). Each checker is first fed a planted defect.
//
// The figures come from one run of the chapter programs that draw them (as in
// tests/test_figures.cpp, into a directory of their own; DT_FIGURES_DIR checks a finished run's
// instead). The rules' data live beside the figures: figures/ch2/meaning_pairs.txt,
// notation.txt and promises.txt.
#include <doctest/doctest.h>

#include "figure_run.h"
#include "svg_attr.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../chapters/colour_vision.h"
#include "../chapters/figure_data.h"
#include "../chapters/process.h"

namespace fs = std::filesystem;

namespace {

const fs::path kFigDir = fs::path(DT_SOURCE_DIR) / "figures" / "ch2";
const char* const kMathFamily = "DejaVu Math TeX Gyre";
const ch::Vision kVisions[] = {ch::Vision::Normal, ch::Vision::Protanopia, ch::Vision::Deuteranopia,
                               ch::Vision::Tritanopia};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// The lines of a rules file that are not comments or blank.
std::vector<std::string> dataLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!trim(line).empty() && trim(line)[0] != '#') out.push_back(line);
  return out;
}

// ---- the palette -----------------------------------------------------------------------------

/// The colours of style.gp: every `C_NAME = "#rrggbb"` (or "black", "white"), and C_SERIES.k for
/// the k-th word of C_SERIES; black and white themselves under their own names.
std::map<std::string, std::string> palette(const std::string& style) {
  std::map<std::string, std::string> p = {{"black", "#000000"}, {"white", "#ffffff"}};
  const std::regex role(R"re(\n(C_[A-Z_]+) = "([^"]*)")re");
  for (auto it = std::sregex_iterator(style.begin(), style.end(), role); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1], value = (*it)[2];
    if (name == "C_SERIES") {
      std::istringstream words(value);
      int k = 0;
      for (std::string w; words >> w;) p[name + "." + std::to_string(++k)] = w;
    } else {
      p[name] = value == "black" ? "#000000" : value == "white" ? "#ffffff" : value;
    }
  }
  return p;
}

/// Roles that share a colour (black and white, the ink and the paper, are no roles).
std::vector<std::string> sharedColours(const std::map<std::string, std::string>& pal) {
  std::map<std::string, std::string> seen;
  std::vector<std::string> out;
  for (const auto& [name, hex] : pal) {
    if (name == "black" || name == "white" || hex == "#000000" || hex == "#ffffff") continue;
    std::string h = hex;
    for (char& c : h) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (seen.count(h)) out.push_back(seen[h] + " and " + name + " are both " + h);
    else seen[h] = name;
  }
  return out;
}

/// Colours written out in a figure script (`#rrggbb`, `0xrrggbb`, a colour name) instead of a
/// style.gp role; white and black (the paper and the ink) may be written.
std::vector<std::string> scriptColourLiterals(const std::string& text) {
  std::vector<std::string> out;
  const std::regex hex(R"(#[0-9a-fA-F]{6}\b|0x[0-9a-fA-F]{6}\b)"), named(R"(rgb\s*["']([a-z][a-z-]*)["'])");
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    // The code of the line: up to a '#' outside quotes (gnuplot's comments).
    std::string code;
    char quote = 0;
    for (char c : line) {
      if (quote == 0 && c == '#') break;
      if (quote == 0 && (c == '"' || c == '\'')) quote = c;
      else if (c == quote) quote = 0;
      code += c;
    }
    for (auto it = std::sregex_iterator(code.begin(), code.end(), hex); it != std::sregex_iterator(); ++it) {
      std::string h = (*it)[0];
      for (char& c : h) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (h == "0xffffff" || h == "0x000000" || h == "#ffffff" || h == "#000000") continue;
      out.push_back("line " + std::to_string(n) + ": " + (*it)[0].str());
    }
    for (auto it = std::sregex_iterator(code.begin(), code.end(), named); it != std::sregex_iterator(); ++it)
      if ((*it)[1] != "black" && (*it)[1] != "white" && (*it)[1] != "variable")
        out.push_back("line " + std::to_string(n) + ": " + (*it)[0].str());
  }
  return out;
}

/// One meaning-pair of figures/ch2/meaning_pairs.txt.
struct MeaningPair {
  std::string a, b;
  std::vector<std::string> figures;
  std::string cue, meaning;
};

std::vector<MeaningPair> meaningPairs(const std::string& text) {
  std::vector<MeaningPair> out;
  for (const std::string& line : dataLines(text)) {
    std::istringstream in(line);
    MeaningPair p;
    std::string figs;
    in >> p.a >> p.b >> figs >> p.cue;
    std::getline(in, p.meaning);
    p.meaning = trim(p.meaning);
    std::istringstream f(figs);
    for (std::string w; std::getline(f, w, ',');) p.figures.push_back(w);
    if (p.cue.empty() || p.meaning.empty()) throw std::runtime_error("meaning_pairs.txt: a line without all its columns: " + line);
    out.push_back(p);
  }
  return out;
}

/// The least CIEDE2000 of two colours over the four kinds of vision, and the vision where it is.
std::pair<double, ch::Vision> leastDifference(const std::string& x, const std::string& y) {
  std::pair<double, ch::Vision> best{1e300, ch::Vision::Normal};
  for (ch::Vision v : kVisions) {
    const double d = ch::seenDifference(ch::parseHex(x), ch::parseHex(y), v);
    if (d < best.first) best = {d, v};
  }
  return best;
}

// ---- what an SVG draws (gnuplot's svg terminal) ----------------------------------------------

struct SvgSpan {
  std::string family, text;
  double size, dy;
};
struct SvgText {
  std::vector<SvgSpan> spans;
  std::string str;
  double x = 0, y = 0, rotate = 0;
  std::string anchor;
  int panel = 0, plot = 0;  // plot: its group's number in the panel (0: not drawn by a plot)
  bool key = false;         // a key entry: the text of its plot's title
};
struct SvgLine {
  std::string colour, dash;
  double width;
  int panel;
  double cx = 0, cy = 0;  // the mean of its points
  int plot = 0;           // its plot's number in the panel (0: not drawn by a plot)
  std::vector<std::pair<double, double>> pts;  // for a plot's lines: its points
};

SvgLine makeLine(const std::string& colour, const std::string& dash, double width, int panel, double cx = 0, double cy = 0) {
  SvgLine l;
  l.colour = colour, l.dash = dash, l.width = width, l.panel = panel, l.cx = cx, l.cy = cy;
  return l;
}
struct SvgMarker {
  std::string shape, colour;
  int panel;
  double x = 0, y = 0, r = 0;
  int plot = 0;
};
struct SvgArea {  // a filled polygon drawn by a plot (a bar), its extent
  double x0, y0, x1, y1;
  int panel, plot;
};
struct SvgDrawing {
  std::vector<SvgText> texts;
  std::vector<SvgLine> lines;
  std::vector<std::pair<std::string, int>> fills;  // colour, panel
  std::vector<std::pair<double, double>> fillCentres;
  std::vector<SvgMarker> markers;
  std::vector<SvgArea> areas;
};

std::string attr(const std::string& tag, const std::string& name) { return dttest::svgAttr(tag, name); }

std::string hexOf(const std::string& c) { return dttest::svgHexColour(c); }

std::string unescapeXml(std::string s) {
  const std::pair<const char*, const char*> ents[] = {{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : ents)
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) s.replace(at, std::string(from).size(), to);
  return s;
}

/// The mean of the coordinate pairs of a path's d ("M x,y L x,y ...") or a polygon's points.
std::pair<double, double> centre(const std::string& coords, bool* any = nullptr) {
  double sx = 0, sy = 0;
  int n = 0;
  const char* c = coords.c_str();
  while (*c) {
    if (std::isdigit(static_cast<unsigned char>(*c)) || *c == '-' || *c == '.') {
      char* e = nullptr;
      const double x = std::strtod(c, &e);
      if (e && *e == ',') {
        const double y = std::strtod(e + 1, &e);
        sx += x, sy += y, ++n;
      }
      c = e && e > c ? e : c + 1;
    } else {
      ++c;
    }
  }
  if (any) *any = n > 0;
  return n ? std::pair<double, double>{sx / n, sy / n} : std::pair<double, double>{0, 0};
}

/// Reads what gnuplot's svg terminal draws. A multiplot panel's plots are the groups
/// gnuplot_plot_N (N starts again at 1 in each panel); what a panel draws outside its plots
/// (objects, borders, labels) belongs to the panel whose plots' extent holds its centre.
SvgDrawing readSvg(const std::string& s) {
  SvgDrawing d;
  std::map<int, std::array<double, 4>> extent;  // per panel: x0, y0, x1, y1 of its plots' points
  int depthInPlot = -1, depth = 0;
  std::string plotTitle;
  struct Group {
    std::string stroke, colour;
    double width;
  };
  std::vector<Group> groups;
  int panel = 0, plot = 0;
  dttest::forEachSvgTag(s, [&](const std::string& tag, const std::size_t i, const std::size_t end) -> std::size_t {
    if (tag.compare(0, 3, "<g ") == 0 || tag == "<g>") {
      ++depth;
      Group g{attr(tag, "stroke"), attr(tag, "color"), std::atof(attr(tag, "stroke-width").c_str())};
      if (!groups.empty()) {
        if (g.stroke.empty()) g.stroke = groups.back().stroke;
        if (g.colour.empty()) g.colour = groups.back().colour;
        if (g.width == 0) g.width = groups.back().width;
      }
      groups.push_back(g);
      if (dttest::svgPlotStart(tag, panel, plot)) {
        depthInPlot = depth;
        const std::size_t t0 = s.find("<title>", end), t1 = s.find("</title>", end);
        plotTitle = t0 != std::string::npos && t0 < end + 4 ? unescapeXml(s.substr(t0 + 7, t1 - t0 - 7)) : "";
      }
    } else if (tag == "</g>") {
      if (depth == depthInPlot) depthInPlot = -1;
      --depth;
      if (!groups.empty()) groups.pop_back();
    } else if (tag.compare(0, 5, "<text") == 0) {
      const std::size_t te = s.find("</text>", end);
      const std::string inner = s.substr(end + 1, te - end - 1);
      // The font of a text is on its <g>, before the <text>.
      const std::size_t g0 = s.rfind("<g ", i);
      const std::string gtag = g0 == std::string::npos ? "" : s.substr(g0, s.find('>', g0) - g0 + 1);
      const std::string family = attr(gtag, "font-family");
      const double size = std::atof(attr(gtag, "font-size").c_str());
      SvgText t;
      const std::string tr = attr(gtag, "transform");
      std::sscanf(tr.c_str(), "translate(%lf,%lf)", &t.x, &t.y);
      if (const std::size_t r = tr.find("rotate("); r != std::string::npos) t.rotate = std::atof(tr.c_str() + r + 7);
      t.anchor = attr(gtag, "text-anchor");
      t.panel = panel;
      t.plot = depthInPlot > 0 ? plot : 0;
      const std::regex span(R"(<tspan([^>]*)>([^<]*)</tspan>)");
      double dy = 0;
      for (auto it = std::sregex_iterator(inner.begin(), inner.end(), span); it != std::sregex_iterator(); ++it) {
        const std::string a = " " + (*it)[1].str();
        const std::string f = attr(a, "font-family"), fz = attr(a, "font-size");
        dy += std::atof(attr(a, "dy").c_str());
        SvgSpan sp{f.empty() ? family : f, unescapeXml((*it)[2]), fz.empty() ? size : std::atof(fz.c_str()), dy};
        if (!sp.text.empty()) t.spans.push_back(sp), t.str += sp.text;
      }
      if (t.spans.empty()) {
        const std::string txt = unescapeXml(std::regex_replace(inner, std::regex("<[^>]*>"), ""));
        if (!trim(txt).empty()) t.spans.push_back({family, txt, size, 0}), t.str = txt;
      }
      t.key = t.plot > 0 && !t.spans.empty() && trim(t.str) == trim(plotTitle);
      if (!t.spans.empty()) d.texts.push_back(t);
      return te;
    } else if (tag.compare(0, 5, "<path") == 0 || tag.compare(0, 8, "<polygon") == 0) {
      const int where = depthInPlot > 0 ? panel : -1;  // -1: placed by its centre below
      bool any = false;
      const auto [cx, cy] = centre(attr(tag, tag[1] == 'p' && tag[2] == 'a' ? "d" : "points"), &any);
      if (where > 0 && any) {
        auto it = extent.find(where);
        if (it == extent.end()) extent[where] = {cx, cy, cx, cy};
        else it->second = {std::min(it->second[0], cx), std::min(it->second[1], cy), std::max(it->second[2], cx), std::max(it->second[3], cy)};
      }
      const std::string fill = attr(tag, "fill");
      if (where > 0 && tag.compare(0, 8, "<polygon") == 0 && !fill.empty() && fill != "none") {
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        std::istringstream pts(attr(tag, "points"));
        for (std::string pt; pts >> pt;) {
          double x, y;
          if (std::sscanf(pt.c_str(), "%lf,%lf", &x, &y) == 2) x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
        if (x0 < x1) d.areas.push_back({x0, y0, x1, y1, where, plot});
      }
      if (!fill.empty() && fill != "none" && fill.compare(0, 4, "url(") != 0) {
        d.fills.push_back({hexOf(fill == "currentColor" && !groups.empty() ? groups.back().colour : fill), where});
        d.fillCentres.push_back({cx, cy});
      }
      if (tag.compare(0, 5, "<path") == 0) {
        std::string stroke = attr(tag, "stroke");
        if (stroke.empty() && !groups.empty()) stroke = groups.back().stroke;
        if (stroke == "currentColor" && !groups.empty()) stroke = groups.back().colour;
        if (!stroke.empty() && stroke != "none")
        {
          const std::string w = attr(tag, "stroke-width");
          SvgLine l = makeLine(hexOf(stroke), attr(tag, "stroke-dasharray"), w.empty() ? (groups.empty() ? 1.0 : groups.back().width) : std::atof(w.c_str()), where, cx, cy);
          if (where > 0) {
            l.plot = plot;
            const std::string dd = attr(tag, "d");
            for (std::size_t q = 0; q < dd.size(); ++q) {
              if (dd[q] != 'M' && dd[q] != 'L') continue;
              double x, y;
              if (std::sscanf(dd.c_str() + q + 1, "%lf,%lf", &x, &y) == 2) l.pts.push_back({x, y});
            }
          }
          d.lines.push_back(l);
        }
      }
    } else if (tag.compare(0, 4, "<use") == 0) {
      SvgMarker m{attr(tag, "xlink:href"), hexOf(attr(tag, "color")), panel};
      double sc = 1;
      std::sscanf(attr(tag, "transform").c_str(), "translate(%lf,%lf) scale(%lf)", &m.x, &m.y, &sc);
      m.r = sc;
      m.plot = depthInPlot > 0 ? plot : 0;
      d.markers.push_back(m);
    }
    return end + 1;
  });
  // What no plot drew goes to the panel whose extent holds its centre, or the nearest one.
  auto place = [&](double x, double y) {
    int best = extent.empty() ? 1 : extent.begin()->first;
    double bestD = 1e300;
    for (const auto& [k, e] : extent) {
      const double dx = std::max({e[0] - x, 0.0, x - e[2]}), dy = std::max({e[1] - y, 0.0, y - e[3]});
      if (std::hypot(dx, dy) < bestD) bestD = std::hypot(dx, dy), best = k;
    }
    return best;
  };
  for (SvgLine& l : d.lines)
    if (l.panel < 0) l.panel = place(l.cx, l.cy);
  for (std::size_t k = 0; k < d.fills.size(); ++k)
    if (d.fills[k].second < 0) d.fills[k].second = place(d.fillCentres[k].first, d.fillCentres[k].second);
  for (SvgText& t : d.texts)
    if (t.plot == 0) t.panel = place(t.x, t.y);
  return d;
}

// ---- colour cues and caption promises --------------------------------------------------------

std::vector<double> dashLengths(const std::string& dash) {
  std::vector<double> out;
  std::istringstream in(dash);
  for (std::string w; std::getline(in, w, ',');) out.push_back(std::atof(w.c_str()));
  return out;
}

/// Whether a dash pattern is plain dashes (one dash, one gap), dash-dot (long, gap, dot, gap)
/// or dots (no dash longer than twice the line's width, or than 3 px). The dot of a dash-dot is
/// at most 3/4 of the line's width in the SVG: pngcairo draws a line thinner beside the same
/// dash lengths, and a dot as long as the SVG's width showed in the PNG as a short dash (issue
/// 42: Figure 2.4's dash-dotted circle read as dashed). Anything else with a dash is dashed.
std::string dashKind(const SvgLine& l) {
  const std::vector<double> v = dashLengths(l.dash);
  if (v.empty()) return "solid";
  double longest = 0, shortest = 1e300;
  for (std::size_t k = 0; k < v.size(); k += 2) longest = std::max(longest, v[k]), shortest = std::min(shortest, v[k]);
  if (longest <= std::max(3.0, 2 * l.width)) return "dotted";
  if (v.size() >= 4 && shortest < 0.6 * longest && shortest <= 0.75 * l.width) return "dashdot";
  return "dashed";
}

/// Why a meaning-pair's second cue is not in a figure ("" if it is).
std::string cueMissing(const MeaningPair& p, const std::map<std::string, std::string>& pal, const SvgDrawing& svg) {
  const std::string ca = pal.at(p.a), cb = pal.at(p.b);
  if (p.cue.rfind("dash:", 0) == 0) {
    const std::string dashedRole = p.cue.substr(5);
    if (dashedRole != p.a && dashedRole != p.b) return "the cue names " + dashedRole + ", which is not in the pair";
    const std::string dashed = pal.at(dashedRole), solid = dashedRole == p.a ? cb : ca;
    int nd = 0, ns = 0;
    for (const SvgLine& l : svg.lines) {
      if (l.colour == dashed) {
        if (l.dash.empty()) return "a line in " + dashedRole + "'s colour is solid";
        ++nd;
      } else if (l.colour == solid) {
        if (!l.dash.empty()) return "a line in the other colour " + solid + " is dashed too";
        ++ns;
      }
    }
    if (nd == 0) return "no line in " + dashedRole + "'s colour";
    return "";
  }
  if (p.cue == "marker") {
    std::set<std::string> sa, sb;
    for (const SvgMarker& m : svg.markers) {
      if (m.colour == ca) sa.insert(m.shape);
      if (m.colour == cb) sb.insert(m.shape);
    }
    if (sa.empty() || sb.empty()) return "no point markers in " + std::string(sa.empty() ? p.a : p.b) + "'s colour";
    for (const std::string& s : sa)
      if (sb.count(s)) return "both colours use the marker " + s;
    return "";
  }
  return "unknown cue " + p.cue;
}

/// Every breach of the colour rule: a pair closer than 20 for some reader without a cue, a cue
/// the figure does not draw.
std::vector<std::string> pairBreaches(const std::vector<MeaningPair>& pairs, const std::map<std::string, std::string>& pal,
                                      const std::map<std::string, SvgDrawing>& svgs) {
  std::vector<std::string> out;
  for (const MeaningPair& p : pairs) {
    if (!pal.count(p.a) || !pal.count(p.b)) {
      out.push_back(p.a + " / " + p.b + ": not a colour of style.gp");
      continue;
    }
    const auto [d, v] = leastDifference(pal.at(p.a), pal.at(p.b));
    if (d >= 20) continue;
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s / %s (%s): CIEDE2000 %.1f under %s", p.a.c_str(), p.b.c_str(), p.meaning.c_str(), d,
                  ch::visionName(v));
    if (p.cue == "-") {
      out.push_back(std::string(buf) + ", under 20, and no second cue");
      continue;
    }
    for (const std::string& f : p.figures) {
      const auto it = svgs.find(f);
      if (it == svgs.end()) {
        out.push_back(std::string(buf) + ": cue " + p.cue + " declared for " + f + ", which has no SVG");
        continue;
      }
      const std::string why = cueMissing(p, pal, it->second);
      if (!why.empty()) out.push_back(std::string(buf) + ": cue " + p.cue + " not in " + f + ".svg: " + why);
    }
  }
  return out;
}

/// One promise of figures/ch2/promises.txt.
struct Promise {
  std::string figure, kind, role;
  int panel = 0;
  std::string words;
};

std::vector<Promise> promises(const std::string& text) {
  std::vector<Promise> out;
  for (const std::string& line : dataLines(text)) {
    std::istringstream in(line);
    Promise p;
    in >> p.figure >> p.kind >> p.role;
    std::string rest;
    std::getline(in, rest);
    rest = trim(rest);
    if (rest.rfind("panel ", 0) == 0) {
      p.panel = std::atoi(rest.c_str() + 6);
      rest = trim(rest.substr(rest.find(' ', 6) == std::string::npos ? rest.size() : rest.find(' ', 6)));
    }
    p.words = rest;
    out.push_back(p);
  }
  return out;
}

/// Why a promise is not kept by the SVG ("" if it is).
std::string promiseBroken(const Promise& p, const std::map<std::string, std::string>& pal, const SvgDrawing& svg) {
  if (!pal.count(p.role)) return p.role + " is not a colour of style.gp";
  const std::string c = hexOf(pal.at(p.role));
  const std::string where = p.panel ? " in panel " + std::to_string(p.panel) : "";
  if (p.kind == "fill") {
    for (const auto& [colour, panel] : svg.fills)
      if (colour == c && (p.panel == 0 || panel == p.panel)) return "";
    return "no area filled with " + p.role + " (" + c + ")" + where;
  }
  if (p.kind != "dashed" && p.kind != "dashdot" && p.kind != "dotted" && p.kind != "solid") return "unknown promise " + p.kind;
  std::set<std::string> kinds;
  for (const SvgLine& l : svg.lines)
    if (l.colour == c && (p.panel == 0 || l.panel == p.panel)) {
      if (dashKind(l) == p.kind) return "";
      kinds.insert(dashKind(l));
    }
  std::string seen;
  for (const std::string& k : kinds) seen += (seen.empty() ? "" : ", ") + k;
  return "no " + p.kind + " line in " + p.role + " (" + c + ")" + where + (seen.empty() ? "; no line of that colour at all" : "; its lines are " + seen);
}

// ---- notation --------------------------------------------------------------------------------

struct NotationRow {
  std::string name, tex;
  std::regex rejected;
  std::string rejectedText;
};

std::vector<NotationRow> notation(const std::string& text) {
  std::vector<NotationRow> out;
  for (const std::string& line : dataLines(text)) {
    const std::size_t a = line.find(" | "), b = line.find(" | ", a + 3);
    if (a == std::string::npos || b == std::string::npos) throw std::runtime_error("notation.txt: not three columns: " + line);
    const std::string rej = trim(line.substr(b + 3));
    out.push_back({trim(line.substr(0, a)), trim(line.substr(a + 3, b - a - 3)), std::regex(rej), rej});
  }
  return out;
}

bool isSubOrSuper(const SvgSpan& prev, const SvgSpan& sp) { return sp.size < prev.size - 1e-9 && std::fabs(sp.dy - prev.dy) > 1e-9; }

/// A text's upright part: its spans outside the math font, each math span read as "•".
std::string uprightPart(const SvgText& t) {
  std::string s;
  for (const SvgSpan& sp : t.spans) s += sp.family == kMathFamily ? std::string("\u2022") : sp.text;
  return s;
}

/// Every breach of the notation in one SVG: a rejected form, or an upright ASCII letter with a
/// sub- or superscript.
std::vector<std::string> notationBreaches(const SvgDrawing& svg, const std::vector<NotationRow>& rows) {
  std::vector<std::string> out;
  for (const SvgText& t : svg.texts) {
    const std::string up = uprightPart(t);
    for (const NotationRow& r : rows)
      if (std::regex_search(up, r.rejected)) out.push_back("\"" + t.str + "\" writes " + r.name + " upright or in ASCII (/" + r.rejectedText + "/), not " + r.tex);
    for (std::size_t k = 1; k < t.spans.size(); ++k) {
      const SvgSpan &prev = t.spans[k - 1], &sp = t.spans[k];
      // A one-letter symbol: the span ends in a letter that follows no other letter ("DT" of
      // DT_n is the notes' upright name, set with its index).
      const std::size_t n = prev.text.size();
      const char last = n ? prev.text[n - 1] : ' ', before = n > 1 ? prev.text[n - 2] : ' ';
      if (prev.family != kMathFamily && std::isalpha(static_cast<unsigned char>(last)) &&
          !std::isalpha(static_cast<unsigned char>(before)) && isSubOrSuper(prev, sp))
        out.push_back("\"" + t.str + "\": the upright letter " + std::string(1, last) + " carries the index \"" + sp.text + "\"");
    }
  }
  return out;
}


// ---- charts ------------------------------------------------------------------------------------

/// The value of a tick label: a number ("0.01", "−2", "1000") or a power of ten set as "10" with
/// a superscript ("10^{3}"). False if it is neither.
bool tickValue(const SvgText& t, double& v) {
  auto number = [](std::string s, double& out) {
    for (std::size_t at = s.find("\u2212"); at != std::string::npos; at = s.find("\u2212")) s.replace(at, 3, "-");
    s = trim(s);
    if (s.empty()) return false;
    char* e = nullptr;
    out = std::strtod(s.c_str(), &e);
    return e && *e == 0;
  };
  if (t.spans.size() == 1) return number(t.spans[0].text, v);
  double e;
  if (t.spans.size() == 2 && trim(t.spans[0].text) == "10" && isSubOrSuper(t.spans[0], t.spans[1]) && number(t.spans[1].text, e)) {
    v = std::pow(10.0, e);
    return true;
  }
  return false;
}

/// A panel's y axis, read from its tick labels (right-aligned, upright, left of the plot): log if
/// their values are a geometric progression in pixels, linear if arithmetic. `found` is false
/// where the panel has fewer than three numeric tick labels (a geometric figure).
struct Axis {
  bool found = false, log = false;
  double a = 0, b = 0;  // value = a + b y (log: log10(value) = a + b y)
  double value(double y) const { return log ? std::pow(10.0, a + b * y) : a + b * y; }
};

Axis yAxis(const SvgDrawing& d, int panel) {
  std::vector<std::pair<double, double>> ticks;  // y, value
  for (const SvgText& t : d.texts) {
    double v;
    if (t.plot == 0 && t.panel == panel && t.anchor == "end" && std::fabs(t.rotate) < 1e-9 && tickValue(t, v)) ticks.push_back({t.y, v});
  }
  Axis ax;
  std::sort(ticks.begin(), ticks.end());
  if (ticks.size() == 2) {
    // Two labels a decade or more apart, both powers of ten (0.01 and 0.1): a log axis (a
    // linear one gnuplot labels at least three times).
    const double l0 = std::log10(ticks[0].second), l1 = std::log10(ticks[1].second);
    if (ticks[0].second > 0 && ticks[1].second > 0 && std::fabs(l0 - std::round(l0)) < 1e-9 && std::fabs(l1 - std::round(l1)) < 1e-9 &&
        std::fabs(l0 - l1) >= 1 - 1e-9) {
      ax.found = ax.log = true;
      ax.b = (l1 - l0) / (ticks[1].first - ticks[0].first);
      ax.a = l0 - ax.b * ticks[0].first;
    }
    return ax;
  }
  if (ticks.size() < 3) return ax;
  // How far the values are from a straight line in y (relative to their spread).
  auto misfit = [&](bool log, double& a, double& b) {
    const std::size_t n = ticks.size();
    double sy = 0, sv = 0, syy = 0, syv = 0;
    for (const auto& [y, v0] : ticks) {
      const double v = log ? std::log10(v0) : v0;
      sy += y, sv += v, syy += y * y, syv += y * v;
    }
    b = (n * syv - sy * sv) / (n * syy - sy * sy);
    a = (sv - b * sy) / n;
    double worst = 0, lo = 1e300, hi = -1e300;
    for (const auto& [y, v0] : ticks) {
      const double v = log ? std::log10(v0) : v0;
      worst = std::max(worst, std::fabs(a + b * y - v)), lo = std::min(lo, v), hi = std::max(hi, v);
    }
    return worst / std::max(hi - lo, 1e-300);
  };
  double la, lb, ga = 0, gb = 0;
  const double lin = misfit(false, la, lb);
  bool positive = true;
  for (const auto& t : ticks) positive = positive && t.second > 0;
  const double lg = positive ? misfit(true, ga, gb) : 1e300;
  ax.found = true;
  ax.log = lg < lin;
  ax.a = ax.log ? ga : la;
  ax.b = ax.log ? gb : lb;
  return ax;
}

/// Whether (x, y) is a key entry's sample: on the row of a key text of the same plot, within
/// 4.5 em of the text on the side of its sample (gnuplot puts the sample right of a
/// right-aligned text and left of a left-aligned one).
bool inKeyRow(const SvgDrawing& d, int panel, int plot, double x, double y) {
  for (const SvgText& t : d.texts) {
    if (!t.key || t.panel != panel || t.plot != plot) continue;
    const double em = t.spans[0].size;
    const double along = t.anchor == "end" ? x - t.x : t.x - x;
    if (std::fabs(y - (t.y - 0.3 * em)) < 0.7 * em && along > 0 && along < 4.5 * em) return true;
  }
  return false;
}

/// The y pixels of each series of a panel (a plot's markers, or else the tops of its bars, or
/// else its lines' points), without its key sample.
std::map<int, std::vector<double>> seriesYs(const SvgDrawing& d, int panel) {
  std::map<int, std::vector<double>> ys;
  for (const SvgMarker& m : d.markers)
    if (m.plot > 0 && m.panel == panel && !inKeyRow(d, panel, m.plot, m.x, m.y)) ys[m.plot].push_back(m.y);
  std::map<int, std::vector<double>> lines, bars;
  for (const SvgLine& l : d.lines)
    if (l.plot > 0 && l.panel == panel && l.dash.empty())
      for (const auto& [x, y] : l.pts)
        if (!inKeyRow(d, panel, l.plot, x, y)) lines[l.plot].push_back(y);
  for (const SvgArea& a : d.areas)
    if (a.panel == panel && !inKeyRow(d, panel, a.plot, 0.5 * (a.x0 + a.x1), a.y0)) bars[a.plot].push_back(a.y0);
  for (auto& [plot, v] : bars)  // a bar's outline holds its base: its top is the value
    if (!ys.count(plot)) ys[plot] = v;
  for (auto& [plot, v] : lines)
    if (!ys.count(plot)) ys[plot] = v;
  return ys;
}

/// Every series that spans more than a decade on a linear y axis.
std::vector<std::string> linearDecades(const SvgDrawing& d) {
  std::vector<std::string> out;
  int panels = 0;
  for (const SvgText& t : d.texts) panels = std::max(panels, t.panel);
  for (const SvgMarker& m : d.markers) panels = std::max(panels, m.panel);
  for (int p = 1; p <= panels; ++p) {
    const Axis ax = yAxis(d, p);
    if (!ax.found || ax.log) continue;
    for (const auto& [plot, ys] : seriesYs(d, p)) {
      double lo = 1e300, hi = 0;
      for (double y : ys) {
        const double v = ax.value(y);
        if (v > 0) lo = std::min(lo, v), hi = std::max(hi, v);
      }
      if (hi > 10 * lo) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "panel %d, plot %d spans %.3g to %.3g (%.1f decades) on a linear y axis", p, plot, lo, hi,
                      std::log10(hi / lo));
        out.push_back(buf);
      }
    }
  }
  return out;
}

/// Every data point under a key: the key's box (its entries' texts and the samples drawn on
/// their rows) holds the centre of a marker of a series.
std::vector<std::string> keyCovers(const SvgDrawing& d) {
  std::vector<std::string> out;
  std::map<int, std::array<double, 4>> box;  // per panel
  auto grow = [&](int panel, const std::array<double, 4>& e) {
    auto it = box.find(panel);
    if (it == box.end()) box[panel] = e;
    else it->second = {std::min(it->second[0], e[0]), std::min(it->second[1], e[1]), std::max(it->second[2], e[2]), std::max(it->second[3], e[3])};
  };
  for (const SvgText& t : d.texts) {
    if (!t.key) continue;
    const double em = t.spans[0].size;
    double w = 0;  // the text's width: half an em a character (DejaVu Sans's mean advance)
    for (const SvgSpan& sp : t.spans)
      for (unsigned char c : sp.text) w += (c & 0xC0) != 0x80 ? 0.5 * sp.size : 0;
    const double x0 = t.anchor == "end" ? t.x - w : t.anchor == "middle" ? t.x - w / 2 : t.x;
    grow(t.panel, {x0, t.y - 1.0 * em, x0 + w, t.y + 0.3 * em});
  }
  for (const SvgMarker& m : d.markers)
    if (m.plot > 0 && box.count(m.panel) && inKeyRow(d, m.panel, m.plot, m.x, m.y)) grow(m.panel, {m.x - m.r, m.y - m.r, m.x + m.r, m.y + m.r});
  for (const SvgLine& l : d.lines)
    if (l.plot > 0 && box.count(l.panel))
      for (const auto& [x, y] : l.pts)
        if (inKeyRow(d, l.panel, l.plot, x, y)) grow(l.panel, {x, y, x, y});
  for (const auto& [panel, b] : box) {
    for (const SvgMarker& m : d.markers)
      if (m.plot > 0 && m.panel == panel && !inKeyRow(d, panel, m.plot, m.x, m.y) && m.x > b[0] && m.x < b[2] && m.y > b[1] && m.y < b[3]) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "panel %d: the key (%.0f..%.0f, %.0f..%.0f) covers a point of plot %d at (%.0f, %.0f)", panel, b[0], b[2], b[1], b[3], m.plot, m.x, m.y);
        out.push_back(buf);
      }
  }
  return out;
}

// The image line of a figure in book/*.md ("" if no page embeds it).
std::string captionOf(const std::string& figure) {
  for (const auto& e : fs::directory_iterator(fs::path(DT_SOURCE_DIR) / "book")) {
    if (e.path().extension() != ".md") continue;
    std::istringstream in(slurp(e.path()));
    for (std::string line; std::getline(in, line);)
      if (line.find("\\image html " + figure + ".") != std::string::npos) return line;
  }
  return "";
}

/// Why a timing chart's caption does not state its k ("" if it does): it must say "median of"
/// and cite the key.
std::string timingCaptionMissing(const std::string& caption, const std::string& key) {
  if (caption.empty()) return "no page embeds it";
  if (caption.find("median of") == std::string::npos) return "its caption does not say the times are medians (\"median of\")";
  if (caption.find("@{" + key + "}") == std::string::npos && caption.find("@{" + key + "|") == std::string::npos)
    return "its caption does not cite k as @{" + key + "}";
  return "";
}

// ---- one run of the chapter programs ---------------------------------------------------------

// The chapter programs' run that the figure tests share (tests/figure_run.h); a program that
// failed fails the test that reads the run.
fs::path figureDir() {
  const dttest::FigureRun& run = dttest::figureRun();
  for (const std::string& f : run.failures) FAIL(f << " failed");
  return run.dir;
}

const std::map<std::string, SvgDrawing>& runSvgs() {
  static const std::map<std::string, SvgDrawing> all = [] {
    std::map<std::string, SvgDrawing> m;
    for (const auto& e : fs::directory_iterator(figureDir()))
      if (e.path().extension() == ".svg") m[e.path().stem().string()] = readSvg(slurp(e.path()));
    return m;
  }();
  return all;
}

std::string styleText() { return slurp(kFigDir / "style.gp"); }

}  // namespace

// ---- the colour science ----------------------------------------------------------------------

TEST_CASE("figures rules CIEDE2000 gives the published differences of Sharma Wu and Dalal's test pairs") {
  // Pairs of the test data of Sharma, Wu and Dalal (2005), with their published differences.
  struct Pair {
    ch::Lab x, y;
    double de;
  };
  const Pair pairs[] = {{{50, 2.6772, -79.7751}, {50, 0, -82.7485}, 2.0425},
                        {{50, 3.1571, -77.2803}, {50, 0, -82.7485}, 2.8615},
                        {{50, 0, 0}, {50, -1, 2}, 2.3669},
                        {{50, 2.5, 0}, {73, 25, -18}, 27.1492},
                        {{50, 2.5, 0}, {61, -5, 29}, 22.8977},
                        {{50, 2.5, 0}, {56, -27, -3}, 31.9030},
                        {{50, 2.5, 0}, {58, 24, 15}, 19.4535},
                        {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644}};
  for (const Pair& p : pairs) {
    CHECK(std::fabs(ch::deltaE2000(p.x, p.y) - p.de) < 1e-4);
    CHECK(std::fabs(ch::deltaE2000(p.y, p.x) - p.de) < 1e-4);  // symmetric
  }
  CHECK(ch::deltaE2000({50, 10, 10}, {50, 10, 10}) == 0);
  // sRGB to Lab: white is L* 100, a mid grey 53.39, black 0.
  CHECK(ch::toLab(ch::parseHex("#ffffff")).L == doctest::Approx(100).epsilon(1e-4));
  CHECK(ch::toLab(ch::parseHex("#808080")).L == doctest::Approx(53.585).epsilon(1e-3));
  CHECK(std::fabs(ch::toLab(ch::parseHex("#808080")).a) < 1e-3);
  CHECK_THROWS(ch::parseHex("#12345"));
  CHECK_THROWS(ch::parseHex("red"));
}

TEST_CASE("figures rules the dichromacy simulation keeps greys and merges the notes' red and green") {
  for (const char* grey : {"#000000", "#3c3c3c", "#808080", "#ffffff"})
    for (ch::Vision v : kVisions) CHECK(ch::toHex(ch::simulate(ch::parseHex(grey), v)) == grey);
  // The notes' sign colours (green -1, red +1): apart for a normal eye, not for a red-green
  // colour-blind one; blue against them stays apart for everyone.
  const std::string green = "#1a9641", red = "#d7191c", blue = "#2166ac";
  CHECK(ch::seenDifference(ch::parseHex(green), ch::parseHex(red), ch::Vision::Normal) > 60);
  CHECK(ch::seenDifference(ch::parseHex(green), ch::parseHex(red), ch::Vision::Deuteranopia) < 12);
  CHECK(leastDifference(blue, red).first > 20);
  // Tritanopia confuses blue with green, not red with green.
  CHECK(ch::seenDifference(ch::parseHex(green), ch::parseHex(red), ch::Vision::Tritanopia) > 40);
  CHECK(ch::seenDifference(ch::parseHex("#2b63a8"), ch::parseHex("#2e7d32"), ch::Vision::Tritanopia) < 12);
}

// ---- colour: the rules and their planted defects --------------------------------------------

TEST_CASE("figures rules the colour checks find a shared colour a written colour and a red-green pair") {
  std::map<std::string, std::string> pal = {{"C_A", "#1a9641"}, {"C_B", "#d7191c"}, {"C_C", "#1A9641"}, {"black", "#000000"}};
  CHECK(sharedColours(pal).size() == 1);  // C_A and C_C
  pal.erase("C_C");
  CHECK(sharedColours(pal).empty());
  CHECK(scriptColourLiterals("plot x lc rgb C_A\nset object 1 fc rgb \"white\" # #123456 in a comment\n").empty());
  CHECK(scriptColourLiterals("plot x lc rgb \"#1a9641\"\n").size() == 1);
  CHECK(scriptColourLiterals("plot x using 1:2:($3 ? 0xf6d55c : 0xffffff) lc rgb variable\n").size() == 1);
  CHECK(scriptColourLiterals("plot x lc rgb 'red'\n").size() == 1);
  // The notes' red and green as one meaning-pair: no cue, so a breach.
  std::vector<MeaningPair> pairs = {{"C_A", "C_B", {"fig"}, "-", "sign -1 against +1"}};
  CHECK(pairBreaches(pairs, pal, {}).size() == 1);
  // A declared dash cue that the figure does not draw is a breach; drawn, it passes.
  pairs[0].cue = "dash:C_A";
  SvgDrawing svg;
  svg.lines.push_back(makeLine("#1a9641", "", 2, 1));
  svg.lines.push_back(makeLine("#d7191c", "", 2, 1));
  CHECK(pairBreaches(pairs, pal, {{"fig", svg}}).size() == 1);
  svg.lines[0].dash = "6,4";
  CHECK(pairBreaches(pairs, pal, {{"fig", svg}}).empty());
  // A marker cue: the same shape in both colours is a breach.
  pairs[0].cue = "marker";
  svg.markers = {{"#gpPt7", "#1a9641", 1}, {"#gpPt7", "#d7191c", 1}};
  CHECK(pairBreaches(pairs, pal, {{"fig", svg}}).size() == 1);
  svg.markers[1].shape = "#gpPt5";
  CHECK(pairBreaches(pairs, pal, {{"fig", svg}}).empty());
  // Blue and red need no cue.
  pal["C_A"] = "#2166ac";
  pairs[0].cue = "-";
  CHECK(pairBreaches(pairs, pal, {}).empty());
}

TEST_CASE("figures rules every colour of every figure is a role of style.gp and no two roles share one") {
  const auto pal = palette(styleText());
  REQUIRE(pal.count("C_CAVITY") == 1);
  for (const std::string& s : sharedColours(pal)) FAIL_CHECK("style.gp: " << s);
  for (const auto& e : fs::directory_iterator(kFigDir)) {
    if (e.path().extension() != ".gp" || e.path().filename() == "style.gp") continue;
    for (const std::string& s : scriptColourLiterals(slurp(e.path())))
      FAIL_CHECK(e.path().filename().string() << " " << s << ": a colour written out, not a role of style.gp");
  }
  // The chapter programs write some objects (fills, segments) with their colours: each must be
  // the colour of a role.
  std::set<std::string> values;
  for (const auto& [name, hex] : pal) values.insert(hexOf(hex));
  const std::regex hex("\"(#[0-9a-fA-F]{6})\"");
  for (const auto& e : fs::directory_iterator(fs::path(DT_SOURCE_DIR) / "chapters" / "ch2")) {
    const std::string text = slurp(e.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), hex); it != std::sregex_iterator(); ++it)
      CHECK_MESSAGE(values.count(hexOf((*it)[1])) == 1,
                    e.path().filename().string() << " draws in " << (*it)[1] << ", the colour of no role of style.gp");
  }
}

TEST_CASE("figures rules every meaning pair stays 20 apart for every reader or has a second cue the SVG draws") {
  const auto pal = palette(styleText());
  const auto pairs = meaningPairs(slurp(kFigDir / "meaning_pairs.txt"));
  REQUIRE(pairs.size() >= 10);
  // The sign maps carry no second cue: their colours alone must do.
  for (const MeaningPair& p : pairs)
    if (p.a == "C_MINUS" || p.b == "C_PLUS") CHECK(p.cue == "-");
  for (const std::string& b : pairBreaches(pairs, pal, runSvgs())) FAIL_CHECK(b);
}

TEST_CASE("figures rules the deuteranopia figure is Figure 2.7 in the sign colours a deuteranope sees") {
  const auto pal = palette(styleText());
  const std::string gp = slurp(figureDir() / "sign_colours_deuteranopia.gp");
  for (const char* role : {"C_MINUS", "C_ZERO", "C_PLUS"}) {
    const std::string seen = ch::toHex(ch::simulate(ch::parseHex(pal.at(role)), ch::Vision::Deuteranopia));
    CHECK_MESSAGE(gp.find(std::string("D") + (role + 1) + " = \"" + seen + "\"") != std::string::npos, role << " seen as " << seen << "; " << gp);
  }
  CHECK(fs::file_size(figureDir() / "fig2_7_deuteranopia.png") > 10000);
}

// ---- notation ----------------------------------------------------------------------------------

TEST_CASE("figures rules the notation check rejects ASCII and upright forms and passes the notes' forms") {
  const auto rows = notation(slurp(kFigDir / "notation.txt"));
  REQUIRE(rows.size() >= 10);
  auto text = [](std::vector<SvgSpan> spans) {
    SvgText t;
    t.spans = spans;
    for (const SvgSpan& s : spans) t.str += s.text;
    SvgDrawing d;
    d.texts.push_back(t);
    return d;
  };
  const SvgSpan sans{"Sans", "", 20, 0};
  auto S = [&](const std::string& s, double size = 20, double dy = 0) { return SvgSpan{"Sans", s, size, dy}; };
  auto Mth = [&](const std::string& s, double size = 20, double dy = 0) { return SvgSpan{kMathFamily, s, size, dy}; };
  CHECK(notationBreaches(text({S("(a) naive O(a,b,c)")}), rows).size() == 1);
  CHECK(notationBreaches(text({S("(a) naive InC(a,b,c,d)")}), rows).size() == 1);
  CHECK(notationBreaches(text({S("N"), S("search", 16, 4)}), rows).size() == 2);  // the row and the index rule
  CHECK(notationBreaches(text({S("DT(S) with ghost faces")}), rows).size() == 1);
  CHECK(notationBreaches(text({S("points n (uniform random)")}), rows).size() == 1);
  CHECK(notationBreaches(text({S("slope 1/2 ("), Mth("𝑁"), S(" ∝ n"), S("1/2", 16, -6), S(")")}), rows).size() == 1);
  // The notes' forms pass: math-font spans, and upright words.
  CHECK(notationBreaches(text({S("(a) naive "), Mth("𝒪(𝑎,𝑏,𝑐)")}), rows).empty());
  CHECK(notationBreaches(text({Mth("𝑁"), Mth("search", 16, 4)}), rows).empty());
  CHECK(notationBreaches(text({S("DT("), Mth("𝑆"), S(") with ghost faces")}), rows).empty());
  CHECK(notationBreaches(text({S("10"), S("3", 16, -6)}), rows).empty());  // a tick label
  CHECK(notationBreaches(text({S("(a) DT"), Mth("𝑛", 16, 4)}), rows).empty());  // the notes' DT_n
  CHECK(notationBreaches(text({S("(b) the ball and its adjacencies")}), rows).empty());
  (void)sans;
}

TEST_CASE("figures rules every notation row is a form the math text writer sets") {
  // Each row's notes form is what ch::mathText sets in the math font (it throws on what it
  // cannot), so a script or program that takes the row's form gets the notes' letters, and
  // none of them is left in ASCII.
  for (const NotationRow& r : notation(slurp(kFigDir / "notation.txt"))) {
    std::string m;
    CHECK_NOTHROW(m = ch::mathText(r.tex));
    CHECK_MESSAGE(m.rfind("{/'DejaVu Math TeX Gyre' ", 0) == 0, r.name);
    const bool ascii = std::regex_search(m.substr(25), std::regex("[a-zA-Z]{3,}")) && r.tex.find("mathrm") == std::string::npos;
    CHECK_MESSAGE(!ascii, r.name << ": " << m);
  }
}

TEST_CASE("figures rules no figure writes a symbol of the notes upright or in ASCII") {
  const auto rows = notation(slurp(kFigDir / "notation.txt"));
  REQUIRE(runSvgs().size() >= 20);
  for (const auto& [name, svg] : runSvgs())
    for (const std::string& b : notationBreaches(svg, rows)) FAIL_CHECK(name << ".svg: " << b);
}

// ---- caption truth -----------------------------------------------------------------------------

TEST_CASE("figures rules the promise check finds a dash-dot drawn as dashes and a missing fill") {
  const auto pal = palette(styleText());
  SvgDrawing svg;
  svg.lines.push_back(makeLine(hexOf(pal.at("C_CIRCLE")), "11.9,19.0", 4.8, 1));
  svg.fills.push_back({hexOf(pal.at("C_BALL")), 1});
  CHECK(promiseBroken({"f", "dashed", "C_CIRCLE", 0, ""}, pal, svg).empty());
  CHECK(!promiseBroken({"f", "dashdot", "C_CIRCLE", 0, ""}, pal, svg).empty());
  svg.lines.push_back(makeLine(hexOf(pal.at("C_CIRCLE")), "23.8,9.5,4.8,9.5", 4.8, 1));
  CHECK(!promiseBroken({"f", "dashdot", "C_CIRCLE", 0, ""}, pal, svg).empty());  // its dot as long as the line is wide
  svg.lines.push_back(makeLine(hexOf(pal.at("C_CIRCLE")), "23.8,11.9,2.4,11.9", 4.8, 1));
  CHECK(promiseBroken({"f", "dashdot", "C_CIRCLE", 0, ""}, pal, svg).empty());
  CHECK(!promiseBroken({"f", "dashdot", "C_CIRCLE", 2, ""}, pal, svg).empty());  // not in panel 2
  CHECK(promiseBroken({"f", "fill", "C_BALL", 0, ""}, pal, svg).empty());
  CHECK(!promiseBroken({"f", "fill", "C_CAVITY", 0, ""}, pal, svg).empty());
  CHECK(!promiseBroken({"f", "solid", "C_CIRCLE", 0, ""}, pal, svg).empty());
  svg.lines.push_back(makeLine(hexOf(pal.at("C_CONSTRUCT")), "2,6", 1.5, 1));
  CHECK(promiseBroken({"f", "dotted", "C_CONSTRUCT", 0, ""}, pal, svg).empty());
  CHECK(!promiseBroken({"f", "dashed", "C_CONSTRUCT", 0, ""}, pal, svg).empty());
  const auto parsed = promises("fig_x dashed C_CIRCLE panel 3 the circle (dashed)\n# a comment\nfig_y fill C_BALL green\n");
  REQUIRE(parsed.size() == 2);
  CHECK(parsed[0].panel == 3);
  CHECK(parsed[0].words == "the circle (dashed)");
  CHECK(parsed[1].panel == 0);
}

TEST_CASE("figures rules every caption promise of figures/ch2/promises.txt is drawn in its SVG") {
  const auto pal = palette(styleText());
  const auto all = promises(slurp(kFigDir / "promises.txt"));
  REQUIRE(all.size() >= 20);
  for (const Promise& p : all) {
    const auto it = runSvgs().find(p.figure);
    if (it == runSvgs().end()) {
      FAIL_CHECK(p.figure << ": no SVG in the run, but promises.txt lists it");
      continue;
    }
    const std::string why = promiseBroken(p, pal, it->second);
    CHECK_MESSAGE(why.empty(), p.figure << ".svg, caption \"" << p.words << "\": " << why);
  }
}

// ---- charts --------------------------------------------------------------------------------------

namespace {

/// A chart of one panel: tick labels 0, 50, 100 (or 10^0, 10^1, 10^2) at y = 300, 200, 100
/// (linear: 2 px per unit), a series of markers at the values `vals`, and a key entry "series"
/// at (kx, ky).
SvgDrawing tinyChart(bool log, const std::vector<double>& vals, double kx, double ky) {
  SvgDrawing d;
  const double ys[3] = {300, 200, 100};
  for (int k = 0; k < 3; ++k) {
    SvgText t;
    t.x = 50, t.y = ys[k], t.anchor = "end", t.panel = 1;
    if (log) t.spans = {{"Sans", "10", 20, 0}, {"Sans", std::to_string(k), 16, -8}};
    else t.spans = {{"Sans", std::to_string(50 * k), 20, 0}};
    for (const SvgSpan& sp : t.spans) t.str += sp.text;
    d.texts.push_back(t);
  }
  SvgText key;
  key.spans = {{"Sans", "series", 20, 0}};
  key.str = "series", key.x = kx, key.y = ky, key.anchor = "end", key.panel = 1, key.plot = 1, key.key = true;
  d.texts.push_back(key);
  for (std::size_t i = 0; i < vals.size(); ++i) {
    const double y = log ? 300 - 100 * std::log10(vals[i]) : 300 - 2 * vals[i];
    d.markers.push_back({"#gpPt7", "#1f77b4", 1, 100 + 30.0 * double(i), y, 4, 1});
  }
  d.markers.push_back({"#gpPt7", "#1f77b4", 1, kx + 50, ky - 6, 4, 1});  // the key's sample
  return d;
}

}  // namespace

TEST_CASE("figures rules the chart checks find a decade on a linear axis and a key over a point") {
  // 2 to 90 on a linear axis: over a decade.
  CHECK(linearDecades(tinyChart(false, {2, 10, 90}, 400, 320)).size() == 1);
  CHECK(linearDecades(tinyChart(false, {20, 50, 90}, 400, 320)).empty());
  // The same values on a log axis: fine.
  CHECK(linearDecades(tinyChart(true, {2, 10, 90}, 400, 320)).empty());
  const Axis ax = yAxis(tinyChart(true, {1}, 400, 320), 1);
  CHECK(ax.found);
  CHECK(ax.log);
  CHECK(ax.value(150) == doctest::Approx(std::pow(10.0, 1.5)));
  SvgDrawing two = tinyChart(true, {1}, 400, 320);
  two.texts.erase(two.texts.begin() + 1);  // labels 10^0 and 10^2 only: still a log axis
  CHECK(yAxis(two, 1).log);
  two.texts[0].spans = {{"Sans", "0", 20, 0}};  // 0 and 100: no axis can be read
  two.texts[1].spans = {{"Sans", "100", 20, 0}};
  CHECK(!yAxis(two, 1).found);
  // A key placed on the third point (x 160, y 120) covers it; away from the data it does not.
  CHECK(keyCovers(tinyChart(false, {20, 50, 90}, 200, 126)).size() == 1);
  CHECK(keyCovers(tinyChart(false, {20, 50, 90}, 400, 320)).empty());
  // A timing caption must say "median of" and cite k.
  CHECK(timingCaptionMissing("\\image html f.png \"Times, the median of @{x.runs} runs.\"", "x.runs").empty());
  CHECK(!timingCaptionMissing("\\image html f.png \"Times, the best of @{x.runs} runs.\"", "x.runs").empty());
  CHECK(!timingCaptionMissing("\\image html f.png \"Times, the median of 3 runs.\"", "x.runs").empty());
}

TEST_CASE("figures rules no series of a chart spans more than a decade on a linear axis") {
  REQUIRE(runSvgs().size() >= 20);
  std::map<std::string, std::string> kind;  // figure -> chart or coordinates
  for (const std::string& line : dataLines(slurp(kFigDir / "charts.txt"))) {
    std::istringstream in(line);
    std::string k, f;
    in >> k >> f;
    REQUIRE_MESSAGE((k == "chart" || k == "coordinates"), "charts.txt: " << line);
    kind[f] = k;
  }
  int charts = 0;
  for (const auto& [name, svg] : runSvgs()) {
    const bool axes = yAxis(svg, 1).found;
    CHECK_MESSAGE((!axes || kind.count(name) == 1), name << ".svg has numeric axes but is not in figures/ch2/charts.txt");
    if (kind.count(name) && kind[name] == "chart") {
      ++charts;
      CHECK_MESSAGE(axes, name << ".svg: the check finds no numeric y axis in its first panel");
      for (const std::string& b : linearDecades(svg)) FAIL_CHECK(name << ".svg: " << b);
    }
  }
  CHECK(charts >= 6);
}

TEST_CASE("figures rules no key of a chart covers a data point") {
  int keys = 0;
  for (const auto& [name, svg] : runSvgs()) {
    keys += std::any_of(svg.texts.begin(), svg.texts.end(), [](const SvgText& t) { return t.key; });
    for (const std::string& b : keyCovers(svg)) FAIL_CHECK(name << ".svg: " << b);
  }
  CHECK(keys >= 5);  // the check finds the keys at all
}

TEST_CASE("figures rules every timing chart shows medians and its caption cites their number of runs") {
  std::map<std::string, std::string> values;  // every value the run's programs wrote
  for (const auto& e : fs::directory_iterator(figureDir()))
    if (e.path().filename().string().rfind("values_", 0) == 0) {
      std::istringstream in(slurp(e.path()));
      for (std::string line; std::getline(in, line);)
        if (line.find(' ') != std::string::npos) values[line.substr(0, line.find(' '))] = line.substr(line.find(' ') + 1);
    }
  const auto rows = dataLines(slurp(kFigDir / "timings.txt"));
  REQUIRE(rows.size() >= 4);
  for (const std::string& row : rows) {
    std::istringstream in(row);
    std::string figure, key;
    in >> figure >> key;
    const std::string why = timingCaptionMissing(captionOf(figure), key);
    CHECK_MESSAGE(why.empty(), figure << ": " << why);
    CHECK_MESSAGE(values.count(key) == 1, figure << ": no program of the run wrote the value " << key);
    if (values.count(key)) CHECK_MESSAGE(std::atoi(values[key].c_str()) >= 1, key << " = " << values[key]);
  }
}

TEST_CASE("figures rules Table 2.1's chart has the notes' four values and the sqrt n line over their sizes") {
  // The notes' Table 2.1 (N_search at n = 10^3..10^6), whatever sizes the run measured.
  const std::vector<std::string> notes = dataLines(slurp(figureDir() / "table2_1_notes.dat"));
  REQUIRE(notes.size() == 4);
  const double want[4][2] = {{1e3, 19.8}, {1e4, 56.8}, {1e5, 161}, {1e6, 503}};
  for (int i = 0; i < 4; ++i) {
    double n = 0, v = 0;
    REQUIRE(std::sscanf(notes[std::size_t(i)].c_str(), "%lf %lf", &n, &v) == 2);
    CHECK(n == want[i][0]);
    CHECK(v == doctest::Approx(want[i][1]));
  }
  // The reference line: a segment from 10^3 to 10^6 (drawn with one measured n too), rising as sqrt(n).
  const std::vector<std::string> line = dataLines(slurp(figureDir() / "table2_1_sqrt.dat"));
  REQUIRE(line.size() == 2);
  double n0 = 0, v0 = 0, n1 = 0, v1 = 0;
  REQUIRE(std::sscanf(line[0].c_str(), "%lf %lf", &n0, &v0) == 2);
  REQUIRE(std::sscanf(line[1].c_str(), "%lf %lf", &n1, &v1) == 2);
  CHECK(n0 == 1e3);
  CHECK(n1 == 1e6);
  CHECK(v1 / v0 == doctest::Approx(std::sqrt(1e3)));
}

namespace {

/// What fig_brio_compare's panels (a)-(c) break: an input (a colour) whose markers are not of
/// two shapes (Hilbert hollow, BRIO filled: the orders told apart without lines), and two
/// markers of a panel whose centres are within a marker radius (one hides the other).
std::vector<std::string> orderCueBreaches(const SvgDrawing& d) {
  std::vector<std::string> out;
  for (int panel = 1; panel <= 3; ++panel) {
    std::map<std::string, std::set<std::string>> shapes;  // colour -> marker shapes
    std::vector<const SvgMarker*> ms;
    for (const SvgMarker& m : d.markers)
      if (m.panel == panel && m.plot > 0) shapes[m.colour].insert(m.shape), ms.push_back(&m);
    for (const auto& [colour, s] : shapes)
      if (s.size() != 2) out.push_back("panel " + std::to_string(panel) + ": colour " + colour + " has " + std::to_string(s.size()) + " marker shape(s), not 2");
    for (std::size_t i = 0; i < ms.size(); ++i)
      for (std::size_t j = i + 1; j < ms.size(); ++j)
        if (std::hypot(ms[i]->x - ms[j]->x, ms[i]->y - ms[j]->y) < std::max(ms[i]->r, 1.0))
          out.push_back("panel " + std::to_string(panel) + ": two markers at (" + std::to_string(int(ms[i]->x)) + ", " + std::to_string(int(ms[i]->y)) + ")");
  }
  return out;
}

}  // namespace

TEST_CASE("figures rules fig_brio_compare tells Hilbert from BRIO by marker fill and hides no marker") {
  // The check fails on a planted figure: one colour with one shape, two markers on one spot.
  SvgDrawing planted;
  planted.markers = {{"#gpPt6", "#1f77b4", 1, 100, 100, 4, 1}, {"#gpPt6", "#1f77b4", 1, 100, 101, 4, 2}};
  CHECK(orderCueBreaches(planted).size() == 2);
  planted.markers[1] = {"#gpPt7", "#1f77b4", 1, 120, 100, 4, 2};
  CHECK(orderCueBreaches(planted).empty());
  const auto it = runSvgs().find("fig_brio_compare");
  REQUIRE(it != runSvgs().end());
  for (const std::string& b : orderCueBreaches(it->second)) FAIL_CHECK("fig_brio_compare.svg: " << b);
}
