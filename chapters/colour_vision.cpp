// The bodies of chapters/colour_vision.h's functions (colour-vision simulation, CIEDE2000), compiled once.
#include "colour_vision.h"

namespace ch {

Rgb parseHex(const std::string& hex) {
  unsigned r = 0, g = 0, b = 0;
  char tail = 0;
  if (hex.size() != 7 || hex[0] != '#' || std::sscanf(hex.c_str() + 1, "%2x%2x%2x%c", &r, &g, &b, &tail) != 3)
    throw std::invalid_argument("not a colour #rrggbb: \"" + hex + "\"");
  return {r / 255.0, g / 255.0, b / 255.0};
}

std::string toHex(const Rgb& c) {
  auto byte = [](double v) { return int(std::lround(std::fmin(1.0, std::fmax(0.0, v)) * 255)); };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return buf;
}

double linearToSrgb(double v) {
  v = std::fmin(1.0, std::fmax(0.0, v));
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

const char* visionName(Vision v) {
  switch (v) {
    case Vision::Normal: return "normal vision";
    case Vision::Protanopia: return "protanopia";
    case Vision::Deuteranopia: return "deuteranopia";
    case Vision::Tritanopia: return "tritanopia";
  }
  return "?";
}

const std::array<std::array<double, 3>, 3>& machadoMatrix(Vision v) {
  static const std::array<std::array<double, 3>, 3> identity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  static const std::array<std::array<double, 3>, 3> protan = {{{0.152286, 1.052583, -0.204868},
                                                               {0.114503, 0.786281, 0.099216},
                                                               {-0.003882, -0.048116, 1.051998}}};
  static const std::array<std::array<double, 3>, 3> deutan = {{{0.367322, 0.860646, -0.227968},
                                                               {0.280085, 0.672501, 0.047413},
                                                               {-0.011820, 0.042940, 0.968881}}};
  static const std::array<std::array<double, 3>, 3> tritan = {{{1.255528, -0.076749, -0.178779},
                                                               {-0.078411, 0.930809, 0.147602},
                                                               {0.004733, 0.691367, 0.303900}}};
  switch (v) {
    case Vision::Protanopia: return protan;
    case Vision::Deuteranopia: return deutan;
    case Vision::Tritanopia: return tritan;
    default: return identity;
  }
}

Rgb simulate(const Rgb& c, Vision v) {
  if (v == Vision::Normal) return c;
  const auto& m = machadoMatrix(v);
  const double lin[3] = {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)};
  double out[3];
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * lin[0] + m[i][1] * lin[1] + m[i][2] * lin[2];
  return {linearToSrgb(out[0]), linearToSrgb(out[1]), linearToSrgb(out[2])};
}

Lab toLab(const Rgb& c) {
  const double r = srgbToLinear(c.r), g = srgbToLinear(c.g), b = srgbToLinear(c.b);
  const double X = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
  const double Y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const double Z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
  const double Xn = 0.95047, Yn = 1.0, Zn = 1.08883;
  auto f = [](double t) {
    const double d = 6.0 / 29;
    return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29;
  };
  const double fx = f(X / Xn), fy = f(Y / Yn), fz = f(Z / Zn);
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

double deltaE2000(const Lab& x, const Lab& y) {
  const double pi = M_PI, deg = pi / 180;
  const double C1 = std::hypot(x.a, x.b), C2 = std::hypot(y.a, y.b), Cbar = (C1 + C2) / 2;
  const double Cbar7 = std::pow(Cbar, 7), G = 0.5 * (1 - std::sqrt(Cbar7 / (Cbar7 + std::pow(25.0, 7))));
  const double a1 = (1 + G) * x.a, a2 = (1 + G) * y.a;
  const double C1p = std::hypot(a1, x.b), C2p = std::hypot(a2, y.b);
  auto hue = [&](double b, double a) {
    if (a == 0 && b == 0) return 0.0;
    const double h = std::atan2(b, a) / deg;
    return h < 0 ? h + 360 : h;
  };
  const double h1 = hue(x.b, a1), h2 = hue(y.b, a2);
  const double dL = y.L - x.L, dC = C2p - C1p;
  double dh = 0;
  if (C1p * C2p != 0) {
    dh = h2 - h1;
    if (dh > 180) dh -= 360;
    else if (dh < -180) dh += 360;
  }
  const double dH = 2 * std::sqrt(C1p * C2p) * std::sin(dh / 2 * deg);
  const double Lbar = (x.L + y.L) / 2, Cbarp = (C1p + C2p) / 2;
  double hbar = h1 + h2;
  if (C1p * C2p != 0) {
    if (std::fabs(h1 - h2) <= 180) hbar = (h1 + h2) / 2;
    else hbar = h1 + h2 < 360 ? (h1 + h2 + 360) / 2 : (h1 + h2 - 360) / 2;
  }
  const double T = 1 - 0.17 * std::cos((hbar - 30) * deg) + 0.24 * std::cos(2 * hbar * deg) +
                   0.32 * std::cos((3 * hbar + 6) * deg) - 0.20 * std::cos((4 * hbar - 63) * deg);
  const double dTheta = 30 * std::exp(-std::pow((hbar - 275) / 25, 2));
  const double Cbarp7 = std::pow(Cbarp, 7), RC = 2 * std::sqrt(Cbarp7 / (Cbarp7 + std::pow(25.0, 7)));
  const double SL = 1 + 0.015 * (Lbar - 50) * (Lbar - 50) / std::sqrt(20 + (Lbar - 50) * (Lbar - 50));
  const double SC = 1 + 0.045 * Cbarp, SH = 1 + 0.015 * Cbarp * T;
  const double RT = -std::sin(2 * dTheta * deg) * RC;
  const double l = dL / SL, c = dC / SC, h = dH / SH;
  return std::sqrt(l * l + c * c + h * h + RT * c * h);
}

double seenDifference(const Rgb& x, const Rgb& y, Vision v) {
  return deltaE2000(toLab(simulate(x, v)), toLab(simulate(y, v)));
}

Rgb styleColour(const std::string& styleText, const std::string& role) {
  const std::string key = "\n" + role + " = \"";
  const std::size_t at = styleText.find(key);
  if (at == std::string::npos) throw std::invalid_argument("figures/ch2/style.gp has no colour " + role);
  const std::size_t from = at + key.size(), to = styleText.find('"', from);
  return parseHex(styleText.substr(from, to == std::string::npos ? std::string::npos : to - from));
}

}  // namespace ch
