// Curve JSON (shared/spec/cli.md): parsing with field-path errors, and writing.
#pragma once

#include "casteljau/io/any_curve.hpp"
