#include "book_prose_check.h"

#include "book_rendered_check.h"
#include "book_editions.h"

namespace booktool {

std::vector<AllowedNumber> readAllowedNumbers(const std::string& text, const std::string& file) {
  std::vector<AllowedNumber> out;
  int n = 0;
  for (const std::string& raw : splitLines(text)) {
    ++n;
    std::string l = raw;
    if (!l.empty() && l.back() == '\r') l.pop_back();
    if (l.find_first_not_of(" \t") == std::string::npos || l[l.find_first_not_of(" \t")] == '#') continue;
    const std::size_t bar = l.find(" | ");
    if (bar == std::string::npos || squeeze(l.substr(bar + 3)).empty())
      throw std::runtime_error(file + ":" + std::to_string(n) + ": expected 'regex | reason'");
    out.push_back({squeeze(l.substr(0, bar)), squeeze(l.substr(bar + 3))});
  }
  return out;
}

std::string proseOnly(const std::string& page) {
  std::string s = page;
  auto blank = [&](std::size_t a, std::size_t b) {
    for (std::size_t k = a; k < b && k < s.size(); ++k)
      if (s[k] != '\n') s[k] = ' ';
  };
  auto blankBetween = [&](const std::string& open, const std::string& close, bool nestBraces) {
    std::size_t i = 0;
    while ((i = s.find(open, i)) != std::string::npos) {
      std::size_t end;
      if (nestBraces) {
        int depth = 0;
        end = std::string::npos;
        for (std::size_t k = i + open.size() - 1; k < s.size(); ++k) {
          if (s[k] == '{') ++depth;
          else if (s[k] == '}' && --depth == 0) { end = k + 1; break; }
        }
      } else {
        end = s.find(close, i + open.size());
        if (end != std::string::npos) end += close.size();
      }
      if (end == std::string::npos) end = s.size();
      blank(i, end);
      i = end;
    }
  };
  // Fenced code blocks.
  {
    std::size_t i = 0;
    bool fenced = false;
    std::size_t start = 0;
    while (i < s.size()) {
      std::size_t eol = s.find('\n', i);
      if (eol == std::string::npos) eol = s.size();
      const std::size_t first = s.find_first_not_of(" \t", i);
      const bool fence = first < eol && (s.compare(first, 3, "```") == 0 || s.compare(first, 3, "~~~") == 0);
      if (fence) {
        if (!fenced) start = i;
        else blank(start, eol);
        fenced = !fenced;
      }
      i = eol + 1;
    }
  }
  blankBetween("<!--", "-->", false);
  blankBetween("\\htmlonly", "\\endhtmlonly", false);
  blankBetween("\\f$", "\\f$", false);
  blankBetween("\\f[", "\\f]", false);
  blankBetween("\\f{", "\\f}", false);
  blankBetween("@test{", "", true);
  blankBetween("@{", "", true);
  blankBetween("{#", "}", false);
  // Quotations (of the notes, mostly) are quoted as printed, numbers included.
  blankBetween("“", "”", false);
  {
    std::size_t i = 0;
    while ((i = s.find('"', i)) != std::string::npos) {
      const std::size_t end = s.find('"', i + 1);
      if (end == std::string::npos || s.find('\n', i) < end) { ++i; continue; }
      blank(i, end + 1);
      i = end + 1;
    }
  }
  // Inline code spans.
  {
    std::size_t i = 0;
    while ((i = s.find('`', i)) != std::string::npos) {
      const std::size_t end = s.find('`', i + 1);
      if (end == std::string::npos) break;
      blank(i, end + 1);
      i = end + 1;
    }
  }
  // HTML tags (their attributes hold file names and sizes).
  {
    std::size_t i = 0;
    while ((i = s.find('<', i)) != std::string::npos) {
      const std::size_t end = s.find('>', i);
      if (end == std::string::npos || s.find('\n', i) < end) { ++i; continue; }
      if (end > i + 1 && (std::isalpha(static_cast<unsigned char>(s[i + 1])) || s[i + 1] == '/')) blank(i, end + 1);
      i = end + 1;
    }
  }
  // Commands whose arguments are names, not prose: the whole line, or the argument.
  for (const char* cmd : {"\\snippet", "\\image", "\\htmlinclude", "\\include", "\\anchor", "\\ref", "\\subpage", "\\page"}) {
    std::size_t i = 0;
    const std::string c = cmd;
    while ((i = s.find(c, i)) != std::string::npos) {
      std::size_t end = i + c.size();
      const bool wholeLine = c == "\\snippet" || c == "\\image" || c == "\\htmlinclude" || c == "\\include";
      if (wholeLine) {
        end = s.find('\n', i);
        if (end == std::string::npos) end = s.size();
      } else {
        while (end < s.size() && s[end] == ' ') ++end;
        while (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end]))) ++end;
      }
      blank(i, end);
      i = end;
    }
  }
  // Addresses.
  for (const char* scheme : {"http://", "https://"}) {
    std::size_t i = 0;
    while ((i = s.find(scheme, i)) != std::string::npos) {
      std::size_t end = i;
      while (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end])) && s[end] != ')') ++end;
      blank(i, end);
      i = end;
    }
  }
  return s;
}

std::vector<std::string> proseDefects(const std::string& page, const std::string& file,
                                      const std::vector<AllowedNumber>& allowed) {
  std::vector<std::regex> res;
  for (const AllowedNumber& a : allowed) res.emplace_back(a.pattern);
  std::vector<std::string> out;
  const std::vector<std::string> lines = splitLines(proseOnly(page));
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::string where = file + ":" + std::to_string(k + 1) + ": ";
    const std::string lo = lower(lines[k]);
    // Jargon of the project's own workflow, which a reader cannot follow.
    for (std::size_t at = lo.find("issue "); at != std::string::npos; at = lo.find("issue ", at + 1))
      if (at + 6 < lo.size() && std::isdigit(static_cast<unsigned char>(lo[at + 6])))
        out.push_back(where + "project jargon 'issue N': " + squeeze(lines[k]));
    for (const char* word : {"session", "helper"})
      if (lo.find(word) != std::string::npos)
        out.push_back(where + "project jargon '" + word + "': " + squeeze(lines[k]));
    // Words with a digit.
    std::vector<std::string> words;
    {
      std::istringstream w(lines[k]);
      std::string x;
      while (w >> x) words.push_back(x);
    }
    std::string prev;
    for (std::size_t wi = 0; wi < words.size(); ++wi) {
      std::string t = words[wi];
      // Punctuation around the word: ASCII, and the typographic quotes (UTF-8, whole).
      const std::string punct = ".,;:()[]\"'!?*";
      const auto trim = [&] {
        bool again = true;
        while (again && !t.empty()) {
          again = false;
          if (punct.find(t.back()) != std::string::npos) { t.pop_back(); again = true; }
          else if (punct.find(t.front()) != std::string::npos) { t.erase(0, 1); again = true; }
          for (const char* q : {"“", "”", "‘", "’", "'s", "’s"}) {
            const std::string qs = q;
            if (t.size() >= qs.size() && t.compare(t.size() - qs.size(), qs.size(), qs) == 0) { t.erase(t.size() - qs.size()); again = true; }
            else if (qs[0] != '\'' && t.compare(0, qs.size(), qs) == 0 && qs != "’s") { t.erase(0, qs.size()); again = true; }
          }
        }
      };
      trim();
      bool digit = false;
      for (char c : t) digit = digit || std::isdigit(static_cast<unsigned char>(c));
      // Superscript digits (10⁸) count as digits too.
      for (const char* sup : {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"}) digit = digit || t.find(sup) != std::string::npos;
      if (digit) {
        bool ok = false;
        // The word alone, with the word before it ("Listing 2.5") or after it ("15 cm").
        const std::string pair = prev + " " + t;
        const std::string next = wi + 1 < words.size() ? t + " " + words[wi + 1] : t;
        for (const std::regex& r : res)
          ok = ok || std::regex_match(t, r) || std::regex_match(pair, r) || std::regex_match(next, r);
        if (!ok) out.push_back(where + "a number typed in prose, '" + t + "' (cite a program's @{key}, write it as a formula, or add it to book/prose_numbers.txt with its reason)");
      }
      prev = t;
    }
  }
  return out;
}

void testBounds(const std::string& text, const std::string& file,
                std::map<std::string, std::pair<std::string, std::string>>& out) {
  int n = 0;
  for (const std::string& l : splitLines(text)) {
    ++n;
    const std::size_t at = l.find("// book: ");
    if (at == std::string::npos) continue;
    const std::string key = squeeze(l.substr(at + 9));
    // Only "key" alone to the end of the line (letters, digits, '_' and '.') is a name; the
    // same text inside a string literal, as in test_book.cpp, is not.
    bool name = !key.empty();
    for (char c : key) name = name && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.');
    if (!name) continue;
    const std::string code = l.substr(0, at);
    std::string last;
    for (std::size_t i = 0; i < code.size(); ++i) {
      const bool start = std::isdigit(static_cast<unsigned char>(code[i])) &&
                         (i == 0 || !(std::isalnum(static_cast<unsigned char>(code[i - 1])) || code[i - 1] == '_' || code[i - 1] == '.'));
      if (!start) continue;
      std::size_t j = i;
      while (j < code.size() && (std::isdigit(static_cast<unsigned char>(code[j])) || code[j] == '.')) ++j;
      last = code.substr(i, j - i);
      i = j;
    }
    const std::string where = file + ":" + std::to_string(n) + ": ";
    if (key.empty() || last.empty()) throw std::runtime_error(where + "'// book:' needs a key and a number on its line");
    if (out.count(key)) throw std::runtime_error(where + "key '" + key + "' is also written by " + out[key].second);
    out[key] = {last, file + ":" + std::to_string(n)};
  }
}

}  // namespace booktool
