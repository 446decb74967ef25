// Shared plumbing of the chapter programs: options, output files, gnuplot, tables, progress.
// Header-only so that every chapters/ch2/*.cpp stays a single self-contained program.
#pragma once

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "io.h"

namespace ch {

/// Command-line options common to all chapter programs.
///   --out DIR    where to write (default: DT_OUTPUT_DIR/ch2, i.e. build/output/ch2)
///   --quick      a smaller run (smaller sizes; for slow laptops and smoke tests)
///   --max-n N    the largest point count of the size tables
///   --no-plot    write data and tables but do not call gnuplot
struct Options {
  std::string out = std::string(DT_OUTPUT_DIR) + "/ch2";
  bool quick = false;
  bool plot = true;
  long maxN = 0;  // 0: the program's default
  std::vector<std::string> rest;  // options a program handles itself
};

inline Options parseOptions(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) {
      o.out = argv[++i];
    } else if (a == "--quick") {
      o.quick = true;
    } else if (a == "--no-plot") {
      o.plot = false;
    } else if (a == "--max-n" && i + 1 < argc) {
      o.maxN = std::atol(argv[++i]);
      if (o.maxN <= 0) {
        std::cerr << argv[0] << ": --max-n needs a positive integer\n";
        std::exit(2);
      }
    } else {
      o.rest.push_back(a);
    }
  }
  std::string cmd = "mkdir -p '" + o.out + "'";
  if (std::system(cmd.c_str()) != 0) {
    std::cerr << argv[0] << ": cannot create " << o.out << "\n";
    std::exit(1);
  }
  return o;
}

/// The main() of a chapter program: parses the options, runs `body(options)`, and reports an
/// exception on stderr (prefixed with `name`) with exit status 1. A body that returns an int
/// gives the exit status itself (2 for a usage error, say).
template <class Body>
int runMain(int argc, char** argv, const char* name, Body&& body) {
  const Options o = parseOptions(argc, argv);
  try {
    if constexpr (std::is_void_v<decltype(body(o))>) {
      body(o);
    } else {
      return body(o);
    }
  } catch (const std::exception& e) {
    std::cerr << name << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}

/// Writes a file into the output directory and says so.
inline std::string writeOut(const Options& o, const std::string& name, const std::string& text) {
  const std::string path = o.out + "/" + name;
  dt::writeFileAtomic(path, text);
  std::cout << "wrote " << path << "\n";
  return path;
}

/// The files a gnuplot script promises: every literal `outdir."/NAME"` (or with single quotes)
/// in it. Names built with sprintf (animation frames) are not listed; the script's own exit
/// status covers them.
inline std::vector<std::string> gnuplotOutputs(const std::string& scriptPath) {
  std::ifstream in(scriptPath);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  std::vector<std::string> names;
  for (std::size_t at = s.find("outdir."); at != std::string::npos; at = s.find("outdir.", at + 7)) {
    const std::size_t q = at + 7;
    if (q + 2 >= s.size() || (s[q] != '"' && s[q] != '\'') || s[q + 1] != '/') continue;
    const std::size_t close = s.find(s[q], q + 1);
    if (close != std::string::npos) names.push_back(s.substr(q + 2, close - q - 2));
  }
  return names;
}

/// Runs figures/ch2/<script> with gnuplot; the script reads its data from `datadir` and
/// writes into `outdir` (both set with -e). A figure the book embeds must not go missing
/// quietly: if gnuplot fails, or a file the script names is not written by this run, this
/// throws (runMain turns that into exit status 1) with the script and the file named.
inline void runGnuplot(const Options& o, const std::string& script) {
  if (!o.plot) return;
  const std::string path = std::string(DT_SOURCE_DIR) + "/figures/ch2/" + script;
  const std::vector<std::string> promised = gnuplotOutputs(path);
  for (const auto& name : promised) std::remove((o.out + "/" + name).c_str());
  const std::string cmd = "gnuplot -e \"datadir='" + o.out + "'; outdir='" + o.out + "'\" '" +
                          path + "'";
  const int rc = std::system(cmd.c_str());
  if (rc != 0)
    throw std::runtime_error("gnuplot failed (status " + std::to_string(rc) + ") on " + path +
                             ": its figures were not drawn (is gnuplot installed? bash scripts/deps.sh)");
  for (const auto& name : promised) {
    struct stat st;
    if (stat((o.out + "/" + name).c_str(), &st) != 0 || st.st_size == 0)
      throw std::runtime_error(path + " ran but did not write " + o.out + "/" + name);
  }
  std::cout << "plotted " << path << " into " << o.out << "\n";
}

/// A table printed as Markdown on stdout and written as .md, .csv and .html (the book
/// includes the .html fragment with \htmlinclude).
struct Table {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }

  std::string markdown() const {
    std::ostringstream s;
    if (!caption.empty()) s << caption << "\n\n";
    s << "|";
    for (const auto& h : header) s << " " << h << " |";
    s << "\n|";
    for (std::size_t i = 0; i < header.size(); ++i) s << (i ? " ---: |" : " :--- |");
    s << "\n";
    for (const auto& r : rows) {
      s << "|";
      for (const auto& c : r) s << " " << c << " |";
      s << "\n";
    }
    return s.str();
  }
  std::string csv() const {
    std::ostringstream s;
    for (std::size_t i = 0; i < header.size(); ++i) s << (i ? "," : "") << header[i];
    s << "\n";
    for (const auto& r : rows) {
      for (std::size_t i = 0; i < r.size(); ++i) s << (i ? "," : "") << r[i];
      s << "\n";
    }
    return s.str();
  }
  /// For the book, a table too wide for the text column is set as several narrower tables,
  /// each of these column groups (indices into `header`) one table, in this order; the first
  /// column (the row's key, n or the input) is repeated in each. Empty: one table.
  std::vector<std::vector<std::size_t>> htmlParts;

  std::string html() const {
    std::vector<std::vector<std::size_t>> parts = htmlParts;
    if (parts.empty()) {
      parts.emplace_back();
      for (std::size_t i = 0; i < header.size(); ++i) parts.back().push_back(i);
    }
    std::ostringstream s;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      std::vector<std::size_t> cols = parts[p];
      if (p > 0 && (cols.empty() || cols.front() != 0)) cols.insert(cols.begin(), 0);
      s << "<table class=\"doxtable\">\n";
      if (!caption.empty())
        s << "<caption>" << (p == 0 ? caption : "(continued)") << "</caption>\n";
      s << "<tr>";
      for (std::size_t c : cols) s << "<th>" << header.at(c) << "</th>";
      s << "</tr>\n";
      for (const auto& r : rows) {
        s << "<tr>";
        for (std::size_t c : cols) s << "<td>" << (c < r.size() ? r[c] : "") << "</td>";
        s << "</tr>\n";
      }
      s << "</table>\n";
    }
    return s.str();
  }
  /// Prints the Markdown and writes <stem>.md, <stem>.csv, <stem>.html.
  void emit(const Options& o, const std::string& stem) const {
    std::cout << "\n" << markdown() << "\n";
    writeOut(o, stem + ".md", markdown());
    writeOut(o, stem + ".csv", csv());
    writeOut(o, stem + ".html", html());
  }
};

/// printf-style formatting into a std::string.
template <class... A>
std::string fmt(const char* f, A... a) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

/// The numbers and verdicts a book page quotes in its prose, written by a chapter program as
/// "key value" lines into values_<program>.txt next to its tables. The book build replaces
/// each @{key} of book/*.md by its value and stops on a key that no program wrote, so the
/// text cannot drift from the measurements. A verdict ("rises", "agrees") is a value too,
/// computed from the same numbers the tables show.
class Values {
 public:
  Values(const Options& o, std::string program) : o_(o), program_(std::move(program)) {}
  /// Records `value` under `key` (one word; each key once per program).
  void set(const std::string& key, const std::string& value) {
    if (key.empty() || key.find_first_of(" \t\n{}") != std::string::npos)
      throw std::invalid_argument("value key '" + key + "' must be one word without braces");
    if (value.find('\n') != std::string::npos)
      throw std::invalid_argument("value of '" + key + "' spans lines");
    for (const auto& kv : kv_)
      if (kv.first == key) throw std::invalid_argument("value key '" + key + "' set twice");
    kv_.emplace_back(key, value);
  }
  /// A number, printf-formatted (e.g. "%.1f").
  void num(const std::string& key, double v, const char* format) { set(key, fmt(format, v)); }
  /// One of two words, as the measured condition says.
  void verdict(const std::string& key, bool condition, const char* ifTrue, const char* ifFalse) {
    set(key, condition ? ifTrue : ifFalse);
  }
  /// Writes values_<program>.txt into the output directory.
  void write() const {
    std::string text;
    for (const auto& kv : kv_) text += kv.first + " " + kv.second + "\n";
    writeOut(o_, "values_" + program_ + ".txt", text);
  }

 private:
  const Options& o_;
  std::string program_;
  std::vector<std::pair<std::string, std::string>> kv_;
};

/// Progress of a long run on stderr, at most a few times per second; silent unless stderr is
/// a terminal (logs of the main command stay readable).
class Progress {
 public:
  Progress(std::string what, std::uint64_t total)
      : what_(std::move(what)), total_(total), tty_(isatty(2)),
        t0_(std::chrono::steady_clock::now()), last_(t0_) {}
  void update(std::uint64_t done) {
    if (!tty_) return;
    const auto now = std::chrono::steady_clock::now();
    if (done < total_ && std::chrono::duration<double>(now - last_).count() < 0.25) return;
    last_ = now;
    const double el = std::chrono::duration<double>(now - t0_).count();
    const double rate = el > 0 ? double(done) / el : 0;
    const double left = rate > 0 ? double(total_ - done) / rate : 0;
    std::fprintf(stderr, "\r%s: %llu/%llu (%.0f/s, %.0f s left)   ", what_.c_str(),
                 (unsigned long long)done, (unsigned long long)total_, rate, left);
    if (done >= total_) std::fprintf(stderr, "\n");
  }

 private:
  std::string what_;
  std::uint64_t total_;
  bool tty_;
  std::chrono::steady_clock::time_point t0_, last_;
};

/// Seconds since `t0`.
inline double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace ch
