// SVG path data and transform lists (io/svg_import.hpp): a hand-written scanner for SVG's
// number grammar, the path-data state machine (current point, subpath start, the previous
// control point of S and T) and elliptical arcs as exact rational quadratic pieces.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <system_error>

#include "casteljau/core/error.hpp"
#include "casteljau/io/svg_import.hpp"

namespace casteljau::io {

SvgTransform SvgTransform::operator*(const SvgTransform& m) const {
  return {a * m.a + c * m.b, b * m.a + d * m.b, a * m.c + c * m.d, b * m.c + d * m.d, a * m.e + c * m.f + e, b * m.e + d * m.f + f};
}

namespace {

bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The character at k for a message: 'X', or "the end".
std::string shown(std::string_view s, std::size_t k) {
  if (k >= s.size()) return "the end";
  const char c = s[k];
  if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) {
    static constexpr char hex[] = "0123456789abcdef";
    return std::string("byte 0x") + hex[(static_cast<unsigned char>(c) >> 4) & 15] + hex[static_cast<unsigned char>(c) & 15];
  }
  return "'" + std::string(1, c) + "'";
}

/// Text from the input for a message: at most 32 bytes, then "…" (messages stay short).
std::string excerpt(std::string_view s) { return s.size() <= 32 ? std::string(s) : std::string(s.substr(0, 32)) + "\u2026"; }

/// For a number of SVG's grammar that from_chars finds out of range: > 0 when
/// it is too large, <= 0 when too small (the power of ten of its first significant digit,
/// plus one, plus the exponent; the exponent saturates at 1e6).
long long decimal_magnitude(std::string_view x) {
  std::size_t i = x.empty() || (x[0] != '-' && x[0] != '+') ? 0 : 1;
  long long lead = 0;
  bool seen = false;
  while (i < x.size() && is_digit(x[i])) {
    if (x[i] != '0') seen = true;
    if (seen) ++lead;
    ++i;
  }
  if (i < x.size() && x[i] == '.') {
    ++i;
    while (i < x.size() && is_digit(x[i])) {
      if (!seen && x[i] != '0') seen = true;
      if (!seen) --lead;
      ++i;
    }
  }
  long long exp10 = 0;
  if (i < x.size() && (x[i] == 'e' || x[i] == 'E')) {
    ++i;
    const bool negative = i < x.size() && x[i] == '-';
    if (i < x.size() && (x[i] == '+' || x[i] == '-')) ++i;
    for (; i < x.size() && is_digit(x[i]); ++i) exp10 = std::min<long long>(exp10 * 10 + (x[i] - '0'), 1000000);
    if (negative) exp10 = -exp10;
  }
  return lead + exp10;
}

/// A cursor over text with SVG's number grammar; errors are InvalidArgument at
/// "<field>[offset]".
class Scanner {
 public:
  Scanner(std::string_view text, std::string_view field) : s_(text), field_(field) {}

  [[nodiscard]] std::size_t pos() const { return k_; }
  [[nodiscard]] bool at_end() const { return k_ >= s_.size(); }
  [[nodiscard]] char peek() const { return at_end() ? '\0' : s_[k_]; }
  void advance() { ++k_; }

  void skip_wsp() {
    while (!at_end() && is_wsp(s_[k_])) ++k_;
  }
  /// comma-wsp? : whitespace, at most one comma, whitespace. Returns whether a comma was
  /// seen.
  bool skip_comma_wsp() {
    skip_wsp();
    bool comma = false;
    if (peek() == ',') {
      comma = true;
      ++k_;
      skip_wsp();
    }
    return comma;
  }

  /// Whether a number starts here (sign, digit or '.' followed by a digit).
  [[nodiscard]] bool number_starts() const {
    std::size_t j = k_;
    if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
    if (j < s_.size() && is_digit(s_[j])) return true;
    return j + 1 < s_.size() && s_[j] == '.' && is_digit(s_[j + 1]);
  }

  /// One number of SVG's grammar at the cursor; `what` completes "expected a number
  /// after ..." ("'L'").
  double number(std::string_view after) {
    if (!number_starts()) {
      // "expected a number after 'L'": the command it belongs to; the offset shows where.
      fail(k_, after.empty() ? "expected a number, got " + shown(s_, k_) : "expected a number after " + std::string(after));
    }
    const std::size_t start = k_;
    std::size_t j = k_;
    if (s_[j] == '+' || s_[j] == '-') ++j;
    while (j < s_.size() && is_digit(s_[j])) ++j;
    if (j < s_.size() && s_[j] == '.') {
      ++j;
      while (j < s_.size() && is_digit(s_[j])) ++j;
    }
    if (j < s_.size() && (s_[j] == 'e' || s_[j] == 'E')) {
      std::size_t e = j + 1;
      if (e < s_.size() && (s_[e] == '+' || s_[e] == '-')) ++e;
      if (e < s_.size() && is_digit(s_[e])) {
        while (e < s_.size() && is_digit(s_[e])) ++e;
        j = e;
      }
    }
    // from_chars does not take a leading '+'.
    const std::size_t from = s_[start] == '+' ? start + 1 : start;
    double v = 0;
    const auto r = std::from_chars(s_.data() + from, s_.data() + j, v);
    if (r.ec == std::errc::result_out_of_range) {
      // Underflow reads as zero (a tiny coordinate); overflow is refused. Which one: the
      // decimal magnitude of the first significant digit plus the exponent.
      if (decimal_magnitude(s_.substr(from, j - from)) > 0) {
        fail(start, "the number " + excerpt(s_.substr(start, j - start)) + " is out of range");
      }
      v = 0;
    } else if (r.ec != std::errc() || r.ptr != s_.data() + j) {
      fail(start, "malformed number " + excerpt(s_.substr(start, j - start)));
    }
    k_ = j;
    return v;
  }

  /// A flag of A: one character 0 or 1.
  bool flag(std::string_view after) {
    const char c = peek();
    if (c != '0' && c != '1') fail(k_, "expected a flag (0 or 1) after " + std::string(after) + ", got " + shown(s_, k_));
    ++k_;
    return c == '1';
  }

  [[noreturn]] void fail(std::size_t at, std::string problem) const {
    throw InvalidArgument(std::string(field_) + "[" + std::to_string(at) + "]", std::move(problem));
  }

 private:
  std::string_view s_;
  std::string_view field_;
  std::size_t k_ = 0;
};

constexpr double degrees = std::numbers::pi / 180;

SvgSegment line(const SvgPoint& a, const SvgPoint& b) { return {{a, b}, {}}; }

/// The path-data state machine.
class PathBuilder {
 public:
  std::vector<SvgSubpath> done;

  void move_to(const SvgPoint& p) {
    finite_ = finite_ && std::isfinite(p[0]) && std::isfinite(p[1]);
    finish();
    current_ = start_ = p;
  }
  void add(SvgSegment s) {
    for (const auto& p : s.points) finite_ = finite_ && std::isfinite(p[0]) && std::isfinite(p[1]);
    current_ = s.points.back();
    open_.segments.push_back(std::move(s));
  }
  void close() {
    if (current_ != start_) open_.segments.push_back(line(current_, start_));
    open_.closed = true;
    current_ = start_;
    finish();
  }
  void finish() {
    if (!open_.segments.empty()) done.push_back(std::move(open_));
    open_ = {};
  }
  /// After Z the current point is the start, and the next drawing command starts a new
  /// subpath there (close() has finished the old one).
  [[nodiscard]] const SvgPoint& current() const { return current_; }
  [[nodiscard]] bool finite() const { return finite_; }

 private:
  bool finite_ = true;
  SvgSubpath open_;
  SvgPoint current_{0, 0}, start_{0, 0};
};

/// How many numbers (and flags) one set of a command's arguments holds.
int arity(char upper) {
  switch (upper) {
    case 'M': case 'L': case 'T': return 2;
    case 'H': case 'V': return 1;
    case 'C': return 6;
    case 'S': case 'Q': return 4;
    case 'A': return 7;
    case 'Z': return 0;
    default: return -1;
  }
}

}  // namespace

void append_arc(std::vector<SvgSegment>& segments, const SvgPoint& from, double rx, double ry, double phi_degrees, bool large_arc,
                bool sweep, const SvgPoint& to) {
  // F.6.2: coincident end points draw nothing; a zero radius draws a line.
  if (from == to) return;
  rx = std::fabs(rx);
  ry = std::fabs(ry);
  if (rx == 0 || ry == 0) {
    segments.push_back(line(from, to));
    return;
  }
  // F.6.5 step 1: the mid-point difference in the ellipse's axes.
  const double phi = std::fmod(phi_degrees, 360.0) * degrees;
  const double cphi = std::cos(phi), sphi = std::sin(phi);
  const double dx = (from[0] - to[0]) / 2, dy = (from[1] - to[1]) / 2;
  const double x1 = cphi * dx + sphi * dy, y1 = -sphi * dx + cphi * dy;
  // F.6.6: radii too small for the end points grow by sqrt(Lambda), the arc becomes half
  // the ellipse about the mid-point.
  const double lambda = (x1 / rx) * (x1 / rx) + (y1 / ry) * (y1 / ry);
  double coef = 0;
  if (lambda > 1) {
    const double s = std::sqrt(lambda);
    rx *= s;
    ry *= s;
  } else {
    // F.6.5 step 2: the centre in the rotated frame, on the side the flags choose.
    const double rxy1 = rx * y1, ryx1 = ry * x1;
    const double num = (rx * ry) * (rx * ry) - rxy1 * rxy1 - ryx1 * ryx1;
    const double den = rxy1 * rxy1 + ryx1 * ryx1;
    coef = std::sqrt(std::max(0.0, num / den));
    if (large_arc == sweep) coef = -coef;
  }
  const double cx1 = coef * rx * y1 / ry, cy1 = -coef * ry * x1 / rx;
  // Step 3: the centre.
  const double cx = cphi * cx1 - sphi * cy1 + (from[0] + to[0]) / 2;
  const double cy = sphi * cx1 + cphi * cy1 + (from[1] + to[1]) / 2;
  // Step 4: start angle and sweep, on the unit circle of the ellipse's frame.
  const double ux = (x1 - cx1) / rx, uy = (y1 - cy1) / ry;
  const double vx = (-x1 - cx1) / rx, vy = (-y1 - cy1) / ry;
  const double theta1 = std::atan2(uy, ux);
  double delta = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  if (!sweep && delta > 0) delta -= 2 * std::numbers::pi;
  if (sweep && delta < 0) delta += 2 * std::numbers::pi;
  // A half ellipse (Lambda >= 1, or end points opposite) has delta = +-pi exactly in
  // exact arithmetic; atan2 may give either sign there: the sweep flag decides.
  if (!std::isfinite(delta) || !std::isfinite(theta1) || !std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(rx) ||
      !std::isfinite(ry)) {
    throw InvalidArgument("", "the arc's numbers overflow");
  }
  // Pieces of at most 90 degrees (1e-9 of slack so that a quarter rounded up stays one).
  const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(delta) / (std::numbers::pi / 2) - 1e-9)));
  const double step = delta / n;
  const double w = std::cos(step / 2);
  const auto on_ellipse = [&](double u, double v) {
    const double x = rx * u, y = ry * v;
    return SvgPoint{cx + cphi * x - sphi * y, cy + sphi * x + cphi * y};
  };
  SvgPoint a = from;
  for (int i = 0; i < n; ++i) {
    const double t0 = theta1 + i * step, t1 = theta1 + (i + 1) * step, tm = (t0 + t1) / 2;
    const SvgPoint mid = on_ellipse(std::cos(tm) / w, std::sin(tm) / w);
    const SvgPoint b = i + 1 == n ? to : on_ellipse(std::cos(t1), std::sin(t1));
    segments.push_back({{a, mid, b}, {1.0, w, 1.0}});
    a = b;
  }
}

std::vector<SvgSubpath> parse_path_data(std::string_view d, const SvgTransform& transform) {
  Scanner in(d, "d");
  PathBuilder path;
  in.skip_wsp();
  if (in.at_end()) return {};
  if (in.peek() != 'M' && in.peek() != 'm') {
    in.fail(in.pos(), "path data must start with a moveto ('M' or 'm'), got " + shown(d, in.pos()));
  }
  // The previous segment's last control point for S (after C/S) and T (after Q/T).
  SvgPoint last_cubic{}, last_quad{};
  bool had_cubic = false, had_quad = false;
  while (true) {
    in.skip_wsp();
    if (in.at_end()) break;
    const std::size_t at = in.pos();
    const char letter = in.peek();
    const char upper = static_cast<char>(letter >= 'a' && letter <= 'z' ? letter - 32 : letter);
    const int n = arity(upper);
    if (n < 0) in.fail(at, "expected a path command (MLHVCSQTAZ, or a number continuing the previous one), got " + shown(d, at));
    in.advance();
    const bool relative = letter != upper;
    const std::string after = "'" + std::string(1, letter) + "'";
    if (upper == 'Z') {
      path.close();
      had_cubic = had_quad = false;
      continue;
    }
    // The argument sets: one, then more while a number (or a comma and a number) follows.
    char command = upper;
    in.skip_wsp();
    for (bool first = true;; first = false) {
      if (!first) {
        const std::size_t before = in.pos();
        const bool comma = in.skip_comma_wsp();
        if (!comma && !in.number_starts()) break;
        if (comma && !in.number_starts()) {
          in.fail(in.pos(), "expected a number after ',' (at " + std::to_string(before) + ")");
        }
      }
      double v[7];
      for (int i = 0; i < n; ++i) {
        if (i > 0) in.skip_comma_wsp();
        if (command == 'A' && (i == 3 || i == 4)) {
          v[i] = in.flag(after) ? 1 : 0;
        } else {
          v[i] = in.number(after);
        }
      }
      const SvgPoint p0 = path.current();
      const auto point = [&](int i) { return relative ? SvgPoint{p0[0] + v[i], p0[1] + v[i + 1]} : SvgPoint{v[i], v[i + 1]}; };
      bool cubic = false, quad = false;
      switch (command) {
        case 'M':
          path.move_to(point(0));
          command = 'L';  // later pairs are lines
          break;
        case 'L': path.add(line(p0, point(0))); break;
        case 'H': path.add(line(p0, {relative ? p0[0] + v[0] : v[0], p0[1]})); break;
        case 'V': path.add(line(p0, {p0[0], relative ? p0[1] + v[0] : v[0]})); break;
        case 'C':
          last_cubic = point(2);
          path.add({{p0, point(0), last_cubic, point(4)}, {}});
          cubic = true;
          break;
        case 'S': {
          const SvgPoint c1 = had_cubic ? SvgPoint{2 * p0[0] - last_cubic[0], 2 * p0[1] - last_cubic[1]} : p0;
          last_cubic = point(0);
          path.add({{p0, c1, last_cubic, point(2)}, {}});
          cubic = true;
          break;
        }
        case 'Q':
          last_quad = point(0);
          path.add({{p0, last_quad, point(2)}, {}});
          quad = true;
          break;
        case 'T': {
          last_quad = had_quad ? SvgPoint{2 * p0[0] - last_quad[0], 2 * p0[1] - last_quad[1]} : p0;
          path.add({{p0, last_quad, point(0)}, {}});
          quad = true;
          break;
        }
        case 'A': {
          std::vector<SvgSegment> arc;
          try {
            append_arc(arc, p0, v[0], v[1], v[2], v[3] != 0, v[4] != 0, point(5));
          } catch (const InvalidArgument& e) {
            in.fail(at, e.problem());
          }
          for (auto& s : arc) path.add(std::move(s));
          break;
        }
        default: break;
      }
      had_cubic = cubic;
      had_quad = quad;
      if (!path.finite()) in.fail(at, "a coordinate overflows (is not finite)");
    }
  }
  path.finish();
  // The transform, then every coordinate finite.
  for (auto& sub : path.done) {
    for (auto& s : sub.segments) {
      for (auto& p : s.points) {
        p = transform(p);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) throw InvalidArgument("d", "a coordinate overflows after the transform");
      }
    }
  }
  return std::move(path.done);
}

std::vector<double> parse_number_list(std::string_view text, std::string_view field) {
  Scanner in(text, field);
  std::vector<double> out;
  in.skip_wsp();
  while (!in.at_end()) {
    if (!out.empty()) {
      const std::size_t before = in.pos();
      if (in.skip_comma_wsp() && in.at_end()) in.fail(before, "expected a number after ','");
      if (in.at_end()) break;
    }
    out.push_back(in.number(""));
  }
  return out;
}

SvgTransform parse_transform(std::string_view text) {
  Scanner in(text, "transform");
  SvgTransform m;
  in.skip_wsp();
  bool first = true;
  while (true) {
    if (!first) in.skip_comma_wsp();
    in.skip_wsp();
    if (in.at_end()) break;
    first = false;
    const std::size_t at = in.pos();
    std::string name;
    while (!in.at_end() && ((in.peek() >= 'a' && in.peek() <= 'z') || (in.peek() >= 'A' && in.peek() <= 'Z'))) {
      name += in.peek();
      in.advance();
    }
    // How many numbers the function takes: lo to hi (rotate: 1 or 3).
    int lo = 1, hi = 1;
    if (name == "matrix") {
      lo = hi = 6;
    } else if (name == "translate" || name == "scale") {
      hi = 2;
    } else if (name == "rotate") {
      hi = 3;
    } else if (name != "skewX" && name != "skewY") {
      in.fail(at, name.empty() ? "expected a transform function (matrix, translate, scale, rotate, skewX, skewY), got " + shown(text, at)
                               : "unknown transform function '" + excerpt(name) + "' (matrix, translate, scale, rotate, skewX, skewY)");
    }
    in.skip_wsp();
    if (in.peek() != '(') in.fail(in.pos(), "expected '(' after " + name + ", got " + shown(text, in.pos()));
    in.advance();
    in.skip_wsp();
    double v[6] = {0, 0, 0, 0, 0, 0};
    int count = 0;
    const std::string after = "'" + name + "('";
    while (in.peek() != ')') {
      if (in.at_end()) in.fail(in.pos(), "expected ')' to close " + name + "(");
      if (count > 0) in.skip_comma_wsp();
      if (count == hi) {
        in.fail(in.pos(), "expected ')': " + name + " takes at most " + std::to_string(hi) + (hi == 1 ? " number" : " numbers") + ", got " +
                              shown(text, in.pos()));
      }
      v[count++] = in.number(after);
      in.skip_wsp();
    }
    if (count < lo || (name == "rotate" && count == 2)) {
      const std::string takes = name == "rotate" ? "1 or 3 numbers"
                                : lo == hi       ? std::to_string(lo) + (lo == 1 ? " number" : " numbers")
                                                 : std::to_string(lo) + " or " + std::to_string(hi) + " numbers";
      in.fail(in.pos(), name + " takes " + takes + ", got " + std::to_string(count));
    }
    in.advance();  // ')'
    SvgTransform t;
    if (name == "matrix") {
      t = {v[0], v[1], v[2], v[3], v[4], v[5]};
    } else if (name == "translate") {
      t.e = v[0];
      t.f = count == 2 ? v[1] : 0;
    } else if (name == "scale") {
      t.a = v[0];
      t.d = count == 2 ? v[1] : v[0];
    } else if (name == "rotate") {
      const double r = std::fmod(v[0], 360.0) * degrees;
      // Exact at multiples of 90 degrees (cos(pi/2) is 6e-17 in double).
      double cr = std::cos(r), sr = std::sin(r);
      const double q = std::fmod(v[0], 90.0);
      if (q == 0) {
        cr = std::round(cr);
        sr = std::round(sr);
      }
      const SvgTransform rot{cr, sr, -sr, cr, 0, 0};
      if (count == 3) {
        t = SvgTransform{1, 0, 0, 1, v[1], v[2]} * rot * SvgTransform{1, 0, 0, 1, -v[1], -v[2]};
      } else {
        t = rot;
      }
    } else if (std::fabs(std::fmod(v[0], 180.0)) == 90) {
      char text[32];
      const auto r = std::to_chars(text, text + sizeof text, v[0]);
      in.fail(at, name + "(" + std::string(text, r.ptr) + ") is not a finite transform");
    } else if (name == "skewX") {
      t.c = std::tan(std::fmod(v[0], 180.0) * degrees);
    } else {
      t.b = std::tan(std::fmod(v[0], 180.0) * degrees);
    }
    m = m * t;
  }
  const double all[] = {m.a, m.b, m.c, m.d, m.e, m.f};
  for (const double x : all) {
    if (!std::isfinite(x)) in.fail(0, "the transform is not finite (a skew of 90 degrees, or an overflow)");
  }
  return m;
}

}  // namespace casteljau::io
