// An independent oracle for B-spline and NURBS operations: OpenCASCADE's Geom_BSplineCurve
// (libocct-modeling-data-dev). It links no casteljau code. One JSON request per line on
// stdin, one JSON answer per line on stdout:
//
//   {"op": "eval" | "insert_knot" | "remove_knot" | "elevate" | "segment",
//    "degree": p, "knots": [full knot vector], "points": [[x, y, z?], ...],
//    "weights": [...] (optional: NURBS), "eval": [u, ...] (optional),
//    "knot": u, "times": r (insert_knot, remove_knot, elevate), "tolerance": tol (remove_knot),
//    "from": u0, "to": u1 (segment)}
//
// answers {"degree", "knots" (full), "points" (Cartesian, the request's dimension),
// "weights" (NURBS only), "eval": [[point, first derivative, second derivative], ...] at
// the requested parameters on the resulting curve, and for remove_knot "removed": the
// largest k <= times for which RemoveKnot(index, multiplicity - k, tolerance) succeeds}.
//
// Surfaces (Geom_BSplineSurface, evaluated through GeomAdaptor_Surface, its cached
// evaluator): {"op": "surface_eval", "degree": [p, q], "knots": [U, V] (full vectors),
// "points": grid [i][j] of 3-D points, "weights": grid (optional: NURBS), "uv": [[u, v],
// ...]} answers {"eval": [[S, S_u, S_v, S_uu, S_uv, S_vv], ...]} (GeomAdaptor_Surface::D2)
// and {"d0": [S, ...]} (D0 of the same adaptor).
// Errors: {"error": "..."}.
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

struct Curve {
  Handle(Geom_BSplineCurve) c;
  int dim = 3;
  bool rational = false;
};

Curve make(const json& r) {
  const int p = r.at("degree").get<int>();
  const auto flat = r.at("knots").get<std::vector<double>>();
  const auto& pts = r.at("points");
  const int n = static_cast<int>(pts.size());
  Curve out;
  out.dim = static_cast<int>(pts.at(0).size());
  if (out.dim < 1 || out.dim > 3) throw std::runtime_error("dimension must be 1..3");
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) {
    double x[3] = {0, 0, 0};
    for (int k = 0; k < out.dim; ++k) x[k] = pts.at(static_cast<std::size_t>(i)).at(static_cast<std::size_t>(k)).get<double>();
    poles(i + 1) = gp_Pnt(x[0], x[1], x[2]);
  }
  std::vector<double> distinct;
  std::vector<int> mult;
  for (const double u : flat) {
    if (!distinct.empty() && distinct.back() == u) {
      ++mult.back();
    } else {
      distinct.push_back(u);
      mult.push_back(1);
    }
  }
  TColStd_Array1OfReal knots(1, static_cast<int>(distinct.size()));
  TColStd_Array1OfInteger mults(1, static_cast<int>(distinct.size()));
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    knots(static_cast<int>(i) + 1) = distinct[i];
    mults(static_cast<int>(i) + 1) = mult[i];
  }
  if (r.contains("weights")) {
    const auto w = r.at("weights").get<std::vector<double>>();
    TColStd_Array1OfReal weights(1, n);
    for (int i = 0; i < n; ++i) weights(i + 1) = w.at(static_cast<std::size_t>(i));
    out.c = new Geom_BSplineCurve(poles, weights, knots, mults, p);
    out.rational = true;
  } else {
    out.c = new Geom_BSplineCurve(poles, knots, mults, p);
  }
  return out;
}

json coords(double x, double y, double z, int dim) {
  json a = json::array();
  const double v[3] = {x, y, z};
  for (int k = 0; k < dim; ++k) a.push_back(v[k]);
  return a;
}

json describe(const Curve& cv, const json& r) {
  const auto& c = cv.c;
  json out;
  out["degree"] = c->Degree();
  json knots = json::array();
  for (int i = 1; i <= c->NbKnots(); ++i)
    for (int m = 0; m < c->Multiplicity(i); ++m) knots.push_back(c->Knot(i));
  out["knots"] = knots;
  json points = json::array(), weights = json::array();
  for (int i = 1; i <= c->NbPoles(); ++i) {
    const gp_Pnt& q = c->Pole(i);
    points.push_back(coords(q.X(), q.Y(), q.Z(), cv.dim));
    weights.push_back(c->Weight(i));
  }
  out["points"] = points;
  if (cv.rational) out["weights"] = weights;
  if (r.contains("eval")) {
    json ev = json::array();
    for (const auto& uj : r.at("eval")) {
      gp_Pnt q;
      gp_Vec d1, d2;
      c->D2(uj.get<double>(), q, d1, d2);
      ev.push_back({coords(q.X(), q.Y(), q.Z(), cv.dim), coords(d1.X(), d1.Y(), d1.Z(), cv.dim),
                    coords(d2.X(), d2.Y(), d2.Z(), cv.dim)});
    }
    out["eval"] = ev;
  }
  return out;
}

/// The index (1-based) of the distinct knot equal to u, or 0.
int knot_index(const Handle(Geom_BSplineCurve) & c, double u) {
  for (int i = 1; i <= c->NbKnots(); ++i)
    if (c->Knot(i) == u) return i;
  return 0;
}

/// Distinct knots and multiplicities of a full knot vector.
void knots_and_mults(const std::vector<double>& flat, std::vector<double>& distinct, std::vector<int>& mult) {
  for (const double u : flat) {
    if (!distinct.empty() && distinct.back() == u) {
      ++mult.back();
    } else {
      distinct.push_back(u);
      mult.push_back(1);
    }
  }
}

json surface_eval(const json& r) {
  const int p = r.at("degree").at(0).get<int>(), q = r.at("degree").at(1).get<int>();
  const auto& pts = r.at("points");
  const int rows = static_cast<int>(pts.size()), cols = static_cast<int>(pts.at(0).size());
  TColgp_Array2OfPnt poles(1, rows, 1, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const auto& x = pts.at(static_cast<std::size_t>(i)).at(static_cast<std::size_t>(j));
      poles(i + 1, j + 1) = gp_Pnt(x.at(0).get<double>(), x.at(1).get<double>(), x.at(2).get<double>());
    }
  std::vector<double> du, dv;
  std::vector<int> mu, mv;
  knots_and_mults(r.at("knots").at(0).get<std::vector<double>>(), du, mu);
  knots_and_mults(r.at("knots").at(1).get<std::vector<double>>(), dv, mv);
  TColStd_Array1OfReal uk(1, static_cast<int>(du.size())), vk(1, static_cast<int>(dv.size()));
  TColStd_Array1OfInteger um(1, static_cast<int>(du.size())), vm(1, static_cast<int>(dv.size()));
  for (std::size_t i = 0; i < du.size(); ++i) {
    uk(static_cast<int>(i) + 1) = du[i];
    um(static_cast<int>(i) + 1) = mu[i];
  }
  for (std::size_t i = 0; i < dv.size(); ++i) {
    vk(static_cast<int>(i) + 1) = dv[i];
    vm(static_cast<int>(i) + 1) = mv[i];
  }
  Handle(Geom_BSplineSurface) s;
  if (r.contains("weights")) {
    TColStd_Array2OfReal w(1, rows, 1, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) w(i + 1, j + 1) = r.at("weights").at(static_cast<std::size_t>(i)).at(static_cast<std::size_t>(j)).get<double>();
    s = new Geom_BSplineSurface(poles, w, uk, vk, um, vm, p, q);
  } else {
    s = new Geom_BSplineSurface(poles, uk, vk, um, vm, p, q);
  }
  GeomAdaptor_Surface a(s);
  json ev = json::array(), d0 = json::array();
  for (const auto& uv : r.at("uv")) {
    const double u = uv.at(0).get<double>(), v = uv.at(1).get<double>();
    gp_Pnt x;
    gp_Vec su, sv, suu, svv, suv;
    a.D2(u, v, x, su, sv, suu, svv, suv);
    ev.push_back({coords(x.X(), x.Y(), x.Z(), 3), coords(su.X(), su.Y(), su.Z(), 3), coords(sv.X(), sv.Y(), sv.Z(), 3),
                  coords(suu.X(), suu.Y(), suu.Z(), 3), coords(suv.X(), suv.Y(), suv.Z(), 3), coords(svv.X(), svv.Y(), svv.Z(), 3)});
    const gp_Pnt y = a.Value(u, v);
    d0.push_back(coords(y.X(), y.Y(), y.Z(), 3));
  }
  return {{"eval", ev}, {"d0", d0}};
}

json answer(const json& r) {
  const std::string op = r.at("op").get<std::string>();
  if (op == "surface_eval") return surface_eval(r);
  Curve cv = make(r);
  if (op == "eval") return describe(cv, r);
  if (op == "insert_knot") {
    const double u = r.at("knot").get<double>();
    const int times = r.value("times", 1);
    const int i = knot_index(cv.c, u);
    const int have = i ? cv.c->Multiplicity(i) : 0;
    // InsertKnot raises the multiplicity to `have + times` (Add = true adds to it).
    cv.c->InsertKnot(u, times, 0.0, true);
    (void)have;
    return describe(cv, r);
  }
  if (op == "remove_knot") {
    const double u = r.at("knot").get<double>();
    const int times = r.value("times", 1);
    const double tol = r.value("tolerance", 1e-12);
    const int i = knot_index(cv.c, u);
    if (i == 0) throw std::runtime_error("not a knot");
    const int m = cv.c->Multiplicity(i);
    int removed = 0;
    Handle(Geom_BSplineCurve) best = Handle(Geom_BSplineCurve)::DownCast(cv.c->Copy());
    for (int k = 1; k <= times && k <= m; ++k) {
      Handle(Geom_BSplineCurve) trial = Handle(Geom_BSplineCurve)::DownCast(cv.c->Copy());
      if (!trial->RemoveKnot(i, m - k, tol)) break;
      removed = k;
      best = trial;
    }
    cv.c = best;
    json out = describe(cv, r);
    out["removed"] = removed;
    return out;
  }
  if (op == "elevate") {
    cv.c->IncreaseDegree(cv.c->Degree() + r.at("times").get<int>());
    return describe(cv, r);
  }
  if (op == "segment") {
    cv.c->Segment(r.at("from").get<double>(), r.at("to").get<double>());
    return describe(cv, r);
  }
  throw std::runtime_error("unknown op " + op);
}

}  // namespace

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    if (line.empty()) continue;
    json out;
    try {
      out = answer(json::parse(line));
    } catch (const Standard_Failure& e) {
      out = {{"error", std::string("OCCT: ") + e.GetMessageString()}};
    } catch (const std::exception& e) {
      out = {{"error", e.what()}};
    }
    std::cout << out.dump(-1, ' ', false, json::error_handler_t::replace) << '\n' << std::flush;
  }
  return 0;
}
