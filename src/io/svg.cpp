// SVG writer and renderer (placeholder until the gallery work lands).
#include "casteljau/io/svg.hpp"

namespace casteljau::io {
std::string render_svg(std::span<const AnyCurve>, const RenderStyle&) { return "<svg xmlns=\"http://www.w3.org/2000/svg\"/>\n"; }
}  // namespace casteljau::io
