// A piece of the book tool (book_tool.h lists them all):
// the rendered check: literal markup a reader sees in the HTML, broken links.
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

namespace booktool {

// ---- the rendered check -------------------------------------------------------------------

struct Defect {
  std::string what;
  std::string context;
};

std::string lower(std::string s);

/// The text of some HTML: tags removed; a block-level tag (paragraph, item, cell, ...)
/// becomes a space, since the reader sees a break there.
std::string stripTags(const std::string& s);

/// Removes every element that opens with `open` (e.g. "<pre") up to its matching `close`,
/// counting nested elements of the same tag.
std::string dropElements(const std::string& html, const std::string& open,
                         const std::string& tag);

std::string decodeEntities(const std::string& s);

/// Replaces each MathJax formula's source (\(..\), \[..\], \begin{..}..\end{..}) by `with`.
std::string replaceMath(const std::string& s, const std::string& with);

/// The part of a Doxygen page a reader reads: from the title to the footer.
std::string readableRegion(const std::string& html);

/// True for a page of the book (book_tool gives each one its navigation bar); the API
/// reference's pages quote C++ signatures and comments, where * and _{ are code.
bool isBookPage(const std::string& html);

/// Everything on a rendered page that a reader should not see: markup Doxygen left as typed
/// (outside code and formulas) and unsubstituted @{..} or @test{..}. Whether tables and
/// figures fit the column is measured in a browser (book/layout_check.sh). On pages of the
/// API reference only unprocessed commands count.
std::vector<Defect> renderedDefects(const std::string& html);

/// Local links (href="file#anchor") of a page whose file or anchor does not exist; `exists`
/// answers for a file name, `anchors` gives the ids of a file.
template <class Exists, class Anchors>
std::vector<Defect> brokenLinks(const std::string& html, Exists exists, Anchors anchors) {
  std::vector<Defect> out;
  std::size_t i = 0;
  const std::string region = readableRegion(html);
  while ((i = region.find("href=\"", i)) != std::string::npos) {
    i += 6;
    const std::size_t end = region.find('"', i);
    if (end == std::string::npos) break;
    const std::string href = region.substr(i, end - i);
    i = end;
    if (href.empty() || href.find(':') != std::string::npos || href[0] == '/') continue;
    const std::size_t hash = href.find('#');
    const std::string file = href.substr(0, hash), anchor = hash == std::string::npos ? "" : href.substr(hash + 1);
    if (!file.empty() && !exists(file)) {
      out.push_back({"link to a missing page", href});
      continue;
    }
    if (!anchor.empty() && !file.empty() && !anchors(file).count(anchor))
      out.push_back({"link to a missing anchor", href});
  }
  return out;
}

/// The id="..." and name="..." values of a page.
std::set<std::string> anchorsOf(const std::string& html);

}  // namespace booktool
