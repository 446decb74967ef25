// Shared plumbing of the chapter programs: options, output files, gnuplot, tables, progress.
// Header-only so that every chapters/ch2/*.cpp stays a single self-contained program.
#pragma once

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <new>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "io.h"
#include "process.h"

namespace ch {

/// An option one program adds to the common ones, e.g. {"--reps", "N", "runs per kernel", 1,
/// 1000}. An empty `value` makes a flag; "N" an integer checked against [lo, hi] while the
/// options are read; any other value name (e.g. "LIST") text the program checks itself.
struct ExtraOption {
  std::string name, value, help;
  long lo = 0, hi = 0;
};

/// What a chapter program declares about itself, so that every program reads its options the
/// same way and --help lists them the same way.
struct Program {
  std::string name;     ///< as in messages, e.g. "sec2_1_kernel"
  std::string purpose;  ///< one line for --help
  long minN = 1000, maxN = 10000000;  ///< what --max-n may be, checked before anything is written
  std::vector<std::string> figures;   ///< what --only accepts: the stems of its gnuplot scripts
  std::vector<ExtraOption> extras;    ///< options of this program only
};

/// A usage error found after the options were read (e.g. a bad --threads list): runMain
/// prints it as one line and exits with status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What a chapter program is doing, for the message when memory runs out: "computing" (set by
/// runMain), "writing FILE" (writeOut) or "drawing SCRIPT" (runGnuplot); a program may set its
/// own ("measuring 10^7 points").
std::string& phase();

/// The options of a chapter program (ch::parseOptions reads them; `--help` lists them):
///   --out DIR    where to write (default: DT_OUTPUT_DIR/ch2, i.e. build/output/ch2)
///   --quick      a smaller run (smaller sizes; for slow laptops and smoke tests)
///   --max-n N    the largest point count of the size tables
///   --no-plot    write data and tables but do not call gnuplot
///   --seed N     other random points than the book's fixed seeds
///   --only FIG   draw that figure only; tables and values are left as they are
///   --size WxH   the figures' size in pixels, instead of the style's
/// and the program's own (Program::extras).
struct Options {
  std::string out = std::string(DT_OUTPUT_DIR) + "/ch2";  ///< absolute after parseOptions
  bool quick = false;
  bool plot = true;
  long maxN = 0;  ///< 0: the program's default
  std::optional<std::uint64_t> seedOption;  ///< --seed
  std::string only;                         ///< --only: one figure (a gnuplot script's stem)
  int width = 0, height = 0;                ///< --size; 0: the style's size
  std::map<std::string, std::string> extra;  ///< the program's own options given ("" for a flag)

  /// The seed to use where the book uses `bookSeed`: `bookSeed` itself unless --seed N was
  /// given, else a seed made of N and `bookSeed` (so two random sets of one program stay
  /// different from each other, and each changes with N).
  std::uint64_t seed(std::uint64_t bookSeed) const;
  /// False when --only names another figure: the program skips the work of this one.
  bool wants(const std::string& figure) const { return only.empty() || only == figure; }
  /// True unless --only was given: tables and values_<program>.txt are written only then.
  bool everything() const { return only.empty(); }
  bool has(const std::string& name) const { return extra.count(name) > 0; }
  /// An integer option of the program's own (checked when read), or `dflt` if not given.
  long number(const std::string& name, long dflt) const {
    const auto it = extra.find(name);
    return it == extra.end() ? dflt : std::stol(it->second);
  }
};

/// The one-line usage of a program: every option, in the same order everywhere.
std::string usageLine(const Program& p);

/// What --help prints: the usage, the purpose, one line per option.
std::string helpText(const Program& p);

/// Reads a whole integer: digits, or a number in scientific notation that is a whole number
/// (1e5, 2.5e3). Returns nothing for anything else (1.5, 12abc, 0x10, an overflow).
std::optional<long> parseWhole(const std::string& text);

/// Reads the options of program `p` (see Options). A usage error (an unknown option, a missing
/// or malformed value, an option given twice, an extra argument, a --max-n outside what the
/// program can do) is one line on stderr and exit status 2, before anything is written.
/// --help prints helpText and exits 0. Creates the output directory (exit 1 if it cannot)
/// unless `createOut` is false.
Options parseOptions(int argc, char** argv, const Program& p, bool createOut = true);

/// The main() of a chapter program: reads the options (parseOptions), runs `body(options)`,
/// and reports an exception on stderr (prefixed with the program's name) with exit status 1,
/// a UsageError with status 2. A body that returns an int gives the exit status itself.
/// `check`, if given, checks the program's own option values (throws UsageError) before the
/// output directory is created: a bad value leaves nothing behind.
template <class Body>
int runMain(int argc, char** argv, const Program& p, Body&& body,
            const std::function<void(const Options&)>& check = {}) {
  Options o = parseOptions(argc, argv, p, false);
  if (check) {
    try {
      check(o);
    } catch (const UsageError& e) {  // nothing created yet
      std::cerr << p.name << ": " << e.what() << "; usage: " << usageLine(p) << "\n";
      return 2;
    }
  }
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) {
    std::cerr << p.name << ": cannot create the output directory '" << o.out << "': " << ec.message() << "\n";
    return 1;
  }
  phase() = "computing";
  try {
    if constexpr (std::is_void_v<decltype(body(o))>) {
      body(o);
    } else {
      return body(o);
    }
  } catch (const UsageError& e) {
    std::cerr << p.name << ": " << e.what() << "; usage: " << usageLine(p) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << p.name << ": out of memory while " << phase() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << p.name << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}

/// Writes a file into the output directory and says so.
std::string writeOut(const Options& o, const std::string& name, const std::string& text);

/// The files a gnuplot script promises: every literal `outdir."/NAME"` (or with single quotes)
/// in it. Names built with sprintf (animation frames) are not listed; the script's own exit
/// status covers them.
std::vector<std::string> gnuplotOutputs(const std::string& scriptPath);

/// Why a figure file is cut short, or "" if it looks whole: a PNG must end with its IEND chunk,
/// an SVG with its closing tag (gnuplot writing into a full disk stops anywhere). Other kinds
/// are not judged.
std::string figureTruncated(const std::string& path);

/// `text` as a gnuplot single-quoted string: gnuplot reads nothing inside one but '' (one
/// quote), so a path with ", $(...), ;, \ or a space stays the path. (parseOptions refuses a
/// newline in --out.)
std::string gnuplotQuote(const std::string& text);

/// Runs figures/ch2/<script> with gnuplot, without a shell: gnuplot runs in figures/ch2 (the
/// scripts load style.gp from there) and gets `datadir` and `outdir` (both --out) as gnuplot
/// strings on its command line, plus the environment variable DT_DATADIR for scripts that
/// hand the data directory to a command (`system("cat \"$DT_DATADIR/...\"")`: the shell
/// expands it without reading it as code); --size adds `fig_size_w`, `fig_size_h`, which
/// style.gp's fig_open prefers to its table. Skipped with --no-plot, and with --only naming
/// another figure. A figure the book embeds must not go missing quietly: if gnuplot fails, or
/// a file the script names is not written by this run, this throws (runMain turns that into
/// exit status 1) with the script and the file named.
void runGnuplot(const Options& o, const std::string& script);

/// A table printed as Markdown on stdout and written as .md, .csv and .html (the book
/// includes the .html fragment with \htmlinclude).
/// The mathematics of a table's caption, header and cells, typed in ASCII for the CSV and the
/// terminal ("N_search/sqrt(n)", "2^-53", "0 <= i < 256", "O(a,b,c)", "1e+06", "a -> b"), set for a
/// page: sub- and superscripts, √, ≤, ≪, →, ±, ⌈log₄ n⌉, the notes' 𝒪 and 𝒞 (as the figures print them, figures/ch2/notation.txt), and '<', '>', '&'
/// escaped.
std::string htmlMath(std::string s);

struct Table {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }

  std::string markdown() const;
  std::string csv() const;
  /// For the book, a table too wide for the text column is set as several narrower tables,
  /// each of these column groups (indices into `header`) one table, in this order; the first
  /// column (the row's key, n or the input) is repeated in each. Empty: one table.
  std::vector<std::vector<std::size_t>> htmlParts;

  std::string html() const;
  /// Prints the Markdown and writes <stem>.md, <stem>.csv, <stem>.html.
  /// Nothing with --only (a figure alone leaves the tables of the last full run as they are).
  void emit(const Options& o, const std::string& stem) const;
};

/// printf-style formatting into a std::string.
template <class... A>
std::string fmt(const char* f, A... a) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

/// The spread of some measurements beside their median (ch::median, timing.h), "min-max" in `format` ("-" for fewer
/// than two): a wide one says the machine was noisy.
std::string spread(const std::vector<double>& v, const char* format);

/// The numbers and verdicts a book page quotes in its prose, written by a chapter program as
/// "key value" lines into values_<program>.txt next to its tables. The book build replaces
/// each @{key} of book/*.md by its value and stops on a key that no program wrote, so the
/// text cannot drift from the measurements. A verdict ("rises", "agrees") is a value too,
/// computed from the same numbers the tables show.
class Values {
 public:
  Values(const Options& o, std::string program) : o_(o), program_(std::move(program)) {}
  /// Records `value` under `key` (one word; each key once per program).
  void set(const std::string& key, const std::string& value);
  /// A number, printf-formatted (e.g. "%.1f").
  void num(const std::string& key, double v, const char* format) { set(key, fmt(format, v)); }
  /// How a measured `last` compares with `first`, in three ways (a cost can fall as well as rise).
  void trend(const std::string& key, double first, double last);
  /// One of two words, as the measured condition says.
  void verdict(const std::string& key, bool condition, const char* ifTrue, const char* ifFalse) {
    set(key, condition ? ifTrue : ifFalse);
  }
  /// Writes values_<program>.txt into the output directory.
  /// Nothing with --only: the values of the last full run stay as they are.
  /// The value recorded under `key` (a test reads a verdict back with it).
  const std::string& get(const std::string& key) const;
  void write() const;

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
  void update(std::uint64_t done);

 private:
  std::string what_;
  std::uint64_t total_;
  bool tty_;
  std::chrono::steady_clock::time_point t0_, last_;
};

/// Seconds since `t0`.
double secondsSince(std::chrono::steady_clock::time_point t0);

}  // namespace ch
