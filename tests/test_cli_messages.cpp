/// \file test_cli_messages.cpp What delaunay2d's messages name: the notes on merged duplicates (the first ten one by one with their lines, the rest counted, whatever their number) and the line of the point that --method super cannot enclose.
#include <doctest/doctest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "support.h"

namespace {

// The lines of `err` that name a merged duplicate, and the summary line of the rest ("" if none).
struct Notes {
  std::vector<std::string> named;
  std::string rest;
};
Notes notesOf(const std::string& err) {
  Notes n;
  std::istringstream in(err);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find(" duplicates point ") != std::string::npos) n.named.push_back(line);
    if (line.find(" more duplicate points merged ") != std::string::npos) n.rest = line;
  }
  return n;
}

}  // namespace

TEST_CASE("cli messages delaunay2d names ten merged duplicates and counts the others for 10 11 and 13 copies") {
  // Four distinct points (lines 1-4), then `copies` copies of the second one (line 2).
  for (int copies : {10, 11, 13}) {
    CAPTURE(copies);
    const std::string in = dttest::tmpPath("many_dups.xy"), out = dttest::tmpPath("many_dups_out");
    std::string text = "0 0\n1 0\n0 1\n1 1\n";
    for (int c = 0; c < copies; ++c) text += "1 0\n";
    dttest::writeText(in, text);
    const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "'");
    REQUIRE(r.status == 0);
    const Notes n = notesOf(r.err);
    REQUIRE(n.named.size() == 10);
    for (int k = 0; k < 10; ++k) {
      const std::string want = in + ":" + std::to_string(5 + k) + ": point " + std::to_string(5 + k) +
                               " duplicates point 2 (line 2); merged";
      CHECK(dttest::contains(n.named[std::size_t(k)], want));
    }
    if (copies == 10) {
      CHECK(n.rest.empty());
    } else {
      CHECK(dttest::contains(n.rest, in + ": " + std::to_string(copies - 10) +
                                         " more duplicate points merged (" + std::to_string(copies) + " in all)"));
    }
    // Point 15 and later are never named.
    CHECK_FALSE(dttest::contains(r.err, "point 15 duplicates"));
    CHECK(dttest::readText(out + ".ele").rfind("2 3 0", 0) == 0);  // two triangles
  }
}

TEST_CASE("cli messages delaunay2d --method super names the line of the point too close to overflow") {
  // Comments and blank lines make line numbers differ from point numbers; of two points near
  // the overflow threshold the farther one is named, wherever it stands in the file.
  struct Case {
    const char* text;
    int line;
  };
  const Case cases[] = {
      {"# near the overflow threshold\n0 0\n1 0\n\n-1.5e308 1\n0 1\n# the farthest:\n1.7976931348623157e308 -2\n1 1\n", 8},
      {"0 0\n\n-1.7976931348623157e308 0\n# a nearer one:\n1.7e308 1.7e308\n1 0\n0 1\n", 3},
  };
  for (const Case& c : cases) {
    CAPTURE(c.line);
    const std::string in = dttest::tmpPath("overflow_super.xy"), out = dttest::tmpPath("overflow_super_out");
    std::remove((out + ".ele").c_str());
    dttest::writeText(in, c.text);
    const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --method super");
    CHECK(r.status == 2);
    CHECK_MESSAGE(dttest::contains(r.err, in + ":" + std::to_string(c.line) + ": --method super cannot enclose"), r.err);
    CHECK_FALSE(dttest::fileExists(out + ".ele"));
  }
}
