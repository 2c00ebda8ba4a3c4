// `casteljau serve`: the explorer page and every command over HTTP (docs/cli.md, "casteljau
// serve"; the design in docs/architecture.md, "The server"). The only translation unit
// that includes cpp-httplib.
//
// Requests are computed in worker processes (one request at a time each), forked by a
// single-threaded spawner process that the server forks at start-up, before any thread
// exists. For each request a worker arms two timers on itself (CPU time at the limit, wall
// time at four times it) whose signals end it, so a request past its budget stops wherever
// it is, in any loop of the library; the server then starts a new worker in its place.
#include "serve_routes.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <vector>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>

#include <httplib.h>

#include "explorer_assets.hpp"
#include "request.hpp"

namespace casteljau::cli {
namespace {

// ------------------------------------------------------------------------------------------
// Plain descriptor I/O (EINTR retried).

bool write_all(int fd, std::string_view s) {
  while (!s.empty()) {
    const ssize_t n = ::send(fd, s.data(), s.size(), MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    s.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

timeval to_timeval(double seconds) {
  timeval tv{};
  tv.tv_sec = static_cast<time_t>(seconds);
  tv.tv_usec = static_cast<suseconds_t>((seconds - static_cast<double>(tv.tv_sec)) * 1e6);
  if (tv.tv_sec == 0 && tv.tv_usec == 0) tv.tv_usec = 1;
  return tv;
}

// ------------------------------------------------------------------------------------------
// The compute side. A request travels to a worker process as two length-prefixed strings
// (the command's name, the body); the answer comes back as one frame, a kind byte then
// the text's length (8 bytes) then the text, so that a worker ended by its timer (or a
// crash) is told from one that answered.



void append_length(std::string& s, std::uint64_t n) { s.append(reinterpret_cast<const char*>(&n), sizeof n); }

std::string frame(char kind, std::string_view text) {
  std::string f(1, kind);
  append_length(f, text.size());
  f.append(text);
  return f;
}

/// Reads exactly n bytes; false at end of file or on an error.
bool read_exact(int fd, char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t r = ::read(fd, p, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r;
    n -= static_cast<std::size_t>(r);
  }
  return true;
}

bool read_string(int fd, std::string& s, std::size_t limit) {
  std::uint64_t n;
  if (!read_exact(fd, reinterpret_cast<char*>(&n), sizeof n) || n > limit) return false;
  s.resize(n);
  return read_exact(fd, s.data(), n);
}

void set_timers(double cpu_seconds, double wall_seconds) {
  itimerval cpu{}, wall{};
  if (cpu_seconds > 0) cpu.it_value = to_timeval(cpu_seconds);
  if (wall_seconds > 0) wall.it_value = to_timeval(wall_seconds);
  ::setitimer(ITIMER_PROF, &cpu, nullptr);
  ::setitimer(ITIMER_REAL, &wall, nullptr);
}

/// A worker: answers requests from fd one after the other until end of file. Each request
/// arms two timers on the process, CPU time at the limit (what "computed for more than"
/// counts, whatever the machine's load) and wall time at four times it plus a second as
/// a backstop, disarmed before the answer is written; either signal's default action ends
/// the process wherever it is, and the server replaces it.
[[noreturn]] void worker(int fd, const ServeOptions& options) {
  std::signal(SIGCHLD, SIG_DFL);
  std::signal(SIGPROF, SIG_DFL);
  std::signal(SIGALRM, SIG_DFL);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  const pid_t self = ::getpid();
  if (!write_all(fd, std::string_view(reinterpret_cast<const char*>(&self), sizeof self))) ::_exit(0);
  std::string name, body;
  for (;;) {
    if (!read_string(fd, name, 64) || !read_string(fd, body, options.max_body)) ::_exit(0);
    set_timers(options.time_limit, 4 * options.time_limit + 1);
    const Computed c = compute_in_process(name, body, options);
    const std::string out = frame(c.kind, c.text);
    set_timers(0, 0);
    if (!write_all(fd, out)) ::_exit(0);
  }
}

/// The spawner: receives one socket per worker to start on ctl and forks the worker.
/// Single-threaded, so a fork copies no lock held by another thread.
[[noreturn]] void spawner(int ctl, const ServeOptions& options, pid_t server) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != server) ::_exit(0);
  std::signal(SIGCHLD, SIG_IGN);  // workers are reaped by the system
  std::signal(SIGINT, SIG_IGN);   // a terminal's Ctrl-C stops the server, which stops us
  for (;;) {
    char byte;
    iovec iov{&byte, 1};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    const ssize_t n = ::recvmsg(ctl, &msg, MSG_CMSG_CLOEXEC);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(0);  // the server is gone
    const cmsghdr* c = CMSG_FIRSTHDR(&msg);
    if (!c || c->cmsg_level != SOL_SOCKET || c->cmsg_type != SCM_RIGHTS) continue;
    int fd;
    std::memcpy(&fd, CMSG_DATA(c), sizeof fd);
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::close(ctl);
      worker(fd, options);
    }
    ::close(fd);  // fork failed: the server sees end of file instead of the worker's pid
  }
}

/// The server's side: `jobs` worker processes, each computing one request at a time.
class Computer {
 public:
  explicit Computer(const ServeOptions& options) : options_(options) {
    int sv[2];
    if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, sv) != 0) throw std::runtime_error(std::strerror(errno));
    const pid_t server = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(std::string("cannot fork: ") + std::strerror(errno));
    if (pid == 0) {
      ::close(sv[0]);
      spawner(sv[1], options, server);
    }
    ::close(sv[1]);
    ctl_ = sv[0];
    for (unsigned i = 0; i < jobs(options); ++i) idle_.push_back(start_worker());
  }

  static unsigned jobs(const ServeOptions& options) {
    return options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  }

  /// The request computed by an idle worker (waiting for one); a worker that did not answer
  /// is replaced.
  Computed compute(std::string_view name, std::string_view body) {
    Worker w;
    {
      std::unique_lock lock(mutex_);
      idle_changed_.wait(lock, [&] { return !idle_.empty(); });
      w = idle_.back();
      idle_.pop_back();
    }
    bool alive = false;
    Computed r = exchange(w, name, body, alive);
    if (!alive) {
      if (w.fd >= 0) ::close(w.fd);
      if (w.pid > 0) ::kill(w.pid, SIGKILL);  // if it still runs (the wall backstop)
      w = start_worker();
    }
    {
      std::lock_guard lock(mutex_);
      idle_.push_back(w);
    }
    idle_changed_.notify_one();
    return r;
  }

 private:
  struct Worker {
    int fd = -1;
    pid_t pid = -1;
  };

  /// A new worker from the spawner ({-1, -1} when that fails: its next request answers
  /// 500 and tries again).
  Worker start_worker() {
    int sv[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) return {};
    char byte = 0;
    iovec iov{&byte, 1};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    cmsghdr* c = CMSG_FIRSTHDR(&msg);
    c->cmsg_level = SOL_SOCKET;
    c->cmsg_type = SCM_RIGHTS;
    c->cmsg_len = CMSG_LEN(sizeof(int));
    std::memcpy(CMSG_DATA(c), &sv[1], sizeof(int));
    ssize_t n;
    do {
      n = ::sendmsg(ctl_, &msg, MSG_NOSIGNAL);
    } while (n < 0 && errno == EINTR);
    ::close(sv[1]);
    Worker w{sv[0], -1};
    if (n != 1 || !read_exact(w.fd, reinterpret_cast<char*>(&w.pid), sizeof w.pid)) {
      ::close(w.fd);
      return {};
    }
    return w;
  }

  Computed exchange(const Worker& w, std::string_view name, std::string_view body, bool& alive) {
    Computed r;
    if (w.fd < 0) {
      r.text = "internal: no compute process could be started";
      return r;
    }
    std::string request;
    append_length(request, name.size());
    request.append(name);
    append_length(request, body.size());
    request.append(body);
    const auto start = std::chrono::steady_clock::now();
    write_all(w.fd, request);  // a worker that stopped reading has ended: seen below

    // Read the frame; past the wall backstop (the worker's own timers end it long before)
    // the request is abandoned and the worker killed.
    const auto backstop = start + std::chrono::duration<double>(4 * options_.time_limit + 2);
    std::string in;
    std::uint64_t length = 0;
    constexpr std::size_t head = 1 + sizeof length;
    char buf[1 << 16];
    for (;;) {
      if (in.size() >= head) {
        std::memcpy(&length, in.data() + 1, sizeof length);
        if (in.size() - head >= length) break;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(backstop - std::chrono::steady_clock::now()).count();
      if (left <= 0) break;
      pollfd p{w.fd, POLLIN, 0};
      const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
      if (ready < 0 && errno != EINTR) break;
      if (ready <= 0) continue;
      const std::size_t want = in.size() >= head ? std::min<std::uint64_t>(sizeof buf, head + length - in.size()) : head - in.size();
      const ssize_t n = ::read(w.fd, buf, want);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      in.append(buf, static_cast<std::size_t>(n));
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (in.size() < head || in.size() - head != length) {
      if (elapsed >= options_.time_limit) {
        r.timed_out = true;
      } else {
        r.text = "internal: the computation ended without an answer";
      }
      return r;
    }
    alive = true;
    r.kind = in[0];
    r.text = in.substr(head);
    return r;
  }

  ServeOptions options_;
  int ctl_ = -1;
  std::mutex mutex_;
  std::condition_variable idle_changed_;
  std::vector<Worker> idle_;
};

/// The connection threads: one per connection for as long as it lasts (httplib serves a
/// keep-alive connection, or a slow client's request, on one thread), started when every
/// thread is busy, up to `max_threads`, and ended after 10 s without work. A fixed pool
/// (httplib's ThreadPool) lets a few hundred idle or slow connections hold every thread
/// while the others wait in its queue; here they each hold their own thread (a few KiB of
/// memory, the stack being reserved address space) until their keep-alive or read timeout
/// closes them, and other clients are served meanwhile.
class ElasticPool : public httplib::TaskQueue {
 public:
  explicit ElasticPool(std::size_t max_threads) : max_threads_(max_threads) {}

  void enqueue(std::function<void()> fn) override {
    std::unique_lock lock(mutex_);
    jobs_.push_back(std::move(fn));
    if (idle_ >= jobs_.size() || threads_ >= max_threads_) {
      lock.unlock();
      work_.notify_one();
      return;
    }
    ++threads_;
    try {
      std::thread([this] { run(); }).detach();
    } catch (const std::system_error&) {
      --threads_;  // no thread now: the job waits for a running one
    }
  }

  void shutdown() override {
    std::unique_lock lock(mutex_);
    stopping_ = true;
    work_.notify_all();
    ended_.wait(lock, [&] { return threads_ == 0; });
  }

 private:
  void run() {
    std::unique_lock lock(mutex_);
    for (;;) {
      ++idle_;
      const bool got = work_.wait_for(lock, std::chrono::seconds(10), [&] { return !jobs_.empty() || stopping_; });
      --idle_;
      if (jobs_.empty() && (stopping_ || !got)) break;
      auto fn = std::move(jobs_.front());
      jobs_.pop_front();
      lock.unlock();
      fn();
      lock.lock();
    }
    --threads_;
    ended_.notify_all();
  }

  const std::size_t max_threads_;
  std::mutex mutex_;
  std::condition_variable work_, ended_;
  std::deque<std::function<void()>> jobs_;
  std::size_t threads_ = 0, idle_ = 0;
  bool stopping_ = false;
};

/// As many open files as the system allows this process (each connection is one), so that
/// a default soft limit of 1024 does not refuse the 1001st client.
void raise_open_file_limit() {
  rlimit r{};
  if (::getrlimit(RLIMIT_NOFILE, &r) == 0 && r.rlim_cur < r.rlim_max) {
    r.rlim_cur = r.rlim_max;
    ::setrlimit(RLIMIT_NOFILE, &r);
  }
}

/// httplib 0.11 listens with a backlog of 5 connections: a burst of clients connecting at
/// once overflows it and their connections wait for the kernel to retry (1 s, then 3 s...).
/// Calling listen() again on the listening socket (found among this process's descriptors:
/// httplib does not expose it) sets the backlog to the system's maximum.
void widen_backlog(int port) {
  DIR* dir = ::opendir("/proc/self/fd");
  if (!dir) return;
  while (const dirent* entry = ::readdir(dir)) {
    const int fd = std::atoi(entry->d_name);
    if (fd <= 2 || fd == ::dirfd(dir)) continue;
    int listening = 0;
    socklen_t length = sizeof listening;
    if (::getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &listening, &length) != 0 || !listening) continue;
    sockaddr_storage address{};
    socklen_t address_length = sizeof address;
    if (::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &address_length) != 0) continue;
    int bound = -1;
    if (address.ss_family == AF_INET) bound = ntohs(reinterpret_cast<const sockaddr_in&>(address).sin_port);
    if (address.ss_family == AF_INET6) bound = ntohs(reinterpret_cast<const sockaddr_in6&>(address).sin6_port);
    if (bound == port) ::listen(fd, SOMAXCONN);
  }
  ::closedir(dir);
}

void set_error(httplib::Response& res, int status, std::string_view message) {
  res.status = status;
  res.set_content(error_json(message), "application/json");
}

std::string format_seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

}  // namespace

Computed compute_in_process(std::string_view name, std::string_view body, const ServeOptions& options) {
  if (name == batch_name) return {kind_json, answer_batch(body, options.font_dir)};
  if (!command_exists(name)) return {kind_not_served, "command: unknown command " + quoted_text(name)};
  const Answer a = answer_named(name, body, options.font_dir);
  if (a.status == exit_ok) return {a.is_svg ? kind_svg : kind_json, a.text};
  return {a.status == exit_bad_input ? kind_bad : kind_internal, clipped(a.error, max_message)};
}

void add_routes(httplib::Server& server, const ServeOptions& options, const std::string& listing_text, Compute compute) {
  const bool glyph_served = !options.font_dir.empty();
  // Every response is whole: httplib would cut any of them to a request's Range (an error's
  // {"error": ...} too, found by the http fuzz target), so ranges are dropped before
  // routing. The Request is httplib's own non-const object, handed to handlers as const.
  server.set_pre_routing_handler([](const httplib::Request& req, httplib::Response&) {
    const_cast<httplib::Request&>(req).ranges.clear();
    return httplib::Server::HandlerResponse::Unhandled;
  });
  // The page: the embedded files, by exact path (nothing else is read: no file system).
  for (const auto& asset : explorer_assets()) {
    const std::string path = asset.path == "index.html" ? "/" : "/" + std::string(asset.path);
    server.Get(path, [asset](const httplib::Request&, httplib::Response& res) {
      res.set_content(std::string(asset.body), std::string(asset.type));
      res.set_header("Cache-Control", "no-cache");
    });
  }
  server.Get("/api", [&listing_text](const httplib::Request&, httplib::Response& res) {
    res.set_content(listing_text, "application/json");
  });
  // The body is read here, piece by piece, and refused as soon as it passes the limit:
  // httplib's own limit holds for a Content-Length but not for a chunked body, which it
  // would otherwise gather whole in memory.
  // The body, or false with the error response set (413 past the limit, 400 when it could
  // not be read).
  const auto read_request_body = [&options](const httplib::Request& req, httplib::Response& res,
                                            const httplib::ContentReader& read_body, std::string& body) {
    // Past the limit the rest is read and dropped, up to 1 MiB more, so that a client
    // that sent a little too much gets its 413 on a connection still in step; beyond
    // that the connection is dropped.
    // A Content-Length past the limit: refused before reading, and the connection closed
    // (reading first made a client that stopped sending wait for the 5 s read timeout).
    const std::string declared = req.get_header_value("Content-Length");
    if (!declared.empty() && (declared.size() > 18 || std::stoull("0" + declared) > options.max_body)) {
      res.set_header("Connection", "close");
      set_error(res, 413, "request: the body is larger than the limit of " + std::to_string(options.max_body) + " bytes");
      return false;
    }
    bool too_big = false;
    std::size_t dropped = 0;
    const bool read = read_body([&](const char* data, std::size_t n) {
      if (!too_big && body.size() + n > options.max_body) {
        too_big = true;
        std::string().swap(body);
      }
      if (too_big) {
        dropped += n;
        return dropped <= (1u << 20);
      }
      body.append(data, n);
      return true;
    });
    if (too_big) {
      if (!read) res.set_header("Connection", "close");
      set_error(res, 413, "request: the body is larger than the limit of " + std::to_string(options.max_body) + " bytes");
      return false;
    }
    if (!read) {
      res.set_header("Connection", "close");
      set_error(res, 400, "request: the body could not be read (malformed chunks, or the client stopped sending)");
      return false;
    }
    return true;
  };
  const auto time_limit_error = [&options](httplib::Response& res) {
    set_error(res, 503, "request: computed for more than " + format_seconds(options.time_limit) +
                            " s (the server's time limit); its work was stopped");
  };
  // The handlers outlive this function: they hold copies (options and listing_text are the
  // caller's, alive while the server runs).
  server.Post(R"(/api/([A-Za-z0-9_]{1,64}))", [=](const httplib::Request& req, httplib::Response& res,
                                                   const httplib::ContentReader& read_body) {
    std::string body;
    if (!read_request_body(req, res, read_body, body)) return;
    const std::string name = req.matches[1];
    if (!command_exists(name)) {
      set_error(res, 404, "command: unknown command " + quoted_text(name));
      return;
    }
    if (name == "glyph" && !glyph_served) {
      set_error(res, 404,
                "command: glyph is not served: its font is a file on the server (start the server with --font-dir DIR to "
                "let it read the fonts in DIR by file name)");
      return;
    }
    const auto r = compute(name, body);
    if (r.timed_out) {
      time_limit_error(res);
      return;
    }
    switch (r.kind) {
      case kind_json:
        res.set_content(r.text, "application/json");
        break;
      case kind_svg:
        res.set_content(r.text, "image/svg+xml");
        break;
      case kind_bad:
        set_error(res, 400, r.text);
        break;
      case kind_not_served:
        set_error(res, 404, r.text);
        break;
      default:
        set_error(res, 500, r.text);
        break;
    }
  });
  // The batch: several requests in one body, one line each ({"command", "request"}),
  // computed one after the other by one worker within one time limit, answered by one line
  // each (docs/cli.md, "casteljau serve"). Outside /api/ so that it names no command. The
  // explorer sends each update of a view as one batch: one round trip instead of eight.
  server.Post("/batch", [=](const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& read_body) {
    std::string body;
    if (!read_request_body(req, res, read_body, body)) return;
    const auto r = compute(batch_name, body);
    if (r.timed_out) {
      time_limit_error(res);
    } else if (r.kind == kind_json) {
      res.set_content(r.text, "application/x-ndjson");
    } else {
      set_error(res, 500, r.text);
    }
  });
  // Every error status carries {"error": ...}: the ones httplib answers itself (no such
  // path, a body over the limit, a malformed request) get one here.
  server.set_error_handler([&options](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    switch (res.status) {
      case 404:
        set_error(res, 404, "path: no such page or command: " + quoted_text(clipped(req.path, 200)));
        break;
      case 413:
        set_error(res, 413, "request: the body is larger than the limit of " + std::to_string(options.max_body) + " bytes");
        break;
      case 416:  // a Range header httplib could not parse (ranges are not served: above)
        set_error(res, 400, "request: malformed Range header (responses are always whole)");
        break;
      default:
        set_error(res, res.status, "request: refused with HTTP status " + std::to_string(res.status));
        break;
    }
  });

}

int serve(const ServeOptions& options) {
  // The spawner first, while this process has one thread.
  Computer computer(options);
  std::signal(SIGPIPE, SIG_IGN);

  const bool glyph_served = !options.font_dir.empty();
  const std::string listing_text = api_listing_text(glyph_served);

  httplib::Server server;
  const unsigned jobs = Computer::jobs(options);
  // httplib serves a connection on one thread for as long as it lasts (keep-alive, a slow
  // client), while at most `jobs` requests compute: a thread per connection (ElasticPool),
  // so that idle or slow clients do not keep the others waiting; an idle connection is
  // closed after 2 s, a client silent for 5 s in mid-request too. A keep-alive connection
  // serves up to 10,000 requests (httplib's default, 5, made a browser or a benchmark
  // client open a new connection every fifth request).
  raise_open_file_limit();
  server.new_task_queue = [] { return new ElasticPool(4096); };
  server.set_keep_alive_timeout(2);
  server.set_keep_alive_max_count(10000);
  server.set_payload_max_length(options.max_body);
  // httplib writes the head and the body apart: without TCP_NODELAY, Nagle's algorithm holds
  // the body until the client's delayed ACK, 40 ms per response.
  server.set_tcp_nodelay(true);

  add_routes(server, options, listing_text, [&computer](std::string_view name, std::string_view body) { return computer.compute(name, body); });

  int port = options.port;
  if (port == 0) {
    port = server.bind_to_any_port(options.host);
    if (port < 0) throw std::runtime_error("cannot listen on " + options.host);
  } else if (!server.bind_to_port(options.host, port)) {
    throw std::runtime_error("cannot listen on " + options.host + ":" + std::to_string(port) + " (in use, or not an address of this machine)");
  }
  widen_backlog(port);
  const bool v6 = options.host.find(':') != std::string::npos;
  std::printf("casteljau serve: http://%s%s%s:%d/ (%u requests computed at once, %s s each at most)\n", v6 ? "[" : "",
              options.host.c_str(), v6 ? "]" : "", port, jobs, format_seconds(options.time_limit).c_str());
  std::fflush(stdout);
  if (!server.listen_after_bind()) throw std::runtime_error("the server stopped");
  return exit_ok;
}

}  // namespace casteljau::cli

/// The module's entry point (modules.cpp finds it by this unmangled name).
extern "C" int casteljau_serve_module(const casteljau::cli::ServeOptions& options) {
  return casteljau::cli::serve(options);
}
