// Geometric predicates of section 2.3.1: orientation and incircle.
//
// Four families, from fastest to safest, so that section 2.3.1 can show each one at work:
//   - naive:    the formula of the notes evaluated in double precision (wrong near degeneracy);
//   - notes:    the notes' static filter (1e-15, 1e-11) with a 200-bit MPFR fallback;
//   - exact:    the exact sign, computed with GMP integers (the oracle);
//   - robust:   a floating-point evaluation behind a provably safe error bound, falling back
//               to the exact sign. This is the one the kernel uses.
//
// Conventions. orient2d(a,b,c) > 0 iff a, b, c turn counter-clockwise; the value computed is the
// notes' (xa-xc)(yb-yc) - (ya-yc)(xb-xc), pivoting on c. incircle(a,b,c,d) > 0 iff d lies
// strictly inside the circle through a, b, c when a, b, c are counter-clockwise (the sign flips
// for a clockwise triangle); it pivots on d.
#pragma once

#include <cstdint>

namespace dt {

/// Counters of predicate calls; the chapter programs read them (share of exact fallbacks,
/// share of time spent in the orientation test). Not thread-safe: one triangulation at a time.
struct PredicateCounters {
  std::uint64_t orient = 0;       ///< calls of orient2d (robust)
  std::uint64_t orientExact = 0;  ///< of which the filter failed: an exact stage decided
  std::uint64_t incircle = 0;     ///< calls of incircle (robust)
  std::uint64_t incircleExact = 0;///< of which the filter failed: an exact stage decided
  std::uint64_t orientSmallInt = 0;   ///< of orientExact, decided in machine arithmetic
  std::uint64_t incircleSmallInt = 0; ///< (stages 2 and 3, see lastPredicateStage)
  std::uint64_t orientExtended = 0;   ///< of orientExact, decided by the extended-exponent
  std::uint64_t incircleExtended = 0; ///< filter (stage 4); the rest went to GMP
  void reset() { *this = PredicateCounters{}; }
};
PredicateCounters& predicateCounters();

/// The notes' orientation value (2.3.1), in plain double arithmetic, pivot c. Its sign is wrong
/// near degeneracy: this is what Figure 2.7 plots.
double orient2dNaiveValue(double ax, double ay, double bx, double by, double cx, double cy);
/// Sign of orient2dNaiveValue: -1, 0 or +1.
int orient2dNaive(double ax, double ay, double bx, double by, double cx, double cy);
/// The incircle determinant in plain double arithmetic, pivot d (3x3 lifted form).
double incircleNaiveValue(double ax, double ay, double bx, double by, double cx, double cy,
                          double dx, double dy);
int incircleNaive(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                  double dy);

/// Exact sign of the orientation determinant for any finite doubles (GMP integers).
int orient2dExact(double ax, double ay, double bx, double by, double cx, double cy);
/// Exact sign of the incircle determinant for any finite doubles (GMP integers).
int incircleExact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                  double dy);

/// The notes' scheme (2.3.1): trust the double result if |O| > 1e-15 max(|coords|)^2, otherwise
/// recompute with 200-bit MPFR floats. Kept to show where it fails; not used by the kernel.
int orient2dNotes(double ax, double ay, double bx, double by, double cx, double cy);
/// The notes' incircle scheme: filter 1e-11 max(|coords|)^4, then 200-bit MPFR.
int incircleNotes(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                  double dy);
/// The notes' filters read charitably, with max(|coords|) instead of the printed signed max.
/// Still not safe (section 2.3.1 of the book shows counterexamples); not used by the kernel.
int orient2dNotesAbs(double ax, double ay, double bx, double by, double cx, double cy);
int incircleNotesAbs(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                     double dy);
/// The 200-bit MPFR evaluation alone (no filter), to show that 200 bits are not always enough.
int orient2dMPFR200(double ax, double ay, double bx, double by, double cx, double cy);
int incircleMPFR200(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                    double dy);
/// The same evaluation order with `bits` bits of MPFR precision (round to nearest).
int orient2dMPFR(int bits, double ax, double ay, double bx, double by, double cx, double cy);
int incircleMPFR(int bits, double ax, double ay, double bx, double by, double cx, double cy,
                 double dx, double dy);
/// A precision (in bits) with which every MPFR operation of orient2dMPFR / incircleMPFR is exact
/// on these inputs, hence the sign too (exercise of section 2.3.1). It grows with the spread of
/// the exponents: 109 bits for doubles of one binade, about 2100 for 1e-308 beside 1e308.
int exactBitsOrient2d(double ax, double ay, double bx, double by, double cx, double cy);
int exactBitsIncircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                      double dy);

/// Robust orientation (2.3.1): double evaluation + safe error bound, exact fallback (the core
/// is dt::pred::orient2d in predicates_inline.h; this adds the counters).
/// The sign is exact for every input of finite doubles.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);
/// Robust incircle (2.3.1): double evaluation + safe error bound, exact fallback.
int incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
             double dy);

/// Stage that decided the last robust call (for tests and the 2.3.1 program): 0 = filter,
/// 1 = exact (GMP), 2 = small multiples of a power of two, evaluated exactly in doubles,
/// 3 = multiples of up to 62 bits, in 128/256-bit integers, 4 = the filter evaluated with a
/// separate integer exponent (no overflow or underflow) (predicates_inline.h, where the stages
/// are defined and proved).
int lastPredicateStage();

}  // namespace dt
