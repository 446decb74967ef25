// book_citations SRC_ROOT: checks the book's citations of tests (book/citations.h) over
// SRC_ROOT/book/*.md and SRC_ROOT/tests/*.cpp; prints each fault as "<file>:<line>: ..." and
// exits 1 if there is one. The book target runs it first, and ctest runs it as book_citations.
#include <dirent.h>

#include <iostream>

#include "citations.h"

namespace {

std::vector<std::string> filesIn(const std::string& dir, const std::string& suffix) {
  std::vector<std::string> out;
  DIR* d = opendir(dir.c_str());
  if (!d) throw std::runtime_error("cannot list " + dir);
  while (dirent* e = readdir(d)) {
    const std::string n = e->d_name;
    if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
      out.push_back(n);
  }
  closedir(d);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: book_citations SRC_ROOT\n";
    return 2;
  }
  try {
    const std::string root = argv[1];
    std::vector<booktool::Page> pages;
    for (const std::string& f : filesIn(root + "/book", ".md"))
      pages.push_back(booktool::parsePage(booktool::readFile(root + "/book/" + f), "book/" + f));
    std::vector<booktool::TestCase> tests;
    for (const std::string& f : filesIn(root + "/tests", ".cpp"))
      for (const auto& t : booktool::testCases(booktool::readFile(root + "/tests/" + f), "tests/" + f))
        tests.push_back(t);
    const std::vector<std::string> errors = booktool::checkCitations(pages, tests);
    for (const std::string& e : errors) std::cerr << e << "\n";
    if (!errors.empty()) {
      std::cerr << "book_citations: " << errors.size() << " citation fault(s)\n";
      return 1;
    }
    std::cout << "book_citations: " << pages.size() << " pages, " << tests.size()
              << " tests, every claim test cited and every citation sound\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "book_citations: " << e.what() << "\n";
    return 1;
  }
}
