// The compiled part of the Python package `casteljau` (python/casteljau/): a thin layer over
// the io library's run-time interfaces, so that it instantiates no curve algorithm of its
// own (docs/python.md, "How it is built"):
// - the registry: the curve types (curve-JSON name, class name, fields) and the commands
//   (name, summary, fields), from which python/casteljau/_curves.py generates the classes
//   and methods;
// - `Curve`: one io::AnyCurve read once from curve JSON, evaluated on numpy arrays (values
//   and derivatives, the GIL released), and the commands run on it (`run`, and `run_each`
//   over the rows of an array: one request per row, in C++);
// - `run(command, request)`: any command, JSON text in and out;
// - `Error` (a ValueError): the library's InvalidArgument as "<where>: <what>", the
//   command line's message.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "casteljau/io/commands.hpp"
#include "casteljau/io/json.hpp"

namespace py = pybind11;
namespace io = casteljau::io;
using casteljau::InvalidArgument;

namespace {

/// The command line's form of a library error (apps/cli/main.cpp): "<where>: <what>", the
/// request itself named "request".
std::string where_what(const InvalidArgument& e) {
  return (e.where().empty() ? std::string("request") : e.where()) + ": " + e.problem();
}

/// A non-finite number as Python prints it ("nan", "inf", "-inf").
std::string number_text(double v) { return std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf"; }

const io::Command& command_named(const std::string& name) {
  const io::Command* c = io::find_command(name);
  if (c == nullptr) throw InvalidArgument("command", "unknown command " + io::quoted(name));
  return *c;
}

/// The response as JSON text (render: its {"svg": ...} form).
std::string response_text(const io::Response& r) { return r.json.dump(); }

/// A curve read once from curve JSON.
class Curve {
 public:
  explicit Curve(const std::string& text) : json_(io::parse_json(text)), curve_(io::curve_from_json(json_)) {}

  [[nodiscard]] int dim() const { return io::dimension(curve_); }
  [[nodiscard]] std::string type() const { return std::string(io::type_name(curve_)); }
  [[nodiscard]] std::pair<double, double> domain() const {
    const auto d = io::domain(curve_);
    return {d.lo, d.hi};
  }
  /// The curve JSON as the library writes it (every field explicit: breaks, knots).
  [[nodiscard]] std::string to_json() const { return io::to_json(curve_).dump(); }

  /// Points (k = 0) or order-k derivatives at every parameter of t, any shape: an array of
  /// shape t.shape + (d,). Errors name "t[j]" with j the flat (C-order) index.
  [[nodiscard]] py::array_t<double> evaluate(const py::array_t<double, py::array::c_style | py::array::forcecast>& t,
                                             int k) const {
    if (k < 0) throw InvalidArgument("nu", "must be >= 0, got " + std::to_string(k));
    const std::size_t n = static_cast<std::size_t>(t.size());
    const std::span<const double> ts(t.data(), n);
    io::PointList out;
    {
      py::gil_scoped_release release;
      out = k == 0 ? io::evaluate(curve_, ts) : io::derivatives(curve_, ts, k);
    }
    std::vector<py::ssize_t> shape(t.shape(), t.shape() + t.ndim());
    shape.push_back(dim());
    py::array_t<double> result(shape);
    std::copy(out.coords.begin(), out.coords.end(), result.mutable_data());
    return result;
  }

  /// The command on this curve: the request (JSON text of an object without the curve)
  /// with the curve under `field`; the response as JSON text.
  [[nodiscard]] std::string run(const std::string& command, const std::string& request,
                                const std::string& field) const {
    const io::Command& c = command_named(command);
    io::Json r = io::parse_json(request);
    r[field] = json_;
    py::gil_scoped_release release;
    return response_text(io::run(c, r));
  }

  /// The command once per row of `rows` (shape (n, m), or (n,) for a number field): the
  /// request with the row under `row_field`; the responses as one JSON array. An error
  /// names the row: "<row_field>[i]: ..." ("points[3]: ..." reads as the caller's array).
  [[nodiscard]] std::string run_each(const std::string& command, const std::string& request, const std::string& field,
                                     const std::string& row_field, const std::string& row_name,
                                     const py::array_t<double, py::array::c_style | py::array::forcecast>& rows) const {
    const io::Command& c = command_named(command);
    io::Json r = io::parse_json(request);
    r[field] = json_;
    if (rows.ndim() != 1 && rows.ndim() != 2) throw InvalidArgument(row_name, "must be a 1-D or 2-D array");
    const std::size_t n = static_cast<std::size_t>(rows.shape(0));
    const std::size_t m = rows.ndim() == 2 ? static_cast<std::size_t>(rows.shape(1)) : 0;
    const double* data = rows.data();
    py::gil_scoped_release release;
    io::OrderedJson all = io::OrderedJson::array();
    for (std::size_t i = 0; i < n; ++i) {
      const std::string here = row_name + "[" + std::to_string(i) + "]";
      if (m == 0) {
        if (!std::isfinite(data[i])) {
          throw InvalidArgument(here, "must be a finite number, got " + number_text(data[i]));
        }
        r[row_field] = data[i];
      } else {
        io::Json row = io::Json::array();
        for (std::size_t j = 0; j < m; ++j) {
          const double v = data[i * m + j];
          if (!std::isfinite(v)) {
            throw InvalidArgument(here + "[" + std::to_string(j) + "]",
                                  "must be a finite number, got " + number_text(v));
          }
          row.push_back(v);
        }
        r[row_field] = std::move(row);
      }
      try {
        all.push_back(io::run(c, r).json);
      } catch (const InvalidArgument& e) {
        if (e.where() == row_field || e.where().starts_with(row_field + "[")) {
          throw InvalidArgument(here + e.where().substr(row_field.size()), e.problem());
        }
        throw;
      }
    }
    return all.dump();
  }

 private:
  io::Json json_;
  io::AnyCurve curve_;
};

py::list curve_types() {
  py::list out;
  for (const auto& t : io::curve_types()) {
    py::list fields;
    for (const auto f : t.fields) fields.append(std::string(f));
    out.append(py::make_tuple(std::string(t.name), std::string(t.class_name), fields));
  }
  return out;
}

py::list commands() {
  py::list out;
  for (const auto& c : io::commands()) {
    py::list fields;
    for (const auto& f : c.fields) {
      fields.append(py::make_tuple(std::string(f.name), std::string(io::field_type_name(f.type)), f.required,
                                   std::string(f.default_json), std::string(f.help)));
    }
    out.append(py::make_tuple(std::string(c.name), std::string(c.summary), fields));
  }
  return out;
}

std::string run(const std::string& command, const std::string& request) {
  const io::Command& c = command_named(command);
  const io::Json r = io::parse_json(request);
  py::gil_scoped_release release;
  return response_text(io::run(c, r));
}

}  // namespace

PYBIND11_MODULE(_casteljau, m) {
  m.doc() = "casteljau's compiled core: the io library's curve registry and commands (see the casteljau package)";

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
  m.def("commands", &commands, "The registry's commands: (name, summary, [(field, type, required, default, help)]).");
  m.def("run", &run, py::arg("command"), py::arg("request"), "Runs a command: request and response as JSON text.");
  m.attr("max_dimension") = io::max_dimension;

  py::class_<Curve>(m, "Curve")
      .def(py::init<const std::string&>(), py::arg("json"))
      .def_property_readonly("dim", &Curve::dim)
      .def_property_readonly("type", &Curve::type)
      .def_property_readonly("domain", &Curve::domain)
      .def("to_json", &Curve::to_json)
      .def("evaluate", &Curve::evaluate, py::arg("t"), py::arg("nu") = 0)
      .def("run", &Curve::run, py::arg("command"), py::arg("request"), py::arg("field") = "curve")
      .def("run_each", &Curve::run_each, py::arg("command"), py::arg("request"), py::arg("field"), py::arg("row_field"),
           py::arg("row_name"), py::arg("rows"));
}
