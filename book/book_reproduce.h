// A piece of the book tool (book_tool.h lists them all):
// the "Reproduce this page" box.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cctype>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "book_pages.h"
#include "book_editions.h"

namespace booktool {

// ---- "Reproduce this page" ----------------------------------------------------------------
// A section page names its program(s) and tests in one line,
//   <!-- reproduce: programs: sec2_3_4_algorithms; tests: 2.3.4 *; ctest: test_2_3_4 -->
// and book_tool puts in its place a box: the commands (full and --quick), the wall time of the
// program in this build's run of the main command (value run.<program>.seconds, written by
// scripts/main.sh), the files of the page as links, and the commands that run its tests.

/// Percent-encodes what a relative URL path cannot hold as typed (spaces, quotes, '%', '#').
std::string urlPath(const std::string& p);

struct ReproduceSpec {
  std::vector<std::string> programs;
  std::string tests, ctest;
};

/// Reads a "<!-- reproduce: ... -->" line; false if the line is not one.
bool parseReproduce(const std::string& line, ReproduceSpec& spec, std::string& error);

/// The box (raw HTML for Doxygen). `page` is the page's text (for the files it embeds),
/// `values` the measured values, `outputUrl` the output directory relative to the pages,
/// `exists` answers whether a file of the output directory exists.
template <class Exists>
std::string reproduceBox(const ReproduceSpec& spec, const std::string& page,
                         const std::map<std::string, std::pair<std::string, std::string>>& values,
                         const std::string& outputUrl, Exists exists) {
  auto code = [](const std::string& s) {
    std::string e = htmlText(s);
    std::string out;
    for (std::size_t i = 0; i < e.size(); ++i)  // "--" must not become an en dash
      out += (e[i] == '-' && ((i + 1 < e.size() && e[i + 1] == '-') || (i > 0 && e[i - 1] == '-')))
                 ? std::string("&#45;")
                 : std::string(1, e[i]);
    return "<code>" + out + "</code>";
  };
  std::ostringstream o;
  o << "\\htmlonly[block]<div class=\"reproduce\"><b>Reproduce this page</b> (from the repository's root, "
       "once <code>bash scripts/main.sh</code> has built everything):<ul>\n";
  for (const std::string& p : spec.programs) {
    o << "<li>" << code("build/" + p) << " (the full run) or " << code("build/" + p + " --quick")
      << " (small sizes); ";
    auto it = values.find("run." + p + ".seconds");
    // Which run timed it: the main command's options (values_run.txt), "none" for the full run.
    auto opts = values.find("run.options");
    const bool full = opts == values.end() || opts->second.first == "none";
    if (it != values.end() && full)
      o << "the full run of this build's main command took it " << htmlText(it->second.first) << " s of wall time.";
    else if (it != values.end())
      o << "this build's main command, run with " << code(opts->second.first) << ", took it "
        << htmlText(it->second.first) << " s of wall time.";
    else
      o << "not timed in this build (the main command, <code>bash scripts/main.sh</code>, times every program).";
    o << "</li>\n";
  }
  // The files this page shows, from the output directory.
  std::vector<std::string> files;
  for (const std::string& l : splitLines(page)) {
    std::istringstream w(l);
    std::string cmd, a, b;
    w >> cmd >> a >> b;
    std::string name = cmd == "\\image" ? b : cmd == "\\htmlinclude" ? a : "";
    if (name.empty()) continue;
    if (!name.empty() && name.front() == '"') name = name.substr(1, name.find('"', 1) - 1);
    const std::string stem = name.substr(0, name.rfind('.'));
    if (cmd == "\\htmlinclude") {
      for (const char* ext : {".csv", ".md", ".html"})
        if (exists(stem + ext)) files.push_back(stem + ext);
    } else if (exists(name)) {
      files.push_back(name);
    }
  }
  for (const std::string& p : spec.programs)
    if (exists("values_" + p + ".txt")) files.push_back("values_" + p + ".txt");
  if (!files.empty()) {
    o << "<li>What it writes that this page shows, in <code>build/output/ch2/</code>: ";
    for (std::size_t k = 0; k < files.size(); ++k)
      o << (k ? ", " : "") << "<a href=\"" << htmlEscape(urlPath(outputUrl + "/" + files[k])) << "\">"
        << htmlText(files[k]) << "</a>";
    o << ".</li>\n";
  }
  // No full stop after the command: a narrow page wrapped it onto a line of its own.
  o << "<li>The page's tests: " << code("build/dt_tests -tc=\"" + spec.tests + "\"") << ", or "
    << code("ctest --test-dir build -R \"" + spec.ctest + "\"") << "</li>\n";
  o << "</ul></div>\\endhtmlonly\n";
  return o.str();
}

}  // namespace booktool
