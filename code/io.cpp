#include "io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace dt {

namespace {

struct Line {
  long number;                      // 1-based line number in the file
  std::vector<std::string> fields;  // whitespace-separated, comment removed
  std::string text;                 // the line as written (for messages)
};

[[noreturn]] void bad(const std::string& path, long line, const std::string& what) {
  throw InputError(path + ":" + std::to_string(line) + ": " + what);
}

// A field or line as it can be printed in a message: control and non-ASCII bytes become '?',
// long values are cut.
std::string shown(const std::string& s) {
  std::string out;
  for (char c : s.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
  return "'" + out + (s.size() > 40 ? "...'" : "'");
}

// The non-empty lines of the text, without comments. Rejects binary data.
std::vector<Line> splitLines(const std::string& text, const std::string& path) {
  std::vector<Line> out;
  std::size_t pos = 0;
  // A UTF-8 byte order mark (Windows editors write one) is not part of the first field.
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) pos = 3;
  long n = 0;
  while (pos < text.size()) {
    const std::size_t eol = std::min(text.find('\n', pos), text.size());
    std::string s = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++n;
    if (!s.empty() && s.back() == '\r') s.pop_back();  // Windows line ending
    for (std::size_t i = 0; i < s.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      if (c == '\r')
        bad(path, n, "carriage return inside the line (old Mac line endings?): lines must end "
                     "with LF or CR LF");
      if ((c < 32 && c != '\t' && c != '\v' && c != '\f') || c == 127)
        bad(path, n, "binary or control character (code " + std::to_string(c) + ") at column " +
                         std::to_string(i + 1) + ": not a text file");
    }
    Line l{n, {}, s};
    const auto hash = s.find('#');
    if (hash != std::string::npos) s.erase(hash);
    std::istringstream is(s);
    std::string f;
    while (is >> f) l.fields.push_back(f);
    if (!l.fields.empty()) out.push_back(std::move(l));
  }
  return out;
}

double toCoordinate(const std::string& path, long line, const std::string& f, const char* what) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(f.c_str(), &end);
  if (end == f.c_str() || *end != '\0')
    bad(path, line, std::string(what) + " " + shown(f) + " is not a number" +
                        (f.find(',') != std::string::npos
                             ? " (fields are separated by spaces; the decimal mark is '.')"
                             : ""));
  if (std::isnan(v)) bad(path, line, std::string(what) + " " + shown(f) + " is NaN");
  if (std::isinf(v))
    bad(path, line, std::string(what) + " " + shown(f) +
                        (errno == ERANGE ? " overflows a double" : " is infinite"));
  // strtod returns 0 for a nonzero value below the smallest subnormal: the point would move.
  if (v == 0 && errno == ERANGE)
    bad(path, line, std::string(what) + " " + shown(f) + " underflows to 0 in a double");
  return v;
}

bool isInteger(const std::string& f) {
  errno = 0;
  char* end = nullptr;
  std::strtol(f.c_str(), &end, 10);
  return end != f.c_str() && *end == '\0' && errno != ERANGE;
}

long toInteger(const std::string& path, long line, const std::string& f, const char* what) {
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(f.c_str(), &end, 10);
  if (end == f.c_str() || *end != '\0' || errno == ERANGE)
    bad(path, line, std::string(what) + " " + shown(f) + " is not an integer");
  return v;
}

std::string plural(std::size_t n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

}  // namespace

std::string readFile(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InputError(path + ": is a directory, not a point file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file for reading");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return s.str();
}

PointSet parseNode(const std::string& text, const std::string& path) {
  const std::vector<Line> lines = splitLines(text, path);
  PointSet ps;
  ps.path = path;
  if (lines.empty())
    throw InputError(path + (text.empty() ? ": empty file" : ": only blank lines and comments") +
                     " (a .node file starts with '<points> 2 <attributes> <markers>')");
  const Line& h = lines[0];
  const char* headerForm = " (a .node file starts with '<points> 2 <attributes> <markers>')";
  if (h.fields.size() > 4)
    bad(path, h.number, "header " + shown(h.text) + " has " + plural(h.fields.size(), "field") +
                            "; expected at most 4" + headerForm);
  if (!isInteger(h.fields[0]))
    bad(path, h.number, "point count " + shown(h.fields[0]) + " is not an integer" +
                            headerForm + (h.fields.size() == 2 ? "; for 'x y' lines do not name "
                                                                 "the file *.node"
                                                               : ""));
  const long n = toInteger(path, h.number, h.fields[0], "point count");
  const long dim = h.fields.size() > 1 ? toInteger(path, h.number, h.fields[1], "dimension") : 2;
  const long nattr =
      h.fields.size() > 2 ? toInteger(path, h.number, h.fields[2], "attribute count") : 0;
  const long nmark =
      h.fields.size() > 3 ? toInteger(path, h.number, h.fields[3], "marker count") : 0;
  if (n < 0) bad(path, h.number, "point count " + std::to_string(n) + " is negative");
  if (dim != 2)
    bad(path, h.number, "dimension " + std::to_string(dim) + " is not 2" + headerForm +
                            (h.fields.size() == 3 ? "; is the header missing?" : ""));
  if (nattr < 0 || nattr > 1000)
    bad(path, h.number, "attribute count " + std::to_string(nattr) + " is not in 0..1000");
  if (nmark != 0 && nmark != 1)
    bad(path, h.number, "marker count " + std::to_string(nmark) + " is not 0 or 1");
  const std::size_t have = lines.size() - 1;
  if (std::size_t(n) > have)
    bad(path, lines.back().number,
        "file ends after " + std::to_string(have) + " of the " + std::to_string(n) +
            " points announced in the header (line " + std::to_string(h.number) + ")");
  if (std::size_t(n) < have)
    bad(path, lines[n + 1].number,
        "extra line " + shown(lines[n + 1].text) + ": the header (line " +
            std::to_string(h.number) + ") announces " + plural(std::size_t(n), "point"));
  const std::size_t want = 3 + std::size_t(nattr) + std::size_t(nmark);
  ps.xy.reserve(2 * std::size_t(n));
  for (long i = 0; i < n; ++i) {
    const Line& l = lines[i + 1];
    if (l.fields.size() != want)
      bad(path, l.number, shown(l.text) + " has " + plural(l.fields.size(), "field") +
                              "; expected " + std::to_string(want) + " (number, x, y" +
                              (nattr ? ", " + plural(std::size_t(nattr), "attribute") : "") +
                              (nmark ? ", marker" : "") + ", as the header on line " +
                              std::to_string(h.number) + " says)");
    const long num = toInteger(path, l.number, l.fields[0], "point number");
    if (i == 0) {
      if (num != 0 && num != 1)
        bad(path, l.number, "first point number is " + std::to_string(num) + "; expected 0 or 1");
      ps.firstIndex = num;
    } else if (num != ps.firstIndex + i) {
      bad(path, l.number, "point number " + std::to_string(num) + "; expected " +
                              std::to_string(ps.firstIndex + i) + " (numbers start at " +
                              std::to_string(ps.firstIndex) + " on line " +
                              std::to_string(lines[1].number) + " and follow on)");
    }
    ps.xy.push_back(toCoordinate(path, l.number, l.fields[1], "x"));
    ps.xy.push_back(toCoordinate(path, l.number, l.fields[2], "y"));
    for (std::size_t k = 3; k < 3 + std::size_t(nattr); ++k)
      toCoordinate(path, l.number, l.fields[k], "attribute");
    if (nmark) toInteger(path, l.number, l.fields[want - 1], "boundary marker");
    ps.number.push_back(num);
    ps.line.push_back(l.number);
  }
  return ps;
}

PointSet parseXY(const std::string& text, const std::string& path) {
  const std::vector<Line> lines = splitLines(text, path);
  PointSet ps;
  ps.path = path;
  ps.firstIndex = 1;
  if (lines.empty())
    throw InputError(path + (text.empty() ? ": empty file" : ": only blank lines and comments") +
                     " (expected 'x y' lines)");
  for (const Line& l : lines) {
    if (l.fields.size() != 2)
      bad(path, l.number,
          shown(l.text) + " has " + plural(l.fields.size(), "field") + "; expected 'x y'" +
              (l.number == lines[0].number && l.fields.size() == 4
                   ? " (a .node header? name the file *.node)"
                   : ""));
    ps.xy.push_back(toCoordinate(path, l.number, l.fields[0], "x"));
    ps.xy.push_back(toCoordinate(path, l.number, l.fields[1], "y"));
    ps.number.push_back(long(ps.number.size()) + 1);
    ps.line.push_back(l.number);
  }
  return ps;
}

PointSet readNode(const std::string& path) { return parseNode(readFile(path), path); }

PointSet readXY(const std::string& path) { return parseXY(readFile(path), path); }

PointSet readPoints(const std::string& path) {
  const std::string ext = ".node";
  if (path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0)
    return readNode(path);
  return readXY(path);
}

void writeFileAtomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out << content;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error(path + ": write failed");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot rename temporary file into place");
  }
}

std::string eleText(const std::vector<std::array<int, 3>>& tri, const std::vector<long>& number,
                    long firstIndex) {
  std::string s;
  s.reserve(tri.size() * 32 + 32);
  s += std::to_string(tri.size()) + " 3 0\n";
  for (std::size_t t = 0; t < tri.size(); ++t) {
    s += std::to_string(long(t) + firstIndex);
    for (int k = 0; k < 3; ++k) {
      s += ' ';
      s += std::to_string(number[tri[t][k]]);
    }
    s += '\n';
  }
  return s;
}

std::string mshText(const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri) {
  std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n";
  const std::size_t n = xy.size() / 2;
  s += std::to_string(n) + "\n";
  char buf[96];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, "%zu %.17g %.17g 0\n", i + 1, xy[2 * i], xy[2 * i + 1]);
    s += buf;
  }
  s += "$EndNodes\n$Elements\n" + std::to_string(tri.size()) + "\n";
  for (std::size_t t = 0; t < tri.size(); ++t) {
    std::snprintf(buf, sizeof buf, "%zu 2 2 0 1 %d %d %d\n", t + 1, tri[t][0] + 1, tri[t][1] + 1,
                  tri[t][2] + 1);
    s += buf;
  }
  s += "$EndElements\n";
  return s;
}

std::string svgText(const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri,
                    int size) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
    x0 = std::min(x0, xy[i]);
    x1 = std::max(x1, xy[i]);
    y0 = std::min(y0, xy[i + 1]);
    y1 = std::max(y1, xy[i + 1]);
  }
  // Scale in long double-free steps: (x - x0) / w can overflow for w near DBL_MAX, so halve.
  const double w = std::max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2);
  const double scale = w > 0 ? (size - 20) / 2.0 / w : 1.0;
  auto px = [&](int i) { return 10 + (xy[2 * i] / 2 - x0 / 2) * scale; };
  auto py = [&](int i) { return size - 10 - (xy[2 * i + 1] / 2 - y0 / 2) * scale; };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(size) +
                  "\" height=\"" + std::to_string(size) + "\">\n" +
                  "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
                  "<g fill=\"#dde8f5\" stroke=\"#234\" stroke-width=\"0.5\">\n";
  char buf[160];
  for (const auto& t : tri) {
    std::snprintf(buf, sizeof buf, "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\"/>\n",
                  px(t[0]), py(t[0]), px(t[1]), py(t[1]), px(t[2]), py(t[2]));
    s += buf;
  }
  s += "</g>\n</svg>\n";
  return s;
}

std::string gnuplotTriangles(const std::vector<double>& xy,
                             const std::vector<std::array<int, 3>>& tri) {
  std::string s;
  char buf[96];
  for (const auto& t : tri) {
    for (int k = 0; k <= 3; ++k) {
      const int i = t[k % 3];
      std::snprintf(buf, sizeof buf, "%.17g %.17g\n", xy[2 * i], xy[2 * i + 1]);
      s += buf;
    }
    s += "\n";
  }
  return s;
}

}  // namespace dt
