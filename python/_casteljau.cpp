// The compiled part of the Python package `casteljau` (python/casteljau/): a thin layer over
// the io library's run-time interfaces, so that it instantiates no curve algorithm of its
// own (docs/python.md, "How it is built"):
// - the registries: the curve types (curve-JSON name, class name, fields), the surface
//   types, the commands and the commands' surface forms (name, summary, fields), from which
//   python/casteljau/_curves.py and _surfaces.py generate the classes and methods;
// - `Curve`: one io::AnyCurve read once from curve JSON (a cubic_spline of numpy arrays
//   from the arrays, io/arrays.hpp), evaluated on numpy arrays (values through the
//   library's batch evaluation, below, derivatives and rational curves through the
//   table of its pieces, PieceDerivatives; the GIL released), projected from the rows of
//   an array by io::project_rows, and the commands run on it (`run`);
// - `Surface`: one io::AnySurface, evaluated at (u, v) arrays (points, and the eval
//   command's fields through io::surface_partials), and its commands;
// - `run(command, request)`: any command;
// - `Error` (a ValueError): the library's InvalidArgument as "<where>: <what>", the
//   command line's message.
// Requests go from Python objects (dicts, lists, numbers, numpy arrays, curves) to the
// library's JSON values in C++ and responses come back the same way (arrays of numbers as
// numpy arrays): no JSON text on either side.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "casteljau/algo/span_table.hpp"
#include "casteljau/io/arrays.hpp"
#include "casteljau/io/commands.hpp"
#include "casteljau/io/json.hpp"
#include "casteljau/io/queries.hpp"
#include "casteljau/io/surfaces.hpp"

namespace py = pybind11;
namespace io = casteljau::io;
using casteljau::InvalidArgument;

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The command line's form of a library error (apps/cli/main.cpp): "<where>: <what>", the
/// request itself named "request".
std::string where_what(const InvalidArgument& e) {
  return (e.where().empty() ? std::string("request") : e.where()) + ": " + e.problem();
}

/// A non-finite number as Python prints it ("nan", "inf", "-inf").
std::string number_text(double v) { return std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf"; }

InvalidArgument not_finite(const std::string& where, double v) {
  return InvalidArgument(where, "must be a finite number, got " + number_text(v));
}

const io::Command& command_named(const std::string& name) {
  const io::Command* c = io::find_command(name);
  if (c == nullptr) throw InvalidArgument("command", "unknown command " + io::quoted(name));
  return *c;
}

std::string child(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

// ---------------------------------------------------------------------------------------
// Python objects -> JSON values

io::Json json_of(py::handle v, const std::string& path);

/// A numeric numpy array as nested JSON arrays; a NaN or infinity raises naming its index.
io::Json json_of_array(const py::array& a, const std::string& path) {
  const char kind = a.dtype().kind();
  if (kind == 'c') throw InvalidArgument(path, "must be real numbers, got a complex array");
  if (kind != 'f' && kind != 'i' && kind != 'u') return json_of(a.attr("tolist")(), path);
  const Doubles d = Doubles::ensure(a);
  const std::size_t n = static_cast<std::size_t>(d.size());
  const double* x = d.data();
  const std::vector<py::ssize_t> shape(d.shape(), d.shape() + d.ndim());
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) {
      std::string where = path;
      std::size_t rest = i, stride = n;
      for (const py::ssize_t s : shape) {
        stride /= static_cast<std::size_t>(s);
        where = child(where, rest / stride);
        rest %= stride;
      }
      throw not_finite(where, x[i]);
    }
  }
  if (shape.empty()) return io::Json(x[0]);
  // Built from the innermost arrays outwards, one level of the shape at a time.
  const std::size_t last = static_cast<std::size_t>(shape.back());
  std::vector<io::Json> level;
  level.reserve(n / std::max<std::size_t>(last, 1));
  for (std::size_t i = 0; i < n || (n == 0 && level.empty()); i += std::max<std::size_t>(last, 1)) {
    io::Json row = io::Json::array();
    auto& r = row.get_ref<io::Json::array_t&>();
    r.reserve(last);
    for (std::size_t k = 0; k < last && i + k < n; ++k) r.emplace_back(x[i + k]);
    level.push_back(std::move(row));
    if (n == 0) break;
  }
  for (std::size_t dim = shape.size() - 1; dim-- > 0;) {
    const std::size_t m = static_cast<std::size_t>(shape[dim]);
    std::vector<io::Json> up;
    up.reserve(level.size() / std::max<std::size_t>(m, 1));
    for (std::size_t i = 0; i < level.size(); i += std::max<std::size_t>(m, 1)) {
      io::Json row = io::Json::array();
      auto& r = row.get_ref<io::Json::array_t&>();
      for (std::size_t k = 0; k < m && i + k < level.size(); ++k) r.push_back(std::move(level[i + k]));
      up.push_back(std::move(row));
    }
    level = std::move(up);
  }
  return level.empty() ? io::Json::array() : std::move(level.front());
}

class Curve;
class Surface;
const io::Json* stored_json(py::handle v);

/// v as a JSON value: dicts, lists, tuples, numbers, strings, booleans, None, numpy arrays
/// and scalars, curves and surfaces (their JSON). A NaN or infinity raises naming its path
/// ("points[1][0]", "axis.point[2]"); JSON cannot carry them, and the library refuses them.
io::Json json_of(py::handle v, const std::string& path) {
  if (v.is_none()) return nullptr;
  if (PyBool_Check(v.ptr())) return v.cast<bool>();
  if (PyLong_Check(v.ptr())) {
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
    if (overflow == 0) return i;
    return PyLong_AsDouble(v.ptr());
  }
  if (PyFloat_Check(v.ptr())) {
    const double x = PyFloat_AS_DOUBLE(v.ptr());
    if (!std::isfinite(x)) throw not_finite(path, x);
    return x;
  }
  if (PyUnicode_Check(v.ptr())) return v.cast<std::string>();
  if (PyDict_Check(v.ptr())) {
    io::Json out = io::Json::object();
    for (const auto& [k, x] : py::reinterpret_borrow<py::dict>(v)) {
      const std::string key = py::str(k);
      out[key] = json_of(x, path.empty() ? key : path + "." + key);
    }
    return out;
  }
  if (PyList_Check(v.ptr()) || PyTuple_Check(v.ptr())) {
    io::Json out = io::Json::array();
    std::size_t i = 0;
    for (const auto x : v) {
      out.push_back(json_of(x, child(path, i)));
      ++i;
    }
    return out;
  }
  if (py::isinstance<py::array>(v)) return json_of_array(py::reinterpret_borrow<py::array>(v), path);
  if (const io::Json* j = stored_json(v)) return *j;
  const py::module_ np = py::module_::import("numpy");
  if (py::isinstance(v, np.attr("generic"))) return json_of(v.attr("item")(), path);
  throw py::type_error((path.empty() ? std::string("request") : path) + ": a " +
                       std::string(py::str(py::type::of(v).attr("__name__"))) + " is not JSON data");
}

// ---------------------------------------------------------------------------------------
// JSON values -> Python objects

/// The shape of j when it is a non-empty regular nest of arrays of numbers ([[1, 2], [3,
/// 4]]: {2, 2}), else empty.
template <class J>
std::vector<py::ssize_t> numeric_shape(const J& j) {
  std::vector<py::ssize_t> shape;
  const J* x = &j;
  while (x->is_array()) {
    if (x->empty()) return {};
    shape.push_back(static_cast<py::ssize_t>(x->size()));
    x = &x->front();
  }
  if (!x->is_number() || shape.empty()) return {};
  // Every element at every level must match.
  std::vector<const J*> level{&j};
  for (std::size_t d = 0; d < shape.size(); ++d) {
    std::vector<const J*> next;
    next.reserve(level.size() * static_cast<std::size_t>(shape[d]));
    for (const J* a : level) {
      if (!a->is_array() || a->size() != static_cast<std::size_t>(shape[d])) return {};
      for (const auto& e : *a) next.push_back(&e);
    }
    level = std::move(next);
  }
  for (const J* e : level)
    if (!e->is_number()) return {};
  return shape;
}

template <class J>
void fill_numbers(const J& j, double*& out) {
  if (j.is_array()) {
    for (const auto& e : j) fill_numbers(e, out);
  } else {
    *out++ = j.template get<double>();
  }
}

/// j as Python: objects as dicts, numbers, strings, booleans, null as None; with `arrays`,
/// a regular nest of arrays of numbers as one float64 numpy array (an empty array too),
/// else as lists.
template <class J>
py::object py_of(const J& j, bool arrays) {
  switch (j.type()) {
    case J::value_t::object: {
      py::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = py_of(it.value(), arrays);
      return d;
    }
    case J::value_t::array: {
      if (arrays) {
        if (j.empty()) return py::array_t<double>(0);
        const auto shape = numeric_shape(j);
        if (!shape.empty()) {
          py::array_t<double> a(shape);
          double* out = a.mutable_data();
          fill_numbers(j, out);
          return a;
        }
      }
      py::list l;
      for (const auto& e : j) l.append(py_of(e, arrays));
      return l;
    }
    case J::value_t::string: return py::str(j.template get_ref<const std::string&>());
    case J::value_t::boolean: return py::bool_(j.template get<bool>());
    case J::value_t::number_integer: return py::int_(j.template get<long long>());
    case J::value_t::number_unsigned: return py::int_(j.template get<unsigned long long>());
    case J::value_t::number_float: return py::float_(j.template get<double>());
    default: return py::none();
  }
}

// ---------------------------------------------------------------------------------------
// The evaluation path: the library's batch evaluation of the curve's own type at its
// dimension, built once per curve object, numpy buffers in and out.

/// Evaluates one curve at many parameters through the library's batch evaluation: the
/// members evaluate / evaluate_sorted of cubic splines and Hermite curves (their pieces
/// searched by prefetched groups, or merged for sorted input), the SpanTable of the exact
/// Bezier pieces for every other piecewise polynomial curve (a bucket grid: O(1) per
/// parameter, the previous piece tried first for sorted input), NURBS' own evaluate.
using casteljau::CubicSpline;
using casteljau::Hermite;
using casteljau::Pieces;
using casteljau::Point;
using casteljau::SpanTable;

class BatchEvaluator {
 public:
  virtual ~BatchEvaluator() = default;
  /// The points at t into out (t.size() x d doubles): false, with out unspecified, when a
  /// parameter or a point is not finite (the caller then runs io::evaluate for its error).
  virtual bool evaluate(std::span<const double> t, double* out) const = 0;
};


bool all_finite(const double* v, std::size_t n) {
  bool ok = true;
  for (std::size_t i = 0; i < n; ++i) ok &= std::abs(v[i]) <= 1.7976931348623157e308;  // vectorises; NaN fails
  return ok;
}

template <int D>
std::span<Point<double, D>> points_of(double* out, std::size_t n) {
  static_assert(sizeof(Point<double, D>) == D * sizeof(double) && std::is_standard_layout_v<Point<double, D>>);
  return std::span<Point<double, D>>(reinterpret_cast<Point<double, D>*>(out), n);
}

/// Whether t is in ascending order (then the merge of the curve's own evaluate_sorted).
bool ascending(std::span<const double> t) {
  bool ok = true;
  for (std::size_t i = 1; i < t.size(); ++i) ok &= t[i - 1] <= t[i];
  return ok;
}

/// A curve with evaluate (random order) and evaluate_sorted members: cubic splines and
/// Hermite curves (curves/hermite.hpp: prefetched groups, and a four-way merge).
template <class C>
class SortedMembers final : public BatchEvaluator {
 public:
  explicit SortedMembers(const C& c) : c_(c) {}
  bool evaluate(std::span<const double> t, double* out) const override {
    if (!all_finite(t.data(), t.size())) return false;
    const auto o = points_of<C::dimension>(out, t.size());
    if (ascending(t)) {
      c_.evaluate_sorted(t, o);
    } else {
      c_.evaluate(t, o);
    }
    return all_finite(out, t.size() * C::dimension);
  }

 private:
  const C& c_;
};

/// Piecewise polynomial curves of one degree: the exact Bézier pieces in a SpanTable.
template <int D>
class Table final : public BatchEvaluator {
 public:
  explicit Table(SpanTable<double, D> table) : table_(std::move(table)) {}
  bool evaluate(std::span<const double> t, double* out) const override {
    if (!all_finite(t.data(), t.size())) return false;
    table_.evaluate(t, points_of<D>(out, t.size()));
    return all_finite(out, t.size() * D);
  }

 private:
  SpanTable<double, D> table_;
};

/// Derivatives of order k (k = 0: points) of any curve, and the points of the curves
/// without a batch evaluation: the io library's DerivativeTable of the curve's pieces.
class PieceDerivatives final : public BatchEvaluator {
 public:
  PieceDerivatives(const io::AnyCurve& c, int k) : table_(c, k) {}
  bool evaluate(std::span<const double> t, double* out) const override { return table_.evaluate(t, out); }

 private:
  io::DerivativeTable table_;
};

template <int D>
std::unique_ptr<BatchEvaluator> evaluator_of(const io::AnyCurve& c) {
  if (const auto* s = std::get_if<CubicSpline<double, D>>(&c)) return std::make_unique<SortedMembers<CubicSpline<double, D>>>(*s);
  if (const auto* h = std::get_if<Hermite<double, D>>(&c)) return std::make_unique<SortedMembers<Hermite<double, D>>>(*h);
  if (auto table = SpanTable<double, D>::of(std::get<Pieces<double, D>>(io::pieces(c)))) {
    return std::make_unique<Table<D>>(std::move(*table));
  }
  return nullptr;  // rational curves (NURBS' batch member would instantiate BSpline<double, D + 1>::evaluate
                   // up to D + 1 = 5 here) and degrees above the table's: PieceDerivatives of order 0
}

/// The evaluator of c (which must outlive it), or nullptr when c has none (the caller uses
/// PieceDerivatives). The types are named one by one per dimension rather than through a
/// visit of AnyCurve's 40 alternatives (compile time).
std::unique_ptr<BatchEvaluator> batch_evaluator(const io::AnyCurve& c) {
  return io::dispatch_dimension(io::dimension(c), [&]<int D>() { return evaluator_of<D>(c); });
}

// ---------------------------------------------------------------------------------------
// Curves and surfaces

/// The array's values, checked finite, naming "<name>[j]" (j: the flat index).
void require_finite_array(const Doubles& a, const std::string& name) {
  const double* x = a.data();
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    if (!std::isfinite(x[i])) throw not_finite(child(name, static_cast<std::size_t>(i)), x[i]);
  }
}

/// A curve read once from curve JSON (text, or a Python object).
class Curve {
 public:
  explicit Curve(const py::object& obj) : curve_(from_arrays(obj)) {
    if (!curve_) {
      json_ = py::isinstance<py::str>(obj) ? io::parse_json(obj.cast<std::string>()) : json_of(obj, "");
      has_json_ = true;
      // new from the prvalue (elided): AnyCurve is never moved or copied here, which would
      // instantiate its 40-alternative variant's move (seconds of compile time).
      curve_.reset(new io::AnyCurve(io::curve_from_json(json_)));
    }
  }

  [[nodiscard]] int dim() const { return io::dimension(*curve_); }
  [[nodiscard]] std::string type() const { return std::string(io::type_name(*curve_)); }
  [[nodiscard]] std::pair<double, double> domain() const {
    const auto d = io::domain(*curve_);
    return {d.lo, d.hi};
  }
  /// The curve JSON as the library writes it (every field explicit: breaks, knots): text,
  /// or Python data (lists, as json.loads gives).
  [[nodiscard]] std::string to_json() const { return io::to_json(*curve_).dump(); }
  [[nodiscard]] py::object to_data() const { return py_of(io::to_json(*curve_), false); }
  /// The curve JSON (as given, or as the library writes it for a curve made from arrays).
  [[nodiscard]] const io::Json& json() const {
    if (!has_json_) {
      json_ = io::parse_json(io::to_json(*curve_).dump());
      has_json_ = true;
    }
    return json_;
  }

  /// Points (k = 0) or order-k derivatives at every parameter of t, any shape: an array of
  /// shape t.shape + (d,). Errors name "t[j]" with j the flat (C-order) index. Points go
  /// through the library's batch evaluation when the curve has one (built at the first
  /// call, while the GIL is held: no other thread sees it half built), whatever the
  /// number of parameters, so that a point does not depend on the batch it is in (Dask
  /// blocks against one call).
  [[nodiscard]] py::array_t<double> evaluate(const Doubles& t, int k) const {
    if (k < 0) throw InvalidArgument("nu", "must be >= 0, got " + std::to_string(k));
    const std::size_t n = static_cast<std::size_t>(t.size());
    const std::span<const double> ts(t.data(), n);
    std::vector<py::ssize_t> shape(t.shape(), t.shape() + t.ndim());
    shape.push_back(dim());
    py::array_t<double> result(shape);
    double* out = result.mutable_data();
    // Lagrange curves: their own barycentric formulas at any degree (the tables go through
    // the Bézier form, which the library refuses above degree 15 and which is less
    // accurate than the barycentric evaluation below it).
    const bool direct = io::type_name(*curve_) == "lagrange";
    if (k == 0 && !fast_built_ && !direct) {
      fast_ = batch_evaluator(*curve_);
      fast_built_ = true;
    }
    const BatchEvaluator* path = k == 0 ? fast_.get() : nullptr;
    if (path == nullptr && k <= max_table_order && !direct) {
      // Derivatives, and points of the curves without a batch evaluation (rational ones,
      // degrees above the SpanTable's): the pieces' table of order k, built once.
      if (derivatives_.size() <= static_cast<std::size_t>(k)) derivatives_.resize(static_cast<std::size_t>(k) + 1);
      auto& table = derivatives_[static_cast<std::size_t>(k)];
      if (!table) table = std::make_unique<PieceDerivatives>(*curve_, k);
      path = table.get();
    }
    bool done = false;
    {
      py::gil_scoped_release release;
      if (path != nullptr) done = path->evaluate(ts, out);
      if (!done) {
        // Orders above the tables', and the error of a parameter or a point that is not
        // finite.
        const io::PointList pts = k == 0 ? io::evaluate(*curve_, ts) : io::derivatives(*curve_, ts, k);
        std::copy(pts.coords.begin(), pts.coords.end(), out);
      }
    }
    return result;
  }

  /// The curvature at every parameter of t (the shape of t).
  [[nodiscard]] py::array_t<double> curvature(const Doubles& t) const {
    const std::span<const double> ts(t.data(), static_cast<std::size_t>(t.size()));
    std::vector<py::ssize_t> shape(t.shape(), t.shape() + t.ndim());
    py::array_t<double> result(shape);
    std::vector<double> k;
    {
      py::gil_scoped_release release;
      k = io::curvature(*curve_, ts);
    }
    std::copy(k.begin(), k.end(), result.mutable_data());
    return result;
  }

  /// io::project_rows at each row of points (n, d): (t (n,), point (n, d), distance (n,)).
  /// Errors name "points[i][k]"; rows run without the GIL.
  [[nodiscard]] py::tuple project_rows(const Doubles& points, bool farthest) const {
    const int d = dim();
    if (points.ndim() != 2 || points.shape(1) != d) {
      throw InvalidArgument("points", "must be an array of shape (n, " + std::to_string(d) + ") (the curve's dimension), got " +
                                          std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(
                                              points.shape(), points.shape() + points.ndim()))))));
    }
    const std::size_t n = static_cast<std::size_t>(points.shape(0)), m = static_cast<std::size_t>(d);
    const double* x = points.data();
    for (std::size_t i = 0; i < n * m; ++i) {
      if (!std::isfinite(x[i])) throw not_finite(child(child("points", i / m), i % m), x[i]);
    }
    py::array_t<double> t(static_cast<py::ssize_t>(n)), dist(static_cast<py::ssize_t>(n));
    py::array_t<double> pts(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), d});
    double *to = t.mutable_data(), *po = pts.mutable_data(), *dout = dist.mutable_data();
    const io::ProjectionPieces& pieces = projection_pieces();
    {
      py::gil_scoped_release release;
      io::project_rows(pieces, std::span<const double>(x, n * m), farthest, std::span<double>(to, n),
                       std::span<double>(po, n * m), std::span<double>(dout, n));
    }
    return py::make_tuple(t, pts, dist);
  }

  /// io::project at one point (d,): the project command's answer (t, point, distance and,
  /// on ties, all_t and intervals) as a dict, on the curve's kept pieces (no JSON).
  [[nodiscard]] py::dict project_point(const Doubles& point, bool farthest) const {
    const std::span<const double> q(point.data(), static_cast<std::size_t>(point.size()));
    for (std::size_t k = 0; k < q.size(); ++k) {
      if (!std::isfinite(q[k])) throw not_finite(child("point", k), q[k]);  // the package's message
    }
    const io::ProjectionPieces& pieces = projection_pieces();
    std::optional<io::AnyProjection> r;
    {
      py::gil_scoped_release release;
      r.emplace(io::project(pieces, q, farthest));
    }
    return std::visit(
        []<int D>(const casteljau::Projection<double, D>& p) {
          py::array_t<double> point(D);
          for (int k = 0; k < D; ++k) point.mutable_data()[k] = p.point[k];
          py::dict out;
          out["t"] = p.t;
          out["point"] = point;
          out["distance"] = p.distance;
          if (!p.all_t.empty()) out["all_t"] = py::array_t<double>(static_cast<py::ssize_t>(p.all_t.size()), p.all_t.data());
          if (!p.intervals.empty()) {
            py::array_t<double> iv(std::vector<py::ssize_t>{static_cast<py::ssize_t>(p.intervals.size()), 2});
            for (std::size_t i = 0; i < p.intervals.size(); ++i) {
              iv.mutable_data()[2 * i] = p.intervals[i].lo;
              iv.mutable_data()[2 * i + 1] = p.intervals[i].hi;
            }
            out["intervals"] = iv;
          }
          return out;
        },
        *r);
  }

  /// The command on this curve: the request (a dict without the curve) with the curve
  /// under `field`; the response as Python data (arrays of numbers as numpy arrays).
  [[nodiscard]] py::object run(const std::string& command, const py::dict& request, const std::string& field) const {
    const io::Command& c = command_named(command);
    io::Json r = json_of(request, "");
    r[field] = json();
    io::Response out;
    {
      py::gil_scoped_release release;
      out = io::run(c, r);
    }
    return py_of(out.json, true);
  }

 private:
  /// A cubic_spline given as {type, params, points[, boundary]} with float numpy arrays
  /// params (n,) and points (n, d), made from the arrays without their JSON (W9's build
  /// of 10^6 points: the JSON values alone take longer than the spline); nullopt for
  /// anything else, and for anything the library refuses (the JSON path then gives the
  /// reader's own error).
  static std::unique_ptr<const io::AnyCurve> from_arrays(const py::object& obj) {
    if (!PyDict_Check(obj.ptr())) return nullptr;
    const auto d = py::reinterpret_borrow<py::dict>(obj);
    for (const auto& [k, v] : d) {
      const std::string key = py::str(k);
      if (key != "type" && key != "params" && key != "points" && key != "boundary") return nullptr;
    }
    if (!d.contains("type") || !d.contains("params") || !d.contains("points")) return nullptr;
    if (!py::isinstance<py::str>(d["type"]) || d["type"].cast<std::string>() != "cubic_spline") return nullptr;
    std::string boundary = "natural";
    if (d.contains("boundary")) {
      if (!py::isinstance<py::str>(d["boundary"])) return nullptr;
      boundary = d["boundary"].cast<std::string>();
    }
    const py::object params = d["params"], points = d["points"];
    if (!py::isinstance<py::array>(params) || !py::isinstance<py::array>(points)) return nullptr;
    const auto pa = py::reinterpret_borrow<py::array>(params), qa = py::reinterpret_borrow<py::array>(points);
    if (pa.dtype().kind() != 'f' || qa.dtype().kind() != 'f' || pa.ndim() != 1 || qa.ndim() != 2) return nullptr;
    const Doubles x = Doubles::ensure(pa), y = Doubles::ensure(qa);
    const std::size_t n = static_cast<std::size_t>(x.shape(0));
    const int dim = static_cast<int>(y.shape(1));
    if (n < 2 || static_cast<std::size_t>(y.shape(0)) != n || dim < 1 || dim > io::max_dimension) return nullptr;
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(x.data()[i])) return nullptr;
    for (std::size_t i = 0; i < n * static_cast<std::size_t>(dim); ++i)
      if (!std::isfinite(y.data()[i])) return nullptr;
    try {
      return std::unique_ptr<const io::AnyCurve>(
          new io::AnyCurve(io::cubic_spline_from_arrays(std::span<const double>(x.data(), n), y.data(), dim, boundary)));
    } catch (const InvalidArgument&) {
      return nullptr;
    }
  }

  std::unique_ptr<const io::AnyCurve> curve_;
  mutable io::Json json_;
  mutable bool has_json_ = false;
  mutable std::unique_ptr<BatchEvaluator> fast_;
  mutable bool fast_built_ = false;
  /// The order-k tables (PieceDerivatives), built at the first call of that order.
  static constexpr int max_table_order = 16;
  mutable std::vector<std::unique_ptr<BatchEvaluator>> derivatives_;
  /// The exact pieces for project, made at the first projection (while the GIL is held:
  /// no other thread sees them half made) and kept.
  mutable std::unique_ptr<const io::ProjectionPieces> pieces_;
  [[nodiscard]] const io::ProjectionPieces& projection_pieces() const {
    if (!pieces_) pieces_ = io::projection_pieces(*curve_);
    return *pieces_;
  }
};

/// A surface read once from surface JSON (text, or a Python object).
class Surface {
 public:
  explicit Surface(const py::object& obj)
      : json_(py::isinstance<py::str>(obj) ? io::parse_json(obj.cast<std::string>()) : json_of(obj, "")),
        surface_(io::surface_from_json(json_)) {}

  [[nodiscard]] int dim() const { return surface_.dim(); }
  [[nodiscard]] std::string type() const { return std::string(io::type_name(surface_.kind)); }
  /// ((u0, u1), (v0, v1)).
  [[nodiscard]] py::tuple domain() const {
    const auto& f = surface_.form;
    const auto p = static_cast<std::size_t>(f.p), q = static_cast<std::size_t>(f.q);
    return py::make_tuple(py::make_tuple(f.U[p], f.U[f.U.size() - p - 1]), py::make_tuple(f.V[q], f.V[f.V.size() - q - 1]));
  }
  [[nodiscard]] std::string to_json() const { return io::to_json(surface_).dump(); }
  [[nodiscard]] py::object to_data() const { return py_of(io::to_json(surface_), false); }
  [[nodiscard]] const io::Json& json() const { return json_; }

  /// The points at (u[j], v[j]) (arrays of one shape, the caller broadcasts): shape
  /// u.shape + (d,). Errors name "u[j]" / "v[j]" (flat index).
  [[nodiscard]] py::array_t<double> evaluate(const Doubles& u, const Doubles& v) const {
    if (u.size() != v.size()) throw InvalidArgument("v", "needs one value per u");
    require_finite_array(u, "u");
    require_finite_array(v, "v");
    std::vector<py::ssize_t> shape(u.shape(), u.shape() + u.ndim());
    shape.push_back(dim());
    py::array_t<double> result(shape);
    double* out = result.mutable_data();
    py::gil_scoped_release release;
    io::surface_points(surface_, u.data(), v.data(), static_cast<std::size_t>(u.size()), out);
    return result;
  }

  /// The eval command's answer at the rows of uv (n, 2) (finite; n >= 1), computed on the
  /// arrays (io::surface_partials, the command's values, and its geometry): points,
  /// partials {u, v, uu, uv, vv, ...} of orders 1..k, normals, gaussian, mean, principal
  /// as numpy arrays (a list with None where a normal is undefined, as the command's
  /// null). The command's checks and messages.
  [[nodiscard]] py::dict eval(const Doubles& uv, int k, bool normal, bool curvature) const {
    if (k < 0) throw InvalidArgument("derivatives", "derivative count must be >= 0, got " + std::to_string(k));
    if (k > 64) throw InvalidArgument("derivatives", "derivative count must be <= 64, got " + std::to_string(k));
    for (const auto& [on, field, what] : {std::tuple{normal, "normal", "normals"}, std::tuple{curvature, "curvature", "curvatures"}}) {
      if (on && dim() != 3) throw InvalidArgument(field, std::string(what) + " need a 3-D surface, got " + std::to_string(dim()) + "-D");
    }
    if (uv.ndim() != 2 || uv.shape(1) != 2) throw InvalidArgument("uv", "must be an array of [u, v] pairs");
    const int order = std::max(k, curvature ? 2 : normal ? 1 : 0);
    const std::size_t n = static_cast<std::size_t>(uv.shape(0)), cd = static_cast<std::size_t>(dim()), K = static_cast<std::size_t>(order) + 1;
    const std::size_t block = K * K * cd;
    std::vector<double> u(n), v(n), d(n * block);
    for (std::size_t i = 0; i < n; ++i) {
      u[i] = uv.data()[2 * i];
      v[i] = uv.data()[2 * i + 1];
    }
    std::vector<casteljau::detail::SurfaceGeometry<double>> g;
    {
      py::gil_scoped_release release;
      io::surface_partials(surface_, u.data(), v.data(), n, order, d.data());
      if (normal || curvature) {
        g.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
          const auto at = [&](std::size_t a, std::size_t b) { return d.data() + i * block + (a * K + b) * cd; };
          g[i] = order >= 2 ? casteljau::detail::geometry<double>(at(1, 0), at(0, 1), at(2, 0), at(1, 1), at(0, 2))
                            : casteljau::detail::geometry<double>(at(1, 0), at(0, 1), at(0, 0), at(0, 0), at(0, 0));
        }
      }
    }
    const auto rows = [&](std::size_t width, const auto& value) {
      py::array_t<double> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(width)});
      double* o = a.mutable_data();
      for (std::size_t i = 0; i < n; ++i) value(i, o + i * width);
      return a;
    };
    py::dict out;
    out["points"] = rows(cd, [&](std::size_t i, double* o) { std::copy_n(d.data() + i * block, cd, o); });
    if (k > 0) {
      py::dict p;
      for (std::size_t o = 1; o <= static_cast<std::size_t>(k); ++o) {
        for (std::size_t b = 0; b <= o; ++b) {
          const std::size_t a = o - b;
          p[py::str(std::string(a, 'u') + std::string(b, 'v'))] =
              rows(cd, [&](std::size_t i, double* x) { std::copy_n(d.data() + i * block + (a * K + b) * cd, cd, x); });
        }
      }
      out["partials"] = p;
    }
    // A geometric field: an array of every point's value, or, where some normal is
    // undefined, a list with None there (the command's null).
    bool all_defined = true;
    for (const auto& x : g) all_defined &= x.defined;
    const auto field = [&](std::size_t width, const auto& value) -> py::object {
      py::array a = rows(width, value);
      if (width == 1) a = a.reshape(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n)});
      if (all_defined) return a;
      py::list l;
      for (std::size_t i = 0; i < n; ++i) l.append(g[i].defined ? py::object(a[py::int_(i)]) : py::object(py::none()));
      return l;
    };
    if (normal) out["normals"] = field(3, [&](std::size_t i, double* o) { std::copy_n(g[i].normal, 3, o); });
    if (curvature) {
      out["gaussian"] = field(1, [&](std::size_t i, double* o) { *o = g[i].gaussian; });
      out["mean"] = field(1, [&](std::size_t i, double* o) { *o = g[i].mean; });
      out["principal"] = field(2, [&](std::size_t i, double* o) { o[0] = g[i].k1; o[1] = g[i].k2; });
    }
    return out;
  }

  /// The limit normal at (u, v) (io::limit_normal): a (3,) array, or None where it does not
  /// exist. Errors name "u" / "v" (not finite) and "normal" (not 3-D).
  [[nodiscard]] py::object limit_normal(double u, double v) const {
    if (!std::isfinite(u)) throw InvalidArgument("u", "must be finite");
    if (!std::isfinite(v)) throw InvalidArgument("v", "must be finite");
    std::optional<std::array<double, 3>> n;
    {
      py::gil_scoped_release release;
      n = io::limit_normal(surface_, u, v);
    }
    if (!n) return py::none();
    py::array_t<double> a(3);
    std::copy(n->begin(), n->end(), a.mutable_data());
    return std::move(a);
  }

  [[nodiscard]] py::object run(const std::string& command, const py::dict& request, const std::string& field) const {
    const io::Command& c = command_named(command);
    io::Json r = json_of(request, "");
    r[field] = json_;
    io::Response out;
    {
      py::gil_scoped_release release;
      out = io::run(c, r);
    }
    return py_of(out.json, true);
  }

 private:
  io::Json json_;
  io::AnySurface surface_;
};

const io::Json* stored_json(py::handle v) {
  if (py::isinstance<Curve>(v)) return &v.cast<const Curve&>().json();
  if (py::isinstance<Surface>(v)) return &v.cast<const Surface&>().json();
  // The package's Python wrappers hold the compiled object as _c (curves) or _s (surfaces).
  for (const char* attr : {"_c", "_s"}) {
    if (py::hasattr(v, attr)) {
      const py::object inner = v.attr(attr);
      if (py::isinstance<Curve>(inner)) return &inner.cast<const Curve&>().json();
      if (py::isinstance<Surface>(inner)) return &inner.cast<const Surface&>().json();
    }
  }
  return nullptr;
}

py::list fields_list(std::span<const io::Field> fields) {
  py::list out;
  for (const auto& f : fields) {
    out.append(py::make_tuple(std::string(f.name), std::string(io::field_type_name(f.type)), f.required,
                              std::string(f.default_json), std::string(f.help)));
  }
  return out;
}

py::list curve_types() {
  py::list out;
  for (const auto& t : io::curve_types()) {
    py::list fields;
    for (const auto f : t.fields) fields.append(std::string(f));
    out.append(py::make_tuple(std::string(t.name), std::string(t.class_name), fields));
  }
  return out;
}

py::list surface_types() {
  py::list out;
  for (const auto& t : io::surface_types()) {
    py::list fields;
    for (const auto f : t.fields) fields.append(std::string(f));
    out.append(py::make_tuple(std::string(t.name), fields));
  }
  return out;
}

py::list commands() {
  py::list out;
  for (const auto& c : io::commands()) out.append(py::make_tuple(std::string(c.name), std::string(c.summary), fields_list(c.fields)));
  return out;
}

/// The commands that have a surface form (io::surface_form): (name, summary, fields).
py::list surface_forms() {
  py::list out;
  for (const auto& c : io::commands()) {
    if (const io::Command* s = io::surface_form(c.name)) {
      out.append(py::make_tuple(std::string(s->name), std::string(s->summary), fields_list(s->fields)));
    }
  }
  return out;
}

/// Runs a command: the request as JSON text or Python data, the response as Python data.
py::object run(const std::string& command, const py::object& request) {
  const io::Command& c = command_named(command);
  const io::Json r = py::isinstance<py::str>(request) ? io::parse_json(request.cast<std::string>()) : json_of(request, "");
  io::Response out;
  {
    py::gil_scoped_release release;
    out = io::run(c, r);
  }
  return py_of(out.json, true);
}

}  // namespace

PYBIND11_MODULE(_casteljau, m) {
  m.doc() = "casteljau's compiled core: the io library's registries and commands (see the casteljau package)";

  static py::exception<InvalidArgument> error(m, "Error", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidArgument& e) {
      PyErr_SetString(error.ptr(), where_what(e).c_str());
    } catch (const casteljau::NumericalError& e) {
      PyErr_SetString(error.ptr(), (std::string("numerical: ") + e.what()).c_str());
    }
  });

  m.def("curve_types", &curve_types, "The registry's curve types: (json name, class name, fields).");
  m.def("surface_types", &surface_types, "The registry's surface types: (json name, fields).");
  m.def("commands", &commands, "The registry's commands: (name, summary, [(field, type, required, default, help)]).");
  m.def("surface_forms", &surface_forms, "The surface forms of commands: (name, summary, fields).");
  m.def("run", &run, py::arg("command"), py::arg("request"), "Runs a command: the request as JSON text or Python data.");
  m.def("to_json_text", [](const py::object& v) { return json_of(v, "").dump(); }, py::arg("value"),
        "Python data (with numpy arrays, curves, surfaces) as JSON text; NaN refused naming its path.");
  m.attr("max_dimension") = io::max_dimension;

  py::class_<Curve>(m, "Curve")
      .def(py::init<const py::object&>(), py::arg("json"))
      .def_property_readonly("dim", &Curve::dim)
      .def_property_readonly("type", &Curve::type)
      .def_property_readonly("domain", &Curve::domain)
      .def("to_json", &Curve::to_json)
      .def("to_data", &Curve::to_data)
      .def("evaluate", &Curve::evaluate, py::arg("t"), py::arg("nu") = 0)
      .def("curvature", &Curve::curvature, py::arg("t"))
      .def("project_rows", &Curve::project_rows, py::arg("points"), py::arg("farthest") = false)
      .def("project_point", &Curve::project_point, py::arg("point"), py::arg("farthest") = false)
      .def("run", &Curve::run, py::arg("command"), py::arg("request"), py::arg("field") = "curve");

  py::class_<Surface>(m, "Surface")
      .def(py::init<const py::object&>(), py::arg("json"))
      .def_property_readonly("dim", &Surface::dim)
      .def_property_readonly("type", &Surface::type)
      .def_property_readonly("domain", &Surface::domain)
      .def("to_json", &Surface::to_json)
      .def("to_data", &Surface::to_data)
      .def("evaluate", &Surface::evaluate, py::arg("u"), py::arg("v"))
      .def("eval", &Surface::eval, py::arg("uv"), py::arg("derivatives"), py::arg("normal"), py::arg("curvature"))
      .def("limit_normal", &Surface::limit_normal, py::arg("u"), py::arg("v"))
      .def("run", &Surface::run, py::arg("command"), py::arg("request"), py::arg("field") = "surface");
}
