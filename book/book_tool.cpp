// The book's own build steps (run by the 'book' target, see book/CMakeLists.txt):
//   book_tool prepare BOOK_DIR VALUES_DIR TESTS_DIR OUT_DIR
//     copies BOOK_DIR/*.md into OUT_DIR in the reading order of BOOK_DIR/order.txt, with
//     @{key} and @test{name} replaced and previous/next links added, and writes the claims
//     index; fails, naming page and line, on an unknown key or test name.
//   book_tool prune HTML_DIR
//     removes the empty "File Reference" pages Doxygen writes for the page files themselves.
//   book_tool check HTML_DIR
//     fails on literal markup in the rendered text and broken local links (layout: book/layout_check.sh).
#include <dirent.h>
#include <sys/stat.h>

#include <cstdio>
#include <iostream>

#include "book_tool.h"

namespace {

std::vector<std::string> listDir(const std::string& dir, const std::string& suffix) {
  std::vector<std::string> out;
  DIR* d = opendir(dir.c_str());
  if (!d) return out;
  while (dirent* e = readdir(d)) {
    const std::string n = e->d_name;
    if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
      out.push_back(n);
  }
  closedir(d);
  std::sort(out.begin(), out.end());
  return out;
}

bool isFile(const std::string& p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

void writeFile(const std::string& path, const std::string& text) {
  // Unchanged pages keep their time stamp, so Doxygen's output is not redone for nothing.
  if (isFile(path) && booktool::readFile(path) == text) return;
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

int prepare(const std::string& bookDir, const std::string& valuesDir, const std::string& testsDir,
            const std::string& outDir) {
  std::vector<std::string> errors;
  std::map<std::string, std::pair<std::string, std::string>> values;
  for (const std::string& f : listDir(valuesDir, ".txt"))
    if (f.rfind("values_", 0) == 0)
      booktool::readValues(booktool::readFile(valuesDir + "/" + f), f, values);

  std::vector<booktool::TestCase> tests;
  std::map<std::string, booktool::TestCase> byName;
  for (const std::string& f : listDir(testsDir, ".cpp"))
    for (const auto& t : booktool::testCases(booktool::readFile(testsDir + "/" + f), "tests/" + f)) {
      tests.push_back(t);
      auto [it, fresh] = byName.emplace(t.name, t);
      if (!fresh)
        errors.push_back(t.file + ":" + std::to_string(t.line) + ": test name \"" + t.name +
                         "\" is also used at " + it->second.file + ":" +
                         std::to_string(it->second.line));
    }

  // Reading order: order.txt names the pages (one file a line); the claims index comes last.
  std::vector<std::string> files;
  {
    std::istringstream in(booktool::readFile(bookDir + "/order.txt"));
    std::string s;
    while (std::getline(in, s)) {
      s.erase(0, s.find_first_not_of(" \t"));
      s.erase(s.find_last_not_of(" \t\r") + 1);
      if (s.empty() || s[0] == '#') continue;
      if (isFile(bookDir + "/" + s)) files.push_back(s);  // a listed page may not exist yet
    }
  }
  for (const std::string& f : listDir(bookDir, ".md"))
    if (std::find(files.begin(), files.end(), f) == files.end())
      errors.push_back("book/" + f + ": not in book/order.txt (add it where it belongs in the reading order)");

  std::vector<booktool::Page> order;
  for (const std::string& f : files) {
    const std::string text = booktool::readFile(bookDir + "/" + f);
    booktool::Page p = booktool::parsePage(text, "book/" + f);
    p.text = booktool::substitute(text, p.file, values, byName, errors);
    order.push_back(p);
  }
  const std::string claimsTitle = "Claims index: every test, its source line and how to run it";
  order.push_back({"claims.md", "claims", claimsTitle, booktool::claimsPage(tests, "claims", claimsTitle)});
  if (!errors.empty()) {
    std::cerr << "book: the pages cite what does not exist:\n";
    for (const std::string& e : errors) std::cerr << "  " << e << "\n";
    return 1;
  }
  mkdir(outDir.c_str(), 0755);
  // Pages of an earlier build whose name or place changed must not be read again.
  std::set<std::string> current;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::string base = order[k].file.substr(order[k].file.rfind('/') + 1);
    char num[24];
    std::snprintf(num, sizeof num, "%02zu_", k);
    current.insert(num + base.substr(0, base.rfind('.')) + ".dox");
  }
  for (const std::string& f : listDir(outDir, ".dox"))
    if (!current.count(f)) std::remove((outDir + "/" + f).c_str());
  // Doxygen lists the pages in the order it reads their files, that is by file name: a
  // number in front of each name gives the side bar the reading order.
  for (std::size_t k = 0; k < order.size(); ++k) {
    std::string name = order[k].file.substr(order[k].file.rfind('/') + 1);
    char num[24];
    std::snprintf(num, sizeof num, "%02zu_", k);
    name = num + name.substr(0, name.rfind('.')) + ".dox";
    writeFile(outDir + "/" + name, booktool::asDoxComment(booktool::withNavigation(order, k), order[k].file));
  }
  std::cout << "book: " << order.size() << " pages, " << values.size() << " values, "
            << tests.size() << " tests\n";
  return 0;
}

// Doxygen writes a "File Reference" page for every input file, the book's .dox pages too; no
// page links to these (they hold nothing), so they are removed from the output.
int prune(const std::string& htmlDir) {
  int removed = 0;
  for (const std::string& f : listDir(htmlDir, "_8dox.html"))
    if (f.size() > 3 && std::isdigit(static_cast<unsigned char>(f[0])) &&
        std::isdigit(static_cast<unsigned char>(f[1])) && f[2] == '_')
      removed += std::remove((htmlDir + "/" + f).c_str()) == 0;
  std::cout << "book: removed " << removed << " empty file pages of the book's own pages\n";
  return 0;
}

int check(const std::string& htmlDir) {
  std::map<std::string, std::set<std::string>> anchorCache;
  auto exists = [&](const std::string& f) { return isFile(htmlDir + "/" + f); };
  auto anchors = [&](const std::string& f) -> const std::set<std::string>& {
    auto it = anchorCache.find(f);
    if (it == anchorCache.end())
      it = anchorCache.emplace(f, booktool::anchorsOf(booktool::readFile(htmlDir + "/" + f))).first;
    return it->second;
  };
  int bad = 0;
  for (const std::string& f : listDir(htmlDir, ".html")) {
    // Source listings quote code and comments verbatim; they are code, not text.
    if (f.size() > 12 && f.compare(f.size() - 12, 12, "_source.html") == 0) continue;
    const std::string html = booktool::readFile(htmlDir + "/" + f);
    std::vector<booktool::Defect> d = booktool::renderedDefects(html);
    for (const auto& l : booktool::brokenLinks(html, exists, anchors)) d.push_back(l);
    for (const auto& x : d) {
      std::cerr << "  " << f << ": " << x.what << ": " << x.context << "\n";
      ++bad;
    }
  }
  if (bad) {
    std::cerr << "book: " << bad << " defect(s) a reader would see (listed above)\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string cmd = argc > 1 ? argv[1] : "";
    if (cmd == "prepare" && argc == 6) return prepare(argv[2], argv[3], argv[4], argv[5]);
    if (cmd == "prune" && argc == 3) return prune(argv[2]);
    if (cmd == "check" && argc == 3) return check(argv[2]);
    std::cerr << "usage: book_tool prepare BOOK_DIR VALUES_DIR TESTS_DIR OUT_DIR\n"
                 "       book_tool prune HTML_DIR\n"
                 "       book_tool check HTML_DIR\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "book_tool: " << e.what() << "\n";
    return 1;
  }
}
