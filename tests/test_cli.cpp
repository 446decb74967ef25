/// \file test_cli.cpp End-to-end tests of the command-line triangulator delaunay2d: degenerate
/// families validated exactly from the written .ele, and bad input rejected cleanly.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>

#include "support.h"

using dt::XY;

namespace {

// Runs the CLI on p and validates out.ele exactly; every distinct point must be a vertex.
void runAndValidate(const std::string& name, const XY& p, int first = 1) {
  const std::string in = dttest::tmpPath(name + ".node"), out = dttest::tmpPath(name + "_out");
  std::remove((out + ".ele").c_str());
  dttest::writeText(in, dttest::nodeText(p, first));
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --stats");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto tri = dttest::readEle(out + ".ele", first);
  // Points equal to an earlier one are merged: they must not be used, the others must.
  std::map<std::pair<double, double>, int> firstSeen;
  std::vector<char> must(p.size() / 2, 0);
  for (std::size_t i = 0; i < p.size() / 2; ++i)
    if (firstSeen.emplace(std::make_pair(p[2 * i], p[2 * i + 1]), int(i)).second) must[i] = 1;
  int outOfRange = 0, mergedUsed = 0;
  for (const auto& t : tri)
    for (int v : t) {
      if (v < 0 || v >= int(must.size())) ++outOfRange;
      else if (!must[v]) ++mergedUsed;
    }
  REQUIRE(outOfRange == 0);
  CHECK_MESSAGE(mergedUsed == 0, "a merged duplicate is used by a triangle");
  const dt::CheckReport c = dt::checkDelaunay(p, tri, &must);
  CHECK_MESSAGE(c.ok, name << ": " << c.error);
  CHECK(r.out.find("points: " + std::to_string(p.size() / 2)) != std::string::npos);
  CHECK(r.out.find("triangles: " + std::to_string(tri.size())) != std::string::npos);
  CHECK(r.out.find("triangulation_seconds: ") != std::string::npos);
}

}  // namespace

TEST_CASE("cli delaunay2d writes the exact DT(S) on degenerate families") {
  runAndValidate("grid", dt::gridPoints(30, 30));
  // an integer grid rotated by an angle with rational cos and sin (3/5, 4/5)
  runAndValidate("grid_rotated", dt::rotatedGridPoints(20, 20));
  runAndValidate("circle", dt::circlePoints(400));
  XY col;
  for (int i = 0; i < 300; ++i) {
    col.push_back(i);
    col.push_back(2.0 * i);
  }
  col.insert(col.end(), {10, 0, 100, 500, 299, 0});
  runAndValidate("collinear", col, 0);
  XY dup = dt::uniformPoints(500, 9);
  for (int i = 0; i < 100; ++i) {
    dup.push_back(dup[2 * (i * 3)]);
    dup.push_back(dup[2 * (i * 3) + 1]);
  }
  runAndValidate("duplicates", dup);
  runAndValidate("big", dt::uniformPoints(3000, 2, 1e9, 1e9 + 1));
  runAndValidate("tiny", dt::uniformPoints(3000, 3, 1e-200, 2e-200));
  runAndValidate("convex", dt::circlePoints(1000, 1e6));
  XY sorted = dt::uniformPoints(5000, 4);
  std::vector<std::pair<double, double>> v;
  for (std::size_t i = 0; i < sorted.size() / 2; ++i) v.emplace_back(sorted[2 * i], sorted[2 * i + 1]);
  std::sort(v.begin(), v.end());
  for (std::size_t i = 0; i < v.size(); ++i) {
    sorted[2 * i] = v[i].first;
    sorted[2 * i + 1] = v[i].second;
  }
  runAndValidate("sorted_by_x", sorted);
}

TEST_CASE("cli delaunay2d merges duplicates into the first number and reports them") {
  const std::string in = dttest::tmpPath("dups.xy"), out = dttest::tmpPath("dups_out");
  dttest::writeText(in, "0 0\n1 0\n0 1\n1 0\n1 1\n");
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "'");
  REQUIRE(r.status == 0);
  CHECK(r.err.find("point 4 duplicates point 2") != std::string::npos);
  const std::string ele = dttest::readText(out + ".ele");
  CHECK(ele.find(" 4") == std::string::npos);  // point 4 is used by no triangle
  CHECK(ele.rfind("2 3 0", 0) == 0);            // header: two triangles
}

TEST_CASE("cli delaunay2d answers bad input with a message naming the problem and exit 2 and no output") {
  struct Bad {
    const char* name;
    const char* text;
    const char* expect;  // a piece of the message
  };
  const Bad cases[] = {
      {"malformed.node", "3 2 0 0\n1 0 0\n2 1 zero\n3 0 1\n", "malformed.node:3: y 'zero' is not a number"},
      {"count.node", "4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n", "of the 4 points announced"},
      {"nan.xy", "0 0\n1 0\nnan 1\n", "nan.xy:3: x 'nan' is NaN"},
      {"inf.xy", "0 0\n1 0\n0 1e999\n", "nan"},
      {"two.xy", "0 0\n1 1\n0 0\n", "fewer than 3 distinct points"},
      {"line.xy", "0 0\n1 1\n2 2\n3 3\n", "all points are collinear"},
  };
  for (const Bad& b : cases) {
    CAPTURE(b.name);
    const std::string in = dttest::tmpPath(b.name), out = dttest::tmpPath(std::string(b.name) + "_out");
    std::remove((out + ".ele").c_str());
    dttest::writeText(in, b.text);
    const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "'");
    CHECK(r.status == 2);
    if (std::string(b.name) == "inf.xy")
      CHECK(r.err.find("inf.xy:3: y '1e999' overflows a double") != std::string::npos);
    else
      CHECK_MESSAGE(r.err.find(b.expect) != std::string::npos, r.err);
    CHECK_FALSE(dttest::fileExists(out + ".ele"));
  }
  const dttest::CliResult r = dttest::runCli("'" + dttest::tmpPath("does_not_exist.node") + "' -o x");
  CHECK(r.status == 2);
  CHECK(r.err.find("cannot open") != std::string::npos);
}
