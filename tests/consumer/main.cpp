// A program of another project: triangulates five points with the installed library, through
// its one entry point (the options mean what delaunay2d's do), and validates the result exactly.
#include <dt/check.h>
#include <dt/delaunay.h>
#include <cstdio>

int main() {
  const std::vector<double> xy = {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.25};
  const dt::TriangulateResult r = dt::triangulate(xy);  // DT(S), triangles counter-clockwise
  const dt::CheckReport check = dt::checkDelaunay(r.xy, r.tri);  // exact validation
  std::printf("%zu triangles, %s\n", r.tri.size(), check.ok ? "Delaunay" : check.error.c_str());
  return check.ok && r.tri.size() == 4 ? 0 : 1;
}
