// A program of another project: triangulates five points with the installed library.
#include <dt/check.h>
#include <dt/fast_delaunay.h>
#include <cstdio>

int main() {
  const std::vector<double> xy = {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.25};
  const dt::FastResult r = dt::fastDelaunay(xy);
  const dt::CheckReport check = dt::checkDelaunay(xy, r.tri);
  std::printf("%zu triangles, %s\n", r.tri.size(), check.ok ? "Delaunay" : check.error.c_str());
  return check.ok && r.tri.size() == 4 ? 0 : 1;
}
