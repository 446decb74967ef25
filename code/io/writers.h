// Writers of meshes: Triangle's .ele, Gmsh ASCII .msh, SVG and gnuplot data, through a Writer
// that fills a large buffer and sends it to a file descriptor (or keeps it as a string).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "tri.h"

namespace dt {

/// Text output into a large buffer, flushed to a file descriptor when full (fd >= 0) or kept
/// as a string (fd < 0). Numbers are formatted with std::to_chars. Throws std::runtime_error
/// naming `path` and the system's reason when a write fails; for a `stream` (a pipe or a device,
/// which cannot be taken back) the message also says that it got a partial write, and how much.
class Writer {
 public:
  explicit Writer(int fd = -1, std::string path = "", bool stream = false);
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
  /// Bytes sent to the file descriptor so far.
  unsigned long long sent() const { return sent_; }

 private:
  void reserve(std::size_t n);
  int fd_;
  std::string path_;
  bool stream_;
  unsigned long long sent_ = 0;
  std::vector<char> buf_;
  std::size_t used_ = 0;
};

/// Triangle .ele: "<#triangles> 3 0" then "<i> <a> <b> <c>"; vertex v is written as number[v]
/// or, without `number`, as v + firstIndex.
void writeEle(Writer& w, const std::vector<Tri>& tri, const std::vector<long>* number,
              long firstIndex);
/// The same with vertex v written as index[v] + firstIndex.
void writeEle(Writer& w, const std::vector<Tri>& tri, const std::vector<int>& index,
              long firstIndex);
std::string eleText(const std::vector<Tri>& tri, const std::vector<long>& number,
                    long firstIndex);
/// Gmsh ASCII 2.2 .msh (nodes and 3-node triangles), openable in Gmsh.
void writeMsh(Writer& w, const std::vector<double>& xy, const std::vector<Tri>& tri);
/// The same with the nodes numbered as the input, like writeEle's index map: point v of xy is
/// input point index[v]; the points with used[v] == 0 (merged duplicates) are left out and the
/// others numbered in input order. used empty: every point is a node.
void writeMsh(Writer& w, const std::vector<double>& xy, const std::vector<Tri>& tri,
              const std::vector<int>& index, const std::vector<char>& used);
std::string mshText(const std::vector<double>& xy, const std::vector<Tri>& tri);
/// SVG drawing of the mesh, `size` pixels square. Coordinates are translated, then scaled by
/// a power of two and a factor below `size`: every input of finite doubles (subnormal spans,
/// spans near DBL_MAX) gives finite pixel coordinates.
void writeSvg(Writer& w, const std::vector<double>& xy, const std::vector<Tri>& tri,
              int size = 800);
std::string svgText(const std::vector<double>& xy, const std::vector<Tri>& tri,
                    int size = 800);
/// gnuplot data: each triangle as a closed polyline, blocks separated by blank lines.
std::string gnuplotTriangles(const std::vector<double>& xy,
                             const std::vector<Tri>& tri);

}  // namespace dt
