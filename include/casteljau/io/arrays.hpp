// Run-time operations on plain arrays of numbers, for front ends that hold arrays rather
// than JSON values (the Python package, python/_casteljau.cpp): a curve built from its
// arrays, a curve's derivatives (and rational points) at many parameters, and surface
// points and partial derivatives at many parameters. Compiled in the io library next to the
// readers that instantiate the same templates (src/io/curve_json.cpp,
// src/io/surface_json.cpp), so that a front end instantiates none of them.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "casteljau/io/any_curve.hpp"

namespace casteljau::io {

struct AnySurface;  // io/surfaces.hpp

/// The curve of {"type": "cubic_spline", "params": params, "points": points, "boundary":
/// boundary} built from the arrays themselves: points row-major, params.size() rows of d
/// coordinates, boundary "natural", "not-a-knot" or "periodic". The caller checks the
/// values finite, at least 2 rows and d in 1..max_dimension; the spline's constructor
/// checks the rest (with its own messages: a caller wanting the reader's reads the JSON
/// form instead).
[[nodiscard]] AnyCurve cubic_spline_from_arrays(std::span<const double> params, const double* points, int d,
                                                std::string_view boundary);

/// The order-k derivatives (k = 0: the points) of a curve at many parameters, through its
/// exact Bézier pieces (io::pieces), polynomial or rational, of any degrees: for every
/// curve's derivatives, and the points of the curves without a batch evaluation
/// (rational curves, degrees above SpanTable's). Built once per curve and order, it holds
/// each piece's hodographs of orders 0..k (rational pieces: of the homogeneous form (w P,
/// w), the weights scaled by a power of two so that the largest is in [0.5, 1)) in flat
/// arrays of run-time width: order r + 1 of a degree-q piece on [u_i, u_(i+1)] is q
/// (Q_(j+1) - Q_j) / (u_(i+1) - u_i) of order r's points Q [PT97, eq. 1.9]. A parameter's
/// piece is found by a binary search over the breaks (the previous piece tried first:
/// sorted parameters cost O(1)); the right piece answers at an interior break, the last
/// one at the domain's end, and outside the domain the end pieces continue, as c(t). The
/// value is de Casteljau's algorithm at the local parameter (O(p^2 d) per order), and for
/// rational pieces the quotient rule C^(r) = (A^(r) - sum_(i=1..r) C(r, i) w^(i)
/// C^(r-i)) / w [PT97, eq. 4.8] (O(k^2 d)). Accuracy: inside the domain a convex
/// combination per order, about (p + 2) eps of the hodograph's size; it agrees with each
/// type's own derivative_at (io::derivatives) to about 1e-13 relative (tested from
/// Python). Memory: O(pieces (p + 1) (k + 1) d) numbers.
class DerivativeTable {
 public:
  /// The table of c's pieces for order k >= 0.
  DerivativeTable(const AnyCurve& c, int k);

  /// The order-k derivatives at t into out (t.size() rows of the curve's dimension):
  /// false, with out unspecified, when a parameter or a value is not finite (the caller
  /// then reports the error, e.g. through io::derivatives, which names the parameter), and
  /// for derivatives (k >= 1) of a curve with a rational piece whose weights spread beyond
  /// 2^20 (the table's quotient rule would lose them: io::derivatives uses the library's
  /// forms for such weights).
  /// Const, allocates only its scratch: threads may share a table.
  [[nodiscard]] bool evaluate(std::span<const double> t, double* out) const;

 private:
  template <class P>
  void read(const P& pieces);

  int k_;
  int d_ = 0;
  bool rational_ = false;
  bool declined_ = false;  ///< extreme weights and k >= 1: evaluate() always returns false
  std::vector<double> breaks_;
  std::vector<int> degree_;          ///< per piece
  std::vector<std::size_t> starts_;  ///< per piece: its first number in coef_
  std::vector<double> coef_;         ///< per piece, orders 0..k (rational) or k alone
  std::size_t max_degree_ = 0;
};

/// The surface's points at (u[j], v[j]), j < n, into out (n rows of s.dim() numbers).
/// Outside the domain the end patches extrapolate, as the eval command. Throws
/// InvalidArgument naming "u[j]" for a parameter pair that is not finite.
void surface_points(const AnySurface& s, const double* u, const double* v, std::size_t n, double* out);

/// The partial derivatives of total order 0..k at (u[j], v[j]), j < n, into out: n blocks
/// of (k + 1)^2 s.dim() numbers in casteljau::detail::partials' layout (block j, entry
/// (a (k + 1) + b) s.dim() + c: coordinate c of d^(a+b) S / du^a dv^b; zero where a + b >
/// k), the eval command's values. Throws InvalidArgument naming "uv[j]" (a parameter pair
/// that is not finite, a pole of a rational surface).
void surface_partials(const AnySurface& s, const double* u, const double* v, std::size_t n, int k, double* out);

}  // namespace casteljau::io
