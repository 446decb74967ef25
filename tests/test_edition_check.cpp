/// \file test_edition_check.cpp The edition check of the book tool (booktool::editionLeaks) on planted editions: an answer shown to the student and an answer missing from the teacher's edition are each reported, by line and by value, and clean editions pass.
#include <doctest/doctest.h>

#include <map>
#include <string>
#include <vector>

#include "../book/book_tool.h"

namespace {

bool mentions(const std::vector<std::string>& v, const std::string& what) {
  for (const std::string& s : v)
    if (s.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("edition check a planted answer in the student edition and one missing from the teacher's are reported") {
  std::map<std::string, booktool::AnswerKey> keys;
  keys["9.9-1"].lines = {"return count * 3 - hull;"};
  keys["9.9-1"].values = {"6n - 3h"};
  const std::vector<std::string> ids = {"9.9-1"};
  const std::string neutral = "The exercise asks for the number of edges.\n";
  const std::string withAnswer = neutral + "return count * 3 - hull;\nSo n_e = 6n - 3h here.\n";
  // Clean: the student sees neither, the teacher both.
  CHECK(booktool::editionLeaks(keys, ids, neutral, withAnswer).empty());
  // The student edition shows the line and the value: both reported.
  const auto leak = booktool::editionLeaks(keys, ids, withAnswer, withAnswer);
  CHECK(mentions(leak, "9.9-1: the student edition shows the answer's line 'return count * 3 - hull;'"));
  CHECK(mentions(leak, "9.9-1: the student edition shows the answer's value '6n - 3h'"));
  // The teacher edition lacks them: both reported.
  const auto lack = booktool::editionLeaks(keys, ids, neutral, neutral);
  CHECK(mentions(lack, "9.9-1: the teacher edition lacks the answer's line 'return count * 3 - hull;'"));
  CHECK(mentions(lack, "9.9-1: the teacher edition lacks the answer's value '6n - 3h'"));
  CHECK(lack.size() == 2);
  // An exercise with no marked answer at all is reported too.
  CHECK(mentions(booktool::editionLeaks({}, ids, neutral, withAnswer), "9.9-1: no marked answer"));
}
