// `casteljau serve`: the HTTP server of docs/cli.md ("casteljau serve"), in serve.cpp, the
// one translation unit that includes cpp-httplib.
#pragma once

#include <cstddef>
#include <string>

namespace casteljau::cli {

struct ServeOptions {
  std::string host = "127.0.0.1";    ///< the loopback address unless told otherwise
  int port = 8080;                   ///< 0: any free port (the address printed says which)
  std::size_t max_body = 1 << 20;    ///< larger request bodies: 413
  double time_limit = 2.0;           ///< CPU seconds one request may compute (past it: 503)
  unsigned jobs = 0;                 ///< requests computed at once; 0: the number of cores
  std::string font_dir;              ///< fonts glyph may read, by file name; empty: glyph refused
};

/// Serves until the process is stopped (a signal); returns an exit status when the server
/// cannot start (the address is taken, ...). Defined in serve.cpp, which is built as a
/// module of its own (casteljau-serve.so, with cpp-httplib and through it OpenSSL, zlib and
/// Brotli), so that every other command starts without loading those libraries.
int serve(const ServeOptions& options);

/// serve() through the module: loads casteljau-serve.so from the copy the program carries
/// (modules.cpp), then calls it. Throws std::runtime_error with the system's or the
/// loader's message when it cannot be loaded.
int serve_through_module(const ServeOptions& options);

}  // namespace casteljau::cli
