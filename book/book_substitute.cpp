#include "book_substitute.h"

namespace booktool {

std::string substitute(const std::string& text, const std::string& file,
                       const std::map<std::string, std::pair<std::string, std::string>>& values,
                       const std::map<std::string, TestCase>& tests,
                       std::vector<std::string>& errors) {
  std::string out;
  std::size_t i = 0;
  int line = 1;
  while (i < text.size()) {
    const bool val = text.compare(i, 2, "@{") == 0;
    const bool tst = text.compare(i, 6, "@test{") == 0;
    if (!val && !tst) {
      if (text[i] == '\n') ++line;
      out += text[i++];
      continue;
    }
    const std::size_t open = i + (val ? 2 : 6);
    // The closing brace at depth 0: a test name may hold braces (DT_{n+1}).
    std::size_t close = std::string::npos;
    for (std::size_t k = open, depth = 0; k < text.size() && text[k] != '\n'; ++k) {
      if (text[k] == '{') ++depth;
      else if (text[k] == '}' && depth-- == 0) {
        close = k;
        break;
      }
    }
    const std::size_t eol = text.find('\n', open);
    if (close == std::string::npos || (eol != std::string::npos && close > eol)) {
      errors.push_back(file + ":" + std::to_string(line) + ": " + (val ? "@{" : "@test{") +
                       " is not closed on its line");
      out += text[i++];
      continue;
    }
    std::string key = text.substr(open, close - open);
    // "@{key|fallback}": the fallback text where no program wrote the key (the run summary's
    // timings exist only after the main command has run).
    std::string fallback;
    bool hasFallback = false;
    if (val && key.find('|') != std::string::npos) {
      fallback = key.substr(key.find('|') + 1);
      key = key.substr(0, key.find('|'));
      hasFallback = true;
    }
    if (val) {
      auto it = values.find(key);
      if (it == values.end() && hasFallback) {
        out += fallback;
      } else if (it == values.end()) {
        errors.push_back(file + ":" + std::to_string(line) + ": unknown value key '" + key +
                         "' (no chapter program wrote it)");
      } else {
        out += it->second.first;
      }
    } else {
      auto it = tests.find(key);
      if (it == tests.end()) {
        errors.push_back(file + ":" + std::to_string(line) + ": cites the test \"" + key +
                         "\", which no TEST_CASE in tests/ has");
      } else {
        out += testLink(it->second);
      }
    }
    i = close + 1;
  }
  return out;
}

std::string claimsPage(const std::vector<TestCase>& tests, const std::string& id,
                       const std::string& title) {
  std::map<std::string, std::vector<const TestCase*>> bySection;
  for (const TestCase& t : tests) {
    std::string s = sectionOf(t.name);
    bySection[s.empty() ? "~" + t.file : s].push_back(&t);
  }
  std::ostringstream o;
  o << "\\page " << id << " " << title << "\n\n"
    << "Every test of the repository, generated from the `TEST_CASE` lines of the files in `tests/` when\n"
    << "the book is built. A test's name is its section and the claim it checks. The link goes to\n"
    << "the test's source line; the command runs that test alone, from the repository's root after\n"
    // Commands as raw HTML: Markdown would read the stars of a pattern as emphasis and
    // Doxygen turns "--" into an en dash, and a pasted command must work.
    << "the build (\\htmlonly<code>bash scripts/main.sh</code>\\endhtmlonly, or "
       "\\htmlonly<code>cmake &#45;&#45;build build</code>\\endhtmlonly). "
       "\\htmlonly<code>build/dt_tests -sf=&quot;&#42;test_2_3_4&#42;&quot;</code>\\endhtmlonly\n"
    << "runs the tests of the files whose name matches the pattern; "
       "\\htmlonly<code>ctest &#45;&#45;test-dir build</code>\\endhtmlonly runs them all, one entry per file.\n\n"
    << "\\tableofcontents\n\n";
  for (const auto& [section, list] : bySection) {
    const bool numbered = section[0] != '~';
    const std::string heading = numbered ? "Section " + section : "Tests of " + section.substr(1);
    std::string anchor = "claims_";
    for (char c : heading) anchor += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    o << "# " << heading << " {#" << anchor << "}\n\n";
    o << "\\htmlonly[block]\n<table class=\"claims\">\n<tr><th>Claim</th><th>Test, at its source line</th>"
         "<th>Run it</th></tr>\n";
    for (const TestCase* t : list) {
      std::string claim = t->name.substr(numbered ? section.size() : 0);
      claim.erase(0, claim.find_first_not_of(" :"));
      const std::string base = t->file.substr(t->file.rfind('/') + 1);
      o << "<tr><td><a id=\"" << claimAnchor(t->name) << "\"></a><span class=\"testname\">"
        << htmlText(claim) << "</span></td><td><a href=\"" << sourcePage(t->file) << "#" << lineAnchor(t->line)
        << "\" class=\"testlink\">" << htmlText(base) << ":" << t->line
        << "</a></td><td><code>build/dt_tests -tc=&quot;" << htmlText(t->name)
        << "&quot;</code></td></tr>\n";
    }
    o << "</table>\n\\endhtmlonly\n\n";
  }
  return o.str();
}

}  // namespace booktool
