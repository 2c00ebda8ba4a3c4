// A minimal program against the installed casteljau package: evaluates a cubic, checks
// the textbook midpoint and renders the curve to SVG. Exits non-zero on a mismatch.
#include <cmath>
#include <cstdio>
#include <vector>

#include <casteljau/casteljau.hpp>
#include <casteljau/io/svg.hpp>

int main() {
  using P = casteljau::Point<double, 2>;
  const casteljau::Bezier<double, 2> c{P(0, 0), P(1, 2), P(3, 2), P(4, 0)};
  // (P0 + 3 P1 + 3 P2 + P3) / 8 = (2, 1.5).
  const P mid = c(0.5);
  const bool ok = std::abs(mid[0] - 2.0) < 1e-15 && std::abs(mid[1] - 1.5) < 1e-15;
  const std::vector<casteljau::io::AnyCurve> curves{c};
  const std::string svg = casteljau::io::render_svg(curves);
  std::printf("midpoint (%g, %g), svg of %zu bytes\n", mid[0], mid[1], svg.size());
  return ok && !svg.empty() ? 0 : 1;
}
