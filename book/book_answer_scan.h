// A piece of the book tool (book_tool.h lists them all):
// the answer scan: no line of an answer in a page or source the student edition shows.
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

#include "book_rendered_check.h"

namespace booktool {

/// What an exercise's answer consists of, for the edition check: its source lines (of its
/// code regions, and of the .cpp snippets its page blocks quote) that appear nowhere else in
/// the sources, the plain prose lines of its page blocks, and the values they list.
struct AnswerKey {
  std::set<std::string> lines;   // squeezed
  std::set<std::string> values;
  std::set<std::string> phrases;  // lower case, looked for case-insensitively
  std::set<std::pair<std::string, std::string>> snippets;  // (file, name) its blocks quote
};

/// True for a line of prose with no markup at all, long enough to be the answer's own words.
bool plainProse(const std::string& s);

/// The answer keys of every exercise, from the sources (`code`: file -> text of code/ and
/// tests/; `pages`: file -> text of book/*.md).
std::map<std::string, AnswerKey> answerKeys(const std::map<std::string, std::string>& code,
                                            const std::map<std::string, std::string>& pages);

/// The .cpp snippets that answer blocks quote must differ between the editions: a snippet
/// the student's sources show exactly as the teacher's holds an unmarked answer.
std::vector<std::string> snippetLeaks(const std::map<std::string, AnswerKey>& keys,
                                      const std::map<std::string, std::string>& code);

/// The edition check: for every exercise, none of its answer's lines and values in the
/// student text, all of them in the teacher text (both squeezed, all pages joined), and an
/// answer for every exercise of `ids`. Returns one message per defect.
std::vector<std::string> editionLeaks(const std::map<std::string, AnswerKey>& keys,
                                      const std::vector<std::string>& ids,
                                      const std::string& student, const std::string& teacher);

}  // namespace booktool
