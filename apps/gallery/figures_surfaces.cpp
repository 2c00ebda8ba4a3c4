// Gallery figures of issue 19's surfaces: a surface of revolution, a lofted hull, a Coons
// patch and a bicubic patch with its control net, each with isocurves, and the torus
// tessellated at two tolerances. Each is built and drawn through the command registry
// (the `surface`, `tessellate` and `render` commands), as the command line does: the
// figures are JSON requests, so this file instantiates no surface templates of its own.
#include <cmath>
#include <cstdio>
#include <string>

#include "casteljau/io/commands.hpp"
#include "casteljau/io/json.hpp"
#include "draw.hpp"
#include "figures.hpp"

namespace casteljau::gallery {

namespace {

io::Json call(const char* command, const io::Json& request) {
  const io::Command* c = io::find_command(command);
  if (c == nullptr) throw std::runtime_error(std::string("no command ") + command);
  const io::Response r = io::run(*c, request);
  return io::Json::parse(r.json.dump());
}

io::Json build(const char* request) { return call("surface", io::Json::parse(request))["surface"]; }

/// The surface's picture: render with the given extras, the page `w` x `h` px.
std::string picture(const io::Json& surface, double w, double h, const char* extras) {
  io::Json req = io::Json::parse(extras);
  req["surface"] = surface;
  req["background"] = "none";  // the page's own (and the import_svg read-back's silhouettes)
  req["width"] = w;
  req["height"] = h;
  return call("render", req)["svg"].get<std::string>();
}

/// Two pictures side by side in one <svg> of the page's width: each picture's content (its
/// <svg> element's children) in a group moved to its half.
std::string side_by_side(const std::string& a, const std::string& b, double h) {
  const auto place = [](const std::string& s, double x) {
    const auto open = s.find('>', s.find("<svg ")) + 1, close = s.rfind("</svg>");
    return "<g transform=\"translate(" + std::to_string(static_cast<int>(x)) + ",0)\">" + s.substr(open, close - open) + "</g>";
  };
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(static_cast<int>(fig_width)) + "\" height=\"" +
         std::to_string(static_cast<int>(h)) + "\" viewBox=\"0 0 " + std::to_string(static_cast<int>(fig_width)) + " " +
         std::to_string(static_cast<int>(h)) + "\" role=\"img\">" + place(a, 0) + place(b, fig_width / 2) + "</svg>";
}

}  // namespace

Figure surface_of_revolution() {
  // A vase: a cubic B-spline profile in the xz plane turned about z (exact arcs).
  const io::Json s = build(R"({"construct": "revolve", "axis": {"point": [0,0,0], "direction": [0,0,1]},
    "curve": {"type": "bspline", "degree": 3, "knots": [0,0,0,0,0.25,0.5,0.75,1,1,1,1],
              "points": [[0.6,0,0],[1.3,0,0.3],[1.5,0,1.2],[0.7,0,2.0],[0.5,0,2.6],[0.8,0,3.2],[0.9,0,3.4]]}})");
  Figure f{"surface-of-revolution", "A surface of revolution", "", ""};
  f.svg = side_by_side(picture(s, fig_width / 2, 380, R"({"isocurves": 7, "tolerance": 0.03, "view": {"azimuth": 30, "elevation": 20}})"),
                       picture(s, fig_width / 2, 380, R"({"isocurves": 7, "tolerance": 0.03, "view": {"azimuth": 30, "elevation": 65}})"), 380);
  f.caption = "A cubic B-spline profile turned about the <i>z</i> axis by <code>surface</code> "
              "(<code>revolve</code>): a NURBS surface whose circles are exact rational quadratic arcs of 90 degrees. "
              "Seen from two elevations, with seven isocurves each way: the meridians are copies of the profile, the "
              "parallels circles. Shaded triangles of <code>tessellate</code> within 0.03 (a few pixels), drawn far to near.";
  return f;
}

Figure lofted_hull() {
  // Five cross-sections of a hull (cubic Bézier U shapes at stations along x), skinned.
  std::string curves;
  const double station[] = {0, 1.5, 3, 4.5, 6};
  const double beam[] = {0.25, 0.9, 1.1, 0.9, 0.15};
  const double depth[] = {0.6, 0.9, 1.0, 0.85, 0.4};
  for (int k = 0; k < 5; ++k) {
    char c[400];
    const double x = station[k], b = beam[k], d = depth[k];
    std::snprintf(c, sizeof c, R"(%s{"type": "bezier", "points": [[%g,%g,1],[%g,%g,%g],[%g,%g,%g],[%g,%g,1]]})", k ? "," : "", x, -b, x,
                  -b, 1 - 1.3 * d, x, b, 1 - 1.3 * d, x, b);
    curves += c;
  }
  const io::Json s = build(("{\"construct\": \"loft\", \"curves\": [" + curves + "]}").c_str());
  Figure f{"lofted-hull", "A lofted hull", "", ""};
  io::Json req = io::Json::parse(R"({"isocurves": 6, "tolerance": 0.03, "view": {"azimuth": -55, "elevation": 25}})");
  req["surface"] = s;
  req["curves"] = io::Json::parse("[" + curves + "]");
  req["background"] = "none";
  req["width"] = fig_width;
  req["height"] = 340;
  f.svg = call("render", req)["svg"].get<std::string>();
  f.caption = "Five cubic cross-sections (black) skinned by <code>loft</code> into a bicubic B-spline hull: the "
              "surface passes through every section at its parameter (chord-length spacing), with six isocurves "
              "each way.";
  return f;
}

Figure coons_patch() {
  const char* c0 = R"({"type": "bezier", "points": [[0,0,0],[1,0,0.8],[2,0,-0.4],[3,0,0]]})";
  const char* c1 = R"({"type": "bezier", "points": [[0,3,0.5],[1.5,3,1.5],[3,3,0.5]]})";
  const char* d0 = R"({"type": "bezier", "points": [[0,0,0],[0,1.5,1.2],[0,3,0.5]]})";
  const char* d1 = R"({"type": "bezier", "points": [[3,0,0],[3,1,-0.8],[3,2,0.8],[3,3,0.5]]})";
  const std::string curves = std::string("[") + c0 + "," + c1 + "," + d0 + "," + d1 + "]";
  const io::Json s = build(("{\"construct\": \"coons\", \"curves\": " + curves + "}").c_str());
  Figure f{"coons-patch", "A Coons patch", "", ""};
  io::Json req = io::Json::parse(R"({"isocurves": 8, "tolerance": 0.02, "view": {"azimuth": -60, "elevation": 35}})");
  req["surface"] = s;
  req["curves"] = io::Json::parse(curves);
  req["background"] = "none";
  req["width"] = fig_width;
  req["height"] = 340;
  f.svg = call("render", req)["svg"].get<std::string>();
  f.caption = "The bilinearly blended Coons patch of four boundary curves of different degrees (drawn in colour): "
              "ruled in <i>v</i> plus ruled in <i>u</i> minus the bilinear patch of the corners, written exactly as "
              "one B-spline surface. Its edges are the four curves; eight isocurves each way.";
  return f;
}

Figure bicubic_patch_with_net() {
  const io::Json s = io::Json::parse(R"({"type": "bezier_surface", "points": [
    [[0,0,0],[0,1,0.6],[0,2,0.6],[0,3,0]],
    [[1,0,0.5],[1,1,2.0],[1,2,-0.5],[1,3,0.4]],
    [[2,0,0.3],[2,1,-0.6],[2,2,1.6],[2,3,0.2]],
    [[3,0,0],[3,1,0.4],[3,2,0.4],[3,3,0]]]})");
  Figure f{"bicubic-patch", "A bicubic patch and its control net", "", ""};
  f.svg = picture(s, fig_width, 360, R"({"isocurves": 9, "tolerance": 0.02, "control_net": true, "view": {"azimuth": -50, "elevation": 30}})");
  f.caption = "A bicubic Bézier patch with its 4 x 4 control net (red): the corners are interpolated, the inner "
              "points pull the surface towards them, and the surface stays inside the net's convex hull. Nine "
              "isocurves each way, drawn with the triangles in painter's order, so that the far ones are hidden.";
  return f;
}

Figure torus_tessellation() {
  const io::Json torus = build(R"({"construct": "revolve", "axis": {"point": [0,0,0], "direction": [0,0,1]},
    "curve": {"type": "nurbs", "degree": 2, "knots": [0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1],
              "points": [[4,0,0],[4,0,1],[3,0,1],[2,0,1],[2,0,0],[2,0,-1],[3,0,-1],[4,0,-1],[4,0,0]],
              "weights": [1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1]}})");
  const double tols[2] = {0.15, 0.03};
  std::string pics[2], counts[2];
  for (int k = 0; k < 2; ++k) {
    io::Json req;
    req["surface"] = torus;
    req["tolerance"] = tols[k];
    const io::Json mesh = call("tessellate", req);
    counts[k] = std::to_string(mesh["triangles"].size());
    char extras[160];
    std::snprintf(extras, sizeof extras, R"({"tolerance": %g, "view": {"azimuth": 30, "elevation": 40}})", tols[k]);
    pics[k] = picture(torus, fig_width / 2, 300, extras);
  }
  Figure f{"torus-tessellation", "The torus tessellated at two tolerances", "", ""};
  f.svg = side_by_side(pics[0], pics[1], 300);
  f.caption = "A torus (radii 3 and 1, exact NURBS from <code>revolve</code>) tessellated within 0.15 (left, " + counts[0] +
              " triangles) and 0.03 (right, " + counts[1] +
              " triangles), each triangle shaded flat. The bound holds both ways: every point of the mesh within the "
              "tolerance of the torus and every point of the torus within it of the mesh; the knot lines are grid "
              "lines of the mesh, so the patches meet without cracks.";
  return f;
}

}  // namespace casteljau::gallery
