/// \file test_chapter_options.cpp The options of the chapter programs (chapters/common.h): a hostile --out directory is a directory and never code, every bad option is one line and exit status 2 before anything is written, and --max-n, --only, --size, --seed do what --help says.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#ifndef DT_OUTPUT_DIR
#define DT_OUTPUT_DIR DT_TEST_TMP  // common.h names a default output directory; the tests write under theirs
#endif
#include "../chapters/common.h"
#include "../chapters/process.h"
#include "fast_parallel.h"
#include "support.h"

namespace fs = std::filesystem;

namespace {

struct Run {
  int status = -1;
  std::string out, err;
};

// Runs build/<program> with `args` (no shell), in `cwd`, stdout and stderr to files.
Run chapter(const std::string& program, const std::vector<std::string>& args, const fs::path& cwd) {
  static int counter = 0;
  const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
  const std::string o = dttest::tmpPath("chapter_out_" + tag), e = dttest::tmpPath("chapter_err_" + tag);
  std::vector<std::string> argv = {(fs::path(DT_CLI).parent_path() / program).string()};
  argv.insert(argv.end(), args.begin(), args.end());
  ch::ProcessIo io;
  io.cwd = cwd.string();
  io.stdoutPath = o;
  io.stderrPath = e;
  Run r;
  r.status = ch::runProgram(argv, io);
  r.out = dttest::readText(o);
  r.err = dttest::readText(e);
  fs::remove(o);
  fs::remove(e);
  return r;
}

// A fresh empty directory under the test tree.
fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(dttest::tmpPath(name + "_" + std::to_string(::getpid())));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Width and height of a PNG, from its IHDR chunk (0 0 if it is not one).
std::pair<unsigned, unsigned> pngSize(const fs::path& p) {
  const std::string s = dttest::readText(p.string());
  if (s.size() < 24 || s.compare(1, 3, "PNG") != 0) return {0, 0};
  auto be = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | unsigned(static_cast<unsigned char>(s[at + k]));
    return v;
  };
  return {be(16), be(20)};
}

std::vector<std::string> listing(const fs::path& d) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(d)) names.push_back(e.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("chapter options a hostile --out directory gets the figures and runs nothing") {
  // The names a shell would run: $(...), a quote closing a quoted string then ;, and a name
  // that starts with '-' (an option to mkdir or cat), with a space and an accented letter.
  const fs::path base = freshDir("hostile");
  const std::string name = "q'uo\"te $(touch pwned_dollar); touch pwned_semicolon; é '";
  const fs::path abs = base / name;
  const Run a = chapter("sec2_3_2_adjacencies", {"--quick", "--out", abs.string()}, base);
  INFO(a.err);
  REQUIRE(a.status == 0);
  // fig2_9.gp also reads a file of the output directory through a command (its title: "𝑛 = 12, ...").
  CHECK(fs::file_size(abs / "fig2_9.png") > 1000);
  CHECK(fs::file_size(abs / "fig2_9.svg") > 1000);
  CHECK(dttest::readText((abs / "fig2_9.svg").string()).find(" = 12, ") != std::string::npos);
  CHECK(fs::exists(abs / "table_adjacency_counts.md"));
  // A relative --out that starts with '-'.
  const Run b = chapter("sec2_3_2_adjacencies", {"--quick", "--no-plot", "--out", "-dash é"}, base);
  INFO(b.err);
  REQUIRE(b.status == 0);
  CHECK(fs::exists(base / "-dash é" / "fig2_9_tri.dat"));
  // Nothing else appeared: not in the working directory, nor where gnuplot runs.
  std::vector<std::string> names = listing(base);
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"-dash é", name});
  for (const fs::path& d : {base, fs::path(DT_SOURCE_DIR) / "figures/ch2", fs::path(DT_SOURCE_DIR),
                            fs::current_path()})
    for (const char* stray : {"pwned_dollar", "pwned_semicolon"}) {
      INFO((d / stray).string());
      CHECK_FALSE(fs::exists(d / stray));
    }
  fs::remove_all(base);
}

TEST_CASE("chapter options every bad option is one line and exit status 2 before anything is written") {
  const fs::path base = freshDir("bad_options");
  const std::vector<std::vector<std::string>> bad = {
      {"--bogus"},
      {"--out"},                                // no value
      {"extra"},                                // a positional argument
      {"--quick", "--quick"},                   // twice
      {"--max-n", "1"},                         // below what the program can do
      {"--max-n", "2e9"},                       // above it
      {"--max-n", "1.5"},
      {"--max-n", "1e3x"},
      {"--max-n", "99999999999999999999"},
      {"--max-n", "-5"},
      {"--max-n", ""},
      {"--seed", "-1"},
      {"--seed", "12abc"},
      {"--only", "fig2_1"},                     // another program's figure
      {"--size", "800"},
      {"--size", "10x10"},
      {"--size", "800x450x2"},
      {"--huge"},                               // another program's option
      {"--out", ""}};
  for (const char* program : {"sec2_1_kernel", "sec2_3_2_adjacencies", "bench_parallel"})
    for (std::vector<std::string> args : bad) {
      if (std::string(program) == "sec2_1_kernel" && args[0] == "--only") args[1] = "fig2_9";
      const fs::path out = base / "never";
      std::vector<std::string> full = {"--out", out.string()};
      if (args[0] == "--out") full.clear();  // the case is about --out itself
      full.insert(full.end(), args.begin(), args.end());
      const Run r = chapter(program, full, base);
      std::string shown = program;
      for (const auto& a : args) shown += " [" + a + "]";
      INFO(shown << "\nstderr: " << r.err);
      CHECK(r.status == 2);
      CHECK(r.out.empty());
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      CHECK(r.err.rfind(std::string(program) + ": ", 0) == 0);
      CHECK(r.err.find("usage: " + std::string(program) + " [--out DIR]") != std::string::npos);
      CHECK_FALSE(fs::exists(out));
    }
  // A program's own options are checked the same way (--reps with a value out of range, a
  // --threads list the program reads itself, a --cache-dir without a value or naming no
  // directory).
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--reps", "0"},
                                               std::vector<std::string>{"--reps"},
                                               std::vector<std::string>{"--threads", "1,x"},
                                               std::vector<std::string>{"--cache-dir"},
                                               std::vector<std::string>{"--cache-dir", (base / "absent").string()}}) {
    std::vector<std::string> full = {"--out", (base / "reps").string()};
    full.insert(full.end(), args.begin(), args.end());
    const Run r = chapter("bench_parallel", full, base);
    INFO(args[0] << " " << r.err);
    CHECK(r.status == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  fs::remove_all(base);
}

TEST_CASE("chapter options --help lists every option the same way on every program") {
  for (const char* program : {"sec2_1_kernel", "sec2_3_4_algorithms", "bench_kernels", "opt_ladder"}) {
    const Run r = chapter(program, {"--help"}, fs::current_path());
    INFO(program << "\n" << r.out << r.err);
    CHECK(r.status == 0);
    CHECK(r.out.rfind(std::string("usage: ") + program + " [--out DIR] [--quick] [--max-n N] [--no-plot] "
                      "[--seed N] [--only FIG] [--size WxH]", 0) == 0);
    for (const char* opt : {"\n  --out DIR ", "\n  --quick ", "\n  --max-n N ", "\n  --no-plot ",
                            "\n  --seed N ", "\n  --only FIG ", "\n  --size WxH ", "\n  --help "})
      CHECK(r.out.find(opt) != std::string::npos);
  }
  // A program's own options are in its usage line and have a line each.
  const Run b = chapter("bench_parallel", {"--help"}, fs::current_path());
  INFO(b.out << b.err);
  CHECK(b.status == 0);
  CHECK(b.out.find("[--reps N] [--threads LIST] [--cache-dir DIR] [--help]") != std::string::npos);
  for (const char* opt : {"\n  --reps N ", "\n  --threads LIST ", "\n  --cache-dir DIR "})
    CHECK(b.out.find(opt) != std::string::npos);
}

TEST_CASE("chapter options bench_parallel reads the caches of /sys unless --cache-dir names another directory") {
  const fs::path d = freshDir("cache_dir");
  const Run r = chapter("bench_parallel", {"--quick", "--no-plot", "--max-n", "1000", "--threads", "1", "--out",
                                           d.string()},
                        d);
  INFO(r.err);
  REQUIRE(r.status == 0);
  // The verdict names where the sizes came from, whether it listed caches or none.
  CHECK(dttest::readText((d / "time_per_point_verdict.html").string()).find("/sys/devices/system/cpu/cpu0/cache") !=
        std::string::npos);
  // An empty directory in the format: no cache, no marker, and the verdict names it.
  const fs::path empty = d / "no_caches";
  fs::create_directories(empty);
  const Run e = chapter("bench_parallel", {"--quick", "--no-plot", "--max-n", "1000", "--threads", "1",
                                           "--cache-dir", empty.string(), "--out", d.string()},
                        d);
  INFO(e.err);
  REQUIRE(e.status == 0);
  const std::string verdict = dttest::readText((d / "time_per_point_verdict.html").string());
  CHECK(verdict.find(empty.string() + " lists none") != std::string::npos);
  CHECK(verdict.find("/sys/") == std::string::npos);
  CHECK(dttest::readText((d / "time_per_point_view.gp").string()).find("\nncaches = 0\n") != std::string::npos);
  fs::remove_all(d);
}

namespace {

// The rows of a table's .csv (the header first), cells split at commas.
std::vector<std::vector<std::string>> csvRows(const fs::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(dttest::readText(p.string()));
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) rows.back().push_back(c);
  }
  return rows;
}

// The value of `key` in a values_<program>.txt ("key value" lines); "" if absent.
std::string valueOf(const fs::path& p, const std::string& key) {
  std::istringstream in(dttest::readText(p.string()));
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + " ", 0) == 0) return line.substr(key.size() + 1);
  return "";
}

}  // namespace

TEST_CASE("chapter options bench_parallel writes the time budget of its six runs and leaves out two threads when --threads does") {
  const fs::path d = freshDir("budget");
  // 20000 points: the last rounds are large enough to be shared between two threads.
  const Run r = chapter("bench_parallel", {"--quick", "--no-plot", "--max-n", "20000", "--threads", "1,2", "--out",
                                           d.string()},
                        d);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto rows = csvRows(d / "table_parallel_budget.csv");
  REQUIRE(rows.size() == 7);
  const std::vector<std::string>& head = rows[0];
  auto col = [&](const std::string& name) {
    return std::size_t(std::find(head.begin(), head.end(), name) - head.begin());
  };
  const std::size_t wall = col("wall (ms)"), concurrent = col("concurrent rounds (ms)"), busy = col("busy (ms)"),
                    perPoint = col("busy per point / sequential's");
  REQUIRE(perPoint < head.size());
  const char* labels[] = {"sequential kernel", "shared core alone (slabs)", "shared core alone (locks)",
                          "two threads (slabs)", "two threads (locks)", "two threads (parts and seam)"};
  for (std::size_t i = 0; i < 6; ++i) {
    CAPTURE(labels[i]);
    REQUIRE(rows[i + 1].size() == head.size());
    CHECK(rows[i + 1][0] == labels[i]);
    CHECK(std::atof(rows[i + 1][wall].c_str()) > 0);
    // Every run but the sequential one has concurrent rounds, busy time and a cost per point.
    CHECK((rows[i + 1][concurrent] == "-") == (i == 0));
    if (i > 0) {
      CHECK(std::atof(rows[i + 1][busy].c_str()) > 0);
      CHECK(std::atof(rows[i + 1][perPoint].c_str()) > 0);
    }
  }
  const fs::path values = d / "values_bench_parallel.txt";
  CHECK(valueOf(values, "par.budget_n") == "20000");
  for (const char* key : {"par.budget_share_cost", "par.budget_share_cost_locks", "par.budget_second_thread",
                          "par.budget_second_thread_locks", "par.budget_serial", "par.budget_best2",
                          "par.budget_best2_locks", "par.budget_k4", "par.budget_k8", "par.hw_threads",
                          "par.budget_wall2_parts", "par.budget_seam_parts", "par.budget_parts_k4",
                          "par.budget_parts_k8"}) {
    CAPTURE(key);
    const std::string v = valueOf(values, key);
    CHECK(!v.empty());
    CHECK(v.find("not measured") == std::string::npos);
  }
  // The model divides the shared core's busy time by the threads, most of the sequential wall
  // time: more threads, a clearly smaller share (more than the values' two decimals).
  CHECK(std::atof(valueOf(values, "par.budget_k8").c_str()) < std::atof(valueOf(values, "par.budget_k4").c_str()));
  CHECK(std::atof(valueOf(values, "par.budget_k4").c_str()) < std::atof(valueOf(values, "par.budget_best2").c_str()));
  // The parts' model: their busy time shared by more threads, the seam grown with the cuts.
  CHECK(std::atof(valueOf(values, "par.budget_parts_k4").c_str()) > 0);
  CHECK(std::atof(valueOf(values, "par.budget_parts_k8").c_str()) > 0);
  const std::string verdict = valueOf(values, "par.budget_best2_verdict");
  CHECK((verdict.rfind("even a perfect split", 0) == 0 || verdict.rfind("a perfect split would meet it", 0) == 0));

  // --threads 1: no run with two threads, and the values that need one say so.
  const Run one = chapter("bench_parallel", {"--quick", "--no-plot", "--max-n", "1000", "--threads", "1", "--out",
                                             d.string()},
                          d);
  INFO(one.err);
  REQUIRE(one.status == 0);
  const auto rows1 = csvRows(d / "table_parallel_budget.csv");
  REQUIRE(rows1.size() == 4);
  CHECK(rows1[3][0] == "shared core alone (locks)");
  CHECK(valueOf(values, "par.budget_best2") == "(not measured)");
  CHECK(valueOf(values, "par.budget_share_cost").find("not measured") == std::string::npos);
  CHECK(valueOf(values, "par.budget_best2_verdict").find("not measured") != std::string::npos);
  CHECK(valueOf(values, "model.break_even_n").find("not measured") != std::string::npos);
  fs::remove_all(d);
}

TEST_CASE("chapter options bench_parallel measures the cost model's constants and judges the code's against them") {
  const fs::path d = freshDir("thread_constants");
  const Run r = chapter("bench_parallel", {"--quick", "--no-plot", "--max-n", "20000", "--threads", "1,2", "--out",
                                           d.string()},
                        d);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto rows = csvRows(d / "table_thread_constants.csv");
  // The sizes 10000 and 20000 (the largest n), and five squeezes at 20000.
  REQUIRE(rows.size() == 8);
  const std::vector<std::string>& head = rows[0];
  auto col = [&](const std::string& name) {
    const std::size_t c = std::size_t(std::find(head.begin(), head.end(), name) - head.begin());
    REQUIRE(c < head.size());
    return c;
  };
  const std::size_t cn = col("n"), cw = col("x squeezed to"), cf = col("forecast / uniform"),
                    cr = col("2 threads / 1 (wall)"), cb = col("2 threads beat 1");
  struct Row {
    std::size_t n;
    bool uniform;
    double forecast, ratio;
    bool beat;
  };
  std::vector<Row> got;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    REQUIRE(rows[i].size() == head.size());
    got.push_back({std::size_t(std::atol(rows[i][cn].c_str())), rows[i][cw] == "1 (uniform)",
                   std::atof(rows[i][cf].c_str()), std::atof(rows[i][cr].c_str()), rows[i][cb] == "yes"});
    CHECK(got.back().ratio > 0);
    // The column shows the ratio to two decimals; the verdict is taken on the ratio itself, so a
    // ratio shown as 1.00 may have beaten one thread (0.996) or not (1.004).
    if (std::fabs(got.back().ratio - 1) > 0.005) CHECK(got.back().beat == (got.back().ratio < 1));
  }
  // The forecast is computed, not timed: uniform points give about the reference share, the
  // narrowest band far more than the model's bound.
  CHECK(got[1].uniform);
  CHECK(got[1].forecast > 0.5);
  CHECK(got[1].forecast < 1.5);
  CHECK(got.back().forecast > dt::ParallelModel::maxCutShareRatio);
  // The values are the table's, recomputed: the break-even (the smallest uniform size from which
  // two threads beat one at every larger size) and the bound (the largest forecast at the top
  // size up to which they beat one on every set).
  std::size_t breakEven = 0;
  for (std::size_t i = 2; i-- > 0;) {
    REQUIRE(got[i].uniform);
    if (!got[i].beat) break;
    breakEven = got[i].n;
  }
  std::vector<Row> top(got.begin() + 1, got.end());
  std::stable_sort(top.begin(), top.end(), [](const Row& a, const Row& b) { return a.forecast < b.forecast; });
  double bound = 0;
  for (const Row& t : top) {
    if (!t.beat) break;
    bound = t.forecast;
  }
  const fs::path values = d / "values_bench_parallel.txt";
  CHECK(valueOf(values, "model.n") == "20000");
  CHECK(valueOf(values, "model.break_even_n") ==
        (breakEven ? std::to_string(breakEven) : std::string("(not reached up to 20000)")));
  CHECK(valueOf(values, "model.bound_measured") == (bound > 0 ? ch::fmt("%.2f", bound) : std::string("(none measured)")));
  CHECK(valueOf(values, "model.code_size") == std::to_string(2 * dt::ParallelModel::minPointsPerThread));
  // The model's size (far above 20000) can be judged only where two threads paid.
  CHECK(valueOf(values, "model.size_verdict")
            .rfind(breakEven ? "on the safe side" : "not judged", 0) == 0);
  fs::remove_all(d);
}

TEST_CASE("chapter options --max-n reads 1e3 as 1000") {
  // atol read "1e3" as 1 and the table showed a 1x1 grid.
  const fs::path d = freshDir("max_n_1e3");
  const Run r = chapter("sec2_3_2_adjacencies", {"--quick", "--no-plot", "--max-n", "1e3", "--out", d.string()},
                        d);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::string table = dttest::readText((d / "table_adjacency_counts.csv").string());
  CHECK(table.find("1000") != std::string::npos);
  CHECK(table.find("1x1") == std::string::npos);
  fs::remove_all(d);
}

TEST_CASE("chapter options --only draws one figure at the --size given and leaves the tables alone") {
  const fs::path d = freshDir("only_size");
  const Run r = chapter("sec2_3_5_hilbert", {"--quick", "--only", "fig2_12", "--size", "640x360", "--out",
                                             d.string()},
                        d);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(pngSize(d / "fig2_12.png") == std::make_pair(640u, 360u));
  CHECK(dttest::readText((d / "fig2_12.svg").string()).find("width=\"640\"") != std::string::npos);
  for (const char* absent : {"fig2_11.png", "fig_brio_rounds.png", "table2_2.md", "values_sec2_3_5_hilbert.txt"}) {
    INFO(absent);
    CHECK_FALSE(fs::exists(d / absent));
  }
  // Without --size: the style's size (fig2_12 1400x780 in style.gp's table).
  const Run s = chapter("sec2_3_5_hilbert", {"--quick", "--only", "fig2_12", "--out", d.string()}, d);
  REQUIRE(s.status == 0);
  CHECK(pngSize(d / "fig2_12.png") == std::make_pair(1400u, 780u));
  fs::remove_all(d);
}

TEST_CASE("chapter options --seed changes the random points and no --seed keeps the book's") {
  const fs::path d = freshDir("seed");
  auto points = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"--quick", "--no-plot", "--only", "fig2_12", "--out", d.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const Run r = chapter("sec2_3_5_hilbert", args, d);
    REQUIRE(r.status == 0);
    return dttest::readText((d / "fig2_12_1000.dat").string());
  };
  const std::string book = points({}), again = points({}), one = points({"--seed", "1"}),
                    oneAgain = points({"--seed", "1"}), two = points({"--seed", "2"});
  CHECK(book.size() > 1000);
  CHECK(book == again);
  CHECK(one == oneAgain);
  CHECK(one != book);
  CHECK(two != one);
  // The book's points are the program's fixed seed: the same as the generator's.
  const dt::XY p = dt::uniformPoints(1000, 2012 + 1000);
  std::ostringstream first;
  first << p[0];
  CHECK(book.find("\n" + first.str() + " ") != std::string::npos);
  fs::remove_all(d);
}

TEST_CASE("chapter options a table's page form sets its ASCII mathematics and escapes HTML") {
  CHECK(ch::htmlMath("N_search/sqrt(n)") == "N<sub>search</sub>/√n");
  CHECK(ch::htmlMath("eps = 2^-53, 0 <= i,j < 256") == "eps = 2<sup>−53</sup>, 0 ≤ i,j &lt; 256");
  CHECK(ch::htmlMath("|O| > 1e-15 max(...)^2") == "|𝒪| &gt; 10<sup>−15</sup> max(…)<sup>2</sup>");
  CHECK(ch::htmlMath("naive InC(a,b,c,d), |C| + 2, DT(S0 ∪ S), DT_k") ==
        "naive 𝒞(a,b,c,d), |𝒞| + 2, DT(S<sub>0</sub> ∪ S), DT<sub>k</sub>");
  CHECK(ch::htmlMath("N ~ n^a, n^1.5, t/n (us)") == "N ∼ n<sup>a</sup>, n<sup>1.5</sup>, t/n (µs)");
  CHECK(ch::htmlMath("2^-60..2^60, ±m 2^-e, 1e+06, 1e+-300") ==
        "2<sup>−60</sup>..2<sup>60</sup>, ±m 2<sup>−e</sup>, 10<sup>6</sup>, 10<sup>±300</sup>");
  CHECK(ch::htmlMath("4^d << n, depth ceil(log4 n) + 8, a -> b") == "4<sup>d</sup> ≪ n, depth ⌈log₄ n⌉ + 8, a → b");
  // Words and numbers are left alone: a name with an underscore, a rounded value, an entity.
  CHECK(ch::htmlMath("threads_used 3.2e-05 a&nbsp;b R&D") == "threads_used 3.2e-05 a&nbsp;b R&amp;D");
  ch::Table t;
  t.caption = "x < y";
  t.header = {"n_h"};
  t.add({"a & b"});
  CHECK(t.html().find("<caption>x &lt; y</caption>\n<tr><th>n<sub>h</sub></th></tr>\n<tr><td>a &amp; b</td></tr>") !=
        std::string::npos);
  CHECK(t.csv() == "n_h\na & b\n");
}

TEST_CASE("chapter options a trend verdict follows the measured ratio in three ways") {
  ch::Options o;
  ch::Values v(o, "trend_test");
  v.trend("up", 10.0, 12.6);
  v.trend("flat_up", 10.0, 12.4);
  v.trend("flat_down", 10.0, 7.6);
  v.trend("down", 10.0, 7.4);
  CHECK(v.get("up") == "rises by more than a quarter");
  CHECK(v.get("flat_up") == "stays within a quarter of its first value");
  CHECK(v.get("flat_down") == "stays within a quarter of its first value");
  CHECK(v.get("down") == "falls by more than a quarter");
  CHECK_THROWS_AS(v.get("missing"), std::invalid_argument);
}
