// delaunay2d: the Delaunay triangulation DT(S) of a point file, exact for every input.
//
//   delaunay2d points.node -o out [--method hull|super] [--order O] [--stats]
//              [--svg out.svg] [--msh out.msh] [--no-check] [--kernel fast|listings]
//
// Reads a Triangle .node file or a plain "x y" file, writes out.ele (Triangle format,
// counter-clockwise triangles, vertices numbered as in the input). Exit status: 0 on success,
// 2 on bad input or usage (one line on stderr, nothing written), 1 on an internal error or an
// output that cannot be written. Outputs are all or nothing, and a failure leaves the files
// that were there before as they were (dt::OutputFiles).
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <cmath>
#include <functional>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sched.h>
#include <sys/stat.h>
#include <unistd.h>

#include "delaunay2d.h"

#include "delaunay.h"
#include "fast_parallel.h"
#include "io.h"
#include "output_files.h"
#include "triangulate.h"

namespace {

const char* kUsage =
    "usage: delaunay2d INPUT -o OUT [options]\n"
    "  INPUT          Triangle .node file, or a text file of 'x y' lines; '-' reads\n"
    "                 standard input (a .node file if its first line has 4 fields)\n"
    "  -o OUT         write OUT.ele (OUT may also end in .ele); '-o -' writes the .ele to\n"
    "                 standard output, and OUT naming a named pipe or a character device\n"
    "                 (-o /dev/null: no .ele) gets the .ele itself\n"
    "  --stats        print points, triangles, triangulation_seconds (and of it the\n"
    "                 system's time, triangulation_system_seconds), mean walk steps,\n"
    "                 mean cavity size, threads asked for, used and why, and peak memory,\n"
    "                 one per line, on stdout (on stderr when an output goes to stdout)\n"
    "  --svg FILE     also write an SVG drawing of the mesh ('-': standard output)\n"
    "  --msh FILE     also write a Gmsh ASCII (2.2) mesh ('-': standard output)\n"
    "  --no-check     skip the exact validation of the result (on by default)\n"
    "  --method M     how DT(S) is built: 'hull' (default; ghost faces, points outside the\n"
    "                 hull inserted directly, section 2.2.2) or 'super' (super-triangles,\n"
    "                 then DT(S) recovered from DT(S0 u S) by flips, 2.2.1 and 2.3.6); both\n"
    "                 give the exact DT(S); with --stats, 'super' also prints recovery_flips\n"
    "  --order O      insertion order (section 2.3.5), the same for both kernels: 'brio'\n"
    "                 (default; dt::brioCoinOrder: 8 rounds drawn by biased coins, each\n"
    "                 Hilbert-sorted), 'brio-doubling' (dt::brioOrder: rounds of\n"
    "                 doubling sizes), 'hilbert' (one Hilbert sort: as\n"
    "                 fast on spread-out points, quadratic on points along a curve) or\n"
    "                 'input' (file order: walks grow like sqrt(n), like n on sorted input);\n"
    "                 when a run turns quadratic (any order, either kernel), a warning on\n"
    "                 stderr says so once and what to try instead\n"
    "  --kernel K     'fast' (default: code/fast/fast_delaunay.h, index arrays, inlined filters,\n"
    "                 its own Hilbert sort) or 'listings' (the corrected Listings 2.4-2.7);\n"
    "                 both give the exact DT(S); --method super always uses the listings\n"
    "  --threads N    at most N threads for the fast kernel with --order brio ('auto': the\n"
    "                 machine's cores; default 1: the sequential kernel, one output per\n"
    "                 input); more than one only where the parallel page's cost model says\n"
    "                 they pay (--stats prints threads_requested, threads_used and\n"
    "                 threads_reason), and never more than the CPUs the process may run\n"
    "                 on (capped, with a note); a Delaunay DT(S), on cocircular points\n"
    "                 possibly another than one thread's (the same on every run)\n"
    "  --progress     report progress on stderr (default: only when stderr is a terminal)\n"
    "  --no-progress  never report progress\n"
    "  -h, --help     this help\n"
    "outputs: a file is written beside its target and renamed into place when all are\n"
    "written (through a symlink: beside the file it points to); a named pipe, a device or\n"
    "standard output is written straight into; a directory, socket or block device is refused\n"
    "exit status: 0 success; 1 internal error, output not writable, threads that cannot\n"
    "start, or --stats lost (a closed or full standard output: the outputs are then written);\n"
    "2 bad usage or bad input (one line naming file, line and value, control characters\n"
    "written as \\n or \\xHH); on failure no file output is written and files that were there\n"
    "before are left as they were\n";

struct Options {
  std::string input, out, svg, msh;
  bool stats = false, check = true;
  dt::BuildMethod method = dt::BuildMethod::Hull;
  dt::KernelChoice kernel = dt::KernelChoice::Fast;
  // --order (2.3.5). BRIO by default: a plain Hilbert sort makes points along a curve (a
  // parabola) cost O(n) per insertion, BRIO's random rounds do not (sec2_3_5_hilbert).
  dt::InsertionOrder order = dt::InsertionOrder::Brio;
  int progress = -1;         // --progress 1, --no-progress 0, default -1: if stderr is a tty
  bool statsOnStderr = false;  // an output goes to standard output: it carries only data
  // -o names a stream ('-', /dev/null, a named pipe, /dev/stdout): the .ele is written into it.
  bool eleIntoOut = false;
  // --threads N (fast kernel, BRIO order). Default 1: on cocircular points two threads may
  // return another Delaunay triangulation than one thread (the same one on every run: the
  // book's "parallel" page); more threads are used only where they pay.
  int threads = 1;
};

// A message as one line: a control character (a newline or an escape sequence in a path) is
// written as \n, \t, \r or \xHH, so that it can neither split the line nor drive the terminal.
std::string oneLine(const std::string& text) {
  std::string s;
  for (const char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u != 0x7f) {
      s += c;
    } else if (c == '\n') {
      s += "\\n";
    } else if (c == '\t') {
      s += "\\t";
    } else if (c == '\r') {
      s += "\\r";
    } else {
      const char* hex = "0123456789abcdef";
      s += std::string("\\x") + hex[u >> 4] + hex[u & 15];
    }
  }
  return s;
}

// One error line on stderr: "delaunay2d: " and the text, escaped (oneLine).
void errorLine(const std::string& text) { std::cerr << "delaunay2d: " << oneLine(text) << "\n"; }

[[noreturn]] void usageError(const std::string& why);

// The value of an option word (dt::methodNamed, orderNamed, kernelNamed), or a usage error.
template <class Parse>
auto named(Parse parse, const std::string& word) {
  try {
    return parse(word);
  } catch (const std::invalid_argument& e) {
    usageError(e.what());
  }
}

[[noreturn]] void usageError(const std::string& why) {
  std::cerr << "delaunay2d: " << oneLine(why)
            << " (usage: delaunay2d INPUT -o OUT [options]; delaunay2d --help for more)\n";
  std::exit(2);
}

// The options, one row each: to add one, add a row (its names, whether it takes a value, the
// key under which a repetition is refused, and what it sets) and a line of kUsage.
struct OptionSpec {
  const char* name;
  const char* alias;  // or nullptr
  bool takesValue;
  const char* key;    // options with the same key may be given once between them
  void (*set)(Options& o, const std::string& value);
};

const OptionSpec kOptions[] = {
    {"-o", nullptr, true, "-o", [](Options& o, const std::string& v) { o.out = v; }},
    {"--stats", nullptr, false, "--stats", [](Options& o, const std::string&) { o.stats = true; }},
    {"--svg", nullptr, true, "--svg", [](Options& o, const std::string& v) { o.svg = v; }},
    {"--msh", nullptr, true, "--msh", [](Options& o, const std::string& v) { o.msh = v; }},
    {"--no-check", nullptr, false, "--no-check",
     [](Options& o, const std::string&) { o.check = false; }},
    {"--method", nullptr, true, "--method",
     [](Options& o, const std::string& v) {
       o.method = named(dt::methodNamed, v);
     }},
    {"--order", nullptr, true, "--order",
     [](Options& o, const std::string& v) {
       o.order = named(dt::orderNamed, v);
     }},
    {"--kernel", nullptr, true, "--kernel",
     [](Options& o, const std::string& v) {
       o.kernel = named(dt::kernelNamed, v);
     }},
    {"--progress", nullptr, false, "--progress",
     [](Options& o, const std::string&) { o.progress = 1; }},
    {"--no-progress", nullptr, false, "--progress",
     [](Options& o, const std::string&) { o.progress = 0; }},
    {"--threads", nullptr, true, "--threads",
     [](Options& o, const std::string& v) {
       // 'auto' or digits only: strtol alone would also take " 2", "+2" and "2 ".
       const bool digits = !v.empty() && v.size() <= 4 &&
                           v.find_first_not_of("0123456789") == std::string::npos;
       const long t = v == "auto" ? dt::defaultThreadCount() : digits ? std::atol(v.c_str()) : 0;
       if (t < 1 || t > 1024)
         usageError("--threads must be 'auto' or an integer from 1 to 1024, not '" + v + "'");
       o.threads = int(t);
     }},
};

// Progress on stderr for long runs: the phase, and while the listings insert, the points
// inserted, the rate and the time left; on a terminal one line rewritten in place. Phases are
// shown for inputs of 100000 points or more, the insertion count after half a second.
class Progress {
 public:
  explicit Progress(int mode)  // 1: always, 0: never, -1: if stderr is a terminal
      : on_(mode == 1 || (mode == -1 && tty_)), forced_(mode == 1) {}
  void setTotal(std::size_t n) { total_ = n; }
  void phase(const std::string& what) {
    current_ = what;
    if (on_ && (forced_ || shown_ || total_ >= 100000)) show(what);
  }
  /// The phase under way (named in an out-of-memory message).
  const std::string& current() const { return current_; }
  void startInsertion() {
    insertStart_ = std::chrono::steady_clock::now();
    lastShown_ = 0;
  }
  double insertionSeconds() const { return since(insertStart_); }
  void setQuadratic() { quadratic_ = true; }
  void update(std::size_t done) {
    if (!on_) return;
    const double t = since(insertStart_);
    if (t < 0.5 || t - lastShown_ < 0.25) return;
    // The rate of the last interval: in file order, insertion slows down as n grows.
    const double rate = lastShown_ > 0 ? double(done - lastDone_) / (t - lastShown_) : done / t;
    lastShown_ = t;
    lastDone_ = done;
    // When each insertion costs O(done) (quadratic: WalkWatch), the time grows like done^2.
    const double r = done > 0 ? double(total_) / double(done) : 1.0;
    const double left = quadratic_ ? t * (r * r - 1) : rate > 0 ? double(total_ - done) / rate : 0.0;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%zu of %zu points inserted (%.0f%%), %.0f points/s, about "
                  "%.0f s left", done, total_, total_ ? 100.0 * double(done) / double(total_) : 100.0,
                  rate, left);
    show(buf);
  }
  // The last line (it ends the rewritten line on a terminal).
  void finish(std::size_t points) {
    if (!on_ || !(forced_ || shown_)) return;
    std::fprintf(stderr, "%sdelaunay2d: %zu points triangulated in %.1f s\n",
                 tty_ ? "\r\033[K" : "", points, since(start_));
  }

 private:
  void show(const std::string& what) {
    if (tty_)
      std::fprintf(stderr, "\rdelaunay2d: %s\033[K", what.c_str());
    else
      std::fprintf(stderr, "delaunay2d: %s\n", what.c_str());
    std::fflush(stderr);
    shown_ = true;
  }
  static double since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }
  bool tty_ = ::isatty(STDERR_FILENO) == 1;
  bool on_, forced_;
  bool shown_ = false, quadratic_ = false;
  std::string current_ = "reading the input";
  std::size_t total_ = 0, lastDone_ = 0;
  double lastShown_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(),
                                        insertStart_ = start_;
};

constexpr std::size_t kNamedDuplicates = 10;

// Valid input that the chosen method cannot handle (exit status 2, like bad input).
struct UnsupportedInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An order (any of them, in either kernel) that makes the walks or the cavities grow like the
// number of points inserted makes the run quadratic. Watched between chunks of insertions; one
// warning, which says what to try instead.
class WalkWatch {
 public:
  WalkWatch(dt::InsertionOrder order, bool fastKernel, Progress& progress)
      : order_(order), fast_(fastKernel), progress_(progress) {}
  // `done` of `total` points inserted, with the running sums of walk steps and cavity faces.
  void update(std::size_t done, std::size_t total, std::uint64_t walk, std::uint64_t cavity,
              double seconds) {
    if (warned_ || done <= lastDone_) return;
    const double k = double(done - lastDone_);
    const double w = double(walk - lastWalk_) / k, c = double(cavity - lastCavity_) / k;
    lastDone_ = done, lastWalk_ = walk, lastCavity_ = cavity;
    // A chunk of a few points (the last one) may hold one point's O(n) cavity: not a trend.
    if (done < 2048 || k < 512) return;
    // In a good order both stay O(1); in file order on spread-out points the walks grow like
    // sqrt(n) (about sqrt(done) steps at most): a cost per point far above that is linear.
    const double limit = 4 * std::sqrt(double(done)) + 64;
    bool linear = w >= limit || c >= limit;
    // A slower linear growth (BRIO's last round of collinear points with the listings: about
    // one step more per thousand points) stays under that limit for millions of points: the
    // cost of a chunk is compared with the cost at a quarter as many points. Linear growth
    // multiplies it by 4, sqrt(n) (spread-out points in file order, not flagged) by 2, a good
    // order by 1.
    const double cost = std::max(w, c);
    const auto quarter = std::upper_bound(history_.begin(), history_.end(),
                                          std::make_pair(done / 4, HUGE_VAL));
    if (quarter != history_.begin())
      linear = linear || (cost >= 32 && cost >= 3 * std::max(std::prev(quarter)->second, 1.0));
    history_.emplace_back(done, cost);
    if (!linear) return;
    warned_ = true;
    progress_.setQuadratic();
    // A cost per point growing linearly: the remaining time grows like total^2 - done^2.
    const double r = double(total) / double(done);
    std::string instead = order_ != dt::InsertionOrder::Brio ? "--order brio avoids it"
                          : fast_          ? "--kernel listings may avoid it"
                                           : "--kernel fast may avoid it";
    std::fprintf(stderr,
                 "delaunay2d: warning: %s average %.0f triangles per point after %zu of %zu "
                 "points: --order %s on this input (sorted, along a curve, or cocircular) takes "
                 "quadratic time, about %.0f s in all at this rate; %s\n",
                 w >= c ? "walks" : "cavities", cost, done, total, dt::orderName(order_),
                 seconds * r * r, instead.c_str());
  }

 private:
  dt::InsertionOrder order_;
  bool fast_, warned_ = false;
  Progress& progress_;
  std::size_t lastDone_ = 0;
  std::uint64_t lastWalk_ = 0, lastCavity_ = 0;
  std::vector<std::pair<std::size_t, double>> history_;  // (points done, cost of that chunk)
};

Options parse(int argc, char** argv) {
  Options o;
  std::vector<std::string> given;  // keys of the options seen
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      std::exit(0);
    }
    const OptionSpec* spec = nullptr;
    for (const OptionSpec& s : kOptions)
      if (a == s.name || (s.alias != nullptr && a == s.alias)) spec = &s;
    if (spec != nullptr) {
      if (std::find(given.begin(), given.end(), spec->key) != given.end())
        usageError(a == spec->key ? "option " + a + " given twice"
                                  : "option " + a + " conflicts with an earlier " + spec->key);
      given.push_back(spec->key);
      if (spec->takesValue && i + 1 >= argc) usageError(a + " needs a value");
      spec->set(o, spec->takesValue ? std::string(argv[++i]) : std::string());
    } else if (!a.empty() && a[0] == '-' && a != "-") {
      usageError("unknown option '" + a + "'");
    } else if (o.input.empty()) {
      o.input = a;
    } else {
      usageError("more than one input file ('" + o.input + "' and '" + a + "')");
    }
  }
  if (o.input.empty()) usageError("no input file");
  if (o.out.empty()) usageError("no output name (-o OUT)");
  if (o.out.size() > 4 && o.out.compare(o.out.size() - 4, 4, ".ele") == 0)
    o.out.resize(o.out.size() - 4);
  // -o is a base name: "-o dir/" or "-o dir" would write dir/.ele or dir.ele, never meant.
  struct stat st;
  if (o.out.back() == '/' || (o.out != "-" &&
                              ::stat(o.out.c_str(), &st) == 0 && S_ISDIR(st.st_mode))) {
    const std::string dir = o.out.back() == '/' ? o.out : o.out + "/";
    usageError("-o " + o.out + " names a directory; -o takes a base name (-o " + dir +
               "mesh writes " + dir + "mesh.ele)");
  }
  // "-o /dev/null" discards the .ele rather than create /dev/null.ele; a pipe or a device is
  // written into like "-o -" (dt::planOutputs reports a path that cannot be classified).
  try {
    o.eleIntoOut = o.out == "-" || dt::classifyOutput(o.out).kind == dt::OutputTarget::Stream;
  } catch (const std::exception&) {
  }
  return o;
}

// The outputs asked for, in the order they are written: the .ele first.
std::vector<dt::OutputRequest> outputRequests(const Options& opt) {
  std::vector<dt::OutputRequest> out = {{"-o " + opt.out, opt.eleIntoOut ? opt.out : opt.out + ".ele"}};
  if (!opt.svg.empty()) out.push_back({"--svg", opt.svg});
  if (!opt.msh.empty()) out.push_back({"--msh", opt.msh});
  return out;
}

// Why an output cannot be written because it names standard output or error that the caller
// closed (held by /dev/null since: not a sink); empty if it can.
std::string closedDescriptor(const dt::OutputRequest& r, const bool closedAtStart[3]) {
  const std::string& p = r.path;
  for (int fd : {1, 2}) {
    const std::string n = std::to_string(fd);
    if (closedAtStart[fd] && ((fd == 1 && (p == "-" || p == "/dev/stdout")) ||
                              (fd == 2 && p == "/dev/stderr") || p == "/dev/fd/" + n ||
                              p == "/proc/self/fd/" + n))
      return r.option.substr(0, r.option.find(' ')) + " " + p + ": cannot write to descriptor " +
             n + ": " + std::strerror(EBADF);
  }
  return "";
}

// A pause inside the commit after each rename ("committing N"), and one after the commit
// ("committed", renamed = 0), announced on stderr, so that a test can send a signal or start a
// second run right then. The signals are blocked during and after the commit: once one is
// pending the pause has served its test, and it ends.
void commitPause(std::size_t renamed, long ms) {
  const std::string line = renamed == 0 ? std::string("delaunay2d: committed\n")
                                        : "delaunay2d: committing " + std::to_string(renamed) + "\n";
  (void)!::write(STDERR_FILENO, line.data(), line.size());
  for (long waited = 0; waited < ms; waited += 10) {
    sigset_t pending;
    if (::sigpending(&pending) == 0 && (sigismember(&pending, SIGTERM) == 1 || sigismember(&pending, SIGHUP) == 1 ||
                                        sigismember(&pending, SIGINT) == 1))
      return;
    ::usleep(useconds_t(std::min(10L, ms - waited) * 1000));
  }
}

int delaunay2d(int argc, char** argv, const dt::cli::TestHooks& hooks) {
  // A standard descriptor closed by the caller (>&-) is held by /dev/null, so that no output
  // or temporary opened later takes its number and receives messages; --stats meant for a
  // closed one is reported as lost.
  bool closedAtStart[3] = {false, false, false};
  for (int fd = 0; fd < 3; ++fd)
    if (::fcntl(fd, F_GETFD) < 0 && errno == EBADF) {
      closedAtStart[fd] = true;
      const int null = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
      if (null >= 0 && null != fd) {
        ::dup2(null, fd);
        ::close(null);
      }
    }
  Options parsed = parse(argc, argv);
  // More threads than the CPUs this process may run on only wait for each other.
  cpu_set_t cpus;
  const int usable = ::sched_getaffinity(0, sizeof cpus, &cpus) == 0 ? CPU_COUNT(&cpus) : 0;
  if (usable > 0 && parsed.threads > usable) {
    errorLine("note: --threads " + std::to_string(parsed.threads) + " capped to " +
              std::to_string(usable) + ", the CPUs this process may run on");
    parsed.threads = usable;
  }
  // Every output is classified once, before anything is read; the plan is what is written.
  const std::vector<dt::OutputRequest> requests = outputRequests(parsed);
  for (const dt::OutputRequest& r : requests) {
    const std::string why = closedDescriptor(r, closedAtStart);
    if (!why.empty()) {
      errorLine(why);
      return 1;
    }
  }
  dt::OutputPlan plan;
  try {
    plan = dt::planOutputs(requests, parsed.input);
  } catch (const dt::OutputConflict& e) {
    usageError(e.what());
  } catch (const dt::OutputRefused& e) {
    errorLine(e.what());
    return 2;
  } catch (const std::exception& e) {
    errorLine(e.what());
    return 1;
  }
  if (plan.toStandardOutput) parsed.statsOnStderr = true;
  const Options& opt = parsed;
  Progress progress(opt.progress);
  // Notes on merged duplicates: printed after the run, or after the error line if it fails.
  std::string notes;
  int status = 0;
  try {
    dt::PointSet ps = dt::readPoints(opt.input);
    const std::size_t n = ps.size();
    auto note = [&](std::size_t dup, std::size_t kept) {
      notes += "delaunay2d: " + oneLine(ps.path) + ":" + std::to_string(ps.line(dup)) + ": point " +
               std::to_string(ps.number(dup)) + " duplicates point " +
               std::to_string(ps.number(kept)) + " (line " + std::to_string(ps.line(kept)) +
               "); merged\n";
    };
    // The geometry is the library's (dt::triangulate): here only the options, the progress
    // report and the notes on duplicates.
    WalkWatch watch(opt.order, opt.kernel == dt::KernelChoice::Fast, progress);
    dt::TriangulateOptions to;
    to.method = opt.method;
    to.kernel = opt.kernel;
    to.order = opt.order;
    to.threads = opt.threads;
    to.check = opt.check;
    to.phase = [&](const std::string& what, std::size_t points) {
      progress.setTotal(points);
      progress.phase(what);
      progress.startInsertion();
    };
    to.progress = [&](std::size_t done, std::size_t total, std::uint64_t walk, std::uint64_t cav) {
      progress.update(done);
      watch.update(done, total, walk, cav, progress.insertionSeconds());
    };
    progress.setTotal(n);
    dt::TriangulateResult r;
    try {
      r = dt::triangulate(std::move(ps.xy), to);
    } catch (const dt::UnsupportedInput& e) {
      throw UnsupportedInput(std::to_string(ps.line(e.point)) + ": " + e.what());
    }
    const std::size_t nDup = r.duplicates.size(), nDistinct = n - nDup;
    for (std::size_t j = 0; j < nDup && j < kNamedDuplicates; ++j)  // not 10^6 lines for 10^6 copies
      note(std::size_t(r.duplicates[j].first), std::size_t(r.duplicates[j].second));
    const std::vector<dt::Tri>& tri = r.tri;
    if (nDup > kNamedDuplicates)
      notes += "delaunay2d: " + oneLine(ps.path) + ": " + std::to_string(nDup - kNamedDuplicates) +
               " more duplicate points merged (" + std::to_string(nDup) + " in all)\n";
    const std::vector<double>& xy = r.xy;
    progress.phase("writing " + oneLine(plan.requests[0].path));
    // All or nothing (dt::OutputFiles): every file is written beside its target, then all are
    // renamed into place; on any failure the old files stay as they were.
    dt::OutputFiles files(plan);
    dt::writeEle(files.writer(0), tri, r.input, ps.firstIndex);
    std::size_t next = 1;
    if (!opt.svg.empty()) dt::writeSvg(files.writer(next++), xy, tri);
    if (!opt.msh.empty()) dt::writeMsh(files.writer(next++), xy, tri, r.input, r.used);
    if (hooks.holdOutputsSeconds >= 0) {
      // The outputs are written but not in place; a signal now must remove them.
      for (std::size_t i = 0; i < plan.targets.size(); ++i) files.writer(i).flush();
      std::fprintf(stderr, "delaunay2d: holding\n");
      std::fflush(stderr);
      ::sleep(unsigned(hooks.holdOutputsSeconds));
    }
    dt::OutputHooks commitHooks;
    if (hooks.commitPauseMs >= 0)
      commitHooks.afterRename = [&](std::size_t renamed) { commitPause(renamed, hooks.commitPauseMs); };
    // Once the first output is renamed the run has succeeded: a signal from then on is kept
    // blocked (and dropped at exit), so the exit status and --stats still say so.
    files.commit(dt::OutputFiles::AfterCommit::KeepSignalsBlocked, commitHooks);
    if (hooks.commitPauseMs >= 0) commitPause(0, hooks.commitPauseMs);
    // The outputs are final: a reader that has gone (stdout or stderr a closed pipe) must not
    // turn that into a death by SIGPIPE. Lost notes leave the status 0; lost --stats do not.
    std::signal(SIGPIPE, SIG_IGN);
    progress.finish(nDistinct);
    std::cerr << notes;
    notes.clear();
    if (opt.stats) {
      std::FILE* so = opt.statsOnStderr ? stderr : stdout;
      const char* soName = opt.statsOnStderr ? "standard error" : "standard output";
      std::fprintf(so, "points: %zu\ntriangles: %zu\ntriangulation_seconds: %.6f\n", n, tri.size(),
                   r.seconds);
      if (r.systemSeconds >= 0)
        std::fprintf(so, "triangulation_system_seconds: %.6f\n", r.systemSeconds);
      const double ins = r.insertions ? double(r.insertions) : 1.0;
      std::fprintf(so, "duplicates: %zu\nmean_walk_steps: %.4f\nmean_cavity_size: %.4f\n", nDup,
                   double(r.walkSteps) / ins, double(r.cavityFaces) / ins);
      if (opt.method == dt::BuildMethod::Super)
        std::fprintf(so, "recovery_flips: %llu\n", (unsigned long long)r.recoveryFlips);
      std::fprintf(so, "threads_requested: %d\nthreads_used: %d\nthreads_reason: %s\n",
                   opt.threads, r.threadsUsed, r.threadsReason.c_str());
      std::fprintf(so, "peak_memory_mb: %.1f\n", double(dt::peakResidentKB()) / 1024.0);
      errno = 0;
      if (std::fflush(so) != 0 || std::ferror(so) || closedAtStart[opt.statsOnStderr ? 2 : 1]) {
        const int err = closedAtStart[opt.statsOnStderr ? 2 : 1] ? EBADF : errno;
        errorLine(std::string("--stats: cannot write to ") + soName + ": " +
                  (err != 0 ? std::strerror(err) : "write error") + " (the outputs are written)");
        return 1;
      }
    }
    return 0;
  } catch (const dt::InputError& e) {
    errorLine(e.what());
    status = 2;
  } catch (const dt::DegenerateInput& e) {
    errorLine(opt.input + ": " + e.what() + ": no triangulation exists");
    notes.clear();  // the duplicates do not matter: nothing is triangulated
    status = 2;
  } catch (const UnsupportedInput& e) {
    errorLine(opt.input + ":" + e.what());
    status = 2;
  } catch (const std::bad_alloc&) {
    errorLine((opt.input == "-" ? std::string("stdin") : opt.input) + ": out of memory while " +
              progress.current());
    status = 1;
  } catch (const std::exception& e) {
    errorLine(std::string("error: ") + e.what());
    status = 1;
  }
  std::cerr << notes;
  return status;
}

}  // namespace

int dt::cli::run(int argc, char** argv, const TestHooks& hooks) { return delaunay2d(argc, argv, hooks); }
