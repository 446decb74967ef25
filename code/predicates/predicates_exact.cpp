#include "predicates_exact.h"

#include <gmp.h>

#include <cmath>

namespace dt {

// ---------------------------------------------------------------------------------------------
// Exact signs with GMP integers.
//
// Every finite double is M * 2^E with M an integer of at most 53 bits. Multiplying all the
// coordinates of one predicate by the same power of two 2^-Emin (Emin the smallest E among them)
// turns them into integers without changing the sign of the determinant, which is homogeneous.
// The determinant is then evaluated in exact integer arithmetic. The integers can reach about
// 2100 bits (1e-308 beside 1e308) and are squared in incircle: GMP does not care.
namespace {

struct ExactWorkspace {
  mpz_t v[8];
  mpz_t t[10];
  ExactWorkspace() {
    for (auto& z : v) mpz_init(z);
    for (auto& z : t) mpz_init(z);
  }
  ~ExactWorkspace() {
    for (auto& z : v) mpz_clear(z);
    for (auto& z : t) mpz_clear(z);
  }
  ExactWorkspace(const ExactWorkspace&) = delete;
  ExactWorkspace& operator=(const ExactWorkspace&) = delete;
};

ExactWorkspace& workspace() {
  thread_local ExactWorkspace ws;
  return ws;
}

// Splits x (finite) into an integer mantissa and the exponent of its unit in the last place.
void splitDouble(double x, double& mant, int& e) {
  int ex = 0;
  const double m = std::frexp(x, &ex);  // x = m 2^ex, 0.5 <= |m| < 1 (exact, also subnormals)
  mant = std::ldexp(m, 53);             // integer, |mant| < 2^53
  e = ex - 53;
}

// Loads n doubles into ws.v[0..n) as integers sharing one scale.
//! [loadScaled]
void loadScaled(const double* x, int n, ExactWorkspace& ws) {
  double mant[8];
  int e[8];
  int emin = 0;
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (x[i] == 0) {
      mant[i] = 0;
      e[i] = 0;
      continue;
    }
    splitDouble(x[i], mant[i], e[i]);
    if (!any || e[i] < emin) emin = e[i];
    any = true;
  }
  for (int i = 0; i < n; ++i) {
    mpz_set_d(ws.v[i], mant[i]);  // exact: |mant| < 2^53 is an integer
    if (mant[i] != 0) mpz_mul_2exp(ws.v[i], ws.v[i], static_cast<mp_bitcnt_t>(e[i] - emin));
  }
}
//! [loadScaled]

}  // namespace

//! [orient2dExact]
int orient2dExact(double ax, double ay, double bx, double by, double cx, double cy) {
  ExactWorkspace& ws = workspace();
  const double in[6] = {ax, ay, bx, by, cx, cy};
  loadScaled(in, 6, ws);
  mpz_t* v = ws.v;
  mpz_t* t = ws.t;
  mpz_sub(t[0], v[0], v[4]);  // ax - cx
  mpz_sub(t[1], v[3], v[5]);  // by - cy
  mpz_sub(t[2], v[1], v[5]);  // ay - cy
  mpz_sub(t[3], v[2], v[4]);  // bx - cx
  mpz_mul(t[4], t[0], t[1]);
  mpz_mul(t[5], t[2], t[3]);
  const int cmp = mpz_cmp(t[4], t[5]);
  return (cmp > 0) - (cmp < 0);
}
//! [orient2dExact]

int incircleExact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                  double dy) {
  ExactWorkspace& ws = workspace();
  const double in[8] = {ax, ay, bx, by, cx, cy, dx, dy};
  loadScaled(in, 8, ws);
  mpz_t* v = ws.v;
  mpz_t* t = ws.t;
  // Differences to the pivot d, in place: v[0..5] become adx, ady, bdx, bdy, cdx, cdy.
  for (int i = 0; i < 6; ++i) mpz_sub(v[i], v[i], v[6 + (i & 1)]);
  mpz_t& adx = v[0];
  mpz_t& ady = v[1];
  mpz_t& bdx = v[2];
  mpz_t& bdy = v[3];
  mpz_t& cdx = v[4];
  mpz_t& cdy = v[5];
  mpz_t& det = t[9];
  // alift (bdx cdy - cdx bdy)
  mpz_mul(t[0], adx, adx);
  mpz_addmul(t[0], ady, ady);
  mpz_mul(t[1], bdx, cdy);
  mpz_submul(t[1], cdx, bdy);
  mpz_mul(det, t[0], t[1]);
  // blift (cdx ady - adx cdy)
  mpz_mul(t[0], bdx, bdx);
  mpz_addmul(t[0], bdy, bdy);
  mpz_mul(t[1], cdx, ady);
  mpz_submul(t[1], adx, cdy);
  mpz_addmul(det, t[0], t[1]);
  // clift (adx bdy - bdx ady)
  mpz_mul(t[0], cdx, cdx);
  mpz_addmul(t[0], cdy, cdy);
  mpz_mul(t[1], adx, bdy);
  mpz_submul(t[1], bdx, ady);
  mpz_addmul(det, t[0], t[1]);
  return mpz_sgn(det);
}

}  // namespace dt
