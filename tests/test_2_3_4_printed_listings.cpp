/// \file test_2_3_4_printed_listings.cpp Section 2.3.4 says "the code that is provided here is actually working as is": the printed Listings 2.1-2.8 (tests/printed_listings.h, syntax fixes only) are run here, each in a child process, and the tests assert where they fail.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "check.h"
#include "hilbert.h"
#include "printed_listings.h"
#include "support.h"

namespace {

// How a run of the printed code ended.
enum class Outcome { Valid, InvalidMesh, Terminated, Hung, Crashed, Other };

std::string name(Outcome o) {
  switch (o) {
    case Outcome::Valid: return "finished, mesh valid";
    case Outcome::InvalidMesh: return "finished, mesh rejected by the validator";
    case Outcome::Terminated: return "std::terminate (the bare 'throw;' of Listing 2.7)";
    case Outcome::Hung: return "no end within the time limit";
    case Outcome::Crashed: return "crashed (segmentation fault)";
    default: return "other";
  }
}

// Runs body in a child process, so that a bare `throw;`, an endless loop or a crash end only
// the child; body's return value is the child's exit status (0: valid, 3: invalid mesh).
Outcome inChild(const std::function<int()>& body, unsigned seconds = 2) {
  std::fflush(nullptr);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    // The child: default signal actions (not doctest's handlers), no output, a time limit.
    for (int sig : {SIGABRT, SIGSEGV, SIGALRM, SIGFPE, SIGBUS}) signal(sig, SIG_DFL);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    alarm(seconds);
    _exit(body());
  }
  int status = 0;
  REQUIRE(waitpid(pid, &status, 0) == pid);
  if (WIFEXITED(status)) {
    if (WEXITSTATUS(status) == 0) return Outcome::Valid;
    if (WEXITSTATUS(status) == 3) return Outcome::InvalidMesh;
    return Outcome::Other;
  }
  if (WIFSIGNALED(status)) {
    if (WTERMSIG(status) == SIGABRT) return Outcome::Terminated;
    if (WTERMSIG(status) == SIGALRM) return Outcome::Hung;
    if (WTERMSIG(status) == SIGSEGV) return Outcome::Crashed;
  }
  return Outcome::Other;
}

// Listing 2.7 on p inside the notes' two super-triangles (Algorithm 1: p-1 p-2 p-3 and
// p-2 p-1 p-4); the child checks the final triangles with the exact validator (check.h).
Outcome runPrinted(const dt::XY& p) {
  return inChild([&p] {
    std::vector<printed::Vertex> store;  // addresses stable: reserved once
    store.reserve(p.size() / 2 + 4);
    double lo = 1e300, hi = -1e300;
    for (double v : p) lo = std::min(lo, v), hi = std::max(hi, v);
    const double c = 0.5 * (lo + hi), R = 10 * (hi - lo + 1);
    store.emplace_back(c - R, c - R, 0);  // p-1
    store.emplace_back(c + R, c + R, 0);  // p-2
    store.emplace_back(c - R, c + R, 0);  // p-3
    store.emplace_back(c + R, c - R, 0);  // p-4
    std::vector<printed::Face*> T = {new printed::Face(&store[0], &store[1], &store[2]),
                                     new printed::Face(&store[1], &store[0], &store[3])};
    printed::computeAdjacencies(T);
    std::vector<printed::Vertex*> S;
    for (std::size_t i = 0; i < p.size() / 2; ++i) {
      store.emplace_back(p[2 * i], p[2 * i + 1], 0);
      S.push_back(&store.back());
    }
    printed::delaunayTrgl(S, T);
    std::vector<double> xy;
    for (const printed::Vertex& v : store) xy.insert(xy.end(), {v.x, v.y});
    std::vector<std::array<int, 3>> tri;
    for (printed::Face* f : T)
      tri.push_back({int(f->V[0] - store.data()), int(f->V[1] - store.data()), int(f->V[2] - store.data())});
    return dt::checkDelaunay(xy, tri).ok ? 0 : 3;
  });
}

}  // namespace

TEST_CASE("2.3.4 the printed listings are not working as is: random points") {
  // The printed Listing 2.7 takes bnd[i].V[0], V[1] from an Edge that only knows (vmin, vmax),
  // sorted by address: half of the new faces are clockwise, their inCircle answers the opposite,
  // and the next cavities go wrong. On random points the run ends in the bare `throw;` of the
  // |bnd| = |C| + 2 check, which calls std::terminate, or in a walk that cycles for ever.
  int terminated = 0, hung = 0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    CAPTURE(seed);
    const Outcome o = runPrinted(dt::uniformPoints(200, seed));
    MESSAGE("200 random points, seed " << seed << ": " << name(o));
    CHECK(o != Outcome::Valid);
    terminated += o == Outcome::Terminated;
    hung += o == Outcome::Hung;
  }
  CHECK(terminated >= 1);
  CHECK(hung >= 1);
}

TEST_CASE("2.3.4 the printed listings are not working as is: even a few points give a wrong mesh") {
  // Where it first fails: the smallest prefix of a random set whose result the validator
  // rejects (or that ends abnormally).
  const dt::XY p = dt::uniformPoints(50, 7);
  std::size_t firstBad = 0;
  for (std::size_t k = 1; k <= 50 && firstBad == 0; ++k)
    if (runPrinted(dt::XY(p.begin(), p.begin() + long(2 * k))) != Outcome::Valid) firstBad = k;
  MESSAGE("the printed listings first fail after " << firstBad << " points");
  // One point already: its four ball faces take (vmin, vmax) in address order, and two of them
  // come out clockwise.
  CHECK(firstBad == 1);
}

TEST_CASE("2.3.4 the printed walk never ends when its line passes through a vertex") {
  // Listing 2.6 leaves a face only through an edge that the segment centroid -> p crosses
  // strictly. A 4 x 4 grid of step 3, each square cut by its diagonal (a valid mesh, the notes'
  // own computeAdjacencies links it): from the face (0,0) (3,0) (3,3), whose centroid is (2, 1)
  // exactly, the segment to p = (4, 5) passes exactly through the vertex (3, 3). No edge
  // qualifies and `while (1)` spins. A target just off that line is found.
  auto walk = [](double px, double py) {
    return inChild([px, py] {
      std::vector<printed::Vertex> v;
      v.reserve(16);
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) v.emplace_back(3 * i, 3 * j, 0);
      auto at = [&](int i, int j) { return &v[std::size_t(4 * j + i)]; };
      std::vector<printed::Face*> T;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          T.push_back(new printed::Face(at(i, j), at(i + 1, j), at(i + 1, j + 1)));
          T.push_back(new printed::Face(at(i, j), at(i + 1, j + 1), at(i, j + 1)));
        }
      printed::computeAdjacencies(T);
      printed::Vertex p(px, py, 0);
      printed::Face* f = printed::lineSearch(T[0], &p);
      return f != NULL && f->inCircle(&p) ? 0 : 3;
    });
  };
  const Outcome through = walk(4, 5);
  CHECK(dt::orient2d(2, 1, 3, 3, 4, 5) == 0);  // the line hits (3, 3)
  MESSAGE("walk through the vertex (3, 3): " << name(through));
  CHECK(through == Outcome::Hung);
  CHECK(walk(4.2, 4.8) == Outcome::Valid);
}

TEST_CASE("2.3.4 the printed HilbertCoord (Listing 2.8) gives the corrected digits on finite input") {
  // Listing 2.8 itself works as printed on finite coordinates: same digits as code/orders/hilbert.cpp,
  // ties on the dividing lines included (both send them to the lower quadrant).
  const dt::XY p = dt::uniformPoints(2000, 11);
  const int d = 12;
  for (std::size_t i = 0; i < p.size() / 2 + 4; ++i) {
    // the random points, then the square's centre and points on its dividing lines
    const double x = i < p.size() / 2 ? p[2 * i] : (i % 2 ? 0.5 : 0.25);
    const double y = i < p.size() / 2 ? p[2 * i + 1] : (i % 4 < 2 ? 0.5 : 0.75);
    int a[d], b[d];
    printed::HilbertCoord(x, y, 0.5, 0.5, 0.5, 0, 0, 0.5, d, a);
    dt::HilbertCoord(x, y, 0.5, 0.5, 0.5, 0, 0, 0.5, d, b);
    bool same = true;
    for (int k = 0; k < d; ++k) same = same && a[k] == b[k];
    CHECK(same);
  }
}

TEST_CASE("2.3.4 the printed HilbertCoord leaves every digit unwritten for a NaN coordinate") {
  // All four tests of Listing 2.8 are false for NaN: bits[] keeps whatever it held (here -1),
  // so the caller sorts on garbage. The corrected version rejects NaN (test_2_3_5_hilbert.cpp).
  int bits[8];
  for (int& b : bits) b = -1;
  printed::HilbertCoord(std::numeric_limits<double>::quiet_NaN(), 0.3, 0.5, 0.5, 0.5, 0, 0, 0.5, 8, bits);
  for (int b : bits) CHECK(b == -1);
}
