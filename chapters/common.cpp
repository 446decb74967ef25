// The bodies of chapters/common.h's functions (options, output files, gnuplot, tables, values), compiled once.
#include "common.h"

namespace ch {

std::string& phase() {
  static std::string what = "reading the options";
  return what;
}

std::uint64_t Options::seed(std::uint64_t bookSeed) const {
  if (!seedOption) return bookSeed;
  auto mix = [](std::uint64_t z) {  // splitmix64's finaliser
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  return mix(*seedOption + 0x9e3779b97f4a7c15ULL * (bookSeed + 1)) & 0xffffffffULL;
}

std::string usageLine(const Program& p) {
  std::string u = p.name + " [--out DIR] [--quick] [--max-n N] [--no-plot] [--seed N] [--only FIG] [--size WxH]";
  for (const ExtraOption& e : p.extras) u += " [" + e.name + (e.value.empty() ? "" : " " + e.value) + "]";
  return u + " [--help]";
}

std::string helpText(const Program& p) {
  std::ostringstream s;
  auto line = [&](const std::string& opt, const std::string& what) {
    s << "  " << opt << std::string(opt.size() < 14 ? 14 - opt.size() : 1, ' ') << what << "\n";
  };
  s << "usage: " << usageLine(p) << "\n" << p.purpose << "\n";
  line("--out DIR", "where to write figures, tables and data (default: " + std::string(DT_OUTPUT_DIR) + "/ch2)");
  line("--quick", "a smaller run: smaller sizes, a few seconds");
  line("--max-n N", "the largest point count, " + std::to_string(p.minN) + " to " +
                        std::to_string(p.maxN) + " (1e5 is read as 100000)");
  line("--no-plot", "write data and tables, do not call gnuplot");
  line("--seed N", "other random points than the book's fixed seeds (N from 0 to 2^64-1)");
  std::string figs;
  for (const std::string& f : p.figures) figs += " " + f;
  line("--only FIG", p.figures.empty() ? std::string("draw one figure only (this program draws none)")
                                      : "draw one figure only, tables and values left as they are; FIG:" + figs);
  line("--size WxH", "the figures' size in pixels instead of the style's, e.g. 800x450 (each 64 to 8192)");
  for (const ExtraOption& e : p.extras) line(e.name + (e.value.empty() ? "" : " " + e.value), e.help);
  line("--help", "this list");
  return s.str();
}

std::optional<long> parseWhole(const std::string& text) {
  const char* b = text.data();
  const char* e = b + text.size();
  long v = 0;
  auto r = std::from_chars(b, e, v);
  if (r.ec == std::errc() && r.ptr == e) return v;
  double d = 0;
  auto rd = std::from_chars(b, e, d);
  if (rd.ec != std::errc() || rd.ptr != e || !std::isfinite(d) || d != std::floor(d) ||
      std::fabs(d) > 9.0e15)
    return std::nullopt;
  return long(d);
}

Options parseOptions(int argc, char** argv, const Program& p, bool createOut) {
  Options o;
  auto refuse = [&](const std::string& what) {
    std::cerr << p.name << ": " << what << "; usage: " << usageLine(p) << "\n";
    std::exit(2);
  };
  std::map<std::string, bool> seen;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << helpText(p);
      std::exit(0);
    }
    const ExtraOption* extra = nullptr;
    for (const ExtraOption& e : p.extras)
      if (e.name == a) extra = &e;
    const bool takesValue = a == "--out" || a == "--max-n" || a == "--seed" || a == "--only" ||
                            a == "--size" || (extra && !extra->value.empty());
    const bool known = takesValue || a == "--quick" || a == "--no-plot" || extra;
    if (!known) {
      if (a.size() > 1 && a[0] == '-') refuse("unknown option '" + a + "'");
      refuse("unexpected argument '" + a + "'");
    }
    if (seen[a]) refuse("option " + a + " given twice");
    seen[a] = true;
    std::string v;
    if (takesValue) {
      if (i + 1 >= argc) refuse("option " + a + " needs a value");
      v = argv[++i];
    }
    if (a == "--out") {
      if (v.empty()) refuse("--out needs a directory name, not ''");
      if (v.find('\n') != std::string::npos) refuse("--out: a directory name with a newline is not supported");
      o.out = v;
    } else if (a == "--quick") {
      o.quick = true;
    } else if (a == "--no-plot") {
      o.plot = false;
    } else if (a == "--max-n") {
      const std::optional<long> n = parseWhole(v);
      if (!n || *n < p.minN || *n > p.maxN)
        refuse("--max-n needs a whole number from " + std::to_string(p.minN) + " to " +
               std::to_string(p.maxN) + " (what this program can do), not '" + v + "'");
      o.maxN = *n;
    } else if (a == "--seed") {
      std::uint64_t s = 0;
      auto r = std::from_chars(v.data(), v.data() + v.size(), s);
      if (r.ec != std::errc() || r.ptr != v.data() + v.size())
        refuse("--seed needs a whole number from 0 to 2^64-1, not '" + v + "'");
      o.seedOption = s;
    } else if (a == "--only") {
      bool ok = false;
      std::string figs;
      for (const std::string& f : p.figures) {
        ok = ok || f == v;
        figs += " " + f;
      }
      if (!ok)
        refuse(p.figures.empty() ? "--only " + v + ": this program draws no figure"
                                 : "--only: no figure '" + v + "' here (its figures:" + figs + ")");
      o.only = v;
    } else if (a == "--size") {
      const std::size_t x = v.find('x');
      const std::optional<long> w = x == std::string::npos ? std::nullopt : parseWhole(v.substr(0, x));
      const std::optional<long> h = x == std::string::npos ? std::nullopt : parseWhole(v.substr(x + 1));
      if (!w || !h || *w < 64 || *w > 8192 || *h < 64 || *h > 8192)
        refuse("--size needs WIDTHxHEIGHT in pixels, each 64 to 8192 (e.g. 800x450), not '" + v + "'");
      o.width = int(*w);
      o.height = int(*h);
    } else if (extra->value == "N") {
      const std::optional<long> n = parseWhole(v);
      if (!n || *n < extra->lo || *n > extra->hi)
        refuse(a + " needs a whole number from " + std::to_string(extra->lo) + " to " +
               std::to_string(extra->hi) + ", not '" + v + "'");
      o.extra[a] = std::to_string(*n);
    } else {
      o.extra[a] = v;
    }
  }
  std::error_code ec;
  o.out = std::filesystem::absolute(o.out, ec).lexically_normal().string();
  if (!ec && createOut) std::filesystem::create_directories(o.out, ec);
  if (ec) {
    std::cerr << p.name << ": cannot create the output directory '" << o.out << "': " << ec.message() << "\n";
    std::exit(1);
  }
  return o;
}

std::string writeOut(const Options& o, const std::string& name, const std::string& text) {
  const std::string path = o.out + "/" + name;
  const std::string was = phase();
  phase() = "writing " + path;
  dt::writeFileAtomic(path, text);
  phase() = was;
  std::cout << "wrote " << path << "\n";
  return path;
}

std::vector<std::string> gnuplotOutputs(const std::string& scriptPath) {
  std::ifstream in(scriptPath);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  std::vector<std::string> names;
  for (std::size_t at = s.find("outdir."); at != std::string::npos; at = s.find("outdir.", at + 7)) {
    const std::size_t q = at + 7;
    if (q + 2 >= s.size() || (s[q] != '"' && s[q] != '\'') || s[q + 1] != '/') continue;
    const std::size_t close = s.find(s[q], q + 1);
    if (close != std::string::npos) names.push_back(s.substr(q + 2, close - q - 2));
  }
  return names;
}

std::string figureTruncated(const std::string& path) {
  auto endsWith = [](const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
  };
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  if (endsWith(path, ".png")) {
    static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    if (s.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return "no PNG signature";
    if (!endsWith(s, iend)) return "no IEND chunk at its end";
  } else if (endsWith(path, ".svg")) {
    std::size_t end = s.find_last_not_of(" \t\r\n");
    if (end == std::string::npos || !endsWith(s.substr(0, end + 1), "</svg>")) return "no closing </svg>";
  }
  return "";
}

std::string gnuplotQuote(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

void runGnuplot(const Options& o, const std::string& script) {
  if (!o.plot) return;
  if (!o.wants(script.substr(0, script.rfind(".gp")))) return;
  const std::string dir = std::string(DT_SOURCE_DIR) + "/figures/ch2";
  const std::string path = dir + "/" + script;
  const std::vector<std::string> promised = gnuplotOutputs(path);
  for (const auto& name : promised) std::remove((o.out + "/" + name).c_str());
  std::string vars = "datadir = " + gnuplotQuote(o.out) + "; outdir = " + gnuplotQuote(o.out);
  if (o.width > 0)
    vars += "; fig_size_w = " + std::to_string(o.width) + "; fig_size_h = " + std::to_string(o.height);
  ProcessIo io;
  io.cwd = dir;
  io.env = {{"DT_DATADIR", o.out}};
  const std::string was = phase();
  phase() = "drawing " + path;
  const int rc = runProgram({"gnuplot", "-e", vars, script}, io);
  phase() = was;
  if (rc == 127)
    throw std::runtime_error("could not run gnuplot on " + path +
                             ": its figures were not drawn (is gnuplot installed? bash scripts/deps.sh)");
  if (rc != 0)
    throw std::runtime_error("gnuplot failed (status " + std::to_string(rc) + ") on " + path +
                             ": its figures were not drawn");
  for (const auto& name : promised) {
    struct stat st;
    if (stat((o.out + "/" + name).c_str(), &st) != 0 || st.st_size == 0)
      throw std::runtime_error(path + " ran but did not write " + o.out + "/" + name);
    const std::string cut = figureTruncated(o.out + "/" + name);
    if (!cut.empty()) {
      std::remove((o.out + "/" + name).c_str());  // no half figure left for the book to embed
      throw std::runtime_error(path + " ran but " + o.out + "/" + name + " is cut short (" + cut +
                               "; a full disk?): removed");
    }
  }
  std::cout << "plotted " << path << " into " << o.out << "\n";
}

std::string htmlMath(std::string s) {
  auto sub = [&s](const char* re, const char* to) { s = std::regex_replace(s, std::regex(re), to); };
  sub("<=", "≤");
  sub(">=", "≥");
  sub(">>", "≫");
  sub("<<", "≪");
  sub("->", "→");
  sub("\\+-", "±");
  sub("\\bceil\\(log4 ([A-Za-z])\\)", "⌈log₄ $1⌉");
  sub(" ~ ", " ∼ ");
  sub("&(?![a-z]+;|#[0-9]+;)", "&amp;");
  sub("<", "&lt;");
  sub(">", "&gt;");
  sub("\\(\\.\\.\\.\\)", "(…)");
  sub("sqrt\\(([A-Za-z0-9_]+)\\)", "√$1");
  sub("sqrt\\(", "√(");
  sub("\\b1e(-?[1-9][0-9]*)\\b", "10^$1");
  sub("\\b1e\\+0*([1-9][0-9]*)\\b", "10^$1");
  sub("\\b1e±0*([1-9][0-9]*)\\b", "10^±$1");
  sub("\\|O\\|", "|𝒪|");
  sub("\\bO\\(", "𝒪(");
  sub("\\|InC\\|", "|𝒞|");
  sub("\\bInC\\(", "𝒞(");
  sub("\\|C\\|", "|𝒞|");
  sub("\\bS0\\b", "S<sub>0</sub>");
  sub("\\b(DT|[A-Za-z])_([A-Za-z0-9]+)\\b", "$1<sub>$2</sub>");
  // An exponent is a number (1.5 but not the range dots of "2^-60..2^60") or a name.
  sub("([A-Za-z0-9)])\\^-([0-9]+(?:\\.[0-9]+)?|[A-Za-z][A-Za-z0-9]*)", "$1<sup>−$2</sup>");
  sub("([A-Za-z0-9)])\\^((?:±)?[0-9]+(?:\\.[0-9]+)?|[A-Za-z][A-Za-z0-9]*)", "$1<sup>$2</sup>");
  sub("\\(us\\)", "(µs)");
  return s;
}

std::string spread(const std::vector<double>& v, const char* format) {
  if (v.size() < 2) return "-";
  const auto mm = std::minmax_element(v.begin(), v.end());
  return fmt(format, *mm.first) + "-" + fmt(format, *mm.second);
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string Table::markdown() const {
  std::ostringstream s;
  if (!caption.empty()) s << caption << "\n\n";
  s << "|";
  for (const auto& h : header) s << " " << h << " |";
  s << "\n|";
  for (std::size_t i = 0; i < header.size(); ++i) s << (i ? " ---: |" : " :--- |");
  s << "\n";
  for (const auto& r : rows) {
    s << "|";
    for (const auto& c : r) s << " " << c << " |";
    s << "\n";
  }
  return s.str();
}

std::string Table::csv() const {
  std::ostringstream s;
  for (std::size_t i = 0; i < header.size(); ++i) s << (i ? "," : "") << header[i];
  s << "\n";
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size(); ++i) s << (i ? "," : "") << r[i];
    s << "\n";
  }
  return s.str();
}

std::string Table::html() const {
  std::vector<std::vector<std::size_t>> parts = htmlParts;
  if (parts.empty()) {
    parts.emplace_back();
    for (std::size_t i = 0; i < header.size(); ++i) parts.back().push_back(i);
  }
  std::ostringstream s;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    std::vector<std::size_t> cols = parts[p];
    if (p > 0 && (cols.empty() || cols.front() != 0)) cols.insert(cols.begin(), 0);
    s << "<table class=\"doxtable\">\n";
    if (!caption.empty())
      s << "<caption>" << (p == 0 ? htmlMath(caption) : "(continued)") << "</caption>\n";
    s << "<tr>";
    for (std::size_t c : cols) s << "<th>" << htmlMath(header.at(c)) << "</th>";
    s << "</tr>\n";
    for (const auto& r : rows) {
      s << "<tr>";
      for (std::size_t c : cols) s << "<td>" << (c < r.size() ? htmlMath(r[c]) : "") << "</td>";
      s << "</tr>\n";
    }
    s << "</table>\n";
  }
  return s.str();
}

void Table::emit(const Options& o, const std::string& stem) const {
  if (!o.everything()) return;
  std::cout << "\n" << markdown() << "\n";
  writeOut(o, stem + ".md", markdown());
  writeOut(o, stem + ".csv", csv());
  writeOut(o, stem + ".html", html());
}
void Values::set(const std::string& key, const std::string& value) {
  if (key.empty() || key.find_first_of(" \t\n{}") != std::string::npos)
    throw std::invalid_argument("value key '" + key + "' must be one word without braces");
  if (value.find('\n') != std::string::npos)
    throw std::invalid_argument("value of '" + key + "' spans lines");
  for (const auto& kv : kv_)
    if (kv.first == key) throw std::invalid_argument("value key '" + key + "' set twice");
  kv_.emplace_back(key, value);
}

void Values::trend(const std::string& key, double first, double last) {
  set(key, last > 1.25 * first   ? "rises by more than a quarter"
           : last < 0.75 * first ? "falls by more than a quarter"
                                 : "stays within a quarter of its first value");
}

const std::string& Values::get(const std::string& key) const {
  for (const auto& kv : kv_)
    if (kv.first == key) return kv.second;
  throw std::invalid_argument("no value under '" + key + "'");
}

void Values::write() const {
  if (!o_.everything()) return;
  std::string text;
  for (const auto& kv : kv_) text += kv.first + " " + kv.second + "\n";
  writeOut(o_, "values_" + program_ + ".txt", text);
}
void Progress::update(std::uint64_t done) {
  if (!tty_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total_ && std::chrono::duration<double>(now - last_).count() < 0.25) return;
  last_ = now;
  const double el = std::chrono::duration<double>(now - t0_).count();
  const double rate = el > 0 ? double(done) / el : 0;
  const double left = rate > 0 ? double(total_ - done) / rate : 0;
  std::fprintf(stderr, "\r%s: %llu/%llu (%.0f/s, %.0f s left)   ", what_.c_str(),
               (unsigned long long)done, (unsigned long long)total_, rate, left);
  if (done >= total_) std::fprintf(stderr, "\n");
}

}  // namespace ch
