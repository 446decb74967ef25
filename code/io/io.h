// Reading point sets: Triangle's .node and plain "x y" text. The readers stream the file in
// large blocks (memory does not grow with the length of a line's attributes). The rest of the
// file handling has a header each, included here so that one include serves a program that
// reads, writes and reports: writers.h (the .ele, .msh, SVG and gnuplot texts), output_files.h
// (a set of outputs written all or nothing) and peak_memory.h.
#pragma once

#include "output_files.h"
#include "peak_memory.h"
#include "writers.h"

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
/// device: only regular files and named pipes are read, in blocks, never whole. "-" reads
/// standard input (named "stdin" in messages) as a .node file if its first line has the 4
/// fields of a .node header, else as "x y" lines.
PointSet readPoints(const std::string& path);
/// The whole file as bytes. Throws InputError if it cannot be opened or read.
std::string readFile(const std::string& path);
/// readNode and readXY on text already in memory; `path` names it in messages (the fuzz
/// harnesses call these directly).
PointSet parseNode(const std::string& text, const std::string& path);
PointSet parseXY(const std::string& text, const std::string& path);

}  // namespace dt
