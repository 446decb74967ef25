// Colour vision for the figures: how a colour looks to a reader with protanopia,
// deuteranopia or tritanopia, and how far apart two colours look (CIEDE2000). The figure rules
// (tests/test_figures_rules.cpp) check the style's meaning-pairs with it, and
// sec2_3_1_predicates draws a sign map as a deuteranope sees it.
//
// Simulation: Machado, Oliveira and Fernandes, "A physiologically-based model for simulation of
// color vision deficiency", IEEE TVCG 15(6), 2009. For a dichromat (severity 1.0) the model is
// one 3 x 3 matrix applied to linear RGB; the matrices are the paper's table of severity 1.0.
// Each row sums to 1, so greys (white, black, the text) stay what they are.
// Difference: CIEDE2000 (CIE 142-2001), in the form of Sharma, Wu and Dalal, "The CIEDE2000
// color-difference formula: implementation notes, supplementary test data, and mathematical
// observations", Color Research and Application 30(1), 2005 (kL = kC = kH = 1).
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace ch {

/// An sRGB colour, each channel in [0, 1] (gamma-encoded, as written "#rrggbb").
struct Rgb {
  double r, g, b;
};
/// CIE L*a*b* (D65 white).
struct Lab {
  double L, a, b;
};

/// "#rrggbb" (case-insensitive) as an Rgb; throws on anything else.
Rgb parseHex(const std::string& hex);

/// The colour as "#rrggbb", each channel rounded and clamped to [0, 255].
std::string toHex(const Rgb& c);

/// sRGB transfer function and its inverse (IEC 61966-2-1).
inline double srgbToLinear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double linearToSrgb(double v);

enum class Vision { Normal, Protanopia, Deuteranopia, Tritanopia };

const char* visionName(Vision v);

/// Machado et al. 2009, severity 1.0, on linear RGB (rows: r', g', b').
const std::array<std::array<double, 3>, 3>& machadoMatrix(Vision v);

/// The colour as a reader with vision `v` sees it: the matrix applied to linear RGB, the result
/// clamped to the gamut and encoded again.
Rgb simulate(const Rgb& c, Vision v);

/// sRGB to CIE L*a*b* (D65): linear RGB, XYZ by the sRGB primaries, then the CIE 1976 formulas.
Lab toLab(const Rgb& c);

/// CIEDE2000 colour difference of two L*a*b* colours (kL = kC = kH = 1).
double deltaE2000(const Lab& x, const Lab& y);

/// How far apart two sRGB colours look to a reader with vision `v`.
double seenDifference(const Rgb& x, const Rgb& y, Vision v);

}  // namespace ch

namespace ch {

/// The colour of role `role` in the text of figures/ch2/style.gp (a line `ROLE = "#rrggbb"`);
/// throws, naming the role, if the style has no such line.
Rgb styleColour(const std::string& styleText, const std::string& role);

}  // namespace ch
