// Fuzz target `http`: the server's request path (apps/cli/serve.cpp), from the bytes a
// client sends to the response written back: cpp-httplib's request parsing (request line,
// headers, Content-Length and chunked bodies, keep-alive), our routes (the page, GET /api,
// POST /api/COMMAND, POST /batch, the body limit, the error handler) and the commands,
// computed in this process (no worker processes, no time limit: libFuzzer's -timeout
// flags a slow input). The input is what one connection sends; up to 8 requests on it are
// answered, as on a kept-alive connection.
//
// Built with CASTELJAU_FUZZ only (`make fuzz FUZZ_TARGET=http`): it compiles the server and
// request handling a second time, too much for every build. Its seed corpus
// (tests/fuzz/corpus/http/) is replayed against the real server by tests/cli/test_serve.py.
//
// A bug: a response that is not HTTP/1.1 with a status the contract states (200, 400,
// 404, 413; 503 cannot happen here; HTTP's 100 and 414 are httplib's own), an error status
// without {"error": ...} as its body, an internal error (500), a crash or a sanitizer report.
#include <cstdlib>
#include <string>
#include <string_view>

#include "explorer_assets.hpp"
#include "fuzz_target.hpp"
#include "request.hpp"
#include "serve_routes.hpp"

namespace casteljau::cli {

// The page, small: its routes are the point here, not its text.
std::span<const Asset> explorer_assets() {
  static constexpr Asset assets[] = {{"index.html", "text/html; charset=utf-8", "<!doctype html><title>casteljau explorer</title>"},
                                     {"explorer.js", "text/javascript; charset=utf-8", "\"use strict\";"}};
  return assets;
}

}  // namespace casteljau::cli

namespace {

/// One connection's bytes in, the responses out.
class MemoryStream : public httplib::Stream {
 public:
  explicit MemoryStream(std::string_view in) : in_(in) {}
  bool is_readable() const override { return !in_.empty(); }
  bool is_writable() const override { return true; }
  ssize_t read(char* ptr, size_t size) override {
    const std::size_t n = std::min(size, in_.size());
    std::copy_n(in_.data(), n, ptr);
    in_.remove_prefix(n);
    return static_cast<ssize_t>(n);
  }
  ssize_t write(const char* ptr, size_t size) override {
    out.append(ptr, size);
    return static_cast<ssize_t>(size);
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    ip = "127.0.0.1";
    port = 40000;
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    ip = "127.0.0.1";
    port = 8080;
  }
  socket_t socket() const override { return -1; }
  bool exhausted() const { return in_.empty(); }

  std::string out;

 private:
  std::string_view in_;
};

class FuzzServer : public httplib::Server {
 public:
  using httplib::Server::process_request;
};

const casteljau::cli::ServeOptions& options() {
  static const casteljau::cli::ServeOptions o = [] {
    casteljau::cli::ServeOptions x;
    x.max_body = 64 * 1024;  // small, so that the limit is reached
    return x;
  }();
  return o;
}

FuzzServer& server() {
  static const std::string listing = casteljau::cli::api_listing_text(false);
  static FuzzServer* s = [] {
    auto* x = new FuzzServer;
    x->set_payload_max_length(options().max_body);
    casteljau::cli::add_routes(*x, options(), listing, [](std::string_view name, std::string_view body) {
      return casteljau::cli::compute_in_process(name, body, options());
    });
    return x;
  }();
  return *s;
}

/// Every response in out: "HTTP/1.1 NNN ...", a status of the contract (or HTTP's own 100
/// Continue before a body, 414 for a request line over httplib's 8 KiB), an error body
/// for an error status. A response to HEAD has a Content-Length and no body: what follows
/// its head is then the next response (or nothing).
void check_responses(std::string_view out) {
  while (!out.empty()) {
    if (out.substr(0, 9) != "HTTP/1.1 " || out.size() < 12) std::abort();
    const int status = std::atoi(std::string(out.substr(9, 3)).c_str());
    if (status != 100 && status != 200 && status != 400 && status != 404 && status != 413 && status != 414) std::abort();
    const std::size_t head_end = out.find("\r\n\r\n");
    if (head_end == std::string_view::npos) std::abort();
    const std::string_view head = out.substr(0, head_end);
    out.remove_prefix(head_end + 4);
    const std::size_t at = head.find("Content-Length: ");
    const std::size_t length = at == std::string_view::npos ? 0 : std::strtoull(std::string(head.substr(at + 16, 20)).c_str(), nullptr, 10);
    if (length == 0 || out.empty() || out.substr(0, 9) == "HTTP/1.1 ") {
      if (status >= 400 && length == 0) std::abort();  // an error without its body
      continue;
    }
    if (length > out.size()) std::abort();
    // A compressed body (the client accepted gzip or brotli) is not read here.
    const bool encoded = head.find("Content-Encoding: ") != std::string_view::npos;
    if (status != 200 && !encoded && out.substr(0, 10) != "{\"error\":\"") std::abort();
    out.remove_prefix(length);
  }
}

}  // namespace

CASTELJAU_FUZZ_TARGET(http) {
  (void)mode;
  MemoryStream stream(std::string_view(reinterpret_cast<const char*>(input.data()), input.size()));
  bool closed = false;
  for (int i = 0; i < 8 && !closed && !stream.exhausted(); ++i) {
    if (!server().process_request(stream, false, closed, nullptr)) break;
  }
  check_responses(stream.out);
  return 0;
}
