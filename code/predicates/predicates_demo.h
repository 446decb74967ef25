// The demonstration variants of the predicates of section 2.3.1 (naive, the notes' filters,
// MPFR): kept to show where each one fails; not used by the kernel.
#pragma once

namespace dt {

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
/// Exercise 2.3.1-2: a precision (in bits) with which every MPFR operation of orient2dMPFR /
/// incircleMPFR is exact on these inputs, hence the sign too.
int exactBitsOrient2d(double ax, double ay, double bx, double by, double cx, double cy);
int exactBitsIncircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                      double dy);

}  // namespace dt
