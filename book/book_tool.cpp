// The book's own build steps (run by the 'book' target, see book/CMakeLists.txt):
//   book_tool sources SRC_ROOT OUT_ROOT EDITION
//     copies code/ and tests/ of SRC_ROOT into OUT_ROOT as the edition (student or teacher)
//     shows them: the student's without the solution regions (Doxygen reads this copy, for
//     the snippets and the source browser).
//   book_tool prepare BOOK_DIR VALUES_DIR TESTS_DIR OUT_DIR EDITION
//     copies BOOK_DIR/*.md into OUT_DIR in the reading order of BOOK_DIR/order.txt, with
//     @{key} and @test{name} replaced, solution blocks dropped (student) or framed as answers
//     (teacher), and previous/next links added, and writes the claims index; fails, naming
//     page and line, on an unknown key or test name.
//   book_tool check-editions SRC_ROOT STUDENT_HTML TEACHER_HTML
//     fails if the student edition shows any line or value of an exercise's answer, or the
//     teacher edition misses one, or an exercise of exercises/exercises.txt has no marked answer.
//   book_tool prune HTML_DIR
//     removes the empty "File Reference" pages Doxygen writes for the page files themselves.
//   book_tool check HTML_DIR
//     fails on literal markup in the rendered text and broken local links (layout: book/layout_check.sh).
//   book_tool printbook HTML_DIR ORDER_FILE OUT_HTML
//     the pages of ORDER_FILE (written by prepare) as one file to print, with a contents list.
//   book_tool pagefill PAGE.pgm...
//     how far down each printed page has ink (book/pdf_check.sh).
//   book_tool access HTML_DIR ALT_FILE
//     lang on every page, the search field labelled, every figure of a book page a <figure>
//     with its caption and the alt text its page gives (ALT_FILE, written by prepare); fails
//     on a figure without one (axe-core then measures the pages: book/axe_check.sh).
#include <dirent.h>
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "book_access.h"
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

// Replaces each "<!-- reproduce: ... -->" line of a page by its box (booktool::reproduceBox).
std::string withReproduceBoxes(const std::string& text, const std::string& file,
                               const std::map<std::string, std::pair<std::string, std::string>>& values,
                               const std::string& valuesDir, const std::string& outDir,
                               booktool::Edition edition, std::vector<std::string>& errors) {
  namespace fs = std::filesystem;
  // The pages land in <book>/<edition>/, beside <book>/pages_<edition>/ (book/CMakeLists.txt).
  const fs::path html = fs::absolute(fs::path(outDir)).parent_path() /
                        (edition == booktool::Edition::Student ? "student" : "teacher");
  const std::string url = fs::absolute(fs::path(valuesDir)).lexically_relative(html).generic_string();
  std::string out;
  int n = 0;
  for (const std::string& line : booktool::splitLines(text)) {
    ++n;
    booktool::ReproduceSpec spec;
    std::string error;
    if (!booktool::parseReproduce(line, spec, error)) {
      out += line + "\n";
      continue;
    }
    if (!error.empty()) {
      errors.push_back(file + ":" + std::to_string(n) + ": " + error);
      continue;
    }
    out += booktool::reproduceBox(spec, text, values, url,
                                  [&](const std::string& f) { return isFile(valuesDir + "/" + f); });
    out += "\n" + booktool::claimsSummary(text);
  }
  return out;
}

// The student's edition includes, for each table a chapter program wrote, a copy without the
// rows an exercise asks for (bookaccess::studentTable), beside its sources (an example path of
// Doxygen), when there is such a row.
std::string studentTables(const std::string& text, const std::string& valuesDir, const std::string& outDir) {
  const std::string src = std::filesystem::absolute(std::filesystem::path(outDir)).parent_path().string() +
                          "/sources_student/";
  std::string out;
  for (const std::string& line : booktool::splitLines(text)) {
    const std::string lead = "\\htmlinclude ";
    const std::size_t at = line.find(lead);
    if (at != std::string::npos) {
      std::string name = booktool::squeeze(line.substr(at + lead.size()));
      name = name.substr(0, name.find(' '));
      if (isFile(valuesDir + "/" + name)) {
        const std::string table = booktool::readFile(valuesDir + "/" + name);
        const std::string mine = bookaccess::studentTable(table);
        if (mine != table) {
          writeFile(src + "student_" + name, mine);
          out += line.substr(0, at) + lead + "student_" + name + "\n";
          continue;
        }
      }
    }
    out += line + "\n";
  }
  return out;
}

int prepare(const std::string& bookDir, const std::string& valuesDir, const std::string& testsDir,
            const std::string& outDir, booktool::Edition edition) {
  std::vector<std::string> errors;
  std::map<std::string, std::pair<std::string, std::string>> values;
  for (const std::string& f : listDir(valuesDir, ".txt"))
    if (f.rfind("values_", 0) == 0)
      booktool::readValues(booktool::readFile(valuesDir + "/" + f), f, values);

  std::vector<booktool::TestCase> tests;
  std::map<std::string, booktool::TestCase> byName;
  for (const std::string& f : listDir(testsDir, ".cpp"))
    booktool::testBounds(booktool::readFile(testsDir + "/" + f), "tests/" + f, values);
  for (const std::string& f : listDir(testsDir, ".cpp"))
    for (const auto& t : booktool::testCases(booktool::readFile(testsDir + "/" + f), "tests/" + f)) {
      tests.push_back(t);
      auto [it, fresh] = byName.emplace(t.name, t);
      if (!fresh)
        errors.push_back(t.file + ":" + std::to_string(t.line) + ": test name \"" + t.name +
                         "\" is also used at " + it->second.file + ":" +
                         std::to_string(it->second.line));
    }

  // Reading order: order.txt names the pages (one file a line, "teacher" after the name for
  // a page only the teacher's edition has); the claims index comes last.
  std::vector<std::string> files, listed;
  {
    std::istringstream in(booktool::readFile(bookDir + "/order.txt"));
    std::string s;
    while (std::getline(in, s)) {
      std::istringstream w(s);
      std::string name, flag;
      w >> name >> flag;
      if (name.empty() || name[0] == '#') continue;
      listed.push_back(name);
      if (!flag.empty() && flag != "teacher")
        errors.push_back("book/order.txt: '" + flag + "' after " + name + " (only 'teacher' may follow a page)");
      if (flag == "teacher" && edition == booktool::Edition::Student) continue;
      if (isFile(bookDir + "/" + name)) files.push_back(name);  // a listed page may not exist yet
    }
  }
  for (const std::string& f : listDir(bookDir, ".md"))
    if (std::find(listed.begin(), listed.end(), f) == listed.end())
      errors.push_back("book/" + f + ": not in book/order.txt (add it where it belongs in the reading order)");

  std::vector<booktool::Page> order;
  std::map<std::string, std::string> alts;  // figure file -> its alt text (book_tool access)
  for (const std::string& f : files) {
    std::string text = booktool::editionPage(booktool::readFile(bookDir + "/" + f), "book/" + f, edition);
    if (edition == booktool::Edition::Student) text = booktool::studentLinks(text);
    text = withReproduceBoxes(text, "book/" + f, values, valuesDir, outDir, edition, errors);
    {
      // The edition's copy of the sources (book_tool sources) lies beside the pages.
      const std::string src = std::filesystem::absolute(std::filesystem::path(outDir)).parent_path().string() +
                              (edition == booktool::Edition::Student ? "/sources_student/" : "/sources_teacher/");
      text = booktool::withListingCaptions(text, [&](const std::string& file) {
        return isFile(src + file) ? booktool::readFile(src + file) : std::string();
      });
    }
    booktool::Page p = booktool::parsePage(text, "book/" + f);
    // The student edition has no solutions page: a link to it must sit in a solution block.
    if (edition == booktool::Edition::Student)
      for (const char* ref : {"\\ref sol_", "\\ref solutions "})
        if (text.find(ref) != std::string::npos)
          errors.push_back("book/" + f + ": links to a solution (" + std::string(ref) +
                           ") outside a solution block; the student edition has none");
    // A number the page types that a program or a test bound holds: cite it instead.
    {
      std::vector<std::string> programs;
      for (const std::string& l : booktool::splitLines(booktool::readFile(bookDir + "/" + f))) {
        booktool::ReproduceSpec spec;
        std::string error;
        if (booktool::parseReproduce(l, spec, error)) programs = spec.programs;
      }
      // On the source as written, so that the line numbers are the file's.
      for (const std::string& e : bookaccess::typedValues(booktool::readFile(bookDir + "/" + f), p.file, values, programs))
        errors.push_back(e);
    }
    p.text = booktool::substitute(text, p.file, values, byName, errors);
    for (const auto& [img, alt] : bookaccess::figureAlts(p.text, p.file, errors)) alts[img] = alt;
    if (edition == booktool::Edition::Student) p.text = studentTables(p.text, valuesDir, outDir);
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
  {
    std::string a, ids;
    for (const auto& [img, alt] : alts) a += img + "\t" + alt + "\n";
    writeFile(outDir + "/alt.txt", a);
    // The reading order for the printed book (book_tool printbook).
    for (const booktool::Page& p : order) ids += p.id + "\t" + p.title + "\n";
    writeFile(outDir + "/print_order.txt", ids);
  }
  std::cout << "book: " << order.size() << " pages, " << values.size() << " values, "
            << tests.size() << " tests\n";
  return 0;
}

// The folders of sources an edition copies: code/, each room of code/ (code/rooms.txt) and tests/.
std::vector<std::string> sourceDirs(const std::string& srcRoot) {
  std::vector<std::string> dirs{"code"};
  std::istringstream rooms(booktool::readFile(srcRoot + "/code/rooms.txt"));
  std::string l;
  while (std::getline(rooms, l))
    if (!l.empty() && l.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string::npos) dirs.push_back("code/" + l);
  dirs.push_back("tests");
  return dirs;
}

// The sources as an edition shows them (see booktool::editionCode).
int sources(const std::string& srcRoot, const std::string& outRoot, booktool::Edition edition) {
  mkdir(outRoot.c_str(), 0755);
  int n = 0;
  for (const std::string& dir : sourceDirs(srcRoot)) {
    const std::string from = srcRoot + "/" + dir, to = outRoot + "/" + dir;
    mkdir(to.c_str(), 0755);
    for (const char* ext : {".h", ".cpp"})
      for (const std::string& f : listDir(from, ext)) {
        const std::string rel = dir + "/" + f;
        writeFile(to + "/" + f, booktool::editionCode(booktool::readFile(from + "/" + f), rel, edition));
        ++n;
      }
  }
  std::cout << "book: " << n << " source files for the " << (edition == booktool::Edition::Student ? "student" : "teacher")
            << "'s edition\n";
  return 0;
}

// All the text of an edition's pages (tags removed, entities decoded, whitespace squeezed).
std::string editionText(const std::string& htmlDir) {
  std::string all;
  for (const std::string& f : listDir(htmlDir, ".html"))
    all += booktool::squeeze(booktool::decodeEntities(booktool::stripTags(booktool::readFile(htmlDir + "/" + f)))) + "\n";
  return all;
}

int checkEditions(const std::string& srcRoot, const std::string& studentDir, const std::string& teacherDir) {
  std::map<std::string, std::string> code, pages;
  for (const std::string& dir : sourceDirs(srcRoot))
    for (const char* ext : {".h", ".cpp"})
      for (const std::string& f : listDir(srcRoot + "/" + dir, ext))
        code[dir + "/" + f] = booktool::readFile(srcRoot + "/" + dir + "/" + f);
  for (const std::string& f : listDir(srcRoot + "/book", ".md"))
    pages["book/" + f] = booktool::readFile(srcRoot + "/book/" + f);
  std::vector<std::string> ids;
  {
    std::istringstream in(booktool::readFile(srcRoot + "/exercises/exercises.txt"));
    std::string l;
    while (std::getline(in, l))
      if (l.rfind("id:", 0) == 0) ids.push_back(booktool::squeeze(l.substr(3)));
  }
  const auto keys = booktool::answerKeys(code, pages);
  const std::string student = editionText(studentDir), teacher = editionText(teacherDir);
  std::vector<std::string> bad = booktool::editionLeaks(keys, ids, student, teacher);
  for (const std::string& l : booktool::snippetLeaks(keys, code)) bad.push_back(l);
  for (const char* m : {"// BEGIN SOLUTION", "// END SOLUTION"}) {
    if (student.find(m) != std::string::npos) bad.push_back(std::string("the student edition shows a marker '") + m + "'");
    if (teacher.find(m) != std::string::npos) bad.push_back(std::string("the teacher edition shows a marker '") + m + "'");
  }
  if (isFile(studentDir + "/solutions.html")) bad.push_back("the student edition has the solutions page");
  std::size_t items = 0;
  for (const auto& [id, k] : keys) items += k.lines.size() + k.values.size();
  for (const std::string& b : bad) std::cerr << "  " << b << "\n";
  if (!bad.empty()) {
    std::cerr << "book: " << bad.size() << " edition defect(s) (listed above)\n";
    return 1;
  }
  std::cout << "book: editions checked: " << ids.size() << " exercises, " << items
            << " answer lines and values, none in the student's edition, all in the teacher's\n";
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

// Every page of an edition made accessible (book/book_access.h): lang, the search field's
// label, figures with their alt text (from the pages' "<!-- alt: -->" lines, gathered by
// prepare into ALT_FILE) and captions.
int access(const std::string& htmlDir, const std::string& altFile) {
  std::map<std::string, std::string> alts;
  for (const std::string& l : booktool::splitLines(booktool::readFile(altFile))) {
    const std::size_t tab = l.find('\t');
    if (tab != std::string::npos) alts[l.substr(0, tab)] = l.substr(tab + 1);
  }
  std::vector<std::string> errors;
  int figures = 0, pages = 0;
  std::set<std::string> suite;  // the test suite's own pages (bookaccess::isSuitePage)
  for (const std::string& f : listDir(htmlDir, ".html"))
    if (bookaccess::isSuitePage(booktool::readFile(htmlDir + "/" + f))) suite.insert(f);
  for (const std::string& f : listDir(htmlDir, ".html")) {
    const std::string html = booktool::readFile(htmlDir + "/" + f);
    std::string out = bookaccess::withSkipLink(bookaccess::withSearchLabel(bookaccess::withLang(html)));
    if (!suite.count(f)) out = bookaccess::withoutLinksIntoSuite(out, suite);
    if (booktool::isBookPage(out)) {
      out = bookaccess::withoutNestedMarkers(bookaccess::withTableCaptions(bookaccess::withFigures(out, f, alts, errors)));
      for (std::size_t at = out.find("<figure class=\"image\""); at != std::string::npos;
           at = out.find("<figure class=\"image\"", at + 1))
        ++figures;
    }
    if (out != html) { writeFile(htmlDir + "/" + f, out); ++pages; }
  }
  for (const std::string& f : listDir(htmlDir, ".js")) {
    const std::string js = booktool::readFile(htmlDir + "/" + f);
    const std::string out = bookaccess::withSearchLabel(js);
    if (out != js) writeFile(htmlDir + "/" + f, out);
  }
  for (const std::string& e : errors) std::cerr << "  " << e << "\n";
  if (!errors.empty()) {
    std::cerr << "book: " << errors.size() << " figure(s) without alt text (listed above)\n";
    return 1;
  }
  std::cout << "book: " << pages << " pages given lang and a labelled search field, " << figures
            << " figures with alt text and caption\n";
  return 0;
}

// The printed book: one HTML file, HTML_DIR/print.html, with a contents list and every page of
// the reading order (ORDER_FILE, written by prepare) as a section that starts a new sheet,
// links between pages made links inside the file, other links given a printed target
// (bookaccess::printPage); Chromium prints it (book/print_book.sh).
int printbook(const std::string& htmlDir, const std::string& orderFile, const std::string& outFile) {
  std::vector<std::pair<std::string, std::string>> order;
  for (const std::string& l : booktool::splitLines(booktool::readFile(orderFile))) {
    const std::size_t tab = l.find('\t');
    if (tab != std::string::npos && isFile(htmlDir + "/" + l.substr(0, tab) + ".html"))
      order.push_back({l.substr(0, tab), l.substr(tab + 1)});
  }
  if (order.empty()) throw std::runtime_error(orderFile + ": no page of " + htmlDir);
  std::set<std::string> ids;
  for (const auto& [id, title] : order) ids.insert(id);
  const std::string first = booktool::readFile(htmlDir + "/" + order.front().first + ".html");
  const std::size_t body = first.find("<body>");
  if (body == std::string::npos) throw std::runtime_error(htmlDir + "/index.html: no <body>");
  std::string out = first.substr(0, body) + "<body>\n<div id=\"doc-content\">\n";
  out += "<nav class=\"printtoc\" aria-label=\"Contents\"><h1>Contents</h1>\n<ol>\n";
  for (const auto& [id, title] : order)
    out += "<li><a href=\"#print_" + id + "\">" + title + "</a></li>\n";
  out += "</ol></nav>\n";
  for (const auto& [id, title] : order)
    out += "<section class=\"printpage\" id=\"print_" + id + "\">\n" +
           bookaccess::printPage(booktool::readFile(htmlDir + "/" + id + ".html"), ids) + "\n</section>\n";
  out += "</div>\n</body>\n</html>\n";
  writeFile(outFile, out);
  std::cout << "book: " << outFile << ": " << order.size() << " pages to print\n";
  return 0;
}

// How full each printed page is: for each PGM image (a page, pdftoppm -gray), the share of its
// height from the top of the page down to its last row with ink, the bottom margin (where
// the page number is) left out. One "FILE SHARE" line each.
int pagefill(int argc, char** argv) {
  for (int a = 2; a < argc; ++a) {
    std::ifstream in(argv[a], std::ios::binary);
    std::string magic;
    int w = 0, h = 0, maxval = 0;
    in >> magic >> w >> h >> maxval;
    in.get();
    if (!in || magic != "P5" || w <= 0 || h <= 0 || maxval <= 0 || maxval > 255)
      throw std::runtime_error(std::string(argv[a]) + ": not an 8-bit binary PGM image");
    std::vector<unsigned char> px(std::size_t(w) * h);
    in.read(reinterpret_cast<char*>(px.data()), std::streamsize(px.size()));
    if (!in) throw std::runtime_error(std::string(argv[a]) + ": image data cut short");
    const int body = h - h * 18 / 297;  // the bottom margin of the print style (18 mm of A4)
    int last = 0;
    for (int y = 0; y < body; ++y)
      for (int x = 0; x < w; ++x)
        if (px[std::size_t(y) * w + x] < maxval * 7 / 8) { last = y + 1; break; }
    std::printf("%s %.3f\n", argv[a], double(last) / body);
  }
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
    if (cmd == "sources" && argc == 5) return sources(argv[2], argv[3], booktool::editionNamed(argv[4]));
    if (cmd == "prepare" && argc == 7)
      return prepare(argv[2], argv[3], argv[4], argv[5], booktool::editionNamed(argv[6]));
    if (cmd == "check-editions" && argc == 5) return checkEditions(argv[2], argv[3], argv[4]);
    if (cmd == "prune" && argc == 3) return prune(argv[2]);
    if (cmd == "check" && argc == 3) return check(argv[2]);
    if (cmd == "access" && argc == 4) return access(argv[2], argv[3]);
    if (cmd == "printbook" && argc == 5) return printbook(argv[2], argv[3], argv[4]);
    if (cmd == "pagefill" && argc >= 3) return pagefill(argc, argv);
    std::cerr << "usage: book_tool sources SRC_ROOT OUT_ROOT student|teacher\n"
                 "       book_tool prepare BOOK_DIR VALUES_DIR TESTS_DIR OUT_DIR student|teacher\n"
                 "       book_tool check-editions SRC_ROOT STUDENT_HTML TEACHER_HTML\n"
                 "       book_tool prune HTML_DIR\n"
                 "       book_tool check HTML_DIR\n"
                 "       book_tool access HTML_DIR ALT_FILE\n"
                 "       book_tool printbook HTML_DIR ORDER_FILE OUT_HTML\n"
                 "       book_tool pagefill PAGE.pgm...\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "book_tool: " << e.what() << "\n";
    return 1;
  }
}
