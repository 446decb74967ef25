// A piece of the book tool (book_tool.h lists them all):
// substituting: @{key} by its value, @test{name} by a link to the test; the claims page.
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

namespace booktool {

/// Replaces @{key} by its value and @test{name} by a link to the test; every unknown key or
/// test name is reported as "<file>:<line>: ..." in `errors`.
std::string substitute(const std::string& text, const std::string& file,
                       const std::map<std::string, std::pair<std::string, std::string>>& values,
                       const std::map<std::string, TestCase>& tests,
                       std::vector<std::string>& errors);

/// The claims index page (Markdown for Doxygen): one table per section, as raw HTML.
std::string claimsPage(const std::vector<TestCase>& tests, const std::string& id,
                       const std::string& title);

}  // namespace booktool
