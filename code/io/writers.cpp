// The writers of code/io/writers.h: a buffered Writer and the .ele, .msh, SVG and gnuplot texts.
#include "writers.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <unistd.h>

namespace dt {

namespace {
std::string sysReason() { return std::strerror(errno); }
}  // namespace

// ---- writing --------------------------------------------------------------------------------

Writer::Writer(int fd, std::string path, bool stream)
    : fd_(fd), path_(std::move(path)), stream_(stream) {
  buf_.resize(fd >= 0 ? std::size_t(1) << 20 : 4096);
}

void Writer::reserve(std::size_t n) {
  if (buf_.size() - used_ >= n) return;
  flush();
  if (buf_.size() - used_ < n) buf_.resize(std::max(2 * buf_.size(), used_ + n));
}

void Writer::flush() {
  if (fd_ < 0) return;
  std::size_t done = 0;
  while (done < used_) {
    const ssize_t r = ::write(fd_, buf_.data() + done, used_ - done);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      const std::string why = sysReason();
      if (!stream_) throw std::runtime_error(path_ + ": cannot write: " + why);
      // A pipe or a device keeps what it got: say so, and how much.
      throw std::runtime_error(path_ + ": cannot write: " + why + " (a stream: it got a partial " +
                               "write of " + std::to_string(sent_) + " bytes)");
    }
    done += std::size_t(r);
    sent_ += std::size_t(r);
  }
  used_ = 0;
}

Writer& Writer::put(std::string_view s) {
  reserve(s.size());
  std::memcpy(buf_.data() + used_, s.data(), s.size());
  used_ += s.size();
  return *this;
}

Writer& Writer::put(long v) {
  reserve(24);
  used_ = std::size_t(std::to_chars(buf_.data() + used_, buf_.data() + buf_.size(), v).ptr -
                      buf_.data());
  return *this;
}

Writer& Writer::put(double v, int precision) {
  reserve(precision < 0 ? 330 : 40);  // fixed notation of 1e308 has 309 digits
  char* b = buf_.data() + used_;
  char* e = buf_.data() + buf_.size();
  // %.2f for pixels (precision < 0 means fixed with -precision digits), %.{p}g otherwise.
  const auto r = precision < 0 ? std::to_chars(b, e, v, std::chars_format::fixed, -precision)
                               : std::to_chars(b, e, v, std::chars_format::general, precision);
  used_ = std::size_t(r.ptr - buf_.data());
  return *this;
}

namespace {
template <class Number>
void writeEleWith(Writer& w, const std::vector<Tri>& tri, long firstIndex,
                  Number number) {
  w.put(long(tri.size())).put(" 3 0\n");
  for (std::size_t t = 0; t < tri.size(); ++t) {
    w.put(long(t) + firstIndex);
    for (int k = 0; k < 3; ++k) w.put(' ').put(number(tri[t][k]));
    w.put('\n');
  }
}
}  // namespace

void writeEle(Writer& w, const std::vector<Tri>& tri, const std::vector<long>* number,
              long firstIndex) {
  writeEleWith(w, tri, firstIndex, [&](int v) {
    return number ? (*number)[std::size_t(v)] : long(v) + firstIndex;
  });
}

void writeEle(Writer& w, const std::vector<Tri>& tri, const std::vector<int>& index,
              long firstIndex) {
  writeEleWith(w, tri, firstIndex, [&](int v) { return long(index[std::size_t(v)]) + firstIndex; });
}

std::string eleText(const std::vector<Tri>& tri, const std::vector<long>& number,
                    long firstIndex) {
  Writer w;
  writeEle(w, tri, &number, firstIndex);
  return w.str();
}

void writeMsh(Writer& w, const std::vector<double>& xy, const std::vector<Tri>& tri) {
  const std::size_t n = xy.size() / 2;
  w.put("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n").put(long(n)).put('\n');
  for (std::size_t i = 0; i < n; ++i)
    w.put(long(i) + 1).put(' ').put(xy[2 * i], 17).put(' ').put(xy[2 * i + 1], 17).put(" 0\n");
  w.put("$EndNodes\n$Elements\n").put(long(tri.size())).put('\n');
  for (std::size_t t = 0; t < tri.size(); ++t) {
    w.put(long(t) + 1).put(" 2 2 0 1");
    for (int k = 0; k < 3; ++k) w.put(' ').put(long(tri[t][k]) + 1);
    w.put('\n');
  }
  w.put("$EndElements\n");
}

void writeMsh(Writer& w, const std::vector<double>& xy, const std::vector<Tri>& tri,
              const std::vector<int>& index, const std::vector<char>& used) {
  const std::size_t n = index.size();
  std::vector<int> node(n, -1);  // by input index: its node number, or -1 if left out
  for (std::size_t i = 0; i < n; ++i)
    if (used.empty() || used[i]) node[std::size_t(index[i])] = 0;
  int k = 0;
  for (int& v : node)
    if (v == 0) v = k++;
  std::vector<double> nodes(2 * std::size_t(k));
  for (std::size_t i = 0; i < n; ++i)
    if (used.empty() || used[i]) {
      const std::size_t j = std::size_t(node[std::size_t(index[i])]);
      nodes[2 * j] = xy[2 * i];
      nodes[2 * j + 1] = xy[2 * i + 1];
    }
  std::vector<Tri> renumbered(tri);
  for (auto& t : renumbered)
    for (int& v : t) v = node[std::size_t(index[std::size_t(v)])];
  writeMsh(w, nodes, renumbered);
}

std::string mshText(const std::vector<double>& xy, const std::vector<Tri>& tri) {
  Writer w;
  writeMsh(w, xy, tri);
  return w.str();
}

void writeSvg(Writer& w, const std::vector<double>& xy, const std::vector<Tri>& tri,
              int size) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
    x0 = std::min(x0, xy[i]);
    x1 = std::max(x1, xy[i]);
    y0 = std::min(y0, xy[i + 1]);
    y1 = std::max(y1, xy[i + 1]);
  }
  if (!(x0 <= x1)) x0 = x1 = y0 = y1 = 0;  // no point
  // Translate, then scale by a power of two, then by a factor below `size`: none can overflow.
  // x - x0 overflows only if a coordinate exceeds 2^1022 in magnitude; then both are halved
  // first (exact there: such numbers are far from the subnormals).
  const double big = 0x1p1022;
  const bool halve = std::max({std::fabs(x0), std::fabs(x1), std::fabs(y0), std::fabs(y1)}) >= big;
  const double h = halve ? 0.5 : 1.0;
  const double span = std::max(x1 * h - x0 * h, y1 * h - y0 * h);  // finite, >= 0
  // 2^e span lies in [1, 2): the offsets 2^e (x - x0) h are in [0, 2), and k <= size - 20
  // maps the largest to size - 20 exactly.
  const int e = span > 0 ? -std::ilogb(span) : 0;
  const double k = (size - 20) / (span > 0 ? std::ldexp(span, e) : 2.0);
  auto px = [&](int i) { return 10 + std::ldexp(xy[2 * i] * h - x0 * h, e) * k; };
  auto py = [&](int i) { return size - 10 - std::ldexp(xy[2 * i + 1] * h - y0 * h, e) * k; };
  w.put("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").put(long(size))
      .put("\" height=\"").put(long(size)).put("\">\n")
      .put("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
           "<g fill=\"#dde8f5\" stroke=\"#234\" stroke-width=\"0.5\">\n");
  for (const auto& t : tri) {
    w.put("<polygon points=\"");
    for (int j = 0; j < 3; ++j) w.put(j ? " " : "").put(px(t[j]), -2).put(',').put(py(t[j]), -2);
    w.put("\"/>\n");
  }
  w.put("</g>\n</svg>\n");
}

std::string svgText(const std::vector<double>& xy, const std::vector<Tri>& tri,
                    int size) {
  Writer w;
  writeSvg(w, xy, tri, size);
  return w.str();
}

std::string gnuplotTriangles(const std::vector<double>& xy,
                             const std::vector<Tri>& tri) {
  Writer w;
  for (const auto& t : tri) {
    for (int k = 0; k <= 3; ++k) {
      const int i = t[k % 3];
      w.put(xy[2 * i], 17).put(' ').put(xy[2 * i + 1], 17).put('\n');
    }
    w.put('\n');
  }
  return w.str();
}

}  // namespace dt
