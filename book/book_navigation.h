// A piece of the book tool (book_tool.h lists them all):
// the navigation and the Doxygen output: previous/next links, the page as a Doxygen comment,
// the summary at the top of a section page, listing captions.
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

/// Previous/next links for the page at `k` of the reading order.
std::string navLine(const std::vector<Page>& order, std::size_t k);

/// Inserts the navigation after a page's first line and at its end; the main page also gets
/// the list of all pages in reading order.
std::string withNavigation(const std::vector<Page>& order, std::size_t k);

/// A page as a Doxygen comment block (.dox): Doxygen gives such a page its own id as file
/// name and no empty "File Reference" page, as it does for a .md input. Every line gets the
/// comment decoration "* ", which Doxygen strips, so a line that starts with *emphasis* keeps
/// its first star.
std::string asDoxComment(const std::string& page, const std::string& file);

// ---- the summary at the top of a section page ----------------------------------------------

/// The cells of a Markdown table row; a '|' inside a formula, a code span or @test{..} (test
/// names hold |C|) does not split.
std::vector<std::string> tableCells(const std::string& row);

/// A short summary for the top of a page, from its claims table (the first table after a
/// heading that starts with "Claims", whose heading carries the anchor {#id}): each claim of
/// the notes with its verdict (measured values cited by @{key} are substituted later, with the
/// rest of the page). Empty if the page has no claims table.
std::string claimsSummary(const std::string& page);

// ---- listing captions -----------------------------------------------------------------------

/// The first and last line (1-based) of the code between the "//! [name]" markers of a source
/// text, as \snippet shows it; {0, 0} if the snippet is not there.
std::pair<int, int> snippetRange(const std::string& text, const std::string& name);

/// Puts above each "\snippet file name" line of a page a caption naming the file and the
/// line range, linked to that line of the source browser. `source` reads a file of the
/// edition's sources ("" if absent).
template <class Source>
std::string withListingCaptions(const std::string& page, Source source) {
  std::string out;
  for (const std::string& l : splitLines(page)) {
    std::istringstream w(l);
    std::string cmd, file, name;
    w >> cmd >> file >> name;
    if (cmd == "\\snippet" && !name.empty()) {
      const auto [a, b] = snippetRange(source(file), name);
      if (a > 0) {
        char range[64];
        std::snprintf(range, sizeof range, "lines %d&ndash;%d", a, b);
        out += "\\htmlonly[block]<div class=\"listingcaption\"><a href=\"" + sourcePage(file) + "#" +
               lineAnchor(a) + "\"><code>" + htmlText(file) + "</code>, " + range + "</a></div>\\endhtmlonly\n";
      }
    }
    out += l + "\n";
  }
  return out;
}

}  // namespace booktool
