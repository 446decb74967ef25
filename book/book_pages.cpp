#include "book_pages.h"

namespace booktool {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void readValues(const std::string& text, const std::string& file,
                std::map<std::string, std::pair<std::string, std::string>>& out) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const auto sp = line.find(' ');
    if (sp == std::string::npos || sp == 0)
      throw std::runtime_error(file + ":" + std::to_string(n) + ": expected 'key value', got '" +
                               line + "'");
    const std::string key = line.substr(0, sp), value = line.substr(sp + 1);
    auto it = out.find(key);
    if (it != out.end())
      throw std::runtime_error(file + ":" + std::to_string(n) + ": key '" + key +
                               "' is also written by " + it->second.second);
    out[key] = {value, file};
  }
}

std::vector<TestCase> testCases(const std::string& text, const std::string& file) {
  std::vector<TestCase> out;
  std::size_t lineStart = 0;
  int n = 0;
  while (lineStart < text.size()) {
    ++n;
    std::size_t eol = text.find('\n', lineStart);
    if (eol == std::string::npos) eol = text.size();
    const std::size_t first = text.find_first_not_of(" \t", lineStart);
    if (first < eol && text.compare(first, 10, "TEST_CASE(") == 0) {
      std::string name;
      std::size_t i = first + 10;
      bool ok = false;
      while (true) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i >= text.size() || text[i] != '"') break;
        for (++i; i < text.size() && text[i] != '"'; ++i) {
          if (text[i] == '\\' && i + 1 < text.size()) ++i;
          name += text[i];
        }
        ++i;
        ok = true;
      }
      if (ok) out.push_back({name, file, n});
    }
    lineStart = eol + 1;
  }
  return out;
}

std::string sourcePage(const std::string& file) {
  const std::string base = file.substr(file.rfind('/') == std::string::npos ? 0 : file.rfind('/') + 1);
  std::string out;
  for (char c : base) {
    if (c == '_') out += "__";
    else if (c == '.') out += "_8";
    else if (c == '-') out += "-";
    else out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out + "_source.html";
}

std::string lineAnchor(int line) {
  std::string d = std::to_string(line);
  while (d.size() < 5) d = "0" + d;
  return "l" + d;
}

std::string sectionOf(const std::string& name) {
  std::size_t i = 0;
  while (i < name.size() && (std::isdigit(static_cast<unsigned char>(name[i])) || name[i] == '.')) ++i;
  if (i == 0 || !std::isdigit(static_cast<unsigned char>(name[0]))) return "";
  std::string s = name.substr(0, i);
  while (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::string claimAnchor(const std::string& name) {
  std::string out = "claim_";
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(c)) : '_';
  return out;
}

std::string htmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string htmlText(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += "&#124;";
    else if (c == '*') out += "&#42;";
    else if (c == '_') out += "&#95;";
    else if (c == '\\') out += "&#92;";
    else if (c == '@') out += "&#64;";
    else out += htmlEscape(std::string(1, c));
  }
  return out;
}

std::string testLink(const TestCase& t) {
  return "\\htmlonly<a href=\"" + sourcePage(t.file) + "#" + lineAnchor(t.line) +
         "\" class=\"testlink\"><code class=\"testname\">" + htmlText(t.name) +
         "</code></a>\\endhtmlonly";
}

Page parsePage(const std::string& text, const std::string& file) {
  Page p{file, "", "", text};
  std::istringstream in(text);
  std::string first;
  while (std::getline(in, first) && first.find_first_not_of(" \t\r") == std::string::npos) {
  }
  std::istringstream w(first);
  std::string cmd;
  w >> cmd;
  if (cmd == "\\mainpage") {
    p.id = "index";
  } else if (cmd == "\\page") {
    w >> p.id;
  } else {
    throw std::runtime_error(file + ":1: a page starts with \\page <id> <title> or \\mainpage");
  }
  std::getline(w, p.title);
  p.title.erase(0, p.title.find_first_not_of(" \t"));
  return p;
}

}  // namespace booktool
