#include "book_reproduce.h"

namespace booktool {

std::string urlPath(const std::string& p) {
  std::string out;
  for (unsigned char c : p) {
    if (std::isalnum(c) || std::string("/._-~").find(char(c)) != std::string::npos) {
      out += char(c);
    } else {
      char b[4];
      std::snprintf(b, sizeof b, "%%%02X", c);
      out += b;
    }
  }
  return out;
}

bool parseReproduce(const std::string& line, ReproduceSpec& spec, std::string& error) {
  const std::string lead = "<!-- reproduce:";
  const std::size_t a = line.find(lead);
  if (a == std::string::npos) return false;
  const std::size_t end = line.find("-->", a);
  if (end == std::string::npos) {
    error = "a reproduce line must end with -->";
    return true;
  }
  std::string body = line.substr(a + lead.size(), end - a - lead.size());
  std::size_t s = 0;
  while (s < body.size()) {
    std::size_t semi = body.find(';', s);
    if (semi == std::string::npos) semi = body.size();
    const std::string part = body.substr(s, semi - s);
    const std::size_t colon = part.find(':');
    const std::string key = squeeze(part.substr(0, colon)), val = colon == std::string::npos ? "" : squeeze(part.substr(colon + 1));
    if (key == "programs") {
      std::istringstream w(val);
      std::string p;
      while (w >> p) spec.programs.push_back(p);
    } else if (key == "tests") {
      spec.tests = val;
    } else if (key == "ctest") {
      spec.ctest = val;
    } else if (!key.empty()) {
      error = "unknown field '" + key + "' in a reproduce line (programs, tests, ctest)";
    }
    s = semi + 1;
  }
  if (spec.programs.empty() || spec.tests.empty() || spec.ctest.empty())
    error = "a reproduce line needs programs, tests and ctest";
  return true;
}

}  // namespace booktool
