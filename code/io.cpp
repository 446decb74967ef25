#include "io.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <sys/stat.h>
#include <unistd.h>

namespace dt {

namespace {

[[noreturn]] void bad(const std::string& path, long line, const std::string& what) {
  throw InputError(path + ":" + std::to_string(line) + ": " + what);
}

std::string sysReason() { return std::strerror(errno); }

// A field or line as it can be printed in a message: control and non-ASCII bytes become '?',
// long values are cut.
std::string shown(std::string_view s) {
  std::string out = "'";
  for (char c : s.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
  return out + (s.size() > 40 ? "...'" : "'");
}

bool isControl(unsigned char c) {
  return (c < 32 && c != '\t' && c != '\v' && c != '\f' && c != '\n' && c != '\r') || c == 127;
}

// The lines of a text, one at a time, from memory or from a file descriptor read in blocks
// (only the current line and the rest of its block are held). Each line is checked for
// control characters; a final '\r' (Windows line ending) is removed.
class LineSource {
 public:
  LineSource(std::string_view text, const std::string& path)
      : path_(path), data_(text.data()), len_(text.size()), eof_(true) {
    start();
  }
  LineSource(int fd, const std::string& path) : path_(path), fd_(fd), block_(kBlock) {
    data_ = block_.data();
    // The first block whole (a pipe may deliver it in pieces), to look at it before parsing.
    while (!eof_ && len_ < kFirst) fill();
    start();
  }
  // The next line; false at the end of the text.
  bool next(std::string_view& line) {
    for (;;) {
      const char* base = data_ + pos_;
      const void* nl = pos_ < len_ ? std::memchr(base, '\n', len_ - pos_) : nullptr;
      if (nl != nullptr) {
        const std::size_t l = std::size_t(static_cast<const char*>(nl) - base);
        line = std::string_view(base, l);
        pos_ += l + 1;
        break;
      }
      if (eof_) {
        if (pos_ >= len_) return false;
        line = std::string_view(base, len_ - pos_);
        pos_ = len_;
        break;
      }
      fill();
    }
    ++n_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // Windows line ending
    for (std::size_t i = 0; i < line.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(line[i]);
      if (c == '\r')
        bad(path_, n_, "carriage return inside the line (old Mac line endings?): lines must end "
                       "with LF or CR LF");
      if (isControl(c)) controlChar(n_, i, c);
    }
    return true;
  }
  long number() const { return n_; }
  bool empty() const { return !any_; }

 private:
  static constexpr std::size_t kBlock = std::size_t(1) << 20;  // bytes read at a time
  static constexpr std::size_t kFirst = 1 << 16;  // looked at for binary data before parsing
  static constexpr std::size_t kMaxLine = std::size_t(1) << 26;  // 64 MiB

  [[noreturn]] void controlChar(long line, std::size_t column, unsigned char c) const {
    bad(path_, line, "binary or control character (code " + std::to_string(c) + ") at column " +
                         std::to_string(column + 1) + ": not a text file");
  }

  // Skips a byte order mark and refuses binary data in the first block.
  void start() {
    any_ = len_ > 0;
    // A UTF-8 byte order mark (Windows editors write one) is not part of the first field.
    if (len_ >= 3 && std::memcmp(data_, "\xEF\xBB\xBF", 3) == 0) pos_ = 3;
    long line = 1;
    std::size_t lineStart = pos_;
    for (std::size_t i = pos_; i < std::min(len_, kFirst); ++i) {
      const unsigned char c = static_cast<unsigned char>(data_[i]);
      if (c == '\n') {
        ++line;
        lineStart = i + 1;
      } else if (isControl(c)) {
        controlChar(line, i - lineStart, c);
      }
    }
  }

  // Moves the unread rest of the buffer to its front and reads more after it.
  void fill() {
    if (pos_ > 0) {
      std::memmove(block_.data(), block_.data() + pos_, len_ - pos_);
      len_ -= pos_;
      pos_ = 0;
    }
    if (len_ == block_.size()) {  // one line fills the buffer
      if (block_.size() >= kMaxLine)
        bad(path_, n_ + 1, "line longer than " + std::to_string(kMaxLine >> 20) +
                               " MiB: not a point file");
      block_.resize(2 * block_.size());
    }
    data_ = block_.data();
    for (;;) {
      const ssize_t r = ::read(fd_, block_.data() + len_, block_.size() - len_);
      if (r < 0 && errno == EINTR) continue;
      if (r < 0) throw InputError(path_ + ": read error: " + sysReason());
      if (r == 0) eof_ = true;
      len_ += std::size_t(r);
      return;
    }
  }

  std::string path_;
  int fd_ = -1;
  std::vector<char> block_;
  const char* data_ = nullptr;
  std::size_t pos_ = 0, len_ = 0;
  bool eof_ = false, any_ = false;
  long n_ = 0;  // lines returned so far
};

// The whitespace-separated fields of a line, up to a '#' comment.
void splitFields(std::string_view s, std::vector<std::string_view>& f) {
  f.clear();
  const std::size_t hash = s.find('#');
  if (hash != std::string_view::npos) s = s.substr(0, hash);
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; };
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && space(s[i])) ++i;
    const std::size_t b = i;
    while (i < s.size() && !space(s[i])) ++i;
    if (i > b) f.push_back(s.substr(b, i - b));
  }
}

double toCoordinate(const std::string& path, long line, std::string_view f, const char* what) {
  // std::from_chars (exact, locale-free) when it reads the whole field to a finite value; else
  // strtod, whose messages and forms (a leading '+', hexadecimal) the files may rely on.
  const char* b = f.data();
  const char* e = b + f.size();
  if (f.size() > 1 && *b == '+' && b[1] != '-' && b[1] != '+') ++b;
  double v = 0;
  const auto r = std::from_chars(b, e, v);
  if (r.ec == std::errc() && r.ptr == e && std::isfinite(v)) return v;
  const std::string s(f);
  errno = 0;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0')
    bad(path, line, std::string(what) + " " + shown(f) + " is not a number" +
                        (s.find(',') != std::string::npos
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

// strtol's reading of a whole field (from_chars first, strtol for its other forms).
bool readInteger(std::string_view f, long& v) {
  const char* b = f.data();
  const char* e = b + f.size();
  const auto r = std::from_chars(b, e, v);
  if (r.ec == std::errc() && r.ptr == e) return true;
  const std::string s(f);
  errno = 0;
  char* end = nullptr;
  v = std::strtol(s.c_str(), &end, 10);
  return end != s.c_str() && *end == '\0' && errno != ERANGE;
}

bool isInteger(std::string_view f) {
  long v;
  return readInteger(f, v);
}

long toInteger(const std::string& path, long line, std::string_view f, const char* what) {
  long v = 0;
  if (!readInteger(f, v))
    bad(path, line, std::string(what) + " " + shown(f) + " is not an integer");
  return v;
}

std::string plural(std::size_t n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

void addPoint(PointSet& ps, double x, double y, long line) {
  const std::size_t i = ps.size();
  if (i == 0 || ps.line(i - 1) + 1 != line) ps.lineRuns.emplace_back(i, line);
  ps.xy.push_back(x);
  ps.xy.push_back(y);
}

// `sizeHint`: the file's size in bytes, or 0 if unknown (a pipe).
PointSet parseNodeLines(LineSource& src, const std::string& path, std::size_t sizeHint) {
  PointSet ps;
  ps.path = path;
  const char* headerForm = " (a .node file starts with '<points> 2 <attributes> <markers>')";
  std::vector<std::string_view> f;
  f.reserve(16);
  std::string_view text;
  while (src.next(text)) {
    splitFields(text, f);
    if (!f.empty()) break;
  }
  if (f.empty())
    throw InputError(path + (src.empty() ? ": empty file" : ": only blank lines and comments") +
                     headerForm);
  const long hl = src.number();
  if (f.size() > 4)
    bad(path, hl, "header " + shown(text) + " has " + plural(f.size(), "field") +
                      "; expected at most 4" + headerForm);
  if (!isInteger(f[0]))
    bad(path, hl, "point count " + shown(f[0]) + " is not an integer" + headerForm +
                      (f.size() == 2 ? "; for 'x y' lines do not name the file *.node" : ""));
  const long n = toInteger(path, hl, f[0], "point count");
  const long dim = f.size() > 1 ? toInteger(path, hl, f[1], "dimension") : 2;
  const long nattr = f.size() > 2 ? toInteger(path, hl, f[2], "attribute count") : 0;
  const long nmark = f.size() > 3 ? toInteger(path, hl, f[3], "marker count") : 0;
  if (n < 0) bad(path, hl, "point count " + std::to_string(n) + " is negative");
  if (dim != 2)
    bad(path, hl, "dimension " + std::to_string(dim) + " is not 2" + headerForm +
                      (f.size() == 3 ? "; is the header missing?" : ""));
  if (nattr < 0 || nattr > 1000)
    bad(path, hl, "attribute count " + std::to_string(nattr) + " is not in 0..1000");
  if (nmark != 0 && nmark != 1)
    bad(path, hl, "marker count " + std::to_string(nmark) + " is not 0 or 1");
  const std::size_t want = 3 + std::size_t(nattr) + std::size_t(nmark);
  // A point line has at least 6 bytes: the header cannot make us reserve more than the file.
  ps.xy.reserve(2 * std::min<std::size_t>(std::size_t(n), sizeHint ? sizeHint / 6 + 1 : 1 << 20));
  std::size_t have = 0;
  long lastLine = hl, firstLine = 0;
  while (src.next(text)) {
    splitFields(text, f);
    if (f.empty()) continue;
    const long ln = src.number();
    lastLine = ln;
    if (have == std::size_t(n))
      bad(path, ln, "extra line " + shown(text) + ": the header (line " + std::to_string(hl) +
                        ") announces " + plural(std::size_t(n), "point"));
    if (f.size() != want)
      bad(path, ln, shown(text) + " has " + plural(f.size(), "field") + "; expected " +
                        std::to_string(want) + " (number, x, y" +
                        (nattr ? ", " + plural(std::size_t(nattr), "attribute") : "") +
                        (nmark ? ", marker" : "") + ", as the header on line " +
                        std::to_string(hl) + " says)");
    const long num = toInteger(path, ln, f[0], "point number");
    if (have == 0) {
      if (num != 0 && num != 1)
        bad(path, ln, "first point number is " + std::to_string(num) + "; expected 0 or 1");
      ps.firstIndex = num;
      firstLine = ln;
    } else if (num != ps.firstIndex + long(have)) {
      bad(path, ln, "point number " + std::to_string(num) + "; expected " +
                        std::to_string(ps.firstIndex + long(have)) + " (numbers start at " +
                        std::to_string(ps.firstIndex) + " on line " + std::to_string(firstLine) +
                        " and follow on)");
    }
    const double x = toCoordinate(path, ln, f[1], "x");
    const double y = toCoordinate(path, ln, f[2], "y");
    for (std::size_t k = 3; k < 3 + std::size_t(nattr); ++k)
      toCoordinate(path, ln, f[k], "attribute");
    if (nmark) toInteger(path, ln, f[want - 1], "boundary marker");
    addPoint(ps, x, y, ln);
    ++have;
  }
  if (have < std::size_t(n))
    bad(path, lastLine,
        "file ends after " + std::to_string(have) + " of the " + std::to_string(n) +
            " points announced in the header (line " + std::to_string(hl) + ")");
  return ps;
}

PointSet parseXYLines(LineSource& src, const std::string& path, std::size_t sizeHint) {
  PointSet ps;
  ps.path = path;
  ps.firstIndex = 1;
  // A guess (lines of 16 bytes): the vector grows if the lines are shorter; a bound (4 bytes a
  // line) could reserve far more than the points need.
  ps.xy.reserve(2 * (sizeHint ? sizeHint / 16 + 1 : std::size_t(1) << 16));
  std::vector<std::string_view> f;
  f.reserve(16);
  std::string_view text;
  bool first = true;
  while (src.next(text)) {
    splitFields(text, f);
    if (f.empty()) continue;
    const long ln = src.number();
    if (f.size() != 2)
      bad(path, ln,
          shown(text) + " has " + plural(f.size(), "field") + "; expected 'x y'" +
              (first && f.size() == 4 ? " (a .node header? name the file *.node)" : ""));
    first = false;
    const double x = toCoordinate(path, ln, f[0], "x");
    const double y = toCoordinate(path, ln, f[1], "y");
    addPoint(ps, x, y, ln);
  }
  if (ps.size() == 0)
    throw InputError(path + (src.empty() ? ": empty file" : ": only blank lines and comments") +
                     " (expected 'x y' lines)");
  return ps;
}

bool isNodeName(const std::string& path) {
  const std::string ext = ".node";
  return path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
}

const char* fileKind(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

// Opens a point file: a regular file or a named pipe, nothing else (a device such as /dev/zero
// would never end). Returns the descriptor and the size (0 for a pipe).
int openInput(const std::string& path, std::size_t& size) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw InputError(path + ": is a directory, not a point file");
    if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
      throw InputError(path + ": is " + fileKind(st.st_mode) +
                       ", not a point file (a regular file or a pipe)");
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(path + ": cannot open file for reading: " + sysReason());
  if (::fstat(fd, &st) != 0 || (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))) {
    ::close(fd);
    throw InputError(path + ": is not a point file (a regular file or a pipe)");
  }
  size = S_ISREG(st.st_mode) ? std::size_t(st.st_size) : 0;
#ifdef POSIX_FADV_SEQUENTIAL
  if (size) ::posix_fadvise(fd, 0, 0, POSIX_FADV_SEQUENTIAL);
#endif
  return fd;
}

struct FdCloser {
  int fd;
  ~FdCloser() { ::close(fd); }
};

PointSet readStreaming(const std::string& path, bool node) {
  std::size_t size = 0;
  const FdCloser in{openInput(path, size)};
  LineSource src(in.fd, path);
  return node ? parseNodeLines(src, path, size) : parseXYLines(src, path, size);
}

}  // namespace

long PointSet::line(std::size_t i) const {
  // The last run that starts at or before i.
  auto it = std::upper_bound(lineRuns.begin(), lineRuns.end(), i,
                             [](std::size_t a, const std::pair<std::size_t, long>& r) {
                               return a < r.first;
                             });
  if (it == lineRuns.begin()) return 0;
  --it;
  return it->second + long(i - it->first);
}

std::string readFile(const std::string& path) {
  std::size_t size = 0;
  const FdCloser in{openInput(path, size)};
  std::string s;
  s.reserve(size);
  char buf[1 << 16];
  for (;;) {
    const ssize_t r = ::read(in.fd, buf, sizeof buf);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw InputError(path + ": read error: " + sysReason());
    if (r == 0) return s;
    s.append(buf, std::size_t(r));
  }
}

PointSet parseNode(const std::string& text, const std::string& path) {
  LineSource src(text, path);
  return parseNodeLines(src, path, text.size());
}

PointSet parseXY(const std::string& text, const std::string& path) {
  LineSource src(text, path);
  return parseXYLines(src, path, text.size());
}

PointSet readNode(const std::string& path) { return readStreaming(path, true); }

PointSet readXY(const std::string& path) { return readStreaming(path, false); }

PointSet readPoints(const std::string& path) { return readStreaming(path, isNodeName(path)); }

// ---- writing --------------------------------------------------------------------------------

Writer::Writer(int fd, std::string path) : fd_(fd), path_(std::move(path)) {
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
    if (r < 0) throw std::runtime_error(path_ + ": cannot write: " + sysReason());
    done += std::size_t(r);
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

void writeFileAtomic(const std::string& path, const std::string& content) {
  OutputFiles out;
  out.open(path).put(content);
  out.commit();
}

namespace {
template <class Number>
void writeEleWith(Writer& w, const std::vector<std::array<int, 3>>& tri, long firstIndex,
                  Number number) {
  w.put(long(tri.size())).put(" 3 0\n");
  for (std::size_t t = 0; t < tri.size(); ++t) {
    w.put(long(t) + firstIndex);
    for (int k = 0; k < 3; ++k) w.put(' ').put(number(tri[t][k]));
    w.put('\n');
  }
}
}  // namespace

void writeEle(Writer& w, const std::vector<std::array<int, 3>>& tri, const std::vector<long>* number,
              long firstIndex) {
  writeEleWith(w, tri, firstIndex, [&](int v) {
    return number ? (*number)[std::size_t(v)] : long(v) + firstIndex;
  });
}

void writeEle(Writer& w, const std::vector<std::array<int, 3>>& tri, const std::vector<int>& index,
              long firstIndex) {
  writeEleWith(w, tri, firstIndex, [&](int v) { return long(index[std::size_t(v)]) + firstIndex; });
}

std::string eleText(const std::vector<std::array<int, 3>>& tri, const std::vector<long>& number,
                    long firstIndex) {
  Writer w;
  writeEle(w, tri, &number, firstIndex);
  return w.str();
}

void writeMsh(Writer& w, const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri) {
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

std::string mshText(const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri) {
  Writer w;
  writeMsh(w, xy, tri);
  return w.str();
}

void writeSvg(Writer& w, const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri,
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

std::string svgText(const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri,
                    int size) {
  Writer w;
  writeSvg(w, xy, tri, size);
  return w.str();
}

std::string gnuplotTriangles(const std::vector<double>& xy,
                             const std::vector<std::array<int, 3>>& tri) {
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

// ---- same file, all-or-nothing outputs -----------------------------------------------------

namespace {

std::string canonicalNew(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  const std::string dir =
      slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  char buf[PATH_MAX];
  if (::realpath(dir.c_str(), buf) == nullptr) return path;
  return std::string(buf) + "/" + name;
}

// The temporary files of every OutputFiles, where a signal handler can read them: fixed
// arrays, a name written completely before its slot is marked used.
constexpr int kSlots = 64;
constexpr std::size_t kNameMax = 4096;
char g_tempName[kSlots][kNameMax];
volatile std::sig_atomic_t g_tempUsed[kSlots];
bool g_handlersInstalled = false;

extern "C" void removeTemporariesAndDie(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_tempUsed[i]) ::unlink(g_tempName[i]);  // async-signal-safe
  // SA_RESETHAND restored the default action: the signal, raised again, ends the process once
  // this handler returns, with the status the caller expects from it.
  ::raise(sig);
}

void installHandlers() {
  if (g_handlersInstalled) return;
  g_handlersInstalled = true;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old;
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;  // nohup
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = removeTemporariesAndDie;
    sa.sa_flags = SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    ::sigaction(sig, &sa, nullptr);
  }
}

int registerTemporary(const std::string& name) {
  installHandlers();
  if (name.size() >= kNameMax) return -1;  // not cleaned on a signal, still on every error
  for (int i = 0; i < kSlots; ++i)
    if (!g_tempUsed[i]) {
      std::memcpy(g_tempName[i], name.c_str(), name.size() + 1);
      std::atomic_signal_fence(std::memory_order_seq_cst);
      g_tempUsed[i] = 1;
      return i;
    }
  return -1;
}

void unregisterTemporary(int slot) {
  if (slot >= 0) g_tempUsed[slot] = 0;
}

// Blocks the cleanup signals while the files are renamed (a few system calls).
struct SignalsBlocked {
  sigset_t old;
  SignalsBlocked() {
    sigset_t s;
    sigemptyset(&s);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&s, sig);
    ::sigprocmask(SIG_BLOCK, &s, &old);
  }
  ~SignalsBlocked() { ::sigprocmask(SIG_SETMASK, &old, nullptr); }
};

}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  const bool ea = ::stat(a.c_str(), &sa) == 0, eb = ::stat(b.c_str(), &sb) == 0;
  if (ea && eb) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  if (ea != eb) return false;
  return canonicalNew(a) == canonicalNew(b);
}

struct OutputFiles::File {
  std::string path, tmp;
  int fd = -1;
  int slot = -1;
  std::unique_ptr<Writer> w;
};

OutputFiles::~OutputFiles() { removeAll(); }

void OutputFiles::removeAll() {
  for (File* f : files_) {
    if (f->fd >= 0) ::close(f->fd);
    if (!f->tmp.empty()) ::unlink(f->tmp.c_str());
    unregisterTemporary(f->slot);
    delete f;
  }
  files_.clear();
}

Writer& OutputFiles::open(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw std::runtime_error(path + ": cannot open for writing: it is a directory");
  auto f = std::make_unique<File>();
  f->path = path;
  for (int k = 0;; ++k) {
    f->tmp = path + ".tmp" + std::to_string(::getpid()) + (k ? "." + std::to_string(k) : "");
    f->slot = registerTemporary(f->tmp);  // before it exists: a signal may come at any time
    f->fd = ::open(f->tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (f->fd >= 0) break;
    const int err = errno;
    unregisterTemporary(f->slot);
    f->slot = -1;
    if (err != EEXIST || k >= 100) {
      f->tmp.clear();
      throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(err));
    }
  }
  f->w = std::make_unique<Writer>(f->fd, path);
  files_.push_back(f.release());
  return *files_.back()->w;
}

std::vector<std::string> OutputFiles::temporaries() const {
  std::vector<std::string> t;
  for (const File* f : files_) t.push_back(f->tmp);
  return t;
}

void OutputFiles::commit() {
  for (File* f : files_) {
    f->w->flush();
    const int rc = ::close(f->fd);
    f->fd = -1;
    if (rc != 0) throw std::runtime_error(f->path + ": cannot write: " + sysReason());
  }
  const SignalsBlocked blocked;
  // A hard link to each file that is already there, so that a rename failing half way can
  // put back the ones replaced before it.
  std::vector<std::string> backup(files_.size());
  for (std::size_t i = 0; i < files_.size(); ++i) {
    struct stat st;
    if (::lstat(files_[i]->path.c_str(), &st) != 0) continue;
    const std::string b = files_[i]->tmp + ".old";
    if (::link(files_[i]->path.c_str(), b.c_str()) == 0) backup[i] = b;
  }
  for (std::size_t i = 0; i < files_.size(); ++i) {
    if (::rename(files_[i]->tmp.c_str(), files_[i]->path.c_str()) == 0) {
      files_[i]->tmp.clear();
      continue;
    }
    const std::string why = files_[i]->path + ": cannot rename the temporary file into place: " +
                            sysReason();
    for (std::size_t j = 0; j < i; ++j) {
      if (!backup[j].empty())
        ::rename(backup[j].c_str(), files_[j]->path.c_str());
      else
        ::unlink(files_[j]->path.c_str());
    }
    for (const std::string& b : backup)
      if (!b.empty()) ::unlink(b.c_str());
    throw std::runtime_error(why);
  }
  for (const std::string& b : backup)
    if (!b.empty()) ::unlink(b.c_str());
  for (File* f : files_) {
    unregisterTemporary(f->slot);
    delete f;
  }
  files_.clear();
}

long peakResidentKB() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  long kb = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, "VmHWM:", 6) == 0) kb = std::atol(line + 6);
  std::fclose(f);
  return kb;
}

}  // namespace dt
