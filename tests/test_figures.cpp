/// \file test_figures.cpp Tests of the figures themselves (the figure style, book/figure_style.md):
/// every figure the book embeds is written by a run of the chapter programs, every SVG is
/// well-formed XML in UTF-8, every PNG (and the GIF) has the size figures/ch2/style.gp gives, no
/// label touches anything, each series draws what its data file holds, no panel has a wide
/// blank band, and each PNG shows what its SVG shows.
//
// The suite runs the chapter programs that draw the book's figures once, into a fresh
// directory (--quick --max-n 2000, bench_parallel --max-n 100000: the figures are the full
// ones, the tables small; about 10 s of CPU), so it depends on no earlier run. bench_parallel
// reads a planted cache description (--cache-dir), so that its chart draws all three cache
// markers and their labels go through the same checks. The checkers are tested on bad input too.
#include <doctest/doctest.h>

#include "figure_run.h"
#include "svg_attr.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <map>
#include <stdexcept>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../chapters/cache_sizes.h"
#include "../chapters/process.h"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = DT_SOURCE_DIR;

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---- the names the book embeds -----------------------------------------------------------

/// Every `\image html NAME` of book/*.md, exactly as written.
std::set<std::string> embeddedFigures() {
  std::set<std::string> names;
  const std::regex image(R"(\\image\s+html\s+"?([^\s"]+))");
  for (const auto& e : fs::directory_iterator(kRoot / "book")) {
    if (e.path().extension() != ".md") continue;
    const std::string text = readAll(e.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), image); it != std::sregex_iterator(); ++it)
      names.insert((*it)[1]);
  }
  return names;
}

// ---- UTF-8 and XML well-formedness -------------------------------------------------------

/// Empty if `s` is valid UTF-8 (no overlong forms, no surrogates, at most U+10FFFF), else
/// the offset and byte of the first error.
std::string utf8Error(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    int len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (len == 0 || i + std::size_t(len) > s.size())
      return "byte " + std::to_string(i) + " (0x" + std::to_string(c) + " decimal) starts no UTF-8 character";
    std::uint32_t cp = len == 1 ? c : c & (0x7F >> len);
    for (int k = 1; k < len; ++k) {
      const unsigned char d = static_cast<unsigned char>(s[i + std::size_t(k)]);
      if ((d >> 6) != 0x2) return "byte " + std::to_string(i + std::size_t(k)) + " is not a continuation byte";
      cp = (cp << 6) | (d & 0x3F);
    }
    const std::uint32_t least[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < least[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
      return "byte " + std::to_string(i) + ": overlong form, surrogate or out of range";
    i += std::size_t(len);
  }
  return "";
}

/// Empty if `s` is a well-formed XML document (one root element, tags nested and matched,
/// attributes quoted and not repeated, references well formed, no '<' or bare '&' in text),
/// else a description of the first error. Enough for what gnuplot writes: it does not read
/// DTDs or check names against the full XML name grammar.
std::string xmlError(const std::string& s) {
  std::size_t i = 0;
  std::vector<std::string> open;
  int roots = 0;
  auto at = [&](std::size_t k) { return " at byte " + std::to_string(k); };
  auto isName = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' || c == '.' ||
           static_cast<unsigned char>(c) >= 0x80;
  };
  auto checkRefs = [&](std::size_t from, std::size_t to) -> std::string {
    for (std::size_t k = from; k < to; ++k) {
      if (s[k] == '<') return "'<' in text or attribute" + at(k);
      if (s[k] != '&') continue;
      const std::size_t semi = s.find(';', k);
      if (semi == std::string::npos || semi > to) return "unterminated reference" + at(k);
      const std::string ref = s.substr(k + 1, semi - k - 1);
      static const std::regex ok(R"(#[0-9]+|#x[0-9a-fA-F]+|[A-Za-z_][A-Za-z0-9._-]*)");
      if (!std::regex_match(ref, ok)) return "bad reference &" + ref + ";" + at(k);
      k = semi;
    }
    return "";
  };
  while (i < s.size()) {
    if (s[i] != '<') {
      const std::size_t next = std::min(s.find('<', i), s.size());
      if (open.empty() && s.find_first_not_of(" \t\r\n", i) < next) return "text outside the root element" + at(i);
      if (std::string e = checkRefs(i, next); !e.empty()) return e;
      i = next;
      continue;
    }
    auto skipTo = [&](const char* end, const char* what) -> std::string {
      const std::size_t e = s.find(end, i);
      if (e == std::string::npos) return std::string("unterminated ") + what + at(i);
      i = e + std::strlen(end);
      return "";
    };
    std::string err;
    if (s.compare(i, 4, "<!--") == 0) err = skipTo("-->", "comment");
    else if (s.compare(i, 9, "<![CDATA[") == 0) {
      if (open.empty()) return "CDATA outside the root element" + at(i);
      err = skipTo("]]>", "CDATA section");
    } else if (s.compare(i, 2, "<?") == 0) err = skipTo("?>", "processing instruction");
    else if (s.compare(i, 9, "<!DOCTYPE") == 0) {
      // Skip an internal subset in brackets, if any.
      const std::size_t br = s.find('[', i), gt = s.find('>', i);
      if (br != std::string::npos && br < gt) {
        const std::size_t close = s.find("]>", br);
        if (close == std::string::npos) return "unterminated DOCTYPE" + at(i);
        i = close + 2;
      } else {
        err = skipTo(">", "DOCTYPE");
      }
    } else if (s.compare(i, 2, "</") == 0) {
      std::size_t k = i + 2, b = k;
      while (k < s.size() && isName(s[k])) ++k;
      const std::string name = s.substr(b, k - b);
      while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
      if (k >= s.size() || s[k] != '>') return "bad end tag" + at(i);
      if (open.empty() || open.back() != name)
        return "end tag </" + name + "> does not match <" + (open.empty() ? "" : open.back()) + ">" + at(i);
      open.pop_back();
      i = k + 1;
    } else {
      std::size_t k = i + 1, b = k;
      while (k < s.size() && isName(s[k])) ++k;
      const std::string name = s.substr(b, k - b);
      if (name.empty()) return "'<' not followed by a name" + at(i);
      std::set<std::string> attrs;
      for (;;) {
        const std::size_t ws = k;
        while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
        if (k >= s.size()) return "unterminated tag <" + name + at(i);
        if (s[k] == '>' || s.compare(k, 2, "/>") == 0) break;
        if (k == ws) return "no space before an attribute of <" + name + ">" + at(k);
        const std::size_t ab = k;
        while (k < s.size() && isName(s[k])) ++k;
        const std::string attr = s.substr(ab, k - ab);
        if (attr.empty()) return "bad attribute in <" + name + ">" + at(ab);
        if (!attrs.insert(attr).second) return "attribute " + attr + " repeated in <" + name + ">" + at(ab);
        while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
        if (k >= s.size() || s[k] != '=') return "attribute " + attr + " without a value" + at(k);
        ++k;
        while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
        if (k >= s.size() || (s[k] != '"' && s[k] != '\'')) return "unquoted value of " + attr + at(k);
        const std::size_t close = s.find(s[k], k + 1);
        if (close == std::string::npos) return "unterminated value of " + attr + at(k);
        if (std::string e = checkRefs(k + 1, close); !e.empty()) return e;
        k = close + 1;
      }
      const bool empty = s[k] == '/';
      if (open.empty() && ++roots > 1) return "a second root element <" + name + ">" + at(i);
      if (!empty) open.push_back(name);
      i = k + (empty ? 2 : 1);
    }
    if (!err.empty()) return err;
  }
  if (!open.empty()) return "element <" + open.back() + "> is not closed";
  if (roots != 1) return "no root element";
  return "";
}

/// gnuplot's svg terminal paints the background as a full-size rect at the start: filled
/// white with "background rgb 'white'", fill="none" (transparent) without.
bool whiteBackground(const std::string& svg) {
  static const std::regex white(R"(<rect x="0" y="0" width="\d+" height="\d+" fill="#ffffff")");
  return std::regex_search(svg.substr(0, 4000), white);
}

// ---- image sizes -------------------------------------------------------------------------

using Sizes = std::map<std::string, std::pair<int, int>>;

/// The figure sizes of figures/ch2/style.gp (its FIGSIZES table: name width height).
Sizes styleSizes() {
  const std::string text = readAll(kRoot / "figures/ch2/style.gp");
  Sizes sizes;
  const std::size_t from = text.find("FIGSIZES =");
  if (from == std::string::npos) return sizes;
  const std::size_t to = text.find("\n\n", from);
  const std::string table = text.substr(from, to - from);
  const std::regex entry(R"(([A-Za-z0-9_]+) (\d+) (\d+))");
  for (auto it = std::sregex_iterator(table.begin(), table.end(), entry); it != std::sregex_iterator(); ++it)
    sizes[(*it)[1]] = {std::stoi((*it)[2]), std::stoi((*it)[3])};
  return sizes;
}

std::uint32_t bigEndian32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(s[at + k]);
  return v;
}

/// The width and height of a PNG from its IHDR chunk, or {-1, -1} if it is not a PNG.
std::pair<int, int> pngSize(const std::string& data) {
  static const std::string signature("\x89PNG\r\n\x1a\n", 8);
  if (data.size() < 24 || data.compare(0, 8, signature) != 0 || data.compare(12, 4, "IHDR") != 0)
    return {-1, -1};
  return {int(bigEndian32(data, 16)), int(bigEndian32(data, 20))};
}

/// The logical screen size of a GIF, or {-1, -1} if it is not a GIF.
std::pair<int, int> gifSize(const std::string& data) {
  if (data.size() < 10 || (data.compare(0, 6, "GIF89a") != 0 && data.compare(0, 6, "GIF87a") != 0))
    return {-1, -1};
  auto le16 = [&](std::size_t at) {
    return int(static_cast<unsigned char>(data[at])) | int(static_cast<unsigned char>(data[at + 1])) << 8;
  };
  return {le16(6), le16(8)};
}

/// The style's name of an output file: its stem if the style has it, else the stem without an
/// animation frame's number _NN (fig2_5_anim_07 -> fig2_5_anim; fig2_10 stays fig2_10).
std::string styleName(const fs::path& p, const Sizes& sizes) {
  const std::string stem = p.stem().string();
  static const std::regex frame(R"((.*)_\d\d)");
  std::smatch m;
  if (sizes.count(stem) == 0 && std::regex_match(stem, m, frame)) return m[1];
  return stem;
}

// ---- fonts: advance widths from the TrueType files the figures use ------------------------

/// One TrueType font: its character map and advance widths (cmap formats 4 and 12, hmtx).
struct Font {
  double unitsPerEm = 0;
  std::map<std::uint32_t, std::uint16_t> glyph;  // code point -> glyph index
  std::vector<std::uint16_t> advance;            // per glyph (the last repeats, as hmtx says)
  bool has(std::uint32_t cp) const { return glyph.count(cp) > 0; }
  /// The advance of `cp` in em (0 if the font lacks it).
  double em(std::uint32_t cp) const {
    const auto it = glyph.find(cp);
    if (it == glyph.end() || advance.empty()) return 0;
    return advance[std::min<std::size_t>(it->second, advance.size() - 1)] / unitsPerEm;
  }
};

std::uint16_t be16(const std::string& s, std::size_t at) {
  return std::uint16_t(static_cast<unsigned char>(s[at]) << 8 | static_cast<unsigned char>(s[at + 1]));
}

/// Reads a .ttf file (throws if it is not one).
Font readFont(const fs::path& path) {
  const std::string d = readAll(path);
  if (d.size() < 12) throw std::runtime_error(path.string() + ": not a font");
  std::map<std::string, std::size_t> tables;
  for (std::size_t k = 0, n = be16(d, 4); k < n; ++k)
    tables[d.substr(12 + 16 * k, 4)] = bigEndian32(d, 12 + 16 * k + 8);
  for (const char* t : {"head", "hhea", "hmtx", "cmap"})
    if (!tables.count(t)) throw std::runtime_error(path.string() + ": no " + t + " table");
  Font f;
  f.unitsPerEm = be16(d, tables["head"] + 18);
  const std::size_t nMetrics = be16(d, tables["hhea"] + 34);
  for (std::size_t g = 0; g < nMetrics; ++g) f.advance.push_back(be16(d, tables["hmtx"] + 4 * g));
  const std::size_t cmap = tables["cmap"];
  for (std::size_t k = 0, n = be16(d, cmap + 2); k < n; ++k) {
    const std::size_t sub = cmap + bigEndian32(d, cmap + 4 + 8 * k + 4);
    const int format = be16(d, sub);
    if (format == 4) {
      const std::size_t segs = be16(d, sub + 6) / 2, ends = sub + 14, starts = ends + 2 * segs + 2,
                        deltas = starts + 2 * segs, offsets = deltas + 2 * segs;
      for (std::size_t i = 0; i < segs; ++i) {
        const std::uint32_t end = be16(d, ends + 2 * i), start = be16(d, starts + 2 * i);
        const std::uint16_t delta = be16(d, deltas + 2 * i), ro = be16(d, offsets + 2 * i);
        for (std::uint32_t c = start; c <= end && c != 0xFFFF; ++c) {
          std::uint16_t g = 0;
          if (ro == 0) g = std::uint16_t(c + delta);
          else {
            const std::size_t at = offsets + 2 * i + ro + 2 * (c - start);
            g = be16(d, at);
            if (g) g = std::uint16_t(g + delta);
          }
          if (g) f.glyph.emplace(c, g);
        }
      }
    } else if (format == 12) {
      for (std::size_t i = 0, n12 = bigEndian32(d, sub + 12); i < n12; ++i) {
        const std::size_t at = sub + 16 + 12 * i;
        const std::uint32_t a = bigEndian32(d, at), b = bigEndian32(d, at + 4), g = bigEndian32(d, at + 8);
        for (std::uint32_t c = a; c <= b; ++c) f.glyph[c] = std::uint16_t(g + (c - a));
      }
    }
  }
  return f;
}

/// The font files behind the families the figures name (what fontconfig gives for them on
/// Debian: `fc-match Sans` is DejaVu Sans; the math font is fonts-dejavu-extra's).
const std::map<std::string, fs::path>& fontFiles() {
  static const std::map<std::string, fs::path> files = {
      {"Sans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"},
      {"DejaVu Sans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"},
      {"DejaVuSans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"},
      {"DejaVu Math TeX Gyre", "/usr/share/fonts/truetype/dejavu/DejaVuMathTeXGyre.ttf"}};
  return files;
}

const Font* fontFor(const std::string& family) {
  static std::map<std::string, Font> cache;
  const auto f = fontFiles().find(family);
  if (f == fontFiles().end()) return nullptr;
  auto it = cache.find(family);
  if (it == cache.end()) it = cache.emplace(family, readFont(f->second)).first;
  return &it->second;
}

std::vector<std::uint32_t> codePoints(const std::string& s) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const int len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : 4;
    std::uint32_t cp = len == 1 ? c : c & (0x7F >> len);
    for (int k = 1; k < len && i + std::size_t(k) < s.size(); ++k) cp = (cp << 6) | (s[i + std::size_t(k)] & 0x3F);
    out.push_back(cp);
    i += std::size_t(len);
  }
  return out;
}

// ---- what a gnuplot SVG draws ----------------------------------------------------------------

struct Box {
  double x0, y0, x1, y1;
};
struct Span {
  std::string family, text;
  double size, dy;
};
struct Text {
  std::string str;  // the spans' text, concatenated
  double x, y, rotate;
  std::string anchor, colour;
  std::vector<Span> spans;
  int panel;
  bool inPlot;  // drawn by a plot (with labels, a key entry), not a set label or an axis
  int plot;     // the plot's number in its panel (0: not in a plot)
};
struct Stroke {
  std::vector<std::pair<double, double>> pts;  // a polyline ("M" starts a new one: see `breaks`)
  std::vector<std::size_t> breaks;             // indices where a new subpath starts
  double width;
  std::string colour, dash;
  int panel, plot;
  bool grid = false;  // a grid line (gnuplot writes class="gridline")
};
struct Marker {
  double x, y, r;
  std::string shape, colour;
  int panel, plot;
};
struct PlotGroup {
  int panel, plot;
  std::string title;
  int drawn = 0;  // paths, markers, texts, images of the plot
};
struct Svg {
  double width = 0, height = 0;
  std::vector<Text> texts;
  std::vector<Stroke> strokes;
  std::vector<Marker> markers;
  std::vector<PlotGroup> plots;
};

std::string attr(const std::string& tag, const std::string& name) { return dttest::svgAttr(tag, name); }

std::string unescape(std::string s) {
  const std::pair<const char*, const char*> ents[] = {{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : ents)
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) s.replace(at, std::strlen(from), to);
  return s;
}

/// Parses what gnuplot's svg terminal writes: plot groups (gnuplot_plot_N; N restarts at 1 in
/// each multiplot panel), their paths, point markers and labels, and the texts outside them.
Svg parseSvg(const std::string& s) {
  Svg svg;
  svg.width = std::atof(attr(s.substr(0, 400), "width").c_str());
  svg.height = std::atof(attr(s.substr(0, 400), "height").c_str());
  int panel = 0, plot = 0, depthInPlot = -1, depth = 0;
  double strokeWidth = 1;
  std::string groupTag;
  std::vector<double> widths;  // stroke-width of the open <g>s
  dttest::forEachSvgTag(s, [&](const std::string& tag, const std::size_t i, const std::size_t end) -> std::size_t {
    if (tag.compare(0, 3, "<g ") == 0 || tag == "<g>") {
      ++depth;
      const std::string w = attr(tag, "stroke-width");
      widths.push_back(w.empty() ? (widths.empty() ? 1.0 : widths.back()) : std::atof(w.c_str()));
      if (dttest::svgPlotStart(tag, panel, plot)) {
        depthInPlot = depth;
        PlotGroup g{panel, plot, "", 0};
        const std::size_t t0 = s.find("<title>", end), t1 = s.find("</title>", end);
        if (t0 == end + 1 || (t0 != std::string::npos && t0 < end + 4)) g.title = unescape(s.substr(t0 + 7, t1 - t0 - 7));
        svg.plots.push_back(g);
      }
      groupTag = tag;
      if (attr(tag, "transform").find("translate") != std::string::npos && s.compare(s.find('<', end + 1), 5, "<text") == 0) {
        // A text: <g transform="translate(x,y) rotate(a)" font-family font-size text-anchor><text>spans</text></g>
        Text t;
        const std::string tr = attr(tag, "transform");
        std::sscanf(tr.c_str(), "translate(%lf,%lf)", &t.x, &t.y);
        t.rotate = 0;
        if (const std::size_t r = tr.find("rotate("); r != std::string::npos) t.rotate = std::atof(tr.c_str() + r + 7);
        t.anchor = attr(tag, "text-anchor");
        t.colour = attr(tag, "fill");
        t.panel = panel;
        t.inPlot = depthInPlot > 0;
        t.plot = depthInPlot > 0 ? plot : 0;
        const double size = std::atof(attr(tag, "font-size").c_str());
        const std::string family = attr(tag, "font-family");
        const std::size_t te = s.find("</text>", end);
        const std::string inner = s.substr(end + 1, te - end - 1);
        const std::regex span(R"(<tspan([^>]*)>([^<]*)</tspan>)");
        double dy = 0;
        for (auto it = std::sregex_iterator(inner.begin(), inner.end(), span); it != std::sregex_iterator(); ++it) {
          const std::string a = " " + (*it)[1].str();
          const std::string f = attr(a, "font-family"), fs_ = attr(a, "font-size"), d = attr(a, "dy");
          dy += std::atof(d.c_str());
          Span sp{f.empty() ? family : f, unescape((*it)[2]), fs_.empty() ? size : std::atof(fs_.c_str()), dy};
          if (!sp.text.empty()) t.spans.push_back(sp), t.str += sp.text;
        }
        if (t.spans.empty()) {  // a <text> without spans
          const std::size_t a = inner.find('>');
          const std::string txt = unescape(inner.substr(a + 1, inner.find('<', a) - a - 1));
          if (!txt.empty()) t.spans.push_back({family, txt, size, 0}), t.str = txt;
        }
        if (!t.spans.empty()) {
          svg.texts.push_back(t);
          if (depthInPlot > 0) ++svg.plots.back().drawn;
        }
        return te;
      }
    } else if (tag == "</g>") {
      if (depth == depthInPlot) depthInPlot = -1;
      --depth;
      if (!widths.empty()) widths.pop_back();
    } else if (tag.compare(0, 5, "<path") == 0) {
      strokeWidth = widths.empty() ? 1.0 : widths.back();
      const std::string w = attr(tag, "stroke-width");
      if (!w.empty()) strokeWidth = std::atof(w.c_str());
      const std::string stroke = attr(tag, "stroke"), d = attr(tag, "d");
      // gnuplot outlines a filled polygon with a path in the fill's colour, right after it:
      // part of the fill, not a line.
      const std::size_t prev = s.rfind("<polygon", i);
      const bool outline = prev != std::string::npos && i - prev < 400 + (s.find("/>", prev) - prev) &&
                           s.find("<path", prev) == i && attr(s.substr(prev, s.find("/>", prev) - prev), "fill") == stroke;
      const bool drawsStroke = stroke != "none" && !outline && !(stroke.empty() && attr(groupTag, "stroke") == "none");
      if (depthInPlot > 0 && !d.empty()) ++svg.plots.back().drawn;
      if (drawsStroke && !d.empty()) {
        Stroke st{{}, {}, strokeWidth, stroke.empty() ? attr(groupTag, "stroke") : stroke, attr(tag, "stroke-dasharray"), panel,
                  depthInPlot > 0 ? plot : 0, attr(tag, "class") == "gridline"};
        for (std::size_t q = 0; q < d.size(); ++q) {
          const char c = d[q];
          if (c == 'Z' || c == 'z') {
            if (!st.breaks.empty() && st.pts.size() > st.breaks.back()) st.pts.push_back(st.pts[st.breaks.back()]);
            continue;
          }
          if (c != 'M' && c != 'L') continue;
          if (c == 'M') st.breaks.push_back(st.pts.size());
          char* e = nullptr;
          const double x = std::strtod(d.c_str() + q + 1, &e);
          if (e == nullptr || *e != ',') continue;
          const double y = std::strtod(e + 1, &e);
          st.pts.push_back({x, y});
          q = std::size_t(e - d.c_str()) - 1;
        }
        if (st.pts.size() >= 2) svg.strokes.push_back(st);
      }
    } else if (tag.compare(0, 4, "<use") == 0) {
      Marker m{0, 0, 1, attr(tag, "xlink:href"), attr(tag, "color"), panel, depthInPlot > 0 ? plot : 0};
      const std::string tr = attr(tag, "transform");
      double sc = 1;
      std::sscanf(tr.c_str(), "translate(%lf,%lf) scale(%lf)", &m.x, &m.y, &sc);
      m.r = sc * (m.shape == "#gpPt7" || m.shape == "#gpPt8" || m.shape == "#gpPt9" || m.shape == "#gpPt10" ? 1.33 : 1.0);
      svg.markers.push_back(m);
      if (depthInPlot > 0) ++svg.plots.back().drawn;
    } else if (tag.compare(0, 6, "<image") == 0 || tag.compare(0, 7, "<circle") == 0 || tag.compare(0, 5, "<rect") == 0) {
      if (depthInPlot > 0) ++svg.plots.back().drawn;
    }
    return end + 1;
  });
  return svg;
}

/// A text's ink box in its own frame (x along the baseline from the anchor, y down, before
/// the rotation: the advance widths of its characters in the font each span names, from 0.78
/// em above each span's baseline to 0.24 em below it, DejaVu's ascenders and descenders), and
/// the anchor and rotation that put it on the canvas.
struct TextFrame {
  Box local;
  double x, y;  // the anchor (gnuplot's translate)
  double c, s;  // cos and sin of gnuplot's rotate(a): SVG turns clockwise on screen, y down
  /// A canvas point in the text's frame.
  std::pair<double, double> toLocal(double px, double py) const {
    const double dx = px - x, dy = py - y;
    return {c * dx + s * dy, -s * dx + c * dy};
  }
  /// The four corners of the box on the canvas.
  std::array<std::pair<double, double>, 4> corners() const {
    const double xs[4] = {local.x0, local.x1, local.x1, local.x0}, ys[4] = {local.y0, local.y0, local.y1, local.y1};
    std::array<std::pair<double, double>, 4> out;
    for (int k = 0; k < 4; ++k) out[std::size_t(k)] = {x + c * xs[k] - s * ys[k], y + s * xs[k] + c * ys[k]};
    return out;
  }
};

TextFrame textFrame(const Text& t, std::string* missing = nullptr) {
  // Spaces at either end take their advance but put no ink: gnuplot writes a tick label " 100"
  // (a place for the sign), so the box starts at the first character that is not a space.
  double w = 0, top = 1e300, bottom = -1e300, inkFrom = -1, inkTo = 0;
  for (const Span& sp : t.spans) {
    const Font* f = fontFor(sp.family);
    for (std::uint32_t cp : codePoints(sp.text)) {
      double em = f ? f->em(cp) : 0;
      if (em == 0) {
        if (missing) *missing += sp.family + " lacks U+" + [&] { char b[16]; std::snprintf(b, sizeof b, "%04X", cp); return std::string(b); }() + "; ";
        em = 0.6;
      }
      if (cp != ' ' && inkFrom < 0) inkFrom = w;
      w += em * sp.size;
      if (cp != ' ') inkTo = w;
    }
    top = std::min(top, sp.dy - 0.78 * sp.size);
    bottom = std::max(bottom, sp.dy + 0.24 * sp.size);
  }
  const double x0 = t.anchor == "middle" ? -w / 2 : t.anchor == "end" ? -w : 0;
  const double a = t.rotate * M_PI / 180;
  return {{x0 + std::max(inkFrom, 0.0), top, x0 + inkTo, bottom}, t.x, t.y, std::cos(a), std::sin(a)};
}

/// The ink box of a text in canvas pixels, axis-aligned: for a rotated text (a y label at
/// -90 or 270, a tick label at 30 or 45), the box around its rotated box. The overlap check
/// uses the rotated box itself (textFrame); this one is for where ink reaches.
Box textBox(const Text& t, std::string* missing = nullptr) {
  Box r{1e300, 1e300, -1e300, -1e300};
  for (const auto& [X, Y] : textFrame(t, missing).corners())
    r = {std::min(r.x0, X), std::min(r.y0, Y), std::max(r.x1, X), std::max(r.y1, Y)};
  return r;
}

double boxSegDistance(const Box& b, double ax, double ay, double bx, double by) {
  // 0 if the segment meets the box, else the least distance (sampled finely enough: 0.25 px).
  const double len = std::hypot(bx - ax, by - ay);
  const int n = std::max(1, int(len / 0.25));
  double best = 1e300;
  for (int k = 0; k <= n; ++k) {
    const double x = ax + (bx - ax) * k / n, y = ay + (by - ay) * k / n;
    const double dx = std::max({b.x0 - x, 0.0, x - b.x1}), dy = std::max({b.y0 - y, 0.0, y - b.y1});
    best = std::min(best, std::hypot(dx, dy));
    if (best == 0) return 0;
  }
  return best;
}

bool boxesMeet(const Box& a, const Box& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

/// Whether two texts' rotated boxes share an area: no separating axis among the sides of
/// either box (two rectangles are disjoint if and only if one of their four side directions
/// separates them).
bool framesMeet(const TextFrame& a, const TextFrame& b) {
  const auto ca = a.corners(), cb = b.corners();
  for (const TextFrame* f : {&a, &b})
    for (const auto& [ux, uy] : {std::pair<double, double>{f->c, f->s}, std::pair<double, double>{-f->s, f->c}}) {
      double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
      for (int k = 0; k < 4; ++k) {
        const double pa = ca[std::size_t(k)].first * ux + ca[std::size_t(k)].second * uy;
        const double pb = cb[std::size_t(k)].first * ux + cb[std::size_t(k)].second * uy;
        lo[0] = std::min(lo[0], pa), hi[0] = std::max(hi[0], pa), lo[1] = std::min(lo[1], pb), hi[1] = std::max(hi[1], pb);
      }
      if (hi[0] <= lo[1] || hi[1] <= lo[0]) return false;
    }
  return true;
}

/// Every overlap of a text with something else drawn: a stroke (closer than half its width),
/// a point marker, another text, or the canvas edge; a rotated text is measured by its rotated
/// box. One line per overlap, naming the text (its string and anchor) and what it touches.
///
/// What a text may touch, the same in every figure, charts and geometry alike: only a grid
/// line (gnuplot's class="gridline": drawn first, light grey and dotted, behind everything,
/// a text over it stays legible, as over a grid in print). Nothing else: not the data (a
/// curve, a bar, a key's sample line or marker), not a border, an axis or a tic mark (gnuplot
/// sets a tick label apart from its tic, so one that meets a tic or the axis has been pushed
/// there by something else), not another text, and nothing may run past the canvas.
std::vector<std::string> overlaps(const Svg& svg) {
  std::vector<std::string> out;
  std::vector<TextFrame> frames;
  std::vector<Box> boxes;
  for (const Text& t : svg.texts) frames.push_back(textFrame(t)), boxes.push_back(textBox(t));
  auto name = [](const Text& t) {
    char at[96];
    if (std::abs(t.rotate) > 1e-9) std::snprintf(at, sizeof at, " at (%.0f, %.0f) rotated %g deg", t.x, t.y, t.rotate);
    else std::snprintf(at, sizeof at, " at (%.0f, %.0f)", t.x, t.y);
    return "label \"" + t.str + "\"" + at;
  };
  for (std::size_t i = 0; i < svg.texts.size(); ++i) {
    const Text& t = svg.texts[i];
    const TextFrame& f = frames[i];
    const Box& b = boxes[i];
    if (b.x0 < 0 || b.y0 < 0 || b.x1 > svg.width || b.y1 > svg.height) out.push_back(name(t) + " is cut by the canvas edge");
    for (std::size_t j = i + 1; j < svg.texts.size(); ++j)
      if (boxesMeet(b, boxes[j]) && framesMeet(f, frames[j])) out.push_back(name(t) + " overlaps " + name(svg.texts[j]));
    const std::size_t before = out.size();
    for (const Marker& m : svg.markers) {
      const auto [mx, my] = f.toLocal(m.x, m.y);
      const double dx = std::max({f.local.x0 - mx, 0.0, mx - f.local.x1}), dy = std::max({f.local.y0 - my, 0.0, my - f.local.y1});
      if (std::hypot(dx, dy) < m.r) {
        char buf[96];
        std::snprintf(buf, sizeof buf, " touches a marker %s at (%.0f, %.0f)", m.shape.c_str(), m.x, m.y);
        out.push_back(name(t) + buf);
      }
    }
    for (const Stroke& st : svg.strokes) {
      if (st.grid) continue;
      for (std::size_t k = 0; k + 1 < st.pts.size(); ++k) {
        if (std::find(st.breaks.begin(), st.breaks.end(), k + 1) != st.breaks.end()) continue;
        const auto [ax, ay] = st.pts[k];
        const auto [bx, by] = st.pts[k + 1];
        const auto [lax, lay] = f.toLocal(ax, ay);
        const auto [lbx, lby] = f.toLocal(bx, by);
        if (boxSegDistance(f.local, lax, lay, lbx, lby) < st.width / 2) {
          char buf[200];
          std::snprintf(buf, sizeof buf, " touches %s (%s%s, width %.1f) from (%.0f, %.0f) to (%.0f, %.0f)",
                        st.plot > 0 ? "a line of the data" : "a line of the frame (a border, an axis or a tic)", st.colour.c_str(),
                        st.dash.empty() ? "" : " dashed", st.width, ax, ay, bx, by);
          // gnuplot draws some lines twice (a border over its own tic): say each once.
          if (std::find(out.begin() + std::ptrdiff_t(before), out.end(), name(t) + buf) == out.end()) out.push_back(name(t) + buf);
          break;
        }
      }
    }
  }
  return out;
}

// ---- one run of the chapter programs -----------------------------------------------------

// The chapter programs' run that the figure tests share (tests/figure_run.h).
using dttest::PlantedCache;
using dttest::plantCaches;
using Run = dttest::FigureRun;
const Run& figureRun() { return dttest::figureRun(); }

std::vector<fs::path> outputs(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ext) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

// ---- the checkers can fail -----------------------------------------------------------------

TEST_CASE("figures the UTF-8 check rejects a raw Latin-1 byte and accepts UTF-8") {
  CHECK(utf8Error("N \xe2\x88\x9d n") == "");          // ∝
  CHECK(utf8Error("N {/Symbol \xb5} n") != "");        // what the Symbol font escape wrote
  CHECK(utf8Error("\xc0\xaf") != "");                  // overlong '/'
  CHECK(utf8Error("\xed\xa0\x80") != "");              // a surrogate
  CHECK(utf8Error("\xe2\x88") != "");                  // truncated
}

TEST_CASE("figures the XML check rejects what is not well formed") {
  CHECK(xmlError("<?xml version=\"1.0\"?>\n<svg a=\"1\"><g><text>x &amp; y</text></g><!-- c --></svg>\n") == "");
  CHECK(xmlError("<svg><g></svg></g>") != "");              // crossed
  CHECK(xmlError("<svg><g></g>") != "");                    // not closed
  CHECK(xmlError("<svg a=1></svg>") != "");                 // unquoted
  CHECK(xmlError("<svg a='1' a='2'></svg>") != "");         // repeated attribute
  CHECK(xmlError("<svg>a & b</svg>") != "");                // bare ampersand
  CHECK(xmlError("<svg></svg><svg></svg>") != "");          // two roots
  CHECK(xmlError("") != "");                                // no root
}

TEST_CASE("figures the background check tells a white SVG from a transparent one") {
  CHECK(whiteBackground("<svg>\n<g id=\"gnuplot_canvas\">\n<rect x=\"0\" y=\"0\" width=\"200\" height=\"100\" fill=\"#ffffff\"/>"));
  CHECK_FALSE(whiteBackground("<svg>\n<g id=\"gnuplot_canvas\">\n<rect x=\"0\" y=\"0\" width=\"200\" height=\"100\" fill=\"none\"/>"));
}

TEST_CASE("figures the PNG and GIF size readers read the header and reject other files") {
  std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x05\x78\0\0\x03\x20", 24);
  CHECK(pngSize(png) == std::make_pair(1400, 800));
  png[13] = 'X';
  CHECK(pngSize(png) == std::make_pair(-1, -1));
  CHECK(gifSize(std::string("GIF89a\xf8\x02\x20\x03", 10)) == std::make_pair(760, 800));
  CHECK(gifSize("PNG....xyz") == std::make_pair(-1, -1));
  const Sizes sizes = {{"fig2_5_anim", {760, 800}}, {"fig2_10", {1400, 780}}};
  CHECK(styleName("fig2_5_anim_07.png", sizes) == "fig2_5_anim");
  CHECK(styleName("fig2_10.png", sizes) == "fig2_10");
}

TEST_CASE("figures style.gp gives a size to every figure the book embeds") {
  const auto sizes = styleSizes();
  REQUIRE(sizes.size() >= 20);
  for (const std::string& name : embeddedFigures())
    CHECK_MESSAGE(sizes.count(fs::path(name).stem().string()) == 1, name << " has no size in figures/ch2/style.gp");
}

// ---- the outputs of a run ------------------------------------------------------------------

TEST_CASE("figures every figure the book embeds is written by the chapter programs") {
  const Run& run = figureRun();
  for (const std::string& f : run.failures) FAIL_CHECK("chapter program failed: " << f);
  const auto names = embeddedFigures();
  REQUIRE(names.size() >= 20);
  for (const std::string& name : names) {
    const fs::path p = run.dir / name;  // the exact name, not a prefix or substring
    CHECK_MESSAGE(fs::exists(p), name << " (embedded by the book) was not written into " << run.dir);
    if (fs::exists(p)) CHECK_MESSAGE(fs::file_size(p) > 0, name << " is empty");
  }
}

TEST_CASE("figures every SVG is well-formed XML in UTF-8 with a white background") {
  const Run& run = figureRun();
  const auto svgs = outputs(run.dir, ".svg");
  REQUIRE(svgs.size() >= 20);
  for (const fs::path& p : svgs) {
    const std::string text = readAll(p);
    const std::string u = utf8Error(text);
    CHECK_MESSAGE(u.empty(), p.filename().string() << ": not UTF-8: " << u);
    if (!u.empty()) continue;
    const std::string x = xmlError(text);
    CHECK_MESSAGE(x.empty(), p.filename().string() << ": not well-formed XML: " << x);
    CHECK_MESSAGE(whiteBackground(text), p.filename().string() << ": transparent background");
  }
}

TEST_CASE("figures every PNG and the GIF have the size figures/ch2/style.gp gives") {
  const Run& run = figureRun();
  const auto sizes = styleSizes();
  REQUIRE(sizes.size() >= 20);
  auto images = outputs(run.dir, ".png");
  const auto gifs = outputs(run.dir, ".gif");
  REQUIRE(images.size() >= 20);
  images.insert(images.end(), gifs.begin(), gifs.end());
  for (const fs::path& p : images) {
    const std::string name = styleName(p, sizes);
    const auto it = sizes.find(name);
    CHECK_MESSAGE(it != sizes.end(), p.filename().string() << ": no size in figures/ch2/style.gp");
    if (it == sizes.end()) continue;
    const std::string data = readAll(p);
    const auto got = p.extension() == ".gif" ? gifSize(data) : pngSize(data);
    CHECK_MESSAGE(got == it->second, p.filename().string() << " is " << got.first << " x " << got.second
                                                             << ", the style says " << it->second.first << " x "
                                                             << it->second.second);
  }
}

// ---- the drawing checks can fail -----------------------------------------------------------

namespace {

/// A small SVG as gnuplot writes it: one panel, an edge from (10,50) to (190,50), a point
/// marker at (100,20) and the label `label` at (x, y).
std::string tinySvg(const std::string& label, double x, double y, bool emptyPlot = false) {
  std::string s = "<svg width=\"200\" height=\"100\" viewBox=\"0 0 200 100\">\n<defs></defs>\n"
                  "<g id=\"gnuplot_plot_1\" ><title>edges</title>\n<g fill=\"none\" stroke-width=\"1.50\">\n";
  if (!emptyPlot) s += "\t<path stroke='rgb( 60,  60,  60)'  d='M10.00,50.00 L190.00,50.00  '/></g>\n";
  else s += "</g>\n";
  s += "\t</g>\n<g id=\"gnuplot_plot_2\" ><title>points</title>\n<g fill=\"none\" stroke-width=\"1.00\">\n"
       "\t<use xlink:href='#gpPt6' transform='translate(100.00,20.00) scale(3.00)' color='black'/>\n</g>\n\t</g>\n"
       "<g id=\"gnuplot_plot_3\" ><title>labels</title>\n<g fill=\"none\">\n"
       "\t<g transform=\"translate(" + std::to_string(x) + "," + std::to_string(y) + ")\" stroke=\"none\" fill=\"black\" "
       "font-family=\"Sans\" font-size=\"12.00\"  text-anchor=\"middle\">\n\t\t<text><tspan font-family=\"Sans\" >" + label +
       "</tspan></text>\n\t</g>\n</g>\n\t</g>\n</svg>\n";
  return s;
}

}  // namespace

TEST_CASE("figures the font reader reads DejaVu's advance widths and character maps") {
  const Font* sans = fontFor("Sans");
  REQUIRE(sans != nullptr);
  CHECK(sans->unitsPerEm == 2048);
  CHECK(sans->em(' ') == doctest::Approx(651.0 / 2048));  // DejaVu Sans: space 651, M 1767 units
  CHECK(sans->em('M') == doctest::Approx(1767.0 / 2048));
  CHECK(sans->em('i') < sans->em('m'));
  CHECK_FALSE(sans->has(0x1D45D));  // no math italic p in DejaVu Sans: a figure must name the math font
  const Font* math = fontFor("DejaVu Math TeX Gyre");
  REQUIRE(math != nullptr);
  for (std::uint32_t cp : {0x1D45D, 0x1D49E, 0x212C, 0x1D70E, 0x03A3, 0x2212}) CHECK_MESSAGE(math->has(cp), cp);
}

TEST_CASE("figures the overlap check names a label on a line a marker or another label") {
  // Clear: well above the edge, left of the marker.
  CHECK(overlaps(parseSvg(tinySvg("p", 40, 30))).empty());
  // On the edge (the baseline 2 px below the line: the box spans it).
  const auto onEdge = overlaps(parseSvg(tinySvg("p", 40, 52)));
  REQUIRE(onEdge.size() == 1);
  CHECK(onEdge[0].find("label \"p\" at (40, 52) touches a line of the data") == 0);
  // On the marker.
  const auto onMarker = overlaps(parseSvg(tinySvg("q", 100, 25)));
  REQUIRE(onMarker.size() == 1);
  CHECK(onMarker[0].find("touches a marker") != std::string::npos);
  // A wide label reaches the marker from 40 px away: widths come from the font.
  CHECK(overlaps(parseSvg(tinySvg("p", 70, 30))).empty());
  CHECK_FALSE(overlaps(parseSvg(tinySvg("pppppppppp", 70, 30))).empty());
  // Cut by the canvas edge.
  CHECK_FALSE(overlaps(parseSvg(tinySvg("p", 2, 30))).empty());
}

namespace {

/// A small chart as gnuplot writes it: the frame outside the plots (an axis from (50,150) to
/// (290,150), a tic mark at x = 100 going `ticLength` px down, a grid line at y = 100 with a
/// label "grid" over it), two tick labels rotated by 45 degrees, "alpha" at (100,165) and
/// "beta" at (betaX,165), and one data series (plot 1): a line at y = dataY and a short stroke
/// from (99,188) to (101,188), inside the axis-aligned box around "alpha" but off its
/// rotated box.
std::string tinyChartSvg(double betaX, double dataY, double ticLength) {
  auto text = [](const std::string& s, double x, double y, const std::string& rotate) {
    return "\t<g transform=\"translate(" + std::to_string(x) + "," + std::to_string(y) + ")" + rotate +
           "\" stroke=\"none\" fill=\"black\" font-family=\"Sans\" font-size=\"12.00\"  text-anchor=\"start\">\n"
           "\t\t<text><tspan font-family=\"Sans\" >" + s + "</tspan></text>\n\t</g>\n";
  };
  return "<svg width=\"300\" height=\"200\" viewBox=\"0 0 300 200\">\n<defs></defs>\n"
         "<g fill=\"none\" color=\"gray\" stroke=\"currentColor\" stroke-width=\"1.50\">\n"
         "\t<path stroke='rgb(196, 196, 196)' stroke-dasharray='2,4' class=\"gridline\"  d='M50.00,100.00 L290.00,100.00  '/></g>\n"
         "<g fill=\"none\" color=\"black\" stroke=\"currentColor\" stroke-width=\"1.50\">\n"
         "\t<path stroke='black'  d='M50.00,150.00 L290.00,150.00  '/>\n"
         "\t<path stroke='black'  d='M100.00,150.00 L100.00," + std::to_string(150 + ticLength) + "  '/>\n" +
         text("alpha", 100, 165, " rotate(45)") + text("beta", betaX, 165, " rotate(45)") + text("grid", 200, 104, "") +
         "</g>\n<g id=\"gnuplot_plot_1\" ><title>data</title>\n<g fill=\"none\" stroke-width=\"1.50\">\n"
         "\t<path stroke='rgb( 31, 119, 180)'  d='M50.00," + std::to_string(dataY) + " L290.00," + std::to_string(dataY) +
         " M99.00,188.00 L101.00,188.00  '/></g>\n\t</g>\n</svg>\n";
}

}  // namespace

TEST_CASE("figures the overlap check measures rotated tick labels by their rotated boxes in a chart") {
  // Clean: the labels are 25 px apart along the axis, 17.7 px apart across their baselines
  // (more than their 12.2 px of height), though the boxes around them overlap; the data runs
  // above the axis; the short stroke lies in the corner of the box around "alpha", off its ink;
  // the label "grid" is over a grid line, which a text may cross; the tic mark stops 6 px down.
  const Svg clean = parseSvg(tinyChartSvg(125, 60, 6));
  REQUIRE(clean.texts.size() == 3);
  CHECK(clean.texts[0].rotate == 45);
  CHECK(boxesMeet(textBox(clean.texts[0]), textBox(clean.texts[1])));
  const auto none = overlaps(clean);
  CHECK_MESSAGE(none.empty(), (none.empty() ? "" : none[0]));
  // Two rotated tick labels 10 px apart: 7 px across their baselines, they overlap.
  const auto crowded = overlaps(parseSvg(tinyChartSvg(110, 60, 6)));
  REQUIRE(crowded.size() == 1);
  CHECK(crowded[0] == "label \"alpha\" at (100, 165) rotated 45 deg overlaps label \"beta\" at (110, 165) rotated 45 deg");
  // The data line at y = 185 crosses both rotated labels.
  const auto onData = overlaps(parseSvg(tinyChartSvg(125, 185, 6)));
  REQUIRE(onData.size() == 2);
  CHECK(onData[0].find("label \"alpha\" at (100, 165) rotated 45 deg touches a line of the data") == 0);
  CHECK(onData[1].find("label \"beta\" at (125, 165) rotated 45 deg touches a line of the data") == 0);
  // A tic mark 20 px long reaches into its own label: the frame is no grid line.
  const auto onTic = overlaps(parseSvg(tinyChartSvg(125, 60, 20)));
  REQUIRE(onTic.size() == 1);
  CHECK(onTic[0].find("label \"alpha\" at (100, 165) rotated 45 deg touches a line of the frame") == 0);
}

TEST_CASE("figures the content check finds a plot that draws nothing") {
  const Svg full = parseSvg(tinySvg("p", 40, 30)), empty = parseSvg(tinySvg("p", 40, 30, true));
  REQUIRE(full.plots.size() == 3);
  CHECK(full.plots[0].drawn == 1);
  CHECK(full.plots[1].drawn == 1);
  CHECK(full.plots[2].drawn == 1);
  CHECK(empty.plots[0].drawn == 0);
  CHECK(full.strokes.size() == 1);
  CHECK(full.markers.size() == 1);
}

// ---- what the figures draw -----------------------------------------------------------------

namespace {

std::map<std::string, Svg> runSvgs() {
  std::map<std::string, Svg> out;
  for (const fs::path& p : outputs(figureRun().dir, ".svg")) out[p.stem().string()] = parseSvg(readAll(p));
  return out;
}

const std::map<std::string, Svg>& svgs() {
  static const std::map<std::string, Svg> all = runSvgs();
  return all;
}

}  // namespace

TEST_CASE("figures no text of any figure touches a line a marker another text or the canvas edge") {
  // Every SVG of the run: the geometry figures (whose labels ch::LabelPlacer places; fig2_9's
  // counts sit inside their discs, where the edges stop) and the charts (tick labels, rotated
  // ones too, axis labels, keys, panel titles, labels in the plot such as fig_time_per_point's
  // cache sizes), under one rule (overlaps says what a text may touch: a grid line only).
  REQUIRE(svgs().size() >= 20);
  for (const auto& [name, svg] : svgs())
    for (const std::string& o : overlaps(svg)) FAIL_CHECK(name << ".svg: " << o);
  // The charts are among the figures checked: every one of them was written.
  for (const char* chart : {"fig2_7", "fig2_7_errors", "fig2_8", "fig2_12", "fig_brio_compare", "fig_brio_rounds",
                            "fig_incircle_naive", "fig_incircle_robust", "fig_ladder_time", "fig_outlier_walk",
                            "fig_parabola_cavity", "fig_table2_1_search", "fig_time_per_point"})
    CHECK_MESSAGE(svgs().count(chart) == 1, chart << ".svg was not written");
}

TEST_CASE("figures every plot of every panel of every SVG draws something") {
  REQUIRE(svgs().size() >= 20);
  for (const auto& [name, svg] : svgs()) {
    CHECK_MESSAGE(!svg.plots.empty(), name << ".svg draws no plot");
    for (const PlotGroup& g : svg.plots)
      CHECK_MESSAGE(g.drawn > 0, name << ".svg panel " << g.panel << ": plot " << g.plot << " (" << g.title
                                      << ") draws nothing: its data is out of range or filtered away");
  }
}

namespace {

/// What a plot draws per row or block of its data file: line segments (a block of k rows is
/// k - 1 segments), point markers, labels, or paths (a circle each).
enum class Draws { Segments, Markers, Texts, Paths };

/// One series of a figure whose elements the program wrote into a data file.
struct Series {
  std::string figure;
  int panel, plot;
  std::string file;
  Draws draws;
};

/// The number of elements the data file `text` holds for `d`: rows (not comments), or for
/// segments the rows of each block (blocks end at a blank line) less one.
int dataElements(const std::string& text, Draws d) {
  std::istringstream in(text);
  int rows = 0, segments = 0, block = 0;
  for (std::string line; std::getline(in, line);) {
    const std::size_t k = line.find_first_not_of(" \t\r");
    if (k == std::string::npos) {
      segments += std::max(0, block - 1), block = 0;
      continue;
    }
    if (line[k] == '#') continue;
    ++rows, ++block;
  }
  segments += std::max(0, block - 1);
  return d == Draws::Segments ? segments : rows;
}

/// The number of elements plot `plot` of panel `panel` draws in the SVG: line segments (L
/// commands: gnuplot joins a segment to the previous one when it starts where that ended),
/// markers, texts or distinct paths.
int svgElements(const Svg& svg, int panel, int plot, Draws d) {
  int n = 0;
  std::set<std::vector<std::pair<double, double>>> paths;  // gnuplot strokes an empty circle twice, over itself
  for (const Stroke& st : svg.strokes)
    if (st.panel == panel && st.plot == plot) {
      if (d == Draws::Segments) n += int(st.pts.size() - st.breaks.size());
      if (d == Draws::Paths) n += paths.insert(st.pts).second;
    }
  if (d == Draws::Markers)
    for (const Marker& m : svg.markers) n += m.panel == panel && m.plot == plot;
  if (d == Draws::Texts)
    for (const Text& t : svg.texts) n += t.panel == panel && t.plot == plot;
  return n;
}

/// The series of the geometry figures whose data files hold exactly what they draw (the
/// figures' scripts name these files; panel and plot as numbered in the SVG).
std::vector<Series> knownSeries(const fs::path& dir) {
  std::vector<Series> s = {
      {"fig2_1", 1, 1, "fig2_1_dtn.dat", Draws::Segments},
      {"fig2_1", 1, 2, "fig2_1_points.dat", Draws::Markers},
      {"fig2_1", 1, 3, "fig2_1_p.dat", Draws::Markers},
      {"fig2_1", 1, 4, "fig2_1_p.dat", Draws::Texts},
      {"fig2_1", 2, 2, "fig2_1_circles.dat", Draws::Paths},
      {"fig2_1", 2, 3, "fig2_1_dtn.dat", Draws::Segments},
      {"fig2_1", 2, 5, "fig2_1_points.dat", Draws::Markers},
      {"fig2_1", 2, 6, "fig2_1_p.dat", Draws::Markers},
      {"fig2_6", 1, 3, "fig2_6_all.dat", Draws::Segments},
      {"fig2_6", 1, 4, "fig2_6_crossing.dat", Draws::Segments},
      {"fig2_6", 1, 5, "fig2_6_circle.dat", Draws::Paths},
      {"fig2_6", 1, 6, "fig2_6_points.dat", Draws::Markers},
      {"fig2_6", 1, 7, "fig2_6_super.dat", Draws::Markers},
      {"fig2_6", 1, 8, "fig2_6_super.dat", Draws::Texts},
      {"fig2_6", 1, 9, "fig2_6_labels_a.dat", Draws::Texts},
      {"fig2_6", 2, 3, "fig2_6_kept_edges.dat", Draws::Segments},
      {"fig2_6", 2, 6, "fig2_6_points.dat", Draws::Markers},
      {"fig2_6", 2, 7, "fig2_6_labels.dat", Draws::Texts},
      {"fig2_4", 1, 4, "fig2_4_dt.dat", Draws::Segments},
      {"fig2_4", 1, 9, "fig2_1_points.dat", Draws::Markers},
      {"fig2_4", 1, 10, "fig2_1_p.dat", Draws::Markers},
      {"fig2_9", 1, 1, "fig2_9_tri.dat", Draws::Segments},
      {"fig2_9", 1, 2, "fig2_9_vertices.dat", Draws::Paths},
      {"fig2_9", 1, 3, "fig2_9_vertices.dat", Draws::Texts},
      {"fig2_10", 1, 2, "fig2_10_before.dat", Draws::Segments},
      {"fig2_10", 1, 3, "fig2_10_point.dat", Draws::Markers},
      {"fig2_10", 1, 4, "fig2_10_label.dat", Draws::Texts},
      {"fig2_10", 2, 3, "fig2_10_after.dat", Draws::Segments},
      {"fig2_10", 2, 6, "fig2_10_point.dat", Draws::Markers},
      {"fig2_10", 2, 7, "fig2_10_label.dat", Draws::Texts},
      {"fig_flip", 1, 1, "flip_before_tri.dat", Draws::Segments},
      {"fig_flip", 2, 1, "flip_after_tri.dat", Draws::Segments}};
  int k = 0;
  for (const std::string row : {"outhull", "outline"})
    for (const std::string when : {"before", "after"}) {
      ++k;
      s.push_back({"fig_outside_hull", k, 1, row + "_" + when + ".dat", Draws::Segments});
      s.push_back({"fig_outside_hull", k, 2, row + "_points.dat", Draws::Markers});
      s.push_back({"fig_outside_hull", k, 3, row + "_q.dat", Draws::Markers});
      s.push_back({"fig_outside_hull", k, 4, row + "_label.dat", Draws::Texts});
    }
  // fig_time_per_point's cache markers (bench_parallel), when the run marked some: a dashed
  // line per marker (blocks of two rows) and its label, after the three curves (six when an
  // earlier --max-n run left time_per_point_large.dat).
  std::istringstream view(readAll(dir / "time_per_point_view.gp"));
  for (std::string line; std::getline(view, line);)
    if (line.rfind("ncaches = ", 0) == 0 && std::stoi(line.substr(10)) > 0) {
      const int first = fs::exists(dir / "time_per_point_large.dat") ? 7 : 4;
      s.push_back({"fig_time_per_point", 1, first, "time_per_point_cache_lines.dat", Draws::Segments});
      s.push_back({"fig_time_per_point", 1, first + 1, "time_per_point_caches.dat", Draws::Texts});
    }
  for (int f = 0; fs::exists(dir / ("rec_frame_" + std::to_string(f) + ".dat")); ++f) {
    s.push_back({"fig_recovery_frames", f + 1, 1, "rec_frame_" + std::to_string(f) + ".dat", Draws::Segments});
    s.push_back({"fig_recovery_frames", f + 1, 2, "rec_points.dat", Draws::Markers});
    s.push_back({"fig_recovery_frames", f + 1, 3, "rec_super.dat", Draws::Markers});
  }
  return s;
}

/// Every series of `svg` (figure `name`) whose drawn count differs from its data file's.
std::vector<std::string> seriesMismatches(const std::string& name, const Svg& svg, const std::vector<Series>& series,
                                          const fs::path& dir) {
  std::vector<std::string> out;
  for (const Series& s : series) {
    if (s.figure != name) continue;
    const int want = dataElements(readAll(dir / s.file), s.draws), got = svgElements(svg, s.panel, s.plot, s.draws);
    const char* what[] = {"segments", "markers", "labels", "paths"};
    if (want != got || want == 0)
      out.push_back("panel " + std::to_string(s.panel) + " plot " + std::to_string(s.plot) + " draws " + std::to_string(got) + " " +
                    what[int(s.draws)] + ", its data " + s.file + " holds " + std::to_string(want));
  }
  return out;
}

}  // namespace

TEST_CASE("figures the series count finds a dropped segment marker and label") {
  CHECK(dataElements("# x y\n0 0\n1 1\n\n2 2\n3 3\n4 4\n", Draws::Segments) == 3);
  CHECK(dataElements("# x y\n0 0\n1 1\n\n2 2\n", Draws::Markers) == 3);
  const Svg svg = parseSvg(tinySvg("p", 40, 30));
  CHECK(svgElements(svg, 1, 1, Draws::Segments) == 1);
  CHECK(svgElements(svg, 1, 2, Draws::Markers) == 1);
  CHECK(svgElements(svg, 1, 3, Draws::Texts) == 1);
  const fs::path dir = fs::path(DT_TEST_TMP) / "series_check";
  fs::create_directories(dir);
  std::ofstream(dir / "edges.dat") << "10 50\n190 50\n\n";
  std::ofstream(dir / "points.dat") << "100 20\n";
  std::ofstream(dir / "two.dat") << "100 20\n120 20\n";
  const std::vector<Series> ok = {{"tiny", 1, 1, "edges.dat", Draws::Segments}, {"tiny", 1, 2, "points.dat", Draws::Markers},
                                  {"tiny", 1, 3, "points.dat", Draws::Texts}};
  CHECK(seriesMismatches("tiny", svg, ok, dir).empty());
  // The data holds two points, the figure draws one.
  const std::vector<Series> dropped = {{"tiny", 1, 2, "two.dat", Draws::Markers}};
  REQUIRE(seriesMismatches("tiny", svg, dropped, dir).size() == 1);
  CHECK(seriesMismatches("tiny", svg, dropped, dir)[0] == "panel 1 plot 2 draws 1 markers, its data two.dat holds 2");
  // An empty plot: its segment is gone.
  CHECK(seriesMismatches("tiny", parseSvg(tinySvg("p", 40, 30, true)), ok, dir).size() == 1);
  fs::remove_all(dir);
}

TEST_CASE("figures every series of a geometry figure draws exactly what its data file holds") {
  REQUIRE(svgs().size() >= 20);
  const fs::path dir = figureRun().dir;
  const auto series = knownSeries(dir);
  REQUIRE(series.size() >= 30);
  for (const Series& s : series) CHECK_MESSAGE(svgs().count(s.figure) == 1, s.figure << ".svg was not written");
  for (const auto& [name, svg] : svgs())
    for (const std::string& m : seriesMismatches(name, svg, series, dir)) FAIL_CHECK(name << ".svg: " << m);
}

TEST_CASE("figures the time per point chart of the figure run marks all three planted caches") {
  // Without its three markers the chart's labels would escape the overlap check, and its
  // dashed lines and labels the series count (which applies only when markers are drawn).
  const Run& run = figureRun();
  if (run.caches.empty()) {
    MESSAGE("DT_FIGURES_DIR: another run's chart, with its machine's caches; nothing planted to find");
    return;
  }
  REQUIRE(svgs().count("fig_time_per_point") == 1);
  const std::vector<ch::CacheSize> planted = ch::dataCaches(run.caches);
  REQUIRE(planted.size() == 3);
  INFO("bench_parallel's verdict: " << readAll(run.dir / "time_per_point_verdict.html"));
  CHECK(readAll(run.dir / "time_per_point_view.gp").find("\nncaches = 3\n") != std::string::npos);
  CHECK(dataElements(readAll(run.dir / "time_per_point_cache_lines.dat"), Draws::Segments) == 3);
  const Svg& svg = svgs().at("fig_time_per_point");
  for (const ch::CacheSize& c : planted) {
    const bool drawn = std::any_of(svg.texts.begin(), svg.texts.end(),
                                   [&](const Text& t) { return t.inPlot && t.str == c.label; });
    CHECK_MESSAGE(drawn, "fig_time_per_point.svg has no label " << c.label);
  }
  const auto series = knownSeries(run.dir);
  CHECK(std::count_if(series.begin(), series.end(),
                      [](const Series& s) { return s.figure == "fig_time_per_point"; }) == 2);
}

TEST_CASE("figures the cache markers come from the data and unified caches /sys describes") {
  // A planted copy of /sys/devices/system/cpu/cpu0/cache: L1 instruction and data (in this
  // order, so that an instruction cache taken for L1 would show), L2, L3.
  const fs::path dir = fs::path(DT_TEST_TMP) / "cache_sizes";
  plantCaches(dir, {{"index0", "1", "Instruction", "32K"},
                    {"index1", "1", "Data", "48K"},
                    {"index2", "2", "Unified", "1024K"},
                    {"index3", "3", "Unified", "32M"}});
  const std::vector<ch::CacheSize> c = ch::dataCaches(dir);
  REQUIRE(c.size() == 3);  // the instruction cache is no marker
  CHECK(c[0].level == 1);
  CHECK(c[0].bytes == 48 * 1024);
  CHECK(c[0].label == "L1d 48 KiB");
  CHECK(c[1].level == 2);
  CHECK(c[1].bytes == 1024 * 1024);
  CHECK(c[1].label == "L2 1 MiB");
  CHECK(c[2].level == 3);
  CHECK(c[2].bytes == 32ull * 1024 * 1024);
  CHECK(c[2].label == "L3 32 MiB");
  CHECK(ch::parseCacheSize("32768K") == 32ull * 1024 * 1024);
  CHECK(ch::parseCacheSize("") == 0);
  CHECK(ch::parseCacheSize("12X") == 0);
  fs::remove_all(dir);
}

TEST_CASE("figures no cache marker is invented when /sys lists no cache") {
  const fs::path dir = fs::path(DT_TEST_TMP) / "cache_sizes_empty";
  fs::remove_all(dir);
  fs::create_directories(dir);
  CHECK(ch::dataCaches(dir).empty());
  CHECK(ch::dataCaches(dir / "missing").empty());
  fs::remove_all(dir);
}

TEST_CASE("figures every character of every SVG text is in the font the text names") {
  REQUIRE(svgs().size() >= 20);
  for (const auto& [name, svg] : svgs())
    for (const Text& t : svg.texts) {
      std::string missing;
      for (const Span& sp : t.spans) {
        CHECK_MESSAGE(fontFor(sp.family) != nullptr, name << ".svg: \"" << t.str << "\" names the font " << sp.family
                                                          << ", which is not one of the style's fonts");
        textBox(t, &missing);
      }
      CHECK_MESSAGE(missing.empty(), name << ".svg: \"" << t.str << "\": " << missing << "(a fallback font or a box would show)");
    }
}

TEST_CASE("figures every line of every SVG is at least 1.5 px wide") {
  REQUIRE(svgs().size() >= 20);
  for (const auto& [name, svg] : svgs()) {
    double thinnest = 1e300;
    std::string what;
    for (const Stroke& st : svg.strokes)
      if (st.width < thinnest) thinnest = st.width, what = st.colour;
    CHECK_MESSAGE(thinnest >= 1.5, name << ".svg has a line " << thinnest << " px wide (" << what << ")");
  }
}

TEST_CASE("figures text is at least 7 pt printed at 8 cm for one panel and 15 cm for more (subscripts at 0.8)") {
  REQUIRE(svgs().size() >= 20);
  for (const auto& [name, svg] : svgs()) {
    int panels = 0;
    for (const PlotGroup& g : svg.plots) panels = std::max(panels, g.panel);
    const double printCm = panels > 1 ? 15 : 8, ptPerPx = printCm / 2.54 * 72 / svg.width;
    // A text's size is its largest span's (subscripts are set at 0.8 of it, as in print).
    for (const Text& t : svg.texts) {
      double size = 0;
      for (const Span& sp : t.spans) size = std::max(size, sp.size);
      CHECK_MESSAGE(size * ptPerPx >= 7 - 1e-9, name << ".svg: \"" << t.str << "\" is " << size * ptPerPx << " pt at " << printCm
                                                      << " cm (" << panels << " panels)");
    }
  }
}

TEST_CASE("figures every PNG is at least 1200 px wide") {
  const auto pngs = outputs(figureRun().dir, ".png");
  REQUIRE(pngs.size() >= 20);
  for (const fs::path& p : pngs) {
    const auto [w, h] = pngSize(readAll(p));
    CHECK_MESSAGE(w >= 1200, p.filename().string() << " is " << w << " px wide");
  }
}

namespace {

/// The panel grid of a figure: its columns and rows, read from where the panel titles "(a) ...",
/// "(b) ..." sit (style.gp's panel() centres each at the top of its cell of equal cells);
/// {1, 1} without titles.
std::pair<int, int> panelGrid(const Svg& svg) {
  std::vector<double> xs, ys;
  static const std::regex tag(R"(\([a-l]\) .*)");
  auto add = [](std::vector<double>& v, double a) {
    for (double b : v)
      if (std::abs(a - b) < 2) return;
    v.push_back(a);
  };
  for (const Text& t : svg.texts)
    if (!t.inPlot && std::regex_match(t.str, tag)) add(xs, t.x), add(ys, t.y);
  return {std::max<int>(1, int(xs.size())), std::max<int>(1, int(ys.size()))};
}

/// The blank band at each side (left, right, top, bottom) of each cell of the panel grid, as
/// a fraction of the cell's width or height: ink (line points, markers, text boxes) is given
/// to the cell it lies in, ink past the canvas to the edge it is cut by.
std::vector<std::array<double, 4>> cellBands(const Svg& svg, int cols, int rows) {
  const double cw = svg.width / cols, ch = svg.height / rows;
  std::vector<Box> ink(std::size_t(cols * rows), Box{1e300, 1e300, -1e300, -1e300});
  auto grow = [&](double x, double y) {
    x = std::clamp(x, 0.0, svg.width), y = std::clamp(y, 0.0, svg.height);  // cut by the canvas edge: ink up to it
    const int c = std::min(cols - 1, int(x / cw)), r = std::min(rows - 1, int(y / ch));
    Box& b = ink[std::size_t(r * cols + c)];
    b = {std::min(b.x0, x), std::min(b.y0, y), std::max(b.x1, x), std::max(b.y1, y)};
  };
  for (const Stroke& st : svg.strokes)
    for (const auto& [x, y] : st.pts) grow(x, y);
  for (const Marker& m : svg.markers) grow(m.x - m.r, m.y - m.r), grow(m.x + m.r, m.y + m.r);
  for (const Text& t : svg.texts) {
    const Box b = textBox(t);
    grow(b.x0, b.y0), grow(b.x1, b.y1);
  }
  std::vector<std::array<double, 4>> out;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const Box& b = ink[std::size_t(r * cols + c)];
      if (b.x0 > b.x1) {
        out.push_back({1, 1, 1, 1});  // an empty cell
        continue;
      }
      out.push_back({(b.x0 - c * cw) / cw, ((c + 1) * cw - b.x1) / cw, (b.y0 - r * ch) / ch, ((r + 1) * ch - b.y1) / ch});
    }
  return out;
}

}  // namespace

TEST_CASE("figures the panel band check finds a half-empty panel") {
  Svg svg;
  svg.width = 400, svg.height = 200;
  auto title = [](const std::string& s, double x) { return Text{s, x, 20, 0, "middle", "black", {{"Sans", s, 12, 0}}, 0, false, 0}; };
  svg.texts = {title("(a) left", 100), title("(b) right", 300)};
  REQUIRE(panelGrid(svg) == std::make_pair(2, 1));
  svg.texts.clear();
  // Panel (a) is filled edge to edge; panel (b) only in its left half.
  svg.strokes.push_back({{{5, 30}, {195, 195}}, {0}, 2, "black", "", 1, 1});
  svg.strokes.push_back({{{205, 30}, {300, 195}}, {0}, 2, "black", "", 2, 1});
  const auto bands = cellBands(svg, 2, 1);
  REQUIRE(bands.size() == 2);
  CHECK(bands[0][1] == doctest::Approx(0.025));
  CHECK(bands[1][1] == doctest::Approx(0.5));
  CHECK(bands[1][3] == doctest::Approx(0.025));
}

TEST_CASE("figures no panel of a multi-panel figure has a blank band over 12 percent of its cell") {
  REQUIRE(svgs().size() >= 20);
  const char* side[] = {"left", "right", "top", "bottom"};
  for (const auto& [name, svg] : svgs()) {
    const auto [cols, rows] = panelGrid(svg);
    if (cols * rows < 2) continue;
    const auto bands = cellBands(svg, cols, rows);
    for (std::size_t k = 0; k < bands.size(); ++k)
      for (int s = 0; s < 4; ++s)
        CHECK_MESSAGE(bands[k][std::size_t(s)] <= 0.12, name << ".svg panel " << std::string(1, char('a' + k)) << " (" << rows << " x " << cols
                                                        << " grid): blank band at the " << std::string(side[s]) << ", "
                                                        << 100 * bands[k][std::size_t(s)] << " % of its cell");
  }
}

TEST_CASE("figures no blank band wider than 10 percent of the canvas at any side") {
  REQUIRE(svgs().size() >= 20);
  for (const auto& [name, svg] : svgs()) {
    Box ink{1e300, 1e300, -1e300, -1e300};
    auto grow = [&](double x, double y) { ink = {std::min(ink.x0, x), std::min(ink.y0, y), std::max(ink.x1, x), std::max(ink.y1, y)}; };
    for (const Stroke& st : svg.strokes)
      for (const auto& [x, y] : st.pts)
        if (x >= 0 && y >= 0 && x <= svg.width && y <= svg.height) grow(x, y);
    for (const Marker& m : svg.markers) grow(m.x, m.y);
    for (const Text& t : svg.texts) {
      const Box b = textBox(t);
      grow(b.x0, b.y0), grow(b.x1, b.y1);
    }
    CHECK_MESSAGE(ink.x0 <= 0.1 * svg.width, name << ".svg: blank band at the left, " << ink.x0 << " px of " << svg.width);
    CHECK_MESSAGE(svg.width - ink.x1 <= 0.1 * svg.width, name << ".svg: blank band at the right, " << svg.width - ink.x1 << " px of " << svg.width);
    CHECK_MESSAGE(ink.y0 <= 0.1 * svg.height, name << ".svg: blank band at the top, " << ink.y0 << " px of " << svg.height);
    CHECK_MESSAGE(svg.height - ink.y1 <= 0.1 * svg.height, name << ".svg: blank band at the bottom, " << svg.height - ink.y1 << " px of " << svg.height);
  }
}

// ---- the PNG against its SVG -------------------------------------------------------------------

namespace {

/// A raw DEFLATE stream (RFC 1951) inflated: stored, fixed and dynamic Huffman blocks. Throws
/// on a malformed stream. (The test reads the PNGs itself, so that it depends on no library.)
class Inflater {
 public:
  explicit Inflater(const std::string& in, std::size_t from) : in_(in), pos_(from) {}
  std::string run() {
    for (int last = 0; !last;) {
      last = bits(1);
      const int type = bits(2);
      if (type == 0) stored();
      else if (type == 1) fixed();
      else if (type == 2) dynamic();
      else throw std::runtime_error("inflate: bad block type");
    }
    return out_;
  }

 private:
  struct Huffman {
    std::array<int, 16> count{};
    std::vector<int> symbol;
  };
  int bits(int need) {
    std::uint64_t v = buf_;
    while (cnt_ < need) {
      if (pos_ >= in_.size()) throw std::runtime_error("inflate: stream ends early");
      v |= std::uint64_t(static_cast<unsigned char>(in_[pos_++])) << cnt_;
      cnt_ += 8;
    }
    buf_ = v >> need;
    cnt_ -= need;
    return int(v & ((std::uint64_t(1) << need) - 1));
  }
  static Huffman build(const int* lengths, int n) {
    Huffman h;
    for (int s = 0; s < n; ++s) ++h.count[std::size_t(lengths[s])];
    std::array<int, 16> offs{};
    for (int len = 1; len < 15; ++len) offs[std::size_t(len + 1)] = offs[std::size_t(len)] + h.count[std::size_t(len)];
    h.symbol.assign(std::size_t(n), 0);
    for (int s = 0; s < n; ++s)
      if (lengths[s]) h.symbol[std::size_t(offs[std::size_t(lengths[s])]++)] = s;
    return h;
  }
  int decode(const Huffman& h) {
    int code = 0, first = 0, index = 0;
    for (int len = 1; len <= 15; ++len) {
      code |= bits(1);
      const int count = h.count[std::size_t(len)];
      if (code - count < first) return h.symbol[std::size_t(index + (code - first))];
      index += count, first += count;
      first <<= 1, code <<= 1;
    }
    throw std::runtime_error("inflate: bad code");
  }
  void stored() {
    buf_ = 0, cnt_ = 0;
    if (pos_ + 4 > in_.size()) throw std::runtime_error("inflate: stored block ends early");
    const std::size_t len = static_cast<unsigned char>(in_[pos_]) | std::size_t(static_cast<unsigned char>(in_[pos_ + 1])) << 8;
    pos_ += 4;
    if (pos_ + len > in_.size()) throw std::runtime_error("inflate: stored block ends early");
    out_.append(in_, pos_, len);
    pos_ += len;
  }
  void codes(const Huffman& lencode, const Huffman& distcode) {
    static const int lbase[] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
    static const int lext[] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
    static const int dbase[] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537, 2049, 3073,
                                4097, 6145, 8193, 12289, 16385, 24577};
    static const int dext[] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
    for (;;) {
      int sym = decode(lencode);
      if (sym < 256) out_ += char(sym);
      else if (sym == 256) return;
      else {
        sym -= 257;
        if (sym >= 29) throw std::runtime_error("inflate: bad length");
        const int len = lbase[sym] + bits(lext[sym]);
        const int ds = decode(distcode);
        if (ds >= 30) throw std::runtime_error("inflate: bad distance");
        const std::size_t dist = std::size_t(dbase[ds] + bits(dext[ds]));
        if (dist > out_.size()) throw std::runtime_error("inflate: distance too far back");
        for (int k = 0; k < len; ++k) out_ += out_[out_.size() - dist];
      }
    }
  }
  void fixed() {
    int l[288], d[30];
    for (int s = 0; s < 288; ++s) l[s] = s < 144 ? 8 : s < 256 ? 9 : s < 280 ? 7 : 8;
    for (int& x : d) x = 5;
    codes(build(l, 288), build(d, 30));
  }
  void dynamic() {
    static const int order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    const int nlen = bits(5) + 257, ndist = bits(5) + 1, ncode = bits(4) + 4;
    int lengths[320] = {};
    for (int k = 0; k < ncode; ++k) lengths[order[k]] = bits(3);
    const Huffman lencode = build(lengths, 19);
    int k = 0;
    while (k < nlen + ndist) {
      int sym = decode(lencode);
      if (sym < 16) {
        lengths[k++] = sym;
        continue;
      }
      int len = 0, rep;
      if (sym == 16) {
        if (k == 0) throw std::runtime_error("inflate: repeat with no length");
        len = lengths[k - 1], rep = 3 + bits(2);
      } else if (sym == 17) rep = 3 + bits(3);
      else rep = 11 + bits(7);
      if (k + rep > nlen + ndist) throw std::runtime_error("inflate: too many lengths");
      while (rep--) lengths[k++] = len;
    }
    codes(build(lengths, nlen), build(lengths + nlen, ndist));
  }
  const std::string& in_;
  std::size_t pos_;
  std::uint64_t buf_ = 0;
  int cnt_ = 0;
  std::string out_;
};

/// A PNG's pixels as an ink mask (true where a pixel is darker than 235 in some channel, or
/// not transparent over white): 8-bit grey, RGB, grey+alpha or RGBA, not interlaced (what
/// pngcairo writes). Throws on anything else.
struct InkImage {
  int w = 0, h = 0;
  std::vector<bool> ink;
};
InkImage pngInk(const std::string& data) {
  const auto [w, h] = pngSize(data);
  if (w <= 0) throw std::runtime_error("not a PNG");
  const int depth = static_cast<unsigned char>(data[24]), type = static_cast<unsigned char>(data[25]),
            interlace = static_cast<unsigned char>(data[28]);
  const int channels = type == 0 ? 1 : type == 2 ? 3 : type == 4 ? 2 : type == 6 ? 4 : 0;
  if (depth != 8 || channels == 0 || interlace != 0) throw std::runtime_error("PNG: only 8-bit grey/RGB(A), not interlaced");
  std::string z;
  for (std::size_t at = 8; at + 8 <= data.size();) {
    const std::size_t len = bigEndian32(data, at);
    if (data.compare(at + 4, 4, "IDAT") == 0) z.append(data, at + 8, len);
    at += 12 + len;
  }
  const std::string raw = Inflater(z, 2).run();  // after the 2-byte zlib header
  const std::size_t stride = std::size_t(w) * std::size_t(channels);
  if (raw.size() < std::size_t(h) * (stride + 1)) throw std::runtime_error("PNG: too little pixel data");
  std::vector<unsigned char> prev(stride, 0), cur(stride);
  InkImage img{w, h, std::vector<bool>(std::size_t(w) * std::size_t(h))};
  for (int y = 0; y < h; ++y) {
    const std::size_t row = std::size_t(y) * (stride + 1);
    const int filter = static_cast<unsigned char>(raw[row]);
    for (std::size_t i = 0; i < stride; ++i) {
      const int x = static_cast<unsigned char>(raw[row + 1 + i]);
      const int a = i >= std::size_t(channels) ? cur[i - std::size_t(channels)] : 0, b = prev[i],
                c = i >= std::size_t(channels) ? prev[i - std::size_t(channels)] : 0;
      int p = 0;
      if (filter == 1) p = a;
      else if (filter == 2) p = b;
      else if (filter == 3) p = (a + b) / 2;
      else if (filter == 4) {
        const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
        p = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      } else if (filter != 0) throw std::runtime_error("PNG: bad filter");
      cur[i] = static_cast<unsigned char>(x + p);
    }
    for (int x = 0; x < w; ++x) {
      const unsigned char* px = &cur[std::size_t(x) * std::size_t(channels)];
      const bool hasAlpha = channels == 2 || channels == 4;
      const int alpha = hasAlpha ? px[channels - 1] : 255;
      int darkest = 255;
      for (int k = 0; k < (hasAlpha ? channels - 1 : channels); ++k) darkest = std::min<int>(darkest, px[k]);
      // Over white: a channel shows as 255 - alpha (255 - v) / 255.
      img.ink[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 255 - alpha * (255 - darkest) / 255 < 235;
    }
    std::swap(prev, cur);
  }
  return img;
}

/// The blank bands of each cell of a PNG (as cellBands does for an SVG), and each cell's share
/// of ink pixels.
std::vector<std::array<double, 5>> pngCellBands(const InkImage& img, int cols, int rows) {
  const double cw = double(img.w) / cols, ch = double(img.h) / rows;
  std::vector<Box> ink(std::size_t(cols * rows), Box{1e300, 1e300, -1e300, -1e300});
  std::vector<double> count(std::size_t(cols * rows), 0);
  for (int y = 0; y < img.h; ++y)
    for (int x = 0; x < img.w; ++x) {
      if (!img.ink[std::size_t(y) * std::size_t(img.w) + std::size_t(x)]) continue;
      const std::size_t k = std::size_t(std::min(rows - 1, int(y / ch)) * cols + std::min(cols - 1, int(x / cw)));
      Box& b = ink[k];
      b = {std::min(b.x0, double(x)), std::min(b.y0, double(y)), std::max(b.x1, x + 1.0), std::max(b.y1, y + 1.0)};
      ++count[k];
    }
  std::vector<std::array<double, 5>> out;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const std::size_t k = std::size_t(r * cols + c);
      const Box& b = ink[k];
      if (b.x0 > b.x1) {
        out.push_back({1, 1, 1, 1, 0});
        continue;
      }
      out.push_back({(b.x0 - c * cw) / cw, ((c + 1) * cw - b.x1) / cw, (b.y0 - r * ch) / ch, ((r + 1) * ch - b.y1) / ch, count[k] / (cw * ch)});
    }
  return out;
}

}  // namespace

TEST_CASE("figures the PNG reader inflates and unfilters what pngcairo writes") {
  // A 3 x 2 RGB PNG made by hand: a stored (uncompressed) deflate block, filters None and Sub.
  // Row 0: white, black, white; row 1 (Sub): white, then +0 (white), then -255 (black).
  const std::string rows("\x00\xff\xff\xff\x00\x00\x00\xff\xff\xff"
                         "\x01\xff\xff\xff\x00\x00\x00\x01\x01\x01", 20);
  std::string z("\x78\x01", 2);
  z += '\x01';  // final stored block
  z += char(rows.size()), z += '\0', z += char(~rows.size()), z += '\xff';
  z += rows;
  auto chunk = [](const std::string& type, const std::string& body) {
    std::string c;
    for (int k = 3; k >= 0; --k) c += char((body.size() >> (8 * k)) & 0xff);
    return c + type + body + std::string(4, '\0');  // the CRC is not read
  };
  const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", std::string("\0\0\0\x03\0\0\0\x02\x08\x02\0\0\0", 13)) +
                          chunk("IDAT", z) + chunk("IEND", "");
  const InkImage img = pngInk(png);
  REQUIRE(img.w == 3);
  REQUIRE(img.h == 2);
  CHECK(img.ink == std::vector<bool>{false, true, false, false, false, true});
  // A fixed-Huffman stream: "aaaa" as literal a then a copy (distance 1, length 3).
  const std::string fixedAaaa("\x4b\x04\x02\x00", 4);
  CHECK(Inflater(fixedAaaa, 0).run() == "aaaa");
  CHECK_THROWS(Inflater(std::string("\x07", 1), 0).run());  // block type 3
}

TEST_CASE("figures every PNG shows what its SVG shows in each panel") {
  REQUIRE(svgs().size() >= 20);
  const fs::path dir = figureRun().dir;
  int compared = 0;
  const char* side[] = {"left", "right", "top", "bottom"};
  for (const auto& [name, svg] : svgs()) {
    const fs::path png = dir / (name + ".png");
    if (!fs::exists(png)) continue;
    const auto [cols, rows] = panelGrid(svg);
    const auto s = cellBands(svg, cols, rows);
    const auto p = pngCellBands(pngInk(readAll(png)), cols, rows);
    ++compared;
    for (std::size_t k = 0; k < s.size(); ++k) {
      CHECK_MESSAGE(p[k][4] > 0.002, name << ".png panel " << std::string(1, char('a' + k)) << " is blank: " << 100 * p[k][4] << " % ink");
      // The outer sides only: a text that crosses into the next cell (a tick label, a long
      // title) is split between the cells by its box in the SVG, by its pixels in the PNG.
      const int col = int(k) % cols, row = int(k) / cols;
      const bool outer[4] = {col == 0, col == cols - 1, row == 0, row == rows - 1};
      for (int e = 0; e < 4; ++e)
        if (outer[e])
          CHECK_MESSAGE(std::abs(p[k][std::size_t(e)] - s[k][std::size_t(e)]) <= 0.04,
                      name << " panel " << std::string(1, char('a' + k)) << ": the ink ends " << 100 * p[k][std::size_t(e)] << " % from the "
                           << std::string(side[e]) << " of its cell in the PNG, " << 100 * s[k][std::size_t(e)] << " % in the SVG");
    }
  }
  CHECK(compared >= 20);
}

// ---- the style's roles -----------------------------------------------------------------------

namespace {

std::string hexColour(const std::string& c) { return dttest::svgHexColour(c); }

/// The colour roles of figures/ch2/style.gp: C_NAME = "#rrggbb".
std::map<std::string, std::string> styleRoles() {
  const std::string text = readAll(kRoot / "figures/ch2/style.gp");
  std::map<std::string, std::string> roles;
  const std::regex role(R"re((C_[A-Z_]+) = "(#[0-9a-fA-F]{6})")re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), role); it != std::sregex_iterator(); ++it)
    roles[(*it)[1]] = hexColour((*it)[2]);
  return roles;
}

/// A stroke that is a circle: closed, at least 48 points, all at one distance from their mean.
bool isCircle(const Stroke& st) {
  if (st.pts.size() < 48) return false;
  double cx = 0, cy = 0;
  for (const auto& [x, y] : st.pts) cx += x, cy += y;
  cx /= double(st.pts.size()), cy /= double(st.pts.size());
  double lo = 1e300, hi = 0;
  for (const auto& [x, y] : st.pts) {
    const double r = std::hypot(x - cx, y - cy);
    lo = std::min(lo, r), hi = std::max(hi, r);
  }
  return hi > 10 && hi - lo < 0.03 * hi;
}

/// Every breach of the style's roles in one figure: circles not dark-blue dashed, super-vertex
/// labels without their purple square, role colours where the figure shows no such object.
std::vector<std::string> roleBreaches(const std::string& name, const Svg& svg, const std::map<std::string, std::string>& roles) {
  std::vector<std::string> out;
  auto colourOf = [&](const std::string& role) { return roles.at(role); };
  // (Figure 2.9's discs are vertex markers with a count inside, drawn as filled circles.)
  for (const Stroke& st : svg.strokes)
    if (name != "fig2_9" && isCircle(st) && (hexColour(st.colour) != colourOf("C_CIRCLE") || st.dash.empty()))
      out.push_back("a circle in panel " + std::to_string(st.panel) + " is " + hexColour(st.colour) + (st.dash.empty() ? " solid" : " dashed") +
                    ", not the circumcircles' dark-blue dashed");
  for (const Text& t : svg.texts) {
    if (t.str.rfind("\xf0\x9d\x91\x9d\xe2\x88\x92", 0) != 0) continue;  // "𝑝−": a super-vertex p_{-k}
    if (hexColour(t.colour) != colourOf("C_SUPER")) out.push_back("super-vertex label " + t.str + " is not purple");
    const Box b = textBox(t);
    bool square = false;
    for (const Marker& m : svg.markers)
      if (m.panel == t.panel && m.shape == "#gpPt4" && hexColour(m.colour) == colourOf("C_SUPER") &&
          std::hypot(m.x - 0.5 * (b.x0 + b.x1), m.y - 0.5 * (b.y0 + b.y1)) < 4 * (b.y1 - b.y0))
        square = true;
    if (!square) out.push_back("super-vertex label " + t.str + " (panel " + std::to_string(t.panel) + ") has no purple square beside it");
  }
  // Colours that name an object only where the figure shows that object.
  const std::map<std::string, std::set<std::string>> only = {
      {"C_CONFLICT", {"fig2_6", "fig_recovery_frames", "fig_outside_hull", "fig_flip"}},
      {"C_CAVITY_EDGE", {"fig2_1", "fig2_3", "fig2_10", "fig_flip", "fig_outside_hull"}},
      {"C_SUPER", {"fig2_5", "fig2_6", "fig_recovery_frames"}},
      {"C_KERNEL_EDGE", {"fig2_2"}},
      {"C_SIGHT", {"fig2_2"}}};
  for (const auto& [role, figures] : only) {
    if (figures.count(name)) continue;
    const std::string c = colourOf(role);
    for (const Stroke& st : svg.strokes)
      if (hexColour(st.colour) == c) {
        out.push_back("a line in " + role + "'s colour " + c + ", which this figure has no object of");
        break;
      }
    for (const Marker& m : svg.markers)
      if (hexColour(m.colour) == c) {
        out.push_back("a marker in " + role + "'s colour " + c + ", which this figure has no object of");
        break;
      }
  }
  return out;
}

}  // namespace

TEST_CASE("figures the role check finds a solid circle and a super-vertex without its square") {
  const auto roles = styleRoles();
  REQUIRE(roles.count("C_CIRCLE") == 1);
  REQUIRE(roles.at("C_CIRCLE") == "#1a3f8f");
  Svg svg;
  Stroke circle{{}, {0}, 2, "rgb( 26,  63, 143)", "6,4", 1, 1};
  for (int k = 0; k <= 96; ++k) circle.pts.push_back({100 + 40 * std::cos(k * M_PI / 48), 100 + 40 * std::sin(k * M_PI / 48)});
  svg.strokes.push_back(circle);
  CHECK(roleBreaches("fig2_1", svg, roles).empty());
  svg.strokes[0].dash = "";  // solid: not the circumcircles' style
  CHECK(roleBreaches("fig2_1", svg, roles).size() == 1);
  svg.strokes[0].dash = "6,4";
  svg.strokes[0].colour = "rgb( 46, 125,  50)";  // the ball's green
  CHECK(roleBreaches("fig2_1", svg, roles).size() == 1);
  svg.strokes.clear();
  Text super{"\xf0\x9d\x91\x9d\xe2\x88\x92" "1", 50, 50, 0, "middle", "rgb(123,  50, 148)", {{"DejaVu Math TeX Gyre", "\xf0\x9d\x91\x9d\xe2\x88\x92" "1", 20, 0}}, 1, true, 1};
  svg.texts.push_back(super);
  CHECK(roleBreaches("fig2_5", svg, roles).size() == 1);  // no square
  svg.markers.push_back({60, 70, 5, "#gpPt4", "rgb(123,  50, 148)", 1, 2});
  CHECK(roleBreaches("fig2_5", svg, roles).empty());
  CHECK(roleBreaches("fig_brio_rounds", svg, roles).size() == 1);  // purple where no super-vertex is
}

TEST_CASE("figures every figure keeps the style's roles for circles super-vertices and named objects") {
  REQUIRE(svgs().size() >= 20);
  const auto roles = styleRoles();
  for (const auto& [name, svg] : svgs())
    for (const std::string& b : roleBreaches(name, svg, roles)) FAIL_CHECK(name << ".svg: " << b);
}
