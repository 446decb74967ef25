/// \file test_figures.cpp Tests of the figures themselves (the figure style, book/figure_style.md):
/// every figure the book embeds is written by a run of the chapter programs, every SVG is
/// well-formed XML in UTF-8, and every PNG (and the GIF) has the size figures/ch2/style.gp gives.
//
// The suite runs the chapter programs that draw the book's figures once, into a fresh
// directory (--quick --max-n 2000: the figures are the full ones, the tables small; about
// 10 s of CPU), so it depends on no earlier run. The checkers are tested on bad input too.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../chapters/process.h"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = DT_SOURCE_DIR;

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---- the names the book embeds -----------------------------------------------------------

/// Every `\image html NAME` of book/*.md, exactly as written.
std::set<std::string> embeddedFigures() {
  std::set<std::string> names;
  const std::regex image(R"(\\image\s+html\s+"?([^\s"]+))");
  for (const auto& e : fs::directory_iterator(kRoot / "book")) {
    if (e.path().extension() != ".md") continue;
    const std::string text = readAll(e.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), image); it != std::sregex_iterator(); ++it)
      names.insert((*it)[1]);
  }
  return names;
}

// ---- UTF-8 and XML well-formedness -------------------------------------------------------

/// Empty if `s` is valid UTF-8 (no overlong forms, no surrogates, at most U+10FFFF), else
/// the offset and byte of the first error.
std::string utf8Error(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    int len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (len == 0 || i + std::size_t(len) > s.size())
      return "byte " + std::to_string(i) + " (0x" + std::to_string(c) + " decimal) starts no UTF-8 character";
    std::uint32_t cp = len == 1 ? c : c & (0x7F >> len);
    for (int k = 1; k < len; ++k) {
      const unsigned char d = static_cast<unsigned char>(s[i + std::size_t(k)]);
      if ((d >> 6) != 0x2) return "byte " + std::to_string(i + std::size_t(k)) + " is not a continuation byte";
      cp = (cp << 6) | (d & 0x3F);
    }
    const std::uint32_t least[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < least[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
      return "byte " + std::to_string(i) + ": overlong form, surrogate or out of range";
    i += std::size_t(len);
  }
  return "";
}

/// Empty if `s` is a well-formed XML document (one root element, tags nested and matched,
/// attributes quoted and not repeated, references well formed, no '<' or bare '&' in text),
/// else a description of the first error. Enough for what gnuplot writes: it does not read
/// DTDs or check names against the full XML name grammar.
std::string xmlError(const std::string& s) {
  std::size_t i = 0;
  std::vector<std::string> open;
  int roots = 0;
  auto at = [&](std::size_t k) { return " at byte " + std::to_string(k); };
  auto isName = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' || c == '.' ||
           static_cast<unsigned char>(c) >= 0x80;
  };
  auto checkRefs = [&](std::size_t from, std::size_t to) -> std::string {
    for (std::size_t k = from; k < to; ++k) {
      if (s[k] == '<') return "'<' in text or attribute" + at(k);
      if (s[k] != '&') continue;
      const std::size_t semi = s.find(';', k);
      if (semi == std::string::npos || semi > to) return "unterminated reference" + at(k);
      const std::string ref = s.substr(k + 1, semi - k - 1);
      static const std::regex ok(R"(#[0-9]+|#x[0-9a-fA-F]+|[A-Za-z_][A-Za-z0-9._-]*)");
      if (!std::regex_match(ref, ok)) return "bad reference &" + ref + ";" + at(k);
      k = semi;
    }
    return "";
  };
  while (i < s.size()) {
    if (s[i] != '<') {
      const std::size_t next = std::min(s.find('<', i), s.size());
      if (open.empty() && s.find_first_not_of(" \t\r\n", i) < next) return "text outside the root element" + at(i);
      if (std::string e = checkRefs(i, next); !e.empty()) return e;
      i = next;
      continue;
    }
    auto skipTo = [&](const char* end, const char* what) -> std::string {
      const std::size_t e = s.find(end, i);
      if (e == std::string::npos) return std::string("unterminated ") + what + at(i);
      i = e + std::strlen(end);
      return "";
    };
    std::string err;
    if (s.compare(i, 4, "<!--") == 0) err = skipTo("-->", "comment");
    else if (s.compare(i, 9, "<![CDATA[") == 0) {
      if (open.empty()) return "CDATA outside the root element" + at(i);
      err = skipTo("]]>", "CDATA section");
    } else if (s.compare(i, 2, "<?") == 0) err = skipTo("?>", "processing instruction");
    else if (s.compare(i, 9, "<!DOCTYPE") == 0) {
      // Skip an internal subset in brackets, if any.
      const std::size_t br = s.find('[', i), gt = s.find('>', i);
      if (br != std::string::npos && br < gt) {
        const std::size_t close = s.find("]>", br);
        if (close == std::string::npos) return "unterminated DOCTYPE" + at(i);
        i = close + 2;
      } else {
        err = skipTo(">", "DOCTYPE");
      }
    } else if (s.compare(i, 2, "</") == 0) {
      std::size_t k = i + 2, b = k;
      while (k < s.size() && isName(s[k])) ++k;
      const std::string name = s.substr(b, k - b);
      while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
      if (k >= s.size() || s[k] != '>') return "bad end tag" + at(i);
      if (open.empty() || open.back() != name)
        return "end tag </" + name + "> does not match <" + (open.empty() ? "" : open.back()) + ">" + at(i);
      open.pop_back();
      i = k + 1;
    } else {
      std::size_t k = i + 1, b = k;
      while (k < s.size() && isName(s[k])) ++k;
      const std::string name = s.substr(b, k - b);
      if (name.empty()) return "'<' not followed by a name" + at(i);
      std::set<std::string> attrs;
      for (;;) {
        const std::size_t ws = k;
        while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
        if (k >= s.size()) return "unterminated tag <" + name + at(i);
        if (s[k] == '>' || s.compare(k, 2, "/>") == 0) break;
        if (k == ws) return "no space before an attribute of <" + name + ">" + at(k);
        const std::size_t ab = k;
        while (k < s.size() && isName(s[k])) ++k;
        const std::string attr = s.substr(ab, k - ab);
        if (attr.empty()) return "bad attribute in <" + name + ">" + at(ab);
        if (!attrs.insert(attr).second) return "attribute " + attr + " repeated in <" + name + ">" + at(ab);
        while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
        if (k >= s.size() || s[k] != '=') return "attribute " + attr + " without a value" + at(k);
        ++k;
        while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
        if (k >= s.size() || (s[k] != '"' && s[k] != '\'')) return "unquoted value of " + attr + at(k);
        const std::size_t close = s.find(s[k], k + 1);
        if (close == std::string::npos) return "unterminated value of " + attr + at(k);
        if (std::string e = checkRefs(k + 1, close); !e.empty()) return e;
        k = close + 1;
      }
      const bool empty = s[k] == '/';
      if (open.empty() && ++roots > 1) return "a second root element <" + name + ">" + at(i);
      if (!empty) open.push_back(name);
      i = k + (empty ? 2 : 1);
    }
    if (!err.empty()) return err;
  }
  if (!open.empty()) return "element <" + open.back() + "> is not closed";
  if (roots != 1) return "no root element";
  return "";
}

/// gnuplot's svg terminal paints the background as a full-size rect at the start: filled
/// white with "background rgb 'white'", fill="none" (transparent) without.
bool whiteBackground(const std::string& svg) {
  static const std::regex white(R"(<rect x="0" y="0" width="\d+" height="\d+" fill="#ffffff")");
  return std::regex_search(svg.substr(0, 4000), white);
}

// ---- image sizes -------------------------------------------------------------------------

using Sizes = std::map<std::string, std::pair<int, int>>;

/// The figure sizes of figures/ch2/style.gp (its FIGSIZES table: name width height).
Sizes styleSizes() {
  const std::string text = readAll(kRoot / "figures/ch2/style.gp");
  Sizes sizes;
  const std::size_t from = text.find("FIGSIZES =");
  if (from == std::string::npos) return sizes;
  const std::size_t to = text.find("\n\n", from);
  const std::string table = text.substr(from, to - from);
  const std::regex entry(R"(([A-Za-z0-9_]+) (\d+) (\d+))");
  for (auto it = std::sregex_iterator(table.begin(), table.end(), entry); it != std::sregex_iterator(); ++it)
    sizes[(*it)[1]] = {std::stoi((*it)[2]), std::stoi((*it)[3])};
  return sizes;
}

std::uint32_t bigEndian32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(s[at + k]);
  return v;
}

/// The width and height of a PNG from its IHDR chunk, or {-1, -1} if it is not a PNG.
std::pair<int, int> pngSize(const std::string& data) {
  static const std::string signature("\x89PNG\r\n\x1a\n", 8);
  if (data.size() < 24 || data.compare(0, 8, signature) != 0 || data.compare(12, 4, "IHDR") != 0)
    return {-1, -1};
  return {int(bigEndian32(data, 16)), int(bigEndian32(data, 20))};
}

/// The logical screen size of a GIF, or {-1, -1} if it is not a GIF.
std::pair<int, int> gifSize(const std::string& data) {
  if (data.size() < 10 || (data.compare(0, 6, "GIF89a") != 0 && data.compare(0, 6, "GIF87a") != 0))
    return {-1, -1};
  auto le16 = [&](std::size_t at) {
    return int(static_cast<unsigned char>(data[at])) | int(static_cast<unsigned char>(data[at + 1])) << 8;
  };
  return {le16(6), le16(8)};
}

/// The style's name of an output file: its stem if the style has it, else the stem without an
/// animation frame's number _NN (fig2_5_anim_07 -> fig2_5_anim; fig2_10 stays fig2_10).
std::string styleName(const fs::path& p, const Sizes& sizes) {
  const std::string stem = p.stem().string();
  static const std::regex frame(R"((.*)_\d\d)");
  std::smatch m;
  if (sizes.count(stem) == 0 && std::regex_match(stem, m, frame)) return m[1];
  return stem;
}

// ---- one run of the chapter programs -----------------------------------------------------

/// The directory the chapter programs wrote into (run once per test process), and the
/// programs that failed, with their log.
struct Run {
  fs::path dir;
  std::vector<std::string> failures;
};

const Run& figureRun() {
  static const Run run = [] {
    Run r;
    r.dir = fs::path(DT_TEST_TMP) / "figures";
    fs::remove_all(r.dir);
    fs::create_directories(r.dir);
    const fs::path bin = fs::path(DT_CLI).parent_path();
    // The programs that draw the book's figures (bench_kernels and sec2_3_3 draw none).
    const char* programs[] = {"sec2_1_kernel", "sec2_2_bowyer_watson", "sec2_2_2_outside_hull",
                              "sec2_3_1_predicates", "sec2_3_2_adjacencies", "sec2_3_4_algorithms",
                              "sec2_3_5_hilbert", "sec2_3_6_flips", "opt_ladder",
                              "bench_parallel"};
    // All at once (they are independent and each writes its own files): on two cores the run
    // takes about half its CPU time. Each program's exit status goes to <prog>.rc. The paths
    // reach bash through the environment, never as code.
    std::string script;
    for (const std::string prog : programs) {
      const std::string extra = prog == "sec2_3_4_algorithms" ? " --no-profile" : "";
      script += "( \"$DT_BIN/" + prog + "\" --quick --max-n 2000" + extra + " --out \"$DT_DIR\" > \"$DT_DIR/" +
                prog + ".log\" 2>&1; echo $? > \"$DT_DIR/" + prog + ".rc\" ) & ";
    }
    script += "wait";
    ch::ProcessIo io;
    io.env = {{"DT_BIN", bin.string()}, {"DT_DIR", r.dir.string()}};
    ch::runProgram({"bash", "-c", script}, io);
    for (const std::string prog : programs) {
      const fs::path stem = r.dir / prog;
      if (readAll(stem.string() + ".rc") != "0\n") r.failures.push_back(prog + " (log: " + stem.string() + ".log)");
    }
    return r;
  }();
  return run;
}

std::vector<fs::path> outputs(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ext) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

// ---- the checkers can fail -----------------------------------------------------------------

TEST_CASE("figures the UTF-8 check rejects a raw Latin-1 byte and accepts UTF-8") {
  CHECK(utf8Error("N \xe2\x88\x9d n") == "");          // ∝
  CHECK(utf8Error("N {/Symbol \xb5} n") != "");        // what the Symbol font escape wrote
  CHECK(utf8Error("\xc0\xaf") != "");                  // overlong '/'
  CHECK(utf8Error("\xed\xa0\x80") != "");              // a surrogate
  CHECK(utf8Error("\xe2\x88") != "");                  // truncated
}

TEST_CASE("figures the XML check rejects what is not well formed") {
  CHECK(xmlError("<?xml version=\"1.0\"?>\n<svg a=\"1\"><g><text>x &amp; y</text></g><!-- c --></svg>\n") == "");
  CHECK(xmlError("<svg><g></svg></g>") != "");              // crossed
  CHECK(xmlError("<svg><g></g>") != "");                    // not closed
  CHECK(xmlError("<svg a=1></svg>") != "");                 // unquoted
  CHECK(xmlError("<svg a='1' a='2'></svg>") != "");         // repeated attribute
  CHECK(xmlError("<svg>a & b</svg>") != "");                // bare ampersand
  CHECK(xmlError("<svg></svg><svg></svg>") != "");          // two roots
  CHECK(xmlError("") != "");                                // no root
}

TEST_CASE("figures the background check tells a white SVG from a transparent one") {
  CHECK(whiteBackground("<svg>\n<g id=\"gnuplot_canvas\">\n<rect x=\"0\" y=\"0\" width=\"200\" height=\"100\" fill=\"#ffffff\"/>"));
  CHECK_FALSE(whiteBackground("<svg>\n<g id=\"gnuplot_canvas\">\n<rect x=\"0\" y=\"0\" width=\"200\" height=\"100\" fill=\"none\"/>"));
}

TEST_CASE("figures the PNG and GIF size readers read the header and reject other files") {
  std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x05\x78\0\0\x03\x20", 24);
  CHECK(pngSize(png) == std::make_pair(1400, 800));
  png[13] = 'X';
  CHECK(pngSize(png) == std::make_pair(-1, -1));
  CHECK(gifSize(std::string("GIF89a\xf8\x02\x20\x03", 10)) == std::make_pair(760, 800));
  CHECK(gifSize("PNG....xyz") == std::make_pair(-1, -1));
  const Sizes sizes = {{"fig2_5_anim", {760, 800}}, {"fig2_10", {1400, 780}}};
  CHECK(styleName("fig2_5_anim_07.png", sizes) == "fig2_5_anim");
  CHECK(styleName("fig2_10.png", sizes) == "fig2_10");
}

TEST_CASE("figures style.gp gives a size to every figure the book embeds") {
  const auto sizes = styleSizes();
  REQUIRE(sizes.size() >= 20);
  for (const std::string& name : embeddedFigures())
    CHECK_MESSAGE(sizes.count(fs::path(name).stem().string()) == 1, name << " has no size in figures/ch2/style.gp");
}

// ---- the outputs of a run ------------------------------------------------------------------

TEST_CASE("figures every figure the book embeds is written by the chapter programs") {
  const Run& run = figureRun();
  for (const std::string& f : run.failures) FAIL_CHECK("chapter program failed: " << f);
  const auto names = embeddedFigures();
  REQUIRE(names.size() >= 20);
  for (const std::string& name : names) {
    const fs::path p = run.dir / name;  // the exact name, not a prefix or substring
    CHECK_MESSAGE(fs::exists(p), name << " (embedded by the book) was not written into " << run.dir);
    if (fs::exists(p)) CHECK_MESSAGE(fs::file_size(p) > 0, name << " is empty");
  }
}

TEST_CASE("figures every SVG is well-formed XML in UTF-8 with a white background") {
  const Run& run = figureRun();
  const auto svgs = outputs(run.dir, ".svg");
  REQUIRE(svgs.size() >= 20);
  for (const fs::path& p : svgs) {
    const std::string text = readAll(p);
    const std::string u = utf8Error(text);
    CHECK_MESSAGE(u.empty(), p.filename().string() << ": not UTF-8: " << u);
    if (!u.empty()) continue;
    const std::string x = xmlError(text);
    CHECK_MESSAGE(x.empty(), p.filename().string() << ": not well-formed XML: " << x);
    CHECK_MESSAGE(whiteBackground(text), p.filename().string() << ": transparent background");
  }
}

TEST_CASE("figures every PNG and the GIF have the size figures/ch2/style.gp gives") {
  const Run& run = figureRun();
  const auto sizes = styleSizes();
  REQUIRE(sizes.size() >= 20);
  auto images = outputs(run.dir, ".png");
  const auto gifs = outputs(run.dir, ".gif");
  REQUIRE(images.size() >= 20);
  images.insert(images.end(), gifs.begin(), gifs.end());
  for (const fs::path& p : images) {
    const std::string name = styleName(p, sizes);
    const auto it = sizes.find(name);
    CHECK_MESSAGE(it != sizes.end(), p.filename().string() << ": no size in figures/ch2/style.gp");
    if (it == sizes.end()) continue;
    const std::string data = readAll(p);
    const auto got = p.extension() == ".gif" ? gifSize(data) : pngSize(data);
    CHECK_MESSAGE(got == it->second, p.filename().string() << " is " << got.first << " x " << got.second
                                                             << ", the style says " << it->second.first << " x "
                                                             << it->second.second);
  }
}
