// Curve JSON reading and writing (placeholder until the CLI work lands).
#include "casteljau/io/json.hpp"
