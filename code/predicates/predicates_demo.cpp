// The demonstration variants of section 2.3.1: the notes' formula in plain doubles, the notes'
// filters with 200-bit MPFR, MPFR at any precision. Section 2.3.1 shows where each one fails;
// nothing of the kernel calls them.
#include "predicates_demo.h"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dt {

namespace {
int signOf(double v) { return (v > 0) - (v < 0); }
}  // namespace

// ---------------------------------------------------------------------------------------------
// Naive evaluation: exactly the notes' formula, in the order written.
//! [orient2dNaive]
double orient2dNaiveValue(double ax, double ay, double bx, double by, double cx, double cy) {
  return (ax - cx) * (by - cy) - (ay - cy) * (bx - cx);
}
//! [orient2dNaive]
int orient2dNaive(double ax, double ay, double bx, double by, double cx, double cy) {
  return signOf(orient2dNaiveValue(ax, ay, bx, by, cx, cy));
}

double incircleNaiveValue(double ax, double ay, double bx, double by, double cx, double cy,
                          double dx, double dy) {
  const double adx = ax - dx, ady = ay - dy;
  const double bdx = bx - dx, bdy = by - dy;
  const double cdx = cx - dx, cdy = cy - dy;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
         clift * (adx * bdy - bdx * ady);
}
int incircleNaive(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                  double dy) {
  return signOf(incircleNaiveValue(ax, ay, bx, by, cx, cy, dx, dy));
}

// ---------------------------------------------------------------------------------------------
// The notes' scheme: static filter, then MPFR with 200 bits of precision.
namespace {

// MPFR variables of one precision, reused from call to call (set_prec only when it changes).
struct MpfrWork {
  mpfr_t v[8];
  mpfr_t t[8];
  int bits = 200;
  MpfrWork() {
    for (auto& z : v) mpfr_init2(z, bits);
    for (auto& z : t) mpfr_init2(z, bits);
  }
  ~MpfrWork() {
    for (auto& z : v) mpfr_clear(z);
    for (auto& z : t) mpfr_clear(z);
  }
  void precision(int b) {
    if (b == bits) return;
    bits = b;
    for (auto& z : v) mpfr_set_prec(z, b);
    for (auto& z : t) mpfr_set_prec(z, b);
  }
  MpfrWork(const MpfrWork&) = delete;
  MpfrWork& operator=(const MpfrWork&) = delete;
};

MpfrWork& mpfrWork(int bits) {
  thread_local MpfrWork ws;
  ws.precision(bits);
  return ws;
}

}  // namespace

//! [orient2dMPFR]
int orient2dMPFR(int bits, double ax, double ay, double bx, double by, double cx, double cy) {
  MpfrWork& w = mpfrWork(bits);
  const double in[6] = {ax, ay, bx, by, cx, cy};
  for (int i = 0; i < 6; ++i) mpfr_set_d(w.v[i], in[i], MPFR_RNDN);  // exact when bits >= 53
  // Each operation rounds to `bits` bits: a difference of doubles whose exponents are far
  // apart, or a product of two long differences, does not fit, and the sign can be lost.
  mpfr_sub(w.t[0], w.v[0], w.v[4], MPFR_RNDN);
  mpfr_sub(w.t[1], w.v[3], w.v[5], MPFR_RNDN);
  mpfr_sub(w.t[2], w.v[1], w.v[5], MPFR_RNDN);
  mpfr_sub(w.t[3], w.v[2], w.v[4], MPFR_RNDN);
  mpfr_mul(w.t[4], w.t[0], w.t[1], MPFR_RNDN);
  mpfr_mul(w.t[5], w.t[2], w.t[3], MPFR_RNDN);
  mpfr_sub(w.t[6], w.t[4], w.t[5], MPFR_RNDN);
  return mpfr_sgn(w.t[6]);
}
//! [orient2dMPFR]

int incircleMPFR(int bits, double ax, double ay, double bx, double by, double cx, double cy,
                 double dx, double dy) {
  MpfrWork& w = mpfrWork(bits);
  const double in[8] = {ax, ay, bx, by, cx, cy, dx, dy};
  for (int i = 0; i < 8; ++i) mpfr_set_d(w.v[i], in[i], MPFR_RNDN);
  for (int i = 0; i < 6; ++i) mpfr_sub(w.v[i], w.v[i], w.v[6 + (i & 1)], MPFR_RNDN);
  mpfr_t* v = w.v;
  mpfr_t* t = w.t;
  auto lift = [&](mpfr_t out, mpfr_t x, mpfr_t y) {
    mpfr_mul(out, x, x, MPFR_RNDN);
    mpfr_mul(t[7], y, y, MPFR_RNDN);
    mpfr_add(out, out, t[7], MPFR_RNDN);
  };
  auto minor = [&](mpfr_t out, mpfr_t x1, mpfr_t y1, mpfr_t x2, mpfr_t y2) {
    mpfr_mul(out, x1, y2, MPFR_RNDN);
    mpfr_mul(t[7], x2, y1, MPFR_RNDN);
    mpfr_sub(out, out, t[7], MPFR_RNDN);
  };
  lift(t[0], v[0], v[1]);
  minor(t[1], v[2], v[3], v[4], v[5]);
  mpfr_mul(t[6], t[0], t[1], MPFR_RNDN);
  lift(t[0], v[2], v[3]);
  minor(t[1], v[4], v[5], v[0], v[1]);
  mpfr_mul(t[2], t[0], t[1], MPFR_RNDN);
  mpfr_add(t[6], t[6], t[2], MPFR_RNDN);
  lift(t[0], v[4], v[5]);
  minor(t[1], v[0], v[1], v[2], v[3]);
  mpfr_mul(t[2], t[0], t[1], MPFR_RNDN);
  mpfr_add(t[6], t[6], t[2], MPFR_RNDN);
  return mpfr_sgn(t[6]);
}

int orient2dMPFR200(double ax, double ay, double bx, double by, double cx, double cy) {
  return orient2dMPFR(200, ax, ay, bx, by, cx, cy);
}
int incircleMPFR200(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                    double dy) {
  return incircleMPFR(200, ax, ay, bx, by, cx, cy, dx, dy);
}

// BEGIN SOLUTION 2.3.1-2 (remove)
// Exercise: how many bits make MPFR exact? Scaled as in the exact stage, the inputs are integers
// of at most B bits. Then |differences| < 2^(B+1), products < 2^(2B+2), and the orientation
// value < 2^(2B+3); the incircle lifts and minors are < 2^(2B+3), their products < 2^(4B+6), the
// sum of three < 2^(4B+8). An integer below 2^k has at most k significant bits, so with k bits
// of precision no operation rounds.
namespace {
int scaledBits(const double* x, int n) {
  int emin = 0, emax = 0;
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (x[i] == 0) continue;
    int ex = 0;
    std::frexp(x[i], &ex);  // |x| < 2^ex, unit in the last place 2^(ex-53)
    if (!any || ex - 53 < emin) emin = ex - 53;
    if (!any || ex > emax) emax = ex;
    any = true;
  }
  return any ? emax - emin : 1;
}
}  // namespace
// END SOLUTION 2.3.1-2

int exactBitsOrient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  // BEGIN SOLUTION 2.3.1-2
  const double in[6] = {ax, ay, bx, by, cx, cy};
  return 2 * scaledBits(in, 6) + 3;
  // END SOLUTION 2.3.1-2
}
int exactBitsIncircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                      double dy) {
  // BEGIN SOLUTION 2.3.1-2
  const double in[8] = {ax, ay, bx, by, cx, cy, dx, dy};
  return 4 * scaledBits(in, 8) + 8;
  // END SOLUTION 2.3.1-2
}

// As printed: "max(x_a, y_a, x_b, y_b, x_c, y_c)", a signed maximum (no absolute values).
//! [orient2dNotes]
int orient2dNotes(double ax, double ay, double bx, double by, double cx, double cy) {
  const double o = orient2dNaiveValue(ax, ay, bx, by, cx, cy);
  const double m = std::max({ax, ay, bx, by, cx, cy});
  if (std::fabs(o) > 1e-15 * m * m) return signOf(o);
  return orient2dMPFR200(ax, ay, bx, by, cx, cy);
}
//! [orient2dNotes]

// The notes give only epsilon = 1e-11 for incircle; the determinant has degree 4, so the scale
// is read as max(...)^4, with the same signed maximum as the orientation filter.
int incircleNotes(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                  double dy) {
  const double v = incircleNaiveValue(ax, ay, bx, by, cx, cy, dx, dy);
  const double m = std::max({ax, ay, bx, by, cx, cy, dx, dy});
  if (std::fabs(v) > 1e-11 * m * m * m * m) return signOf(v);
  return incircleMPFR200(ax, ay, bx, by, cx, cy, dx, dy);
}

int orient2dNotesAbs(double ax, double ay, double bx, double by, double cx, double cy) {
  const double o = orient2dNaiveValue(ax, ay, bx, by, cx, cy);
  const double m = std::max({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by),
                             std::fabs(cx), std::fabs(cy)});
  if (std::fabs(o) > 1e-15 * m * m) return signOf(o);
  return orient2dMPFR200(ax, ay, bx, by, cx, cy);
}

int incircleNotesAbs(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                     double dy) {
  const double v = incircleNaiveValue(ax, ay, bx, by, cx, cy, dx, dy);
  const double m = std::max({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by),
                             std::fabs(cx), std::fabs(cy), std::fabs(dx), std::fabs(dy)});
  if (std::fabs(v) > 1e-11 * m * m * m * m) return signOf(v);
  return incircleMPFR200(ax, ay, bx, by, cx, cy, dx, dy);
}

}  // namespace dt
