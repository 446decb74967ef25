/// \file figure_run.h One run of the chapter programs that draw the book's figures, shared by the
/// test files that check those figures (test_figures.cpp, test_figures_rules.cpp).
//
// Each ctest entry is a process of its own. The first entry that needs the figures runs the
// programs (--quick --max-n 2000; bench_parallel --max-n 100000 with a planted cache
// description, so that its chart draws every cache marker) into DT_TEST_TMP/figure_run, under a
// lock; an entry that comes later, or waits on the lock, reads that run. A run is reused only
// while the programs and the figure scripts are the same bytes: their hash is the run's key, and
// a run that did not finish has no key. DT_FIGURES_DIR=DIR checks the figures already in DIR
// (e.g. build/output/ch2 after scripts/main.sh) instead.
#pragma once

#include "../chapters/process.h"

#include <sys/file.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace dttest {

/// A planted cache of the machine's description, as /sys/devices/system/cpu/cpu0/cache lists it.
struct PlantedCache {
  std::string index, level, type, size;
};

/// The caches bench_parallel marks in the figure run (--cache-dir): an instruction cache, which
/// it leaves out, and three data or unified ones small enough that the n at which the kernel's
/// data fills each is within the run's sizes. That n is the size over the bytes per point of the
/// largest n, and a small run's peak memory is mostly the process's own, inherited from the
/// parent it is forked from (about 11 MB at 10^5 points in a Release build, about 110 bytes a
/// point; 60 to 165 MB with the sanitizers, up to about 1700 bytes a point). With --max-n 100000
/// the chart's sizes run from about 316 to 10^5, so 1, 2 and 4 MiB fall inside them for any
/// bytes per point from about 42 to 3300: between about 600 and 40000 points in both builds.
inline const std::vector<PlantedCache>& figureRunCaches() {
  static const std::vector<PlantedCache> caches = {{"index0", "1", "Instruction", "32K"},
                                                   {"index1", "1", "Data", "1024K"},
                                                   {"index2", "2", "Unified", "2M"},
                                                   {"index3", "3", "Unified", "4M"}};
  return caches;
}

inline void plantCaches(const std::filesystem::path& dir, const std::vector<PlantedCache>& caches) {
  std::filesystem::remove_all(dir);
  for (const PlantedCache& c : caches) {
    std::filesystem::create_directories(dir / c.index);
    std::ofstream(dir / c.index / "level") << c.level << "\n";
    std::ofstream(dir / c.index / "type") << c.type << "\n";
    std::ofstream(dir / c.index / "size") << c.size << "\n";
  }
}

/// Where the chapter programs wrote, the planted caches (empty with DT_FIGURES_DIR), and the
/// programs that failed, with their log.
struct FigureRun {
  std::filesystem::path dir;
  std::filesystem::path caches;
  std::vector<std::string> failures;
};

namespace figure_run_detail {

inline const std::vector<std::string>& programs() {
  // bench_kernels and sec2_3_3 draw no figure.
  static const std::vector<std::string> p = {"sec2_1_kernel", "sec2_2_bowyer_watson", "sec2_2_2_outside_hull",
                                             "sec2_3_1_predicates", "sec2_3_2_adjacencies", "sec2_3_4_algorithms",
                                             "sec2_3_5_hilbert", "sec2_3_6_flips", "opt_ladder",
                                             "bench_parallel"};
  return p;
}

// FNV-1a over the bytes of the programs and of every file of figures/ch2 (names included).
inline std::string key(const std::filesystem::path& bin) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const std::string& p : programs()) files.push_back(bin / p);
  std::vector<fs::path> scripts;
  for (const auto& e : fs::directory_iterator(fs::path(DT_SOURCE_DIR) / "figures" / "ch2"))
    if (e.is_regular_file()) scripts.push_back(e.path());
  std::sort(scripts.begin(), scripts.end());
  files.insert(files.end(), scripts.begin(), scripts.end());
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const std::string& bytes) {
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  };
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    mix(f.filename().string());
    mix(std::string(std::istreambuf_iterator<char>(in), {}));
  }
  return std::to_string(h);
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace figure_run_detail

inline const FigureRun& figureRun() {
  static const FigureRun run = [] {
    namespace fs = std::filesystem;
    FigureRun r;
    if (const char* dir = std::getenv("DT_FIGURES_DIR")) {
      r.dir = dir;
      return r;
    }
    const fs::path root = fs::path(DT_TEST_TMP) / "figure_run";
    fs::create_directories(root);
    r.dir = root / "out";
    r.caches = root / "caches";
    const fs::path bin = fs::path(DT_CLI).parent_path();
    const std::string want = figure_run_detail::key(bin);
    // One process at a time past this line; the lock goes with the process.
    const int lock = ::open((root / "lock").c_str(), O_CREAT | O_RDWR, 0644);
    if (lock >= 0) ::flock(lock, LOCK_EX);
    if (figure_run_detail::slurp(root / "key") != want) {
      fs::remove(root / "key");
      fs::remove_all(r.dir);
      fs::create_directories(r.dir);
      plantCaches(r.caches, figureRunCaches());
      // All at once (they are independent and each writes its own files): on two cores the run
      // takes about half its CPU time. Each program's exit status goes to <prog>.rc. The paths
      // reach bash through the environment, never as code.
      std::string script;
      for (const std::string& prog : figure_run_detail::programs()) {
        const std::string extra = prog == "sec2_3_4_algorithms" ? " --max-n 2000 --no-profile"
                                  : prog == "bench_parallel"    ? " --max-n 100000 --cache-dir \"$DT_CACHES\""
                                                                : " --max-n 2000";
        script += "( \"$DT_BIN/" + prog + "\" --quick" + extra + " --out \"$DT_DIR\" > \"$DT_DIR/" + prog +
                  ".log\" 2>&1; echo $? > \"$DT_DIR/" + prog + ".rc\" ) & ";
      }
      script += "wait";
      ch::ProcessIo io;
      io.env = {{"DT_BIN", bin.string()}, {"DT_DIR", r.dir.string()}, {"DT_CACHES", r.caches.string()}};
      ch::runProgram({"bash", "-c", script}, io);
      std::ofstream(root / "key") << want;
    }
    if (lock >= 0) ::close(lock);
    for (const std::string& prog : figure_run_detail::programs()) {
      const fs::path stem = r.dir / prog;
      if (figure_run_detail::slurp(stem.string() + ".rc") != "0\n")
        r.failures.push_back(prog + " (log: " + stem.string() + ".log)");
    }
    return r;
  }();
  return run;
}

}  // namespace dttest
