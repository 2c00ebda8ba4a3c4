// Fuzz target `svg`: SVG reading (io/svg_import.hpp). Every input is given to the three
// readers of outside text there: as path data (parse_path_data, through a rotation so
// that the transform's arithmetic runs too), as a transform list (parse_transform) and as
// a whole SVG document (import_svg: pugixml's tree, the elements, their attributes).
// The dictionary tests/fuzz/svg.dict holds the path commands, element and attribute names,
// transform functions and units.
//
// Bad input must end as InvalidArgument; any other exception, a crash, a sanitizer report
// or a non-finite coordinate in a result is a bug.
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "casteljau/core/error.hpp"
#include "casteljau/io/svg_import.hpp"
#include "fuzz_target.hpp"

namespace {

void check_finite(const std::vector<casteljau::io::SvgSubpath>& subpaths) {
  for (const auto& s : subpaths) {
    if (s.segments.empty()) std::abort();  // empty subpaths are left out
    for (const auto& seg : s.segments) {
      if (seg.points.size() < 2 || seg.points.size() > 4) std::abort();
      for (const auto& p : seg.points) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) std::abort();
      }
      for (const double w : seg.weights) {
        if (!(w > 0) || !std::isfinite(w)) std::abort();
      }
    }
  }
}

}  // namespace

CASTELJAU_FUZZ_TARGET(svg) {
  (void)mode;
  const std::string_view text(reinterpret_cast<const char*>(input.data()), input.size());
  try {
    check_finite(casteljau::io::parse_path_data(text, {0.6, 0.8, -0.8, 0.6, 3, -2}));
  } catch (const casteljau::InvalidArgument&) {
  }
  try {
    (void)casteljau::io::parse_transform(text);
  } catch (const casteljau::InvalidArgument&) {
  }
  try {
    const auto doc = casteljau::io::import_svg(text);
    for (const auto& shape : doc.paths) check_finite(shape.subpaths);
  } catch (const casteljau::InvalidArgument&) {
  }
  return 0;
}
