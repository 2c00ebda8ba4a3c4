// SVG path data out (io/svg_path.hpp): the writer of M, L, Q, C, A and Z commands over a
// curve's exact Bézier pieces, the elliptical-arc form of a rational quadratic, and the
// greedy cubic approximation of the other pieces.
#include "casteljau/io/svg_path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/algo/deviation.hpp"
#include "casteljau/algo/scalar_forms.hpp"  // the work limit (query_work) of work_limits.hpp
#include "work_limits.hpp"

namespace casteljau::io {

namespace {

using casteljau::detail::format_number;
using P2 = Point<double, 2>;
using V2 = Vector<double, 2>;
using Poly = Bezier<double, 2>;
using Rational = RationalBezier<double, 2>;

/// The most cubics one request may write (each costs a few thousand evaluations of its
/// piece while it is fitted): beyond, the tolerance is refused as too small.
constexpr std::size_t max_cubics = 10000;

/// A number in shortest round-trip form ("0.1", "1e+20"); -0 is written 0.
std::string num(double x) { return format_number(x == 0 ? 0.0 : x); }

class Writer {
 public:
  explicit Writer(double join) : join_(join) {}

  /// Moves to p unless the current point is there (within the join tolerance).
  void start(const P2& p) {
    if (have_ && norm(p - current_) <= join_) return;
    close_if_back();
    if (!d_.empty()) d_ += ' ';
    d_ += "M " + num(p[0]) + ' ' + num(p[1]);
    first_ = current_ = p;
    have_ = true;
    drawn_ = false;
  }

  /// One command with its coordinates; `end` is its end point.
  void command(char letter, const std::vector<double>& values, const P2& end) {
    d_ += ' ';
    d_ += letter;
    for (const double v : values) d_ += ' ' + num(v);
    current_ = end;
    drawn_ = true;
  }

  std::string finish() {
    close_if_back();
    return std::move(d_);
  }

 private:
  void close_if_back() {
    if (have_ && drawn_ && norm(current_ - first_) <= join_) d_ += " Z";
    drawn_ = false;
  }

  double join_;
  std::string d_;
  P2 first_{}, current_{};
  bool have_ = false, drawn_ = false;
};

std::vector<double> coords(std::initializer_list<P2> ps) {
  std::vector<double> v;
  for (const P2& p : ps) {
    v.push_back(p[0]);
    v.push_back(p[1]);
  }
  return v;
}

/// A polynomial piece of degree <= 3 (control points P).
void write_polynomial(Writer& w, const std::vector<P2>& P) {
  w.start(P.front());
  switch (P.size()) {
    case 1: return;  // a point: nothing drawn
    case 2: w.command('L', coords({P[1]}), P[1]); return;
    case 3: w.command('Q', coords({P[1], P[2]}), P[2]); return;
    default: w.command('C', coords({P[1], P[2], P[3]}), P[3]); return;
  }
}

/// The elliptical arc of a rational quadratic in standard form (end weights 1, middle
/// weight w in (0, 1)) from P0 through P1's shoulder to P2, as an A command (see the
/// header for the construction). The curve is the image of the unit circle's arc from
/// -phi to phi (cos phi = w) under x U + y V + centre, so its sweep is 2 phi < pi (large
/// arc 0) in every circle SVG maps the ellipse to (they differ from ours by an orthogonal
/// map), and its direction is that of the control polygon's turn.
void write_arc(Writer& w, const P2& P0, const P2& P1, const P2& P2_, double wt) {
  const P2 M = lerp(P0, P2_, 0.5);
  const double one_minus_w2 = (1 - wt) * (1 + wt);
  const V2 U = (wt / one_minus_w2) * (M - P1);
  const V2 V = (0.5 / std::sqrt(one_minus_w2)) * (P2_ - P0);
  // The 2x2 SVD of A = [U V] (columns) in closed form: A = R(phi) diag(s1, s2) R(theta),
  // with E, F, G, H its rotation and reflection parts (Blinn, "Consider the lowly 2x2
  // matrix", 1996). The ellipse's axes are R(phi) e1 (length s1) and R(phi) e2.
  const double p = U[0], q = V[0], r = U[1], s = V[1];
  const double E = (p + s) / 2, F = (p - s) / 2, G = (r + q) / 2, H = (r - q) / 2;
  const double Q = std::hypot(E, H), R = std::hypot(F, G);
  const double rx = Q + R;
  const double ry = std::abs(p * s - q * r) / rx;  // |det| / s1: no cancellation in Q - R
  double rotation = 0;
  // A circle (rx - ry = 2 min(Q, R) = 0 up to rounding, a few ulps: 1e-12 leaves room) has
  // no axis: rotation 0 (the radii then differ by at most 1e-12 of themselves).
  if (std::min(Q, R) > 0.5e-12 * rx) rotation = (std::atan2(H, E) + std::atan2(G, F)) / 2 * (180 / std::numbers::pi);
  const int sweep = cross(P1 - P0, P2_ - P1) > 0 ? 1 : 0;
  w.start(P0);
  w.command('A', {rx, ry, rotation, 0, static_cast<double>(sweep), P2_[0], P2_[1]}, P2_);
}

/// The piece's exact SVG form, or false when it has none (then approximated).
bool write_exact(Writer& w, const Poly& b) {
  if (b.degree() > 3) return false;
  write_polynomial(w, b.points());
  return true;
}

bool write_exact(Writer& w, const Rational& b) {
  const std::vector<P2>& P = b.points();
  const std::vector<double>& W = b.weights();
  const bool equal = std::all_of(W.begin(), W.end(), [&](double x) { return x == W.front(); });
  if (equal && b.degree() <= 3) {
    write_polynomial(w, P);
    return true;
  }
  if (b.degree() <= 1) {  // a point, or a segment traced at a varying speed
    write_polynomial(w, P);
    return true;
  }
  if (b.degree() != 2) return false;
  const double wt = W[1] / std::sqrt(W[0]) / std::sqrt(W[2]);
  if (std::abs(wt - 1) <= 1e-12) {  // a parabola, to rounding
    write_polynomial(w, P);
    return true;
  }
  if (wt > 1) return false;  // a hyperbola
  const V2 a = P[1] - P[0], c = P[2] - P[0];
  if (std::abs(cross(a, c)) <= 1e-14 * norm(a) * norm(c)) {
    // Collinear: the segment P0 P2 when P1 lies between them (the curve stays in the
    // convex hull and moves monotonically), else a fold that SVG cannot hold exactly.
    if (dot(a, c) >= 0 && dot(P[1] - P[2], P[0] - P[2]) >= 0 && norm(c) > 0) {
      w.start(P[0]);
      w.command('L', coords({P[2]}), P[2]);
      return true;
    }
    return false;
  }
  if (wt < 0.7) {
    // More than about 91 degrees of the affine circle: two halves, split at the middle of
    // the standard form (1, w, 1) (the same curve reparametrised), whose halves both have
    // w' = sqrt((1 + w) / 2) >= 0.707.
    const Split<Rational> halves = Rational(P, {1.0, wt, 1.0}).split(0.5);
    return write_exact(w, halves.left) && write_exact(w, halves.right);
  }
  write_arc(w, P[0], P[1], P[2], wt);
  return true;
}

/// The Hermite cubic of piece f on [a, b] (in f's parameter), as a Bézier on [0, 1].
template <class Piece>
Poly hermite_cubic(const Piece& f, double a, double b) {
  const P2 p0 = f(a), p3 = f(b);
  const double h = (b - a) / 3;
  return Poly({p0, p0 + h * f.derivative_at(a, 1), p3 - h * f.derivative_at(b, 1), p3});
}

/// The distance at equal parameters between f on [a, b] and its Hermite cubic.
template <class Piece>
double hermite_deviation(const Piece& f, const Poly& cubic, double a, double b, int samples) {
  const auto g = [&](double u) { return cubic((u - a) / (b - a)); };
  return max_deviation<double>(f, g, std::vector<double>{a, b}, samples);
}

/// Approximates piece `index` by cubics within tolerance (greedy, see the header).
template <class Piece>
void write_approximation(Writer& w, const Piece& f, std::size_t index, double tolerance, SvgPathData& out) {
  // The difference of two polynomials of degree <= max(n, 3) has no peak narrower than the
  // spacing of 16 (n + 1) samples (algo/deviation.hpp); 64 at least, 512 at most.
  const int samples = std::clamp(16 * (f.degree() + 1), 64, 512);
  double a = 0;
  while (a < 1) {
    double best = a, best_dev = 0;
    Poly best_cubic = hermite_cubic(f, a, 1);
    double dev = hermite_deviation(f, best_cubic, a, 1, samples);
    if (dev <= tolerance) {
      best = 1;
      best_dev = dev;
    } else {
      // Bisection on the reach b: fits at lo (or lo = a), not at hi; to 1e-3 of the reach.
      double lo = a, hi = 1;
      for (int it = 0; it < 60 && (lo == a || hi - lo > 1e-3 * (lo - a)); ++it) {
        const double mid = lo + (hi - lo) / 2;
        if (!(mid > a && mid < hi)) break;
        const Poly cubic = hermite_cubic(f, a, mid);
        const double e = hermite_deviation(f, cubic, a, mid, samples);
        if (e <= tolerance) {
          lo = mid;
          best_cubic = cubic;
          best_dev = e;
        } else {
          hi = mid;
        }
      }
      if (lo == a) {
        throw InvalidArgument("tolerance", "too small for piece " + std::to_string(index) + " of the curve: a cubic over " +
                                               format_number(hi - a) + " of its parameter still deviates by " +
                                               format_number(hermite_deviation(f, hermite_cubic(f, a, hi), a, hi, samples)) +
                                               ", more than the tolerance " + format_number(tolerance));
      }
      best = lo;
    }
    if (++out.cubics > max_cubics) {
      throw InvalidArgument("tolerance", "too small: the approximation would need more than " + std::to_string(max_cubics) +
                                             " cubics (piece " + std::to_string(index) + " of the curve); give a larger tolerance");
    }
    out.max_deviation = std::max(out.max_deviation, best_dev);
    write_polynomial(w, best_cubic.points());
    a = best;
  }
}

std::string piece_name(const Poly& b) { return "a degree-" + std::to_string(b.degree()) + " bezier"; }
std::string piece_name(const Rational& b) {
  return b.degree() == 2 ? "a rational quadratic that is not an elliptical arc (a hyperbola or a folded segment)"
                         : "a degree-" + std::to_string(b.degree()) + " rational_bezier";
}

SvgPathData write(const Pieces<double, 2>& p, std::optional<double> tolerance) {
  double size = 0;
  for (const auto& seg : p.segments()) {
    std::visit(
        [&](const auto& b) {
          for (const P2& q : b.points()) size = std::max({size, std::abs(q[0]), std::abs(q[1])});
        },
        seg);
  }
  SvgPathData out;
  Writer w(1e-12 * size);
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::visit(
        [&](const auto& b) {
          // write_exact writes nothing when it fails (an arc's two halves have the same
          // weight and turn, so both are arcs).
          if (write_exact(w, b)) return;
          if (!tolerance) {
            throw InvalidArgument("tolerance", "required: piece " + std::to_string(i) + " of the curve is " + piece_name(b) +
                                                   ", which SVG path data (M, L, Q, C, A) cannot hold exactly; give a "
                                                   "tolerance > 0 to approximate it by cubics");
          }
          out.exact = false;
          write_approximation(w, b, i, *tolerance, out);
        },
        p.segments()[i]);
  }
  out.d = w.finish();
  return out;
}

}  // namespace

SvgPathData to_svg_path(const AnyCurve& c, std::optional<double> tolerance) {
  if (tolerance) {
    require_finite(*tolerance, "tolerance");
    if (!(*tolerance > 0)) throw InvalidArgument("tolerance", "must be > 0, got " + format_number(*tolerance));
  }
  const int d = dimension(c);
  if (d != 2) throw InvalidArgument("curve", "to_svg_path needs a 2-D curve, got a " + std::to_string(d) + "-D curve");
  limits::check_curve_work(c, "curve", "writing the path data");
  return std::visit(
      [&]<class P>(const P& p) -> SvgPathData {
        if constexpr (P::dimension == 2) {
          limits::check_work(p, "curve", "writing the path data");
          return write(p, tolerance);
        } else {
          throw InvalidArgument("curve", "to_svg_path needs a 2-D curve");
        }
      },
      pieces(c));
}

}  // namespace casteljau::io
