// Shared helpers of the test suite: point generators with fixed seeds, and a one-call
// "triangulate and check exactly".
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "check.h"
#include "generators.h"
#include "triangulate.h"
#include "../chapters/process.h"

namespace dttest {

using dt::XY;  // x0 y0 x1 y1 ...

// The point families live in code/orders/generators.h; these names stay for the tests that still
// spell them dttest:: (degenerate, bad-input, progress, fast-kernel and Hilbert tests).
using dt::circlePoints;
using dt::gridPoints;
using dt::uniformPoints;
inline void shuffle(XY& p, unsigned seed) { dt::shufflePoints(p, seed); }

// The seed of a random input of an exercise's test, in a workspace's variant: `scripts/exercise.sh
// release --variant N` (or --roster) records N in the workspace, and `check` passes it to the
// tests as DT_VARIANT, so that each student's tests draw their own inputs and one student's
// printed failure is not another's answer key. Unset or 0: `seed` itself. The tests of an
// exercise hold for every variant (scripts/exercise.sh selftest runs them under one).
inline unsigned variant(unsigned seed) {
  const char* text = std::getenv("DT_VARIANT");
  if (text == nullptr || *text == '\0') return seed;
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text, &end, 10);
  if (*end != '\0' || errno != 0 || *text < '0' || *text > '9')
    throw std::invalid_argument(std::string("DT_VARIANT='") + text + "' is not a variant number");
  if (v == 0) return seed;
  // SplitMix64's finaliser of the pair: nearby variants and seeds give unrelated inputs.
  std::uint64_t z = (std::uint64_t(seed) << 32 ^ v) + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return unsigned(z ^ (z >> 31));
}

// DT(S) with the hull method, extracted and checked exactly. Returns the report.
inline dt::CheckReport triangulateAndCheck(const XY& p, dt::InsertionStats* st = nullptr,
                                           dt::StartRule rule = dt::StartRule::LastCavity) {
  dt::Triangulation T;
  dt::delaunayTrglHull(T, dt::addVertices(T, p), rule, st);
  const dt::CheckReport full = dt::checkTriangulation(T);
  if (!full.ok) return full;
  const dt::PlainMesh m = dt::extractMesh(T, true);
  return dt::checkDelaunay(m.xy, m.tri);
}

// ---- running the command-line triangulator -------------------------------------------------

// DT_TEST_TMP is <build>/test_tmp, or a directory of /tmp when the build's path holds a
// character a shell would read (CMakeLists.txt): the tests quote the paths they build with '...'.
inline std::string tmpPath(const std::string& name) {
  std::filesystem::create_directories(DT_TEST_TMP);
  return std::string(DT_TEST_TMP) + "/" + name;
}

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline bool fileExists(const std::string& path) { return std::ifstream(path).good(); }

/// What a program run by runCaptured() did.
struct RunResult {
  int status = -1;      // its exit status, or -1 when a signal ended it
  std::string out, err; // its stdout and stderr (err is empty when stderr went to out)
};
using CliResult = RunResult;

/// Runs the argument vector `argv` (no shell unless argv names one) with the extra environment
/// `env`, capturing stdout and stderr into files of tmpPath(); with `mergeStderr` both go to out.
inline RunResult runCaptured(const std::vector<std::string>& argv,
                             const std::vector<std::pair<std::string, std::string>>& env = {},
                             bool mergeStderr = false) {
  static int counter = 0;
  // The pid keeps parallel ctest entries (one process per test file) apart.
  const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
  const std::string o = tmpPath("run_out_" + tag), e = tmpPath("run_err_" + tag);
  ch::ProcessIo io;
  io.stdoutPath = o;
  io.stderrPath = mergeStderr ? "&1" : e;
  io.env = env;
  const int rc = ch::runProgram(argv, io);
  RunResult r;
  r.status = rc >= 0 && rc < 128 ? rc : -1;
  r.out = readText(o);
  if (!mergeStderr) r.err = readText(e);
  return r;
}

/// Runs build/delaunay2d with the given arguments, a shell command line the caller writes (and
/// quotes: paths of tmpPath() are safe in '...'). The program's own path reaches the shell
/// through the environment ("$DT_CLI_BIN"), so a build under any path works.
inline CliResult runCli(const std::string& args) {
  return runCaptured({"sh", "-c", "\"$DT_CLI_BIN\" " + args}, {{"DT_CLI_BIN", DT_CLI}});
}

/// Runs scripts/exercise.sh with `args` (each one argument, never read by a shell) and the
/// environment variables `env`.
inline RunResult runExerciseScript(const std::vector<std::string>& args,
                                   const std::vector<std::pair<std::string, std::string>>& env,
                                   bool mergeStderr) {
  std::vector<std::string> argv = {"bash", std::string(DT_SOURCE_DIR) + "/scripts/exercise.sh"};
  argv.insert(argv.end(), args.begin(), args.end());
  return runCaptured(argv, env, mergeStderr);
}

/// The build directory of this test binary (not DT_TEST_TMP's parent: under a build path a
/// shell would misread, DT_TEST_TMP is a directory of /tmp).
inline std::string buildDir() { return DT_BINARY_DIR; }

inline bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

/// Writes points as a Triangle .node file numbered from `first`.
inline std::string nodeText(const XY& p, int first = 1) {
  std::string s = std::to_string(p.size() / 2) + " 2 0 0\n";
  char buf[128];
  for (std::size_t i = 0; i < p.size() / 2; ++i) {
    std::snprintf(buf, sizeof buf, "%zu %.17g %.17g\n", i + first, p[2 * i], p[2 * i + 1]);
    s += buf;
  }
  return s;
}

/// Reads a Triangle .ele file into 0-based triangles, given the numbering base.
inline std::vector<std::array<int, 3>> readEle(const std::string& path, int first) {
  std::istringstream in(readText(path));
  std::size_t n = 0;
  int nodes = 0, attrs = 0;
  in >> n >> nodes >> attrs;
  std::vector<std::array<int, 3>> t(n);
  for (std::size_t i = 0; i < n; ++i) {
    long num;
    in >> num >> t[i][0] >> t[i][1] >> t[i][2];
    for (int& v : t[i]) v -= first;
  }
  return t;
}

}  // namespace dttest

