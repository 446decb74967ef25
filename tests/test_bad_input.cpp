/// \file test_bad_input.cpp Every way a .node or xy file can be wrong, through the delaunay2d binary: one clear message naming file, line and value, exit status 2, and no output file.
#include <doctest/doctest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

#include "support.h"

namespace {

struct Bad {
  const char* name;  // file name: its extension picks the parser
  std::string text;
  const char* expect;  // a piece of the message (after "<file>")
};

// Runs the CLI on a bad file (with every output requested) and checks the contract.
void expectRefused(const Bad& b, const std::string& extra = "") {
  CAPTURE(b.name);
  const std::string in = dttest::tmpPath(b.name);
  const std::string out = dttest::tmpPath(std::string("bad_out_") + b.name);
  for (const char* ext : {".ele", ".svg", ".msh"}) std::remove((out + ext).c_str());
  dttest::writeText(in, b.text);
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --svg '" + out +
                                             ".svg' --msh '" + out + ".msh' " + extra);
  CHECK(r.status == 2);
  // The message names the file (and, in `expect`, the line and the value).
  const std::string want = "delaunay2d: " + in + b.expect;
  CHECK_MESSAGE(r.err.find(want) != std::string::npos, "expected: " << want << "\ngot: " << r.err);
  CHECK_MESSAGE(std::count(r.err.begin(), r.err.end(), '\n') == 1, "one line: " << r.err);
  CHECK(r.out.empty());
  for (const char* ext : {".ele", ".svg", ".msh"}) CHECK_FALSE(dttest::fileExists(out + ext));
}

}  // namespace

TEST_CASE("bad input a wrong or missing point count in a .node header") {
  const Bad cases[] = {
      {"count_high.node", "4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
       ":4: file ends after 3 of the 4 points announced in the header (line 1)"},
      {"count_low.node", "2 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
       ":4: extra line '3 0 1': the header (line 1) announces 2 points"},
      {"count_word.node", "three 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
       ":1: point count 'three' is not an integer"},
      {"count_real.node", "3.0 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
       ":1: point count '3.0' is not an integer"},
      {"count_negative.node", "-3 2 0 0\n", ":1: point count -3 is negative"},
      {"no_header.node", "1 0 0\n2 1 0\n3 0 1\n", ":1: dimension 0 is not 2"},
      {"xy_as_node.node", "0.5 0.25\n1 2\n", ":1: point count '0.5' is not an integer"},
      {"dimension.node", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n", ":1: dimension 3 is not 2"},
      {"markers.node", "3 2 0 2\n1 0 0 1 1\n", ":1: marker count 2 is not 0 or 1"},
      {"header_long.node", "3 2 0 0 7\n", ":1: header '3 2 0 0 7' has 5 fields"},
  };
  for (const Bad& b : cases) expectRefused(b);
}

TEST_CASE("bad input non-numeric fields or NaN or infinities or overflow or underflow") {
  const Bad cases[] = {
      {"word.node", "3 2 0 0\n1 0 0\n2 1 zero\n3 0 1\n", ":3: y 'zero' is not a number"},
      {"word.xy", "0 0\n1 0\nx1 1\n", ":3: x 'x1' is not a number"},
      {"comma.xy", "0 0\n1,5 0\n0 1\n", ":2: x '1,5' is not a number"},
      {"trailing.xy", "0 0\n1.5e 0\n0 1\n", ":2: x '1.5e' is not a number"},
      {"nan.xy", "0 0\n1 0\nnan 1\n", ":3: x 'nan' is NaN"},
      {"nan.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 -NaN\n", ":4: y '-NaN' is NaN"},
      {"inf.xy", "0 0\n1 0\n0 inf\n", ":3: y 'inf' is infinite"},
      {"minus_infinity.node", "3 2 0 0\n1 -Infinity 0\n2 1 0\n3 0 1\n",
       ":2: x '-Infinity' is infinite"},
      {"overflow.xy", "0 0\n1 0\n0 1e999\n", ":3: y '1e999' overflows a double"},
      {"underflow.xy", "0 0\n1 1e-400\n0 1\n", ":2: y '1e-400' underflows to 0"},
      {"number_word.node", "3 2 0 0\n1 0 0\nb 1 0\n3 0 1\n", ":3: point number 'b' is not an integer"},
      {"attribute.node", "3 2 1 0\n1 0 0 a\n2 1 0 1\n3 0 1 1\n", ":2: attribute 'a' is not a number"},
      {"marker.node", "3 2 0 1\n1 0 0 0.5\n2 1 0 1\n3 0 1 1\n",
       ":2: boundary marker '0.5' is not an integer"},
  };
  for (const Bad& b : cases) expectRefused(b);
}

TEST_CASE("bad input empty files or binary garbage or extra columns or odd line endings") {
  std::string binary = "\x7f" "ELF\x02\x01\x01";
  binary += '\0';
  binary += "\x03\x3e\n";
  const char withNul[] = "3 2 0 0\n1 0 0\n2 1\0 0\n3 0 1\n";
  const Bad cases[] = {
      {"empty.node", "", ": empty file"},
      {"empty.xy", "", ": empty file"},
      {"comments.xy", "# nothing here\n\n   \n", ": only blank lines and comments"},
      {"binary.xy", binary, ":1: binary or control character (code 127) at column 1"},
      {"nul.node", std::string(withNul, sizeof withNul - 1),
       ":3: binary or control character (code 0) at column 4"},
      {"latin1.xy", "0 0\n1 0\n0 1\xe9\n", ":3: y '1?' is not a number"},
      {"columns.xy", "0 0\n1 0 5\n0 1\n", ":2: '1 0 5' has 3 fields; expected 'x y'"},
      {"node_as_xy.xy", "3 2 0 0\n1 0 0\n", ":1: '3 2 0 0' has 4 fields; expected 'x y' (a .node header?"},
      {"one_column.xy", "0 0\n1\n0 1\n", ":2: '1' has 1 field; expected 'x y'"},
      {"columns.node", "3 2 0 0\n1 0 0\n2 1 0 9\n3 0 1\n",
       ":3: '2 1 0 9' has 4 fields; expected 3 (number, x, y, as the header on line 1 says)"},
      {"mac_cr.xy", "0 0\r1 0\r0 1\r", ":1: carriage return inside the line"},
  };
  for (const Bad& b : cases) expectRefused(b);
}

TEST_CASE("bad input 0-based and 1-based numbering must be consistent") {
  const Bad cases[] = {
      {"starts_at_2.node", "3 2 0 0\n2 0 0\n3 1 0\n4 0 1\n",
       ":2: first point number is 2; expected 0 or 1"},
      {"mixed_base.node", "3 2 0 0\n0 0 0\n2 1 0\n3 0 1\n",
       ":3: point number 2; expected 1 (numbers start at 0 on line 2 and follow on)"},
      {"repeated_number.node", "3 2 0 0\n1 0 0\n2 1 0\n2 0 1\n",
       ":4: point number 2; expected 3 (numbers start at 1 on line 2 and follow on)"},
  };
  for (const Bad& b : cases) expectRefused(b);
}

TEST_CASE("bad input fewer than 3 distinct points or all collinear has no triangulation") {
  const Bad cases[] = {
      {"none.node", "0 2 0 0\n", ": fewer than 3 distinct points: no triangulation exists"},
      {"one.xy", "1 1\n", ": fewer than 3 distinct points: no triangulation exists"},
      {"two_repeated.xy", "0 0\n1 1\n0 0\n1 1\n1 1\n",
       ": fewer than 3 distinct points: no triangulation exists"},
      {"collinear.xy", "0 0\n1 1\n2 2\n3 3\n", ": all points are collinear: no triangulation exists"},
      {"collinear_dups.node", "5 2 0 0\n0 0 0\n1 4 2\n2 0 0\n3 -2 -1\n4 1e-300 5e-301\n",
       ": all points are collinear: no triangulation exists"},
  };
  for (const char* method : {"hull", "super"}) {
    CAPTURE(method);
    for (const Bad& b : cases) {
      // Each input repeats a point at most; duplicates are reported on stderr first.
      const std::string in = dttest::tmpPath(b.name);
      const std::string out = dttest::tmpPath(std::string("deg_out_") + b.name);
      std::remove((out + ".ele").c_str());
      dttest::writeText(in, b.text);
      const dttest::CliResult r =
          dttest::runCli("'" + in + "' -o '" + out + "' --method " + std::string(method));
      CHECK(r.status == 2);
      CHECK_MESSAGE(r.err.find("delaunay2d: " + in + b.expect) != std::string::npos, r.err);
      CHECK_FALSE(dttest::fileExists(out + ".ele"));
    }
  }
}

TEST_CASE("bad input lookalikes are accepted: Windows line endings or a byte order mark or comments or attributes") {
  struct Good {
    const char* name;
    const char* text;
  };
  const Good cases[] = {
      {"crlf.node", "# made on Windows\r\n4 2 0 0\r\n1 0 0\r\n2 1 0\r\n3 1 1\r\n4 0 1\r\n"},
      {"crlf.xy", "0 0\r\n1 0\r\n1 1\r\n0 1\r\n"},
      {"bom.xy", "\xEF\xBB\xBF" "0 0\n1 0\n1 1\n0 1\n"},
      {"attrs.node", "4 2 2 1 # header\n0 0 0 1.5 2 1\n1 1 0 0 0 1\n\n2 1 1 3 3 0\n3 0 1 -1 1e5 1\n"},
      {"tabs.xy", "0\t0\n1\t0  \n1 1\t# corner\n0 1\n"},
  };
  for (const Good& g : cases) {
    CAPTURE(g.name);
    const std::string in = dttest::tmpPath(g.name), out = dttest::tmpPath(std::string("good_") + g.name);
    dttest::writeText(in, g.text);
    const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "'");
    CHECK_MESSAGE(r.status == 0, r.err);
    CHECK(r.err.empty());
    const int first = std::string(g.name) == "attrs.node" ? 0 : 1;
    const auto tri = dttest::readEle(out + ".ele", first);
    CHECK(tri.size() == 2);  // the unit square: two triangles
    const std::vector<double> square = {0, 0, 1, 0, 1, 1, 0, 1};
    CHECK(dt::checkDelaunay(square, tri).ok);
  }
}

TEST_CASE("bad input usage errors and unwritable output give an exit status and no partial output") {
  const std::string in = dttest::tmpPath("usage.xy"), out = dttest::tmpPath("usage_out");
  dttest::writeText(in, "0 0\n1 0\n0 1\n");
  std::remove((out + ".ele").c_str());
  dttest::CliResult r = dttest::runCli("'" + in + "'");
  CHECK(r.status == 2);
  CHECK(r.err.find("no output name (-o OUT)") != std::string::npos);
  r = dttest::runCli("'" + in + "' -o '" + out + "' --frobnicate");
  CHECK(r.status == 2);
  CHECK(r.err.find("unknown option '--frobnicate'") != std::string::npos);
  r = dttest::runCli("'" + dttest::tmpPath("no_such_file.node") + "' -o '" + out + "'");
  CHECK(r.status == 2);
  CHECK(r.err.find("no_such_file.node: cannot open file for reading") != std::string::npos);
  r = dttest::runCli("'" + std::string(DT_TEST_TMP) + "' -o '" + out + "'");
  CHECK(r.status == 2);
  CHECK(r.err.find(": is a directory") != std::string::npos);
  // The .ele can be written but the SVG cannot: nothing is left behind.
  r = dttest::runCli("'" + in + "' -o '" + out + "' --svg '" + dttest::tmpPath("no/such/dir.svg") + "'");
  CHECK(r.status == 1);
  CHECK(r.err.find("no/such/dir.svg: cannot open for writing") != std::string::npos);
  CHECK_FALSE(dttest::fileExists(out + ".ele"));
  // -o naming a directory would write DIR/.ele or DIR.ele: refused (exit 2), nothing written.
  for (const std::string& o : {std::string(DT_TEST_TMP), std::string(DT_TEST_TMP) + "/", out + "/"}) {
    CAPTURE(o);
    r = dttest::runCli("'" + in + "' -o '" + o + "'");
    CHECK(r.status == 2);
    CHECK(r.err.find(" names a directory; -o takes a base name") != std::string::npos);
    CHECK_FALSE(dttest::fileExists(std::string(DT_TEST_TMP) + "/.ele"));
    CHECK_FALSE(dttest::fileExists(std::string(DT_TEST_TMP) + ".ele"));
  }
}

TEST_CASE("bad input on standard input is named stdin and a .node header there is recognised") {
  const std::string out = dttest::tmpPath("stdin_out");
  struct Case {
    const char* text;
    const char* err;
  };
  const Case cases[] = {
      // 4 fields on the first line: a .node file, so line 3's 'zero' is its y.
      {"3 2 0 0\n1 0 0\n2 1 zero\n3 0 1\n", "delaunay2d: stdin:3: y 'zero' is not a number\n"},
      {"3 2 0 0\n1 0 0\n2 1 0\n", "delaunay2d: stdin:3: file ends after 2 of the 3 points announced "
                                   "in the header (line 1)\n"},
      // 'x y' lines otherwise.
      {"# points\n0 0\n1 0 0\n", "delaunay2d: stdin:3: '1 0 0' has 3 fields; expected 'x y'\n"},
      {"", "delaunay2d: stdin: empty file (expected 'x y' lines)\n"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.text);
    const std::string in = dttest::tmpPath("stdin_case.txt");
    dttest::writeText(in, c.text);
    std::remove((out + ".ele").c_str());
    const dttest::CliResult r = dttest::runCli("- -o '" + out + "' < '" + in + "'");
    CHECK(r.status == 2);
    CHECK(r.err == c.err);
    CHECK_FALSE(dttest::fileExists(out + ".ele"));
  }
}

TEST_CASE("bad input devices are refused and named pipes are read") {
  dttest::CliResult r = dttest::runCli("/dev/zero -o '" + dttest::tmpPath("zero_out") + "'");
  CHECK(r.status == 2);
  CHECK(r.err == "delaunay2d: /dev/zero: is a character device, not a point file (a regular file "
                 "or a pipe)\n");
  CHECK_FALSE(dttest::fileExists(dttest::tmpPath("zero_out.ele")));
  // A named pipe is what a user means by "the output of another program": it is read.
  const std::string fifo = dttest::tmpPath("points_fifo.xy"), out = dttest::tmpPath("fifo_out");
  std::remove(fifo.c_str());
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  ch::ProcessIo io;  // the paths reach sh through the environment, never as code
  io.env = {{"FIFO", fifo}, {"OUT", out}, {"DT_CLI_BIN", DT_CLI}};
  CHECK(ch::runProgram({"sh", "-c", "printf '0 0\\n1 0\\n0 1\\n1 1\\n' > \"$FIFO\" & \"$DT_CLI_BIN\" \"$FIFO\" -o \"$OUT\""},
                       io) == 0);
  CHECK(dttest::readEle(out + ".ele", 1).size() == 2);
  std::remove(fifo.c_str());
}

TEST_CASE("bad input binary data in the first block is named before any field is parsed") {
  // Line 2 is not a number, but line 3 shows the file is not text: the binary data is reported.
  std::string text = "0 0\nPNG IHDR\n";
  text += '\0';
  text += "\x01\x02\n0 1\n";
  const Bad b{"image.xy", text, ":3: binary or control character (code 0) at column 1"};
  expectRefused(b);
}

TEST_CASE("bad input peak memory does not grow with the attributes of a line") {
  // 4000 points with 1000 attributes each (8 MB of text): held one line at a time.
  std::string text = "4000 2 1000 0\n";
  std::string attrs;
  for (int k = 0; k < 1000; ++k) attrs += " 1";
  for (int i = 0; i < 4000; ++i)
    text += std::to_string(i + 1) + " " + std::to_string(i % 97) + " " + std::to_string(i / 97) +
            attrs + "\n";
  const std::string in = dttest::tmpPath("attrs1000.node"), out = dttest::tmpPath("attrs1000_out");
  dttest::writeText(in, text);
  // The program's own peak (VmHWM, printed by --stats): ru_maxrss of a child would also count
  // the pages of this test process that the child had before its exec (73 MB under ASan).
  const dttest::CliResult r = dttest::runCli("'" + in + "' -o '" + out + "' --stats");
  REQUIRE(r.status == 0);
  const std::size_t at = r.out.find("peak_memory_mb: ");
  REQUIRE(at != std::string::npos);
  const double peakMB = std::atof(r.out.c_str() + at + 16);
  CHECK(peakMB > 0);
  CHECK_MESSAGE(peakMB < 24, "peak " << peakMB << " MB for an 8 MB file");
  CHECK(dttest::readEle(out + ".ele", 1).size() > 7000);
}
