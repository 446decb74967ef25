// A piece of the book tool (book_tool.h lists them all):
// the prose check: no measured number typed in a page; the bounds named in the tests.
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

// ---- the prose check (on the page sources) ------------------------------------------------
// A number a reader meets in prose must come from a program (@{key}) or be a formula, code,
// or a number of an allow-list entry (book/prose_numbers.txt: a section number, a
// mathematical constant, ...), each with its reason. Project jargon fails too.

/// One allowed form of a number in prose: a regular expression that the whole word (or the
/// word with the one before or after it: "Listing 2.5", "15 cm") must match, and why such a
/// number may be typed.
struct AllowedNumber {
  std::string pattern, reason;
};

/// Parses book/prose_numbers.txt: "regex | reason" lines, '#' comments; an entry without a
/// reason is an error.
std::vector<AllowedNumber> readAllowedNumbers(const std::string& text, const std::string& file);

/// The prose of a page source: code (fenced and inline), formulas, @{..}/@test{..}, commands
/// with file or anchor arguments, HTML tags and comments are blanked (newlines kept, so line
/// numbers stay right).
std::string proseOnly(const std::string& page);

/// Defects of a page's prose: a word holding a digit that no allow-list entry admits, and the
/// project's jargon ("issue N", "session", "helper"), each as "file:line: what".
std::vector<std::string> proseDefects(const std::string& page, const std::string& file,
                                      const std::vector<AllowedNumber>& allowed);

// ---- bounds named in the tests --------------------------------------------------------------

/// The bounds a test compares with, named for the book: a line of a test file that ends with
/// "// book: <key>" gives <key> the last number literal before the comment ("CHECK(a > 0.38);
/// // book: s234.bound_exp_lo" -> 0.38). The prose cites @{<key>}: the bound it states is then
/// the very number the test compares with. A key without a number is an error.
void testBounds(const std::string& text, const std::string& file,
                std::map<std::string, std::pair<std::string, std::string>>& out);

}  // namespace booktool
