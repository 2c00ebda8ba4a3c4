// The command registry (io/commands.hpp): the API listing names every command of
// docs/cli.md with the request fields documented there (written out here by hand from the
// documentation, not from the registry), validation follows the field list, and the
// render defaults agree with io::RenderStyle's.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "casteljau/io/commands.hpp"
#include "casteljau/io/svg.hpp"

namespace {

using namespace casteljau;

struct Expected {
  std::string name;
  bool required;
};

// docs/cli.md, "Commands": each command's request fields in the order documented, the
// required ones marked.
const std::map<std::string, std::vector<Expected>> documented = {
    {"eval", {{"curve", true}, {"t", true}, {"derivatives", false}, {"curvature", false}, {"frame", false}}},
    {"split", {{"curve", true}, {"t", true}}},
    {"elevate", {{"curve", true}, {"times", true}}},
    {"to_bezier", {{"curve", true}}},
    {"flatten", {{"curve", true}, {"tolerance", true}, {"method", false}}},
    {"insert_knot", {{"curve", true}, {"knot", true}, {"times", false}}},
    {"remove_knot", {{"curve", true}, {"knot", true}, {"times", false}, {"tolerance", false}}},
    {"render",
     {{"curve", false}, {"curves", false}, {"width", false}, {"height", false}, {"padding", false}, {"background", false},
      {"stroke", false}, {"stroke_width", false}, {"control_polygon", false}, {"axes", false}, {"tolerance", false}}},
    {"bounds", {{"curve", true}, {"from", false}, {"to", false}}},
    {"length", {{"curve", true}, {"from", false}, {"to", false}}},
    {"param_at_length", {{"curve", true}, {"lengths", true}}},
    {"project", {{"curve", true}, {"point", true}, {"farthest", false}}},
    {"features", {{"curve", true}}},
    {"distance", {{"curves", true}}},
    {"area", {{"curve", true}}},
    {"intersect", {{"curves", true}}},
    {"subdivide",
     {{"points", true}, {"scheme", true}, {"degree", false}, {"tension", false}, {"iterations", true}, {"closed", false}}},
    {"fit",
     {{"points", true}, {"degree", true}, {"control_points", false}, {"tolerance", false}, {"smoothing", false}, {"parametrization", false},
      {"start_derivative", false}, {"end_derivative", false}, {"closed", false}}},
    {"solve", {{"curve", true}, {"value", true}, {"axis", false}, {"direction", false}}},
    {"refine", {{"curve", true}, {"knots", true}}},
    {"to_bspline", {{"curve", true}}},
    {"reduce", {{"curve", true}, {"times", false}, {"tolerance", true}}},
    {"basis",
     {{"kind", true}, {"degree", false}, {"knots", false}, {"params", false}, {"tension", false}, {"t", true}, {"derivatives", false}}},
    {"frames", {{"curve", true}, {"t", true}, {"method", false}, {"initial_normal", false}}},
    {"import_svg", {{"svg", false}, {"d", false}}},
    {"to_svg_path", {{"curve", true}, {"tolerance", false}}},
    {"glyph", {{"font", true}, {"text", true}, {"size", false}}},
    {"offset",
     {{"curve", true}, {"distance", true}, {"tolerance", true}, {"trim", false}, {"join", false}, {"miter_limit", false}}},
    {"to_quadratic", {{"curve", true}, {"tolerance", true}}},
    {"surface",
     {{"construct", true}, {"curve", false}, {"curves", false}, {"vector", false}, {"axis", false}, {"angle", false}, {"degree", false},
      {"params", false}, {"points", false}, {"control_points", false}, {"parametrization", false}}},
    {"isocurve", {{"surface", true}, {"direction", true}, {"value", true}}},
    {"tessellate", {{"surface", true}, {"tolerance", true}, {"format", false}}},
};

const io::OrderedJson& command_entry(const io::OrderedJson& listing, const std::string& name) {
  for (const auto& c : listing["commands"]) {
    if (c["name"] == name) return c;
  }
  ADD_FAILURE() << name << " is not listed";
  static const io::OrderedJson none;
  return none;
}

const io::OrderedJson& field_entry(const io::OrderedJson& command, const std::string& name) {
  for (const auto& f : command["fields"]) {
    if (f["name"] == name) return f;
  }
  ADD_FAILURE() << name << " is not a field of " << command["name"];
  static const io::OrderedJson none;
  return none;
}

TEST(Commands, ListingHasEveryDocumentedCommandAndField) {
  const io::OrderedJson listing = io::api_listing();
  ASSERT_TRUE(listing.contains("commands"));
  EXPECT_EQ(listing["commands"].size(), documented.size());
  for (const auto& c : listing["commands"]) {
    const std::string name = c["name"];
    ASSERT_TRUE(documented.count(name)) << name << " is listed but not documented";
    EXPECT_FALSE(c["summary"].get<std::string>().empty()) << name;
    const auto& want = documented.at(name);
    ASSERT_EQ(c["fields"].size(), want.size()) << name;
    for (std::size_t i = 0; i < want.size(); ++i) {
      const auto& f = c["fields"][i];
      EXPECT_EQ(f["name"], want[i].name) << name;
      EXPECT_EQ(f["required"], want[i].required) << name << "." << want[i].name;
      EXPECT_TRUE(f.contains("type") && f.contains("help")) << name << "." << want[i].name;
    }
  }
}

TEST(Commands, ListingTypesAndDefaults) {
  const io::OrderedJson listing = io::api_listing();
  const auto& eval = command_entry(listing, "eval");
  EXPECT_EQ(field_entry(eval, "curve")["type"], "curve");
  EXPECT_EQ(field_entry(eval, "t")["type"], "number[]");
  EXPECT_EQ(field_entry(eval, "derivatives")["type"], "integer");
  EXPECT_EQ(field_entry(eval, "derivatives")["default"], 0);
  EXPECT_EQ(field_entry(eval, "frame")["default"], false);
  EXPECT_FALSE(field_entry(eval, "t").contains("default"));
  // docs/cli.md: remove_knot's tolerance defaults to 1e-12, flatten's method to optimal,
  // fit's parametrization to chord, subdivide's tension to 1/16 (exact in binary).
  EXPECT_EQ(field_entry(command_entry(listing, "remove_knot"), "tolerance")["default"], 1e-12);
  EXPECT_EQ(field_entry(command_entry(listing, "remove_knot"), "times")["default"], 1);
  const auto& method = field_entry(command_entry(listing, "flatten"), "method");
  EXPECT_EQ(method["default"], "optimal");
  EXPECT_EQ(method["choices"], io::OrderedJson::array({"uniform", "subdivision", "optimal"}));
  EXPECT_EQ(field_entry(command_entry(listing, "fit"), "parametrization")["default"], "chord");
  // fit's smoothing: a number or the choice "gcv".
  EXPECT_EQ(field_entry(command_entry(listing, "fit"), "smoothing")["type"], "number|string");
  EXPECT_EQ(field_entry(command_entry(listing, "fit"), "smoothing")["choices"], io::OrderedJson::array({"gcv"}));
  EXPECT_EQ(field_entry(command_entry(listing, "subdivide"), "tension")["default"], 1.0 / 16);
  EXPECT_EQ(field_entry(command_entry(listing, "subdivide"), "points")["type"], "point[]");
  const auto& curves = field_entry(command_entry(listing, "distance"), "curves");
  EXPECT_EQ(curves["type"], "curve[]");
  EXPECT_EQ(curves["min_count"], 2);
  EXPECT_EQ(curves["max_count"], 2);
  // Knot operations take B-splines and NURBS (docs/cli.md).
  EXPECT_EQ(field_entry(command_entry(listing, "insert_knot"), "curve")["types"], io::OrderedJson::array({"bspline", "nurbs"}));
}

TEST(Commands, RenderDefaultsAreRenderStyles) {
  const io::RenderStyle style;
  const io::OrderedJson listing = io::api_listing();
  const auto& render = command_entry(listing, "render");
  EXPECT_EQ(field_entry(render, "width")["default"], style.width);
  EXPECT_EQ(field_entry(render, "height")["default"], style.height);
  EXPECT_EQ(field_entry(render, "padding")["default"], style.padding);
  EXPECT_EQ(field_entry(render, "background")["default"], style.background);
  EXPECT_EQ(field_entry(render, "stroke")["default"], style.stroke);
  EXPECT_EQ(field_entry(render, "stroke_width")["default"], style.stroke_width);
  EXPECT_EQ(field_entry(render, "control_polygon")["default"], style.control_polygon);
  EXPECT_EQ(field_entry(render, "axes")["default"], style.axes);
  EXPECT_EQ(field_entry(render, "tolerance")["default"], style.tolerance);
}

std::string error_of(std::string_view command, std::string_view request) {
  try {
    (void)io::run(*io::find_command(command), io::parse_json(request));
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no error";
}

TEST(Commands, ValidationFollowsTheFieldList) {
  EXPECT_EQ(io::find_command("frobnicate"), nullptr);
  EXPECT_EQ(error_of("eval", "[]"), "an eval request must be a JSON object, got array");
  EXPECT_EQ(error_of("eval", R"({"t": [0], "x": 1})"), "x: unknown field 'x' (an eval request has: curve, t, derivatives, curvature, frame)");
  EXPECT_EQ(error_of("split", R"({"t": 0.5})"), "curve: required field is missing");
  EXPECT_EQ(error_of("split", R"({"curve": {"type": "bezier", "points": [[0]]}, "t": "a"})"),
            "t: split parameter must be a number, got string");
  EXPECT_EQ(error_of("flatten", R"({"curve": {"type": "bezier", "points": [[0]]}, "tolerance": 1, "method": "fast"})"),
            "method: unknown method 'fast' (uniform, subdivision, optimal)");
  EXPECT_EQ(error_of("distance", R"({"curves": [{"type": "bezier", "points": [[0]]}]})"), "curves: needs exactly two curves, got 1");
  EXPECT_EQ(error_of("intersect", R"({"curves": {}})"), "curves: must be an array of one or two curve objects, got object");
  EXPECT_EQ(error_of("render", R"({"curves": []})"), "curves: needs at least one curve");
  EXPECT_EQ(error_of("subdivide", R"({"points": [[0], [1]], "scheme": "chaikin", "iterations": 1, "degree": 2})"),
            "degree: only the lane_riesenfeld scheme takes a degree");
}

TEST(Commands, HelpShowsFieldsAndExample) {
  const std::string h = io::help(*io::find_command("remove_knot"));
  EXPECT_NE(h.find("Request:\n"), std::string::npos);
  EXPECT_NE(h.find("tolerance  number, default 1e-12"), std::string::npos) << h;
  EXPECT_NE(h.find("a bspline or nurbs curve"), std::string::npos) << h;
  EXPECT_NE(h.find("Example:\n  echo '"), std::string::npos) << h;
}

}  // namespace
