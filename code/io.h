// Reading and writing point sets and meshes: Triangle's .node/.ele, plain "x y" text, Gmsh
// ASCII .msh, SVG, and gnuplot data.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace dt {

/// A malformed input file. what() names the file, the line and the offending value.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Points read from a file.
struct PointSet {
  std::vector<double> xy;    ///< x0 y0 x1 y1 ...
  std::vector<long> number;  ///< each point's number: from the .node file, or its 1-based line
  std::vector<long> line;    ///< the line each point was read from
  long firstIndex = 0;       ///< 0 or 1: the numbering base of the .node file (1 for xy files)
  std::string path;
  std::size_t size() const { return number.size(); }
};

/// Reads a Triangle .node file: a header "<n> <dim=2> <#attributes> <#markers (0|1)>", then n
/// lines "<number> <x> <y> [attributes...] [marker]"; '#' starts a comment; the first number is
/// 0 or 1 and the next ones follow it. Windows line endings are accepted. Throws InputError.
PointSet readNode(const std::string& path);
/// Reads a plain text file of "x y" lines (blank lines and '#' comments skipped); point numbers
/// are 1, 2, 3, ... in file order. Throws InputError.
PointSet readXY(const std::string& path);
/// readNode if the name ends in ".node", else readXY.
PointSet readPoints(const std::string& path);
/// The whole file as bytes. Throws InputError if it cannot be opened or read.
std::string readFile(const std::string& path);
/// readNode and readXY on text already in memory; `path` names it in messages (the fuzz
/// harnesses call these directly).
PointSet parseNode(const std::string& text, const std::string& path);
PointSet parseXY(const std::string& text, const std::string& path);

/// Writes `content` to `path` through a temporary file renamed into place, so that a failure
/// leaves no partial file. Throws std::runtime_error naming the path.
void writeFileAtomic(const std::string& path, const std::string& content);

/// Triangle .ele text: "<#triangles> 3 0" then "<i> <a> <b> <c>" with the given point numbers.
std::string eleText(const std::vector<std::array<int, 3>>& tri, const std::vector<long>& number,
                    long firstIndex);
/// Gmsh ASCII 2.2 .msh text (nodes and 3-node triangles), openable in Gmsh.
std::string mshText(const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri);
/// SVG drawing of the mesh, scaled to fit `size` pixels.
std::string svgText(const std::vector<double>& xy, const std::vector<std::array<int, 3>>& tri,
                    int size = 800);
/// gnuplot data: each triangle as a closed polyline, blocks separated by blank lines.
std::string gnuplotTriangles(const std::vector<double>& xy,
                             const std::vector<std::array<int, 3>>& tri);

}  // namespace dt
