// A minimal program against the installed casteljau package: evaluates a cubic, checks
// the textbook midpoint, evaluates it at many parameters through the compiled batch
// kernels (casteljau::kernels, linked through casteljau::casteljau) and renders the curve
// to SVG. Exits non-zero on a mismatch.
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

#include <casteljau/casteljau.hpp>
#include <casteljau/io/svg.hpp>

int main() {
  using P = casteljau::Point<double, 2>;
  const casteljau::Bezier<double, 2> c{P(0, 0), P(1, 2), P(3, 2), P(4, 0)};
  // (P0 + 3 P1 + 3 P2 + P3) / 8 = (2, 1.5).
  const P mid = c(0.5);
  bool ok = std::abs(mid[0] - 2.0) < 1e-15 && std::abs(mid[1] - 1.5) < 1e-15;
  // Batch evaluation agrees with c(t). The cubic takes the power form, whose coefficients
  // reach 2^3 max|P| = 32: its rounding is a few eps of 32 (~1e-14); 1e-13 leaves room and
  // still catches any real mismatch.
  std::vector<double> ts(100);
  for (std::size_t j = 0; j < ts.size(); ++j) ts[j] = static_cast<double>(j) / 99.0;
  std::vector<P> out(ts.size());
  casteljau::evaluate(c, std::span<const double>(ts), std::span<P>(out));
  for (std::size_t j = 0; j < ts.size(); ++j) ok = ok && casteljau::distance(out[j], c(ts[j])) < 1e-13;
  const std::vector<casteljau::io::AnyCurve> curves{c};
  const std::string svg = casteljau::io::render_svg(curves);
  std::printf("midpoint (%g, %g), batch kernels %s, svg of %zu bytes\n", mid[0], mid[1],
              casteljau::batch::isa_name(casteljau::batch::active_isa()), svg.size());
  return ok && !svg.empty() ? 0 : 1;
}
