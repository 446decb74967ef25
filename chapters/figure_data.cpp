// The bodies of chapters/figure_data.h's functions (segments, labels, panels, math text), compiled once.
#include "figure_data.h"

namespace ch {

double segDistance(const Seg& s, double x, double y) {
  const double dx = s.x1 - s.x0, dy = s.y1 - s.y0, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((x - s.x0) * dx + (y - s.y0) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(x - s.x0 - t * dx, y - s.y0 - t * dy);
}

std::pair<double, double> labelSpot(double x, double y, double r, double hw, double hh,
                                    const std::vector<Seg>& segs,
                                    const std::vector<double>& avoid) {
  std::pair<double, double> best = {x + r, y + r};
  double bestScore = -1;
  for (int ring = 0; ring < 2; ++ring)  // near the point first; farther if the near ring is crowded
    for (int k = 0; k < 24; ++k) {
      const double a = M_PI / 4 + 2 * M_PI * k / 24, rr = ring ? 2.2 * r : r;
      // The box's centre on an ellipse, so that its near side is about rr from the point: a
      // wide label needs more room sideways than up or down.
      const double cx = x + (rr + hw) * std::cos(a), cy = y + (rr + hh) * std::sin(a);
      double score = 1e300;
      for (double fx : {-1.0, 0.0, 1.0})
        for (double fy : {-1.0, 0.0, 1.0}) {
          const double px = cx + fx * hw, py = cy + fy * hh;
          for (const Seg& s : segs) score = std::min(score, segDistance(s, px, py));
          for (std::size_t i = 0; i + 1 < avoid.size(); i += 2)
            score = std::min(score, std::hypot(px - avoid[i], py - avoid[i + 1]));
        }
      if (ring) score = std::min(score, 0.5 * r);  // a far label only wins if no near one is clear
      if (score > bestScore + 1e-12) bestScore = score, best = {cx, cy};
    }
  return best;
}

std::vector<Seg> triangleSegs(const std::vector<double>& xy,
                              const std::vector<std::array<int, 3>>& tri) {
  std::map<std::pair<int, int>, bool> seen;
  std::vector<Seg> s;
  for (const auto& t : tri)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (!seen.emplace(std::minmax(a, b), true).second) continue;
      s.push_back({xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1]});
    }
  return s;
}

std::string gnuplotSegs(const std::vector<Seg>& segs) {
  std::string out;
  char buf[128];
  for (const Seg& s : segs) {
    std::snprintf(buf, sizeof buf, "%.10g %.10g\n%.10g %.10g\n\n", s.x0, s.y0, s.x1, s.y1);
    out += buf;
  }
  return out;
}

std::string circlePolyline(double cx, double cy, double r, int n) {
  std::string out;
  char buf[96];
  for (int i = 0; i <= n; ++i) {
    const double t = 2 * M_PI * i / n;
    std::snprintf(buf, sizeof buf, "%.10g %.10g\n", cx + r * std::cos(t), cy + r * std::sin(t));
    out += buf;
  }
  return out + "\n";
}

std::string dashedCirclePolyline(double cx, double cy, double r, int dashes, double on) {
  std::string s;
  char buf[80];
  for (int k = 0; k < dashes; ++k) {
    const double a0 = 2 * M_PI * k / dashes, a1 = 2 * M_PI * (k + on) / dashes;
    for (int j = 0; j <= 4; ++j) {
      const double a = a0 + (a1 - a0) * j / 4;
      std::snprintf(buf, sizeof buf, "%.10g %.10g\n", cx + r * std::cos(a), cy + r * std::sin(a));
      s += buf;
    }
    s += "\n";
  }
  return s;
}

std::string gnuplotEdges(const std::vector<double>& xy,
                         const std::vector<std::array<int, 3>>& tri) {
  return gnuplotSegs(triangleSegs(xy, tri));
}

bool clipLine(double ax, double ay, double dx, double dy, double x0, double x1, double y0,
              double y1, Seg& out) {
  double t0 = -1e300, t1 = 1e300;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - x0, x1 - ax, ay - y0, y1 - ay};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  if (t0 > t1) return false;
  out = {ax + t0 * dx, ay + t0 * dy, ax + t1 * dx, ay + t1 * dy};
  return true;
}

void appendUtf8(std::string& out, char32_t cp) {
  if (cp < 0x80) out += char(cp);
  else if (cp < 0x800) out += char(0xC0 | (cp >> 6)), out += char(0x80 | (cp & 0x3F));
  else if (cp < 0x10000)
    out += char(0xE0 | (cp >> 12)), out += char(0x80 | ((cp >> 6) & 0x3F)), out += char(0x80 | (cp & 0x3F));
  else
    out += char(0xF0 | (cp >> 18)), out += char(0x80 | ((cp >> 12) & 0x3F)), out += char(0x80 | ((cp >> 6) & 0x3F)),
        out += char(0x80 | (cp & 0x3F));
}

std::string mathText(const std::string& tex) {
  std::string out = std::string("{/'") + kMathFont + "' ";
  bool upright = false;
  int uprightDepth = 0, depth = 0;
  for (std::size_t i = 0; i < tex.size(); ++i) {
    const char c = tex[i];
    if (c == '\\') {
      std::size_t j = i + 1;
      while (j < tex.size() && std::isalpha(static_cast<unsigned char>(tex[j]))) ++j;
      const std::string cmd = tex.substr(i + 1, j - i - 1);
      auto arg = [&]() {  // the one-letter argument of \mathscr{X}
        if (j + 2 >= tex.size() || tex[j] != '{' || tex[j + 2] != '}') throw std::invalid_argument("mathText: bad argument in " + tex);
        const char a = tex[j + 1];
        j += 3;
        return a;
      };
      if (cmd == "sigma") appendUtf8(out, 0x1D70E);
      else if (cmd == "Sigma") appendUtf8(out, 0x03A3);
      else if (cmd == "Omega") appendUtf8(out, 0x03A9);
      else if (cmd == "cup") appendUtf8(out, 0x222A);
      else if (cmd == "subseteq") appendUtf8(out, 0x2286);
      else if (cmd == "not") appendUtf8(out, 0x0338);
      else if (cmd == "mathscr") {
        const char a = arg();
        // Script capitals: B, E, F, H, I, L, M, R live in Letterlike Symbols.
        static const std::map<char, char32_t> letterlike = {{'B', 0x212C}, {'E', 0x2130}, {'F', 0x2131}, {'H', 0x210B},
                                                            {'I', 0x2110}, {'L', 0x2112}, {'M', 0x2133}, {'R', 0x211B}};
        const auto it = letterlike.find(a);
        appendUtf8(out, it != letterlike.end() ? it->second : char32_t(0x1D49C + (a - 'A')));
      } else if (cmd == "mathrm") {
        if (j >= tex.size() || tex[j] != '{') throw std::invalid_argument("mathText: \\mathrm without braces in " + tex);
        upright = true;
        uprightDepth = depth;
        ++depth;
        ++j;
        i = j - 1;
        continue;
      } else throw std::invalid_argument("mathText: unknown command \\" + cmd + " in " + tex);
      i = j - 1;
      continue;
    }
    if (c == '{') ++depth, out += c;
    else if (c == '}') {
      --depth;
      if (upright && depth == uprightDepth) upright = false;  // the end of \mathrm{...}: no brace written
      else out += c;
    } else if (c == '-') appendUtf8(out, 0x2212);
    else if (!upright && c >= 'a' && c <= 'z') appendUtf8(out, c == 'h' ? char32_t(0x210E) : char32_t(0x1D44E + (c - 'a')));
    else if (!upright && c >= 'A' && c <= 'Z') appendUtf8(out, char32_t(0x1D434 + (c - 'A')));
    else out += c;
  }
  return out + "}";
}

std::string mathTextGif(const std::string& tex) {
  std::string out;
  const std::string italic = "{/'/usr/share/fonts/truetype/dejavu/DejaVuSerif-Italic.ttf' ";
  for (std::size_t i = 0; i < tex.size(); ++i) {
    const char c = tex[i];
    if (std::isalpha(static_cast<unsigned char>(c))) out += italic + c + "}";
    else if (c == '-') out += "{/'" + std::string(kMathFont) + "' \u2212}";
    else if (c == '\\') throw std::invalid_argument("mathTextGif: no commands in the GIF's labels: " + tex);
    else out += c;
  }
  return out;
}

std::string Panel::gnuplot() const {
  char b[400];
  std::snprintf(b, sizeof b,
                "set size noratio; set lmargin at screen %.6f; set rmargin at screen %.6f; "
                "set tmargin at screen %.6f; set bmargin at screen %.6f; set xrange [%.10g:%.10g]; set yrange [%.10g:%.10g]",
                left / W, (left + w) / W, 1 - top / H, 1 - (top + h) / H, x0, x1, y0, y1);
  return b;
}

Panel fitPanel(double W, double H, double cellLeft, double cellTop, double cellW, double cellH, double bx0,
               double bx1, double by0, double by1, double pad) {
  Panel p;
  p.W = W, p.H = H;
  const double aw = cellW - 2 * pad, ah = cellH - 2 * pad;
  const double s = std::min(aw / (bx1 - bx0), ah / (by1 - by0));
  p.w = aw, p.h = ah;
  p.left = cellLeft + pad, p.top = cellTop + pad;
  const double cx = 0.5 * (bx0 + bx1), cy = 0.5 * (by0 + by1);
  p.x0 = cx - 0.5 * aw / s, p.x1 = cx + 0.5 * aw / s;
  p.y0 = cy - 0.5 * ah / s, p.y1 = cy + 0.5 * ah / s;
  return p;
}

FigureSize figureSize(const std::string& name, const std::string& styleGp) {
  std::FILE* f = std::fopen(styleGp.c_str(), "r");
  if (!f) throw std::runtime_error("cannot read " + styleGp);
  std::string text;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
  std::fclose(f);
  FigureSize s;
  const std::size_t at = text.find(" " + name + " ");
  if (at == std::string::npos || std::sscanf(text.c_str() + at + name.size() + 2, "%lf %lf", &s.W, &s.H) != 2)
    throw std::runtime_error(styleGp + ": figure " + name + " has no size in FIGSIZES");
  const std::size_t narrow = text.find("FIG8CM = ");
  const bool is8 = narrow != std::string::npos && text.find(" " + name + " ", narrow) < text.find('\n', narrow);
  s.em = s.W / (is8 ? 28.0 : 50.0);
  return s;
}

Panel cellPanel(const FigureSize& fs, int rows, int cols, int k, double bx0, double bx1, double by0, double by1,
                double bottomEm) {
  const double cw = fs.W / cols, ch = fs.H / rows, r = k / cols, c = k % cols, band = 2.0 * fs.em;
  return fitPanel(fs.W, fs.H, c * cw, r * ch + band, cw, ch - band - bottomEm * fs.em, bx0, bx1, by0, by1, 0.4 * fs.em);
}

double textWidthEm(const std::string& s) {
  double w = 0, scale = 1;
  std::vector<double> stack;
  bool inFont = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (inFont) {  // {/'Font' text: skip the font name up to the space after it
      if (c == '\'') {
        const std::size_t q = s.find('\'', i + 1);
        i = q == std::string::npos ? s.size() : q;
      } else if (c == ' ') inFont = false;
      continue;
    }
    if (c == '_' || c == '^') {
      if (i + 1 < s.size() && s[i + 1] == '{') {  // a script group: its '}' restores the size
        stack.push_back(scale);
        scale *= 0.8;
        ++i;
      } else if (i + 1 < s.size()) {  // a one-character script
        ++i;
        w += 0.62 * 0.8 * scale;
      }
      continue;
    }
    if (c == '{') {
      stack.push_back(scale);
      if (i + 1 < s.size() && s[i + 1] == '/') inFont = true, ++i;
      continue;
    }
    if (c == '}') {
      if (!stack.empty()) scale = stack.back(), stack.pop_back();
      continue;
    }
    if ((c & 0xC0) == 0x80) continue;  // a UTF-8 continuation byte
    w += (c == ' ' ? 0.34 : c == 'i' || c == 'l' || c == ',' || c == '.' || c == '(' || c == ')' ? 0.42 : 0.72) * scale;
  }
  return w;
}

// sqrt(x^2 + y^2) without std::hypot's care for overflow: px values, and the placer calls it
// millions of times (std::hypot was 70 % of Figure 2.5's search).
static inline double fastHypot(double x, double y) { return std::sqrt(x * x + y * y); }

void LabelPlacer::circle(double cx, double cy, double r, double widthPx) {
  for (int k = 0; k < 96; ++k) {
    const double a = 2 * M_PI * k / 96, b = 2 * M_PI * (k + 1) / 96;
    segment(cx + r * std::cos(a), cy + r * std::sin(a), cx + r * std::cos(b), cy + r * std::sin(b), widthPx);
  }
}

std::pair<double, double> LabelPlacer::place(double x, double y, const std::string& text, double preferDeg, double gap) {
  // The box around the anchor, px: gnuplot puts the baseline 0.33 em below the anchor; the
  // ink rises 0.78 em above it and falls 0.24 em below, a subscript 0.3 em lower.
  const bool sub = text.find('_') != std::string::npos, sup = text.find('^') != std::string::npos;
  const double hw = 0.5 * textWidthEm(text) * em_ + 1, up = (sup ? 0.75 : 0.47) * em_ + 1,
               down = (sub ? 0.85 : 0.6) * em_ + 1, hh = 0.5 * (up + down);
  const double X = p_.px(x), Y = p_.py(y);
  double bestScore = -1e300, bx = X, by = Y - hh - em_;
  for (int ring = 0; ring < 18; ++ring) {
    const double r = (0.2 + 0.22 * ring) * em_;
    for (int k = -1; k < 32; ++k) {
      if (k < 0 && std::isnan(preferDeg)) continue;
      const double a = k < 0 ? preferDeg * M_PI / 180 : M_PI / 4 + 2 * M_PI * k / 32;
      // The box's centre on an ellipse around the point, so that its near side is about r px
      // from it: a wide label needs more room sideways than up or down.
      const double ccx = X + (hw + r) * std::cos(a), ccy = Y - (hh + r) * std::sin(a) + 0.5 * (up - down);
      const PxBox b{ccx - hw, ccy - up, ccx + hw, ccy + down};
      double c = clearance(b);
      // Never nearer to another point than to its own: the reader pairs a label with the
      // nearest point.
      const double own = boxPoint(b, X, Y);
      for (const auto& d : discs_)
        if (fastHypot(d[0] - X, d[1] - Y) > 0.5 && boxPoint(b, d[0], d[1]) < own + 0.1 * em_) c = std::min(c, -0.5);
      const double score = std::min(c, gap) - 0.01 * ring;  // clear enough and near beats clearer but far
      if (c >= gap) {
        boxes_.push_back(b);
        return {p_.x0 + (ccx - p_.left) / p_.scale(), p_.y1 - (ccy - p_.top) / p_.scale()};
      }
      if (score > bestScore) bestScore = score, bx = ccx, by = ccy;
    }
  }
  boxes_.push_back({bx - hw, by - up, bx + hw, by + down});
  return {p_.x0 + (bx - p_.left) / p_.scale(), p_.y1 - (by - p_.top) / p_.scale()};
}

std::pair<double, double> LabelPlacer::placeAttached(double x, double y, const std::string& text,
                                                     const std::vector<Seg>& edges, double preferDeg, double gap,
                                                     double maxEm, double* angleDeg) {
  const bool sub = text.find('_') != std::string::npos, sup = text.find('^') != std::string::npos;
  const double hw = 0.5 * textWidthEm(text) * em_ + 1, up = (sup ? 0.75 : 0.47) * em_ + 1,
               down = (sub ? 0.85 : 0.6) * em_ + 1, hh = 0.5 * (up + down);
  const double X = p_.px(x), Y = p_.py(y);
  std::vector<std::array<double, 4>> px;
  for (const Seg& e : edges) px.push_back({p_.px(e.x0), p_.py(e.y0), p_.px(e.x1), p_.py(e.y1)});
  // Whether the anchor (ccx, ccy) keeps the rules: within maxEm, nearer its own point than any
  // other marker, no edge between.
  auto keepsRules = [&](double ccx, double ccy) {
    const PxBox b{ccx - hw, ccy - up, ccx + hw, ccy + down};
    const double midY = 0.5 * (b.y0 + b.y1);
    if (fastHypot(ccx - X, ccy - Y) > maxEm * em_ || fastHypot(ccx - X, midY - Y) > maxEm * em_) return false;
    const double own = boxPoint(b, X, Y), ownAnchor = fastHypot(ccx - X, ccy - Y);
    for (const auto& d : discs_)
      if (fastHypot(d[0] - X, d[1] - Y) > 0.5 &&
          (boxPoint(b, d[0], d[1]) < own + 0.1 * em_ || fastHypot(ccx - d[0], ccy - d[1]) < ownAnchor + 0.1 * em_))
        return false;
    for (const auto& e : px)
      if (crosses(X, Y, ccx, ccy, e)) return false;
    return true;
  };
  if (hasPreferAt_ && !farther_) {
    hasPreferAt_ = false;
    const double ccx = p_.px(preferAt_.first), ccy = p_.py(preferAt_.second);
    const PxBox b{ccx - hw, ccy - up, ccx + hw, ccy + down};
    if (keepsRules(ccx, ccy) && clearance(b) >= gap) {
      boxes_.push_back(b);
      if (angleDeg) *angleDeg = std::atan2(-(ccy - 0.5 * (up - down) - Y) / (hh + 1e-9), (ccx - X) / (hw + 1e-9)) * 180 / M_PI;
      return preferAt_;
    }
  }
  double bestScore = -1e300, bestC = -1e300, bx = NAN, by = NAN, ba = 0;
  for (int ring = 0; ring < 24; ++ring) {
    const double r = 0.08 * ring * em_;
    for (int k = -1; k < 48; ++k) {
      if (k < 0 && std::isnan(preferDeg)) continue;
      const double a = k < 0 ? preferDeg * M_PI / 180 : M_PI / 4 + 2 * M_PI * k / 48;
      const double ccx = X + (hw + r) * std::cos(a), ccy = Y - (hh + r) * std::sin(a) + 0.5 * (up - down);
      const PxBox b{ccx - hw, ccy - up, ccx + hw, ccy + down};
      if (!keepsRules(ccx, ccy)) continue;
      const double c = clearance(b);
      if (c >= gap) {
        boxes_.push_back(b);
        if (angleDeg) *angleDeg = a * 180 / M_PI;
        return {p_.x0 + (ccx - p_.left) / p_.scale(), p_.y1 - (ccy - p_.top) / p_.scale()};
      }
      const double score = c - 0.01 * ring;
      if (score > bestScore) bestScore = score, bestC = c, bx = ccx, by = ccy, ba = a;
    }
  }
  // Nothing within maxEm keeps off every line (a vertex with many edges): farther, up to
  // twice as far, on the same rules, before a label that touches a line.
  if (!farther_ && bestC < 0) {
    farther_ = true;
    const std::size_t nb = boxes_.size();
    double fa = NAN;
    const auto far = placeAttached(x, y, text, edges, preferDeg, gap, 2 * maxEm, &fa);
    farther_ = false;
    if (boxes_.size() > nb && clearance(boxes_.back(), true) >= gap) {
      if (angleDeg) *angleDeg = fa;
      return far;
    }
    boxes_.resize(nb);
  }
  if (std::isnan(bx)) return farther_ ? std::pair<double, double>{NAN, NAN} : place(x, y, text, preferDeg, gap);
  if (angleDeg) *angleDeg = ba * 180 / M_PI;
  boxes_.push_back({bx - hw, by - up, bx + hw, by + down});
  return {p_.x0 + (bx - p_.left) / p_.scale(), p_.y1 - (by - p_.top) / p_.scale()};
}

double LabelPlacer::clearance(const PxBox& b, bool skipLast) const {
  double c = std::min({b.x0 - p_.left, p_.left + p_.w - b.x1, b.y0 - p_.top, p_.top + p_.h - b.y1});
  for (const auto& s : segs_) {
    // A segment whose bounding box is already farther than c cannot lower it.
    const double gx = std::max({std::min(s[0], s[2]) - b.x1, b.x0 - std::max(s[0], s[2]), 0.0}),
                 gy = std::max({std::min(s[1], s[3]) - b.y1, b.y0 - std::max(s[1], s[3]), 0.0});
    if (std::max(gx, gy) - s[4] >= c) continue;
    c = std::min(c, boxSeg(b, s) - s[4]);
  }
  for (const auto& d : discs_) c = std::min(c, boxPoint(b, d[0], d[1]) - d[2]);
  for (std::size_t i = 0; i + (skipLast ? 1 : 0) < boxes_.size(); ++i) {
    const PxBox& o = boxes_[i];
    const double dx = std::max({o.x0 - b.x1, b.x0 - o.x1, 0.0}), dy = std::max({o.y0 - b.y1, b.y0 - o.y1, 0.0});
    c = std::min(c, (dx == 0 && dy == 0) ? -1e3 : fastHypot(dx, dy));  // never on a label
    const double shared = std::min(o.y1, b.y1) - std::max(o.y0, b.y0);
    if (sameLine_ > 0 && shared > 0.5 * std::min(o.y1 - o.y0, b.y1 - b.y0)) c = std::min(c, dx - sameLine_);
  }
  return c;
}

double LabelPlacer::boxPoint(const PxBox& b, double x, double y) {
  const double dx = std::max({b.x0 - x, 0.0, x - b.x1}), dy = std::max({b.y0 - y, 0.0, y - b.y1});
  return fastHypot(dx, dy);
}

bool LabelPlacer::crosses(double x, double y, double u, double v, const std::array<double, 4>& e) {
  const double dx = u - x, dy = v - y, ex = e[2] - e[0], ey = e[3] - e[1];
  const double den = dx * ey - dy * ex;
  if (std::fabs(den) < 1e-12) return false;
  const double t = ((e[0] - x) * ey - (e[1] - y) * ex) / den, s = ((e[0] - x) * dy - (e[1] - y) * dx) / den;
  const double len = fastHypot(dx, dy);
  return s >= 0 && s <= 1 && t * len > 1.5 && t <= 1;
}

double LabelPlacer::boxSeg(const PxBox& b, const std::array<double, 5>& s) {
  // Exact: 0 if the segment meets the box (clipped to it, Liang-Barsky), else the least of
  // the distances from its ends to the box and from the box's corners to it.
  const double dx = s[2] - s[0], dy = s[3] - s[1];
  double t0 = 0, t1 = 1;
  auto clip = [&](double p, double q) {
    if (p == 0) return q >= 0;
    const double r = q / p;
    if (p < 0) {
      if (r > t1) return false;
      t0 = std::max(t0, r);
    } else {
      if (r < t0) return false;
      t1 = std::min(t1, r);
    }
    return true;
  };
  if (clip(-dx, s[0] - b.x0) && clip(dx, b.x1 - s[0]) && clip(-dy, s[1] - b.y0) && clip(dy, b.y1 - s[1])) return 0;
  double best = std::min(boxPoint(b, s[0], s[1]), boxPoint(b, s[2], s[3]));
  const double len2 = dx * dx + dy * dy;
  for (const auto& [cx, cy] : {std::pair{b.x0, b.y0}, std::pair{b.x1, b.y0}, std::pair{b.x0, b.y1}, std::pair{b.x1, b.y1}}) {
    const double t = len2 > 0 ? std::clamp(((cx - s[0]) * dx + (cy - s[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, fastHypot(cx - s[0] - t * dx, cy - s[1] - t * dy));
  }
  return best;
}

}  // namespace ch
