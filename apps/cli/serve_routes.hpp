// The server's routes (serve.cpp), apart from its sockets and worker processes, so that the
// HTTP fuzz target (tests/fuzz/fuzz_http.cpp) runs the same request path in one process.
// Includes cpp-httplib: for serve.cpp and that target only.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <httplib.h>

#include "serve.hpp"

namespace casteljau::cli {

/// What a computation answered: the kind of text, the text, or that it ran past the limit.
constexpr char kind_json = 'j', kind_svg = 's', kind_bad = 'b', kind_internal = 'i', kind_not_served = 'n';

struct Computed {
  char kind = kind_internal;
  std::string text;
  bool timed_out = false;
};

/// The name under which the batch (`POST /batch`) is computed: not a command's name (the
/// API route takes [A-Za-z0-9_] only).
constexpr std::string_view batch_name = "*batch";

/// Computes a command's request (or the batch) in this process, without a time limit.
[[nodiscard]] Computed compute_in_process(std::string_view name, std::string_view body, const ServeOptions& options);

using Compute = std::function<Computed(std::string_view name, std::string_view body)>;

/// The routes of docs/cli.md ("casteljau serve") on server: the page, GET /api (its text
/// listing_text), POST /api/COMMAND and POST /batch computed by compute, and the error
/// handler. options and listing_text must outlive the server.
void add_routes(httplib::Server& server, const ServeOptions& options, const std::string& listing_text, Compute compute);

}  // namespace casteljau::cli
