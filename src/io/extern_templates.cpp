// The explicit instantiation definitions of io/extern_templates.hpp: the library's queries
// at double, compiled once here (at the io layer's -O1) for every translation unit that
// includes that header and links casteljau::io. In the `curves` unity group, whose sources
// (any_curve.cpp, queries.cpp) instantiate these queries anyway.
#include "casteljau/io/extern_templates.hpp"

namespace casteljau {
#define EXTERN_OR_NOT
CASTELJAU_EXTERN_TEMPLATE_LIST
#undef EXTERN_OR_NOT
}  // namespace casteljau
