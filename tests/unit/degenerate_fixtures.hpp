// The shared degenerate fixtures: curves that break naive code (zero length, collinear,
// cusp, huge and tiny coordinates, degree 0). Every algorithm test runs them.
#pragma once

#include <string>
#include <vector>

#include "casteljau/casteljau.hpp"

namespace casteljau::test {

struct Degenerate {
  std::string name;
  Bezier<double, 2> curve;
  double scale;  ///< size of the coordinates, for relative tolerances
};

inline std::vector<Degenerate> degenerate_fixtures() {
  using B = Bezier<double, 2>;
  return {
      {"point_degree0", B{{0.25, -3}}, 3},
      {"all_equal_cubic", B{{1.5, 2.5}, {1.5, 2.5}, {1.5, 2.5}, {1.5, 2.5}}, 2.5},
      {"all_equal_degree12", B(std::vector<Point<double, 2>>(13, Point<double, 2>(-7, 0.1))), 7},
      {"zero_length_line", B{{0, 0}, {0, 0}}, 1},
      {"collinear_monotone", B{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, 3},
      // Collinear but doubling back: the curve runs past the end and returns.
      {"collinear_backtrack", B{{0, 0}, {3, 1.5}, {-1, -0.5}, {2, 1}}, 3},
      {"collinear_vertical", B{{1, 0}, {1, 5}, {1, -2}, {1, 1}}, 5},
      // P1 - P0 and P3 - P2 cross: the hodograph vanishes at t = 1/2 (a cusp).
      {"cusp", B{{0, 0}, {1, 1}, {0, 1}, {1, 0}}, 1},
      {"end_cusp", B{{0, 0}, {0, 0}, {1, 2}, {3, 0}}, 3},
      {"huge_1e150", B{{1e150, -2e150}, {3e150, 1e150}, {-1e150, 2e150}, {2e150, 0}}, 3e150},
      {"tiny_1em150", B{{1e-150, -2e-150}, {3e-150, 1e-150}, {-1e-150, 2e-150}, {2e-150, 0}}, 3e-150},
      {"tiny_offset_from_one", B{{1, 1}, {1 + 1e-15, 1}, {1, 1 + 1e-15}, {1 + 2e-15, 1 + 2e-15}}, 1},
      {"high_degree_wiggle",
       B{{0, 0}, {1, 5}, {2, -5}, {3, 5}, {4, -5}, {5, 5}, {6, -5}, {7, 5}, {8, -5}, {9, 5}, {10, -5}, {11, 0}}, 11},
  };
}

}  // namespace casteljau::test
