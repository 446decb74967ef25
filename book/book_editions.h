// A piece of the book tool (book_tool.h lists them all):
// the editions: solution blocks dropped (student) or framed (teacher).
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

// ---- editions -------------------------------------------------------------------------------
// One source, two books. A solution is marked once: in C++ between the comment lines
// "// BEGIN SOLUTION <id>" and "// END SOLUTION <id>" ("(remove)" after the id: a helper the
// student's stub does not need), in a page between the lines "<!-- BEGIN SOLUTION <id> -->"
// and "<!-- END SOLUTION <id> -->" (scripts/exercise.sh reads the same markers). The student
// edition drops every marked block (C++: the stub scripts/exercise.sh gives a student), the
// teacher edition keeps it and labels it as an answer; the markers themselves are never shown.

enum class Edition { Student, Teacher };

Edition editionNamed(const std::string& s);

/// A marker line: `word` is "BEGIN" or "END"; `md` selects the page form (an HTML comment)
/// instead of the C++ comment. Sets the exercise id and whether the region is "(remove)".
bool solutionMarker(const std::string& line, const std::string& word, bool md,
                    std::string& id, bool& remove);

/// One marked solution block of a file: its exercise, first line (of the BEGIN marker) and
/// the lines between the markers.
struct SolutionBlock {
  std::string id, file;
  int line = 0;
  bool md = false;
  std::vector<std::string> lines;
};

std::vector<std::string> splitLines(const std::string& text);

/// The solution blocks of a file (a page if `md`); an END without its BEGIN, a block left
/// open or a nested block is an error naming the file and line.
std::vector<SolutionBlock> solutionBlocks(const std::string& text, const std::string& file,
                                          bool md);

/// A source file as an edition shows it. Student: a block becomes the one line the student's
/// stub has (scripts/exercise.sh start), a "(remove)" block nothing at all, so a listing shows
/// no gap where an answer was (the student edition's claims index reads these copies, so its
/// line links stay right). Teacher: the lines stay, the markers become comments that say
/// "answer", so line numbers match the repository.
std::string editionCode(const std::string& text, const std::string& file, Edition ed);

/// A page as an edition shows it. Student: blocks dropped. Teacher: each block framed as the
/// answer to its exercise. Lines "<!-- values: a | b -->" inside a block (the answer's
/// distinctive values, for the edition check) are dropped in both. A line
/// "<!-- student: TEXT -->" outside the blocks is TEXT in the student's edition and nothing in
/// the teacher's: where a block shows a full table, the student's edition shows the version
/// without the answer (e.g. "\htmlinclude table_brio_student.html").
std::string editionPage(const std::string& text, const std::string& file, Edition ed);

/// The student edition's text for a link to the solutions page, which it does not have:
/// `\ref solutions "the solutions page"` becomes "the solutions page (teacher's edition)".
std::string studentLinks(const std::string& page);

/// The distinctive values an answer block lists ("<!-- values: 36n | 16n -->"), or with
/// `what` = "phrases", its key phrases ("<!-- phrases: away from the apex -->"): the words a
/// paraphrase of the answer would keep.
std::vector<std::string> blockValues(const SolutionBlock& b, const std::string& what = "values");

/// Whitespace runs as one space, ends trimmed: how text is compared across HTML and sources.
std::string squeeze(const std::string& s);

/// The lines between "//! [name]" markers of a source text (empty if the snippet is absent).
std::vector<std::string> snippetLines(const std::string& text, const std::string& name);

}  // namespace booktool
