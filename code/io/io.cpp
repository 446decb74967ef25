#include "io.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
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
  /// The text read but not yet returned (the first block, before any line is taken).
  std::string_view buffered() const { return std::string_view(data_ + pos_, len_ - pos_); }

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

// Standard input has no name to tell the format by: a first line of 4 fields is a .node
// header ('x y' lines have 2, and Triangle writes all 4 header fields).
bool looksLikeNode(std::string_view text) {
  std::vector<std::string_view> f;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    splitFields(text.substr(0, nl), f);
    if (!f.empty()) return f.size() == 4;
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
  return false;
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

// "-": standard input, a pipe or a file the shell opened (or a terminal), named "stdin" in
// messages; its format is told from its first line (looksLikeNode).
PointSet readStandardInput() {
  const std::string name = "stdin";
  const FdCloser in{::dup(STDIN_FILENO)};
  struct stat st;
  if (in.fd < 0 || ::fstat(in.fd, &st) != 0)
    throw InputError(name + ": cannot read standard input: " + sysReason());
  if (S_ISDIR(st.st_mode) || S_ISBLK(st.st_mode) ||
      (S_ISCHR(st.st_mode) && ::isatty(in.fd) != 1))
    throw InputError(name + ": is " + fileKind(st.st_mode) +
                     ", not a point file (a regular file or a pipe)");
  const std::size_t size = S_ISREG(st.st_mode) ? std::size_t(st.st_size) : 0;
  LineSource src(in.fd, name);
  return looksLikeNode(src.buffered()) ? parseNodeLines(src, name, size)
                                       : parseXYLines(src, name, size);
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

PointSet readPoints(const std::string& path) {
  if (path == "-") return readStandardInput();
  return readStreaming(path, isNodeName(path));
}


}  // namespace dt
