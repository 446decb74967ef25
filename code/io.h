// Reading and writing point sets and meshes: Triangle's .node/.ele, plain "x y" text, Gmsh
// ASCII .msh, SVG, and gnuplot data. The readers stream the file in large blocks (memory does
// not grow with the length of a line's attributes); the writers fill large buffers; a set of
// output files is written all or nothing (OutputFiles).
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dt {

/// A malformed input file. what() names the file, the line and the offending value.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Points read from a file. Point i has the number firstIndex + i (the readers enforce it) and
/// was read from line(i).
struct PointSet {
  std::vector<double> xy;    ///< x0 y0 x1 y1 ...
  long firstIndex = 0;       ///< 0 or 1: the numbering base of the .node file (1 for xy files)
  std::string path;
  /// (first point, its line) of each run of points on consecutive lines: one entry for a file
  /// without blank lines or comments, so that line numbers cost no memory per point.
  std::vector<std::pair<std::size_t, long>> lineRuns;
  std::size_t size() const { return xy.size() / 2; }
  long number(std::size_t i) const { return firstIndex + long(i); }
  long line(std::size_t i) const;
};

/// Reads a Triangle .node file: a header "<n> <dim=2> <#attributes> <#markers (0|1)>", then n
/// lines "<number> <x> <y> [attributes...] [marker]"; '#' starts a comment; the first number is
/// 0 or 1 and the next ones follow it. Windows line endings are accepted. Throws InputError.
PointSet readNode(const std::string& path);
/// Reads a plain text file of "x y" lines (blank lines and '#' comments skipped); point numbers
/// are 1, 2, 3, ... in file order. Throws InputError.
PointSet readXY(const std::string& path);
/// readNode if the name ends in ".node", else readXY. Refuses (InputError) a directory or a
/// device: only regular files and named pipes are read, in blocks, never whole.
PointSet readPoints(const std::string& path);
/// The whole file as bytes. Throws InputError if it cannot be opened or read.
std::string readFile(const std::string& path);
/// readNode and readXY on text already in memory; `path` names it in messages (the fuzz
/// harnesses call these directly).
PointSet parseNode(const std::string& text, const std::string& path);
PointSet parseXY(const std::string& text, const std::string& path);

/// Writes `content` to `path` through a temporary file renamed into place, so that a failure
/// leaves no partial file. Throws std::runtime_error naming the path and the system's reason.
void writeFileAtomic(const std::string& path, const std::string& content);

/// Text output into a large buffer, flushed to a file descriptor when full (fd >= 0) or kept
/// as a string (fd < 0). Numbers are formatted with std::to_chars. Throws std::runtime_error
/// naming `path` and the system's reason when a write fails.
class Writer {
 public:
  explicit Writer(int fd = -1, std::string path = "");
  Writer& put(std::string_view s);
  Writer& put(char c) {
    if (used_ == buf_.size()) reserve(1);
    buf_[used_++] = c;
    return *this;
  }
  Writer& put(long v);
  Writer& put(double v, int precision);  ///< "%.{precision}g"-like, shortest if precision 0
  /// Sends the buffer to the file (fd >= 0); no-op for a string writer.
  void flush();
  /// A string writer's text.
  std::string str() const { return std::string(buf_.data(), used_); }

 private:
  void reserve(std::size_t n);
  int fd_;
  std::string path_;
  std::vector<char> buf_;
  std::size_t used_ = 0;
};

/// Triangle .ele: "<#triangles> 3 0" then "<i> <a> <b> <c>"; vertex v is written as number[v]
/// or, without `number`, as v + firstIndex.
void writeEle(Writer& w, const std::vector<std::array<int, 3>>& tri, const std::vector<long>* number,
              long firstIndex);
/// The same with vertex v written as index[v] + firstIndex.
void writeEle(Writer& w, const std::vector<std::array<int, 3>>& tri, const std::vector<int>& index,
              long firstIndex);
std::string eleText(const std::vector<std::array<int, 3>>& tri, const std::vector<long>& number,
                    long firstIndex);
/// Gmsh ASCII 2.2 .msh (nodes and 3-node triangles), openable in Gmsh.
void writeMsh(Writer& w, const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri);
std::string mshText(const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri);
/// SVG drawing of the mesh, `size` pixels square. Coordinates are translated, then scaled by
/// a power of two and a factor below `size`: every input of finite doubles (subnormal spans,
/// spans near DBL_MAX) gives finite pixel coordinates.
void writeSvg(Writer& w, const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri,
              int size = 800);
std::string svgText(const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri,
                    int size = 800);
/// gnuplot data: each triangle as a closed polyline, blocks separated by blank lines.
std::string gnuplotTriangles(const std::vector<double>& xy,
                             const std::vector<std::array<int, 3>>& tri);

/// Whether two paths name the same file: device and inode for existing files, the canonical
/// parent directory and the name for a file still to be created.
bool sameFile(const std::string& a, const std::string& b);

/// A set of output files written all or nothing (issue 19): each is written to a temporary
/// file beside its target; commit() renames them all into place only when all are written, and
/// if a rename fails it puts the files that were there before back. Until commit, a failure, an
/// exception or SIGINT/SIGTERM/SIGHUP removes the temporaries and leaves every pre-existing
/// file as it was.
class OutputFiles {
 public:
  OutputFiles() = default;
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();  ///< removes the temporaries not committed
  /// Creates the temporary file of `path` and returns a Writer on it (valid until commit).
  Writer& open(const std::string& path);
  /// Flushes and closes every file, then renames them all into place.
  void commit();
  /// The temporary file names (for tests and messages).
  std::vector<std::string> temporaries() const;

 private:
  struct File;
  void removeAll();
  std::vector<File*> files_;
};

/// Peak resident memory of this process so far (VmHWM of /proc/self/status), in kB; 0 where
/// /proc is not available. Counts only this program's own image (unlike ru_maxrss of a child,
/// which includes the pages its parent had before the exec).
long peakResidentKB();

}  // namespace dt
