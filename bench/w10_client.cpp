// W10's load client (docs/performance.md, W10): sends requests to `casteljau serve` over
// CONNECTIONS concurrent keep-alive connections (plain sockets and HTTP/1.1: the client's
// own cost stays far below the server's) and writes, per request, its latency and status.
//
// Usage: w10_client HOST PORT CONNECTIONS REQUESTS
//   REQUESTS: one request per line, "COMMAND<TAB>BODY"; connection c sends the requests
//   c, c + CONNECTIONS, c + 2 CONNECTIONS, ... one after the other.
// Output (stdout): "wall_seconds W" then one line per request, in input order:
//   "LATENCY_MICROSECONDS STATUS" (status 0: the connection failed).
// Built by bench/w10.py (one file, the standard library and POSIX sockets only).
#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace {

int connect_to(const char* host, const char* port) {
  addrinfo hints{}, *res = nullptr;
  hints.ai_socktype = SOCK_STREAM;
  if (::getaddrinfo(host, port, &hints, &res) != 0) return -1;
  int fd = ::socket(res->ai_family, res->ai_socktype, 0);
  if (fd >= 0 && ::connect(fd, res->ai_addr, res->ai_addrlen) != 0) {
    ::close(fd);
    fd = -1;
  }
  ::freeaddrinfo(res);
  if (fd >= 0) {
    int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  }
  return fd;
}

bool send_all(int fd, const std::string& s) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::send(fd, s.data() + done, s.size() - done, MSG_NOSIGNAL);
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

/// Reads one response (head, then Content-Length bytes); its status, 0 on failure.
int read_response(int fd, std::string& buffer) {
  char chunk[1 << 16];
  std::size_t head_end;
  while ((head_end = buffer.find("\r\n\r\n")) == std::string::npos) {
    const ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
    if (n <= 0) return 0;
    buffer.append(chunk, static_cast<std::size_t>(n));
  }
  const int status = std::atoi(buffer.c_str() + 9);  // "HTTP/1.1 200"
  std::size_t length = 0;
  const std::size_t at = buffer.find("Content-Length: ");
  if (at != std::string::npos && at < head_end) length = std::strtoull(buffer.c_str() + at + 16, nullptr, 10);
  const std::size_t total = head_end + 4 + length;
  while (buffer.size() < total) {
    const ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
    if (n <= 0) return 0;
    buffer.append(chunk, static_cast<std::size_t>(n));
  }
  buffer.erase(0, total);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: w10_client HOST PORT CONNECTIONS REQUESTS\n");
    return 2;
  }
  const char* host = argv[1];
  const char* port = argv[2];
  const int connections = std::atoi(argv[3]);
  std::vector<std::string> messages;
  {
    std::ifstream in(argv[4]);
    std::string line;
    while (std::getline(in, line)) {
      const std::size_t tab = line.find('\t');
      const std::string body = line.substr(tab + 1);
      messages.push_back("POST /api/" + line.substr(0, tab) + " HTTP/1.1\r\nHost: " + host +
                         "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) +
                         "\r\n\r\n" + body);
    }
  }
  std::vector<double> latency(messages.size(), 0);
  std::vector<int> status(messages.size(), 0);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  for (int c = 0; c < connections; ++c) {
    threads.emplace_back([&, c] {
      int fd = connect_to(host, port);
      std::string buffer;
      for (std::size_t i = static_cast<std::size_t>(c); i < messages.size(); i += static_cast<std::size_t>(connections)) {
        const auto t0 = std::chrono::steady_clock::now();
        if (fd < 0) fd = connect_to(host, port);
        int s = 0;
        if (fd >= 0 && send_all(fd, messages[i])) s = read_response(fd, buffer);
        if (s == 0 && fd >= 0) {  // closed by the server: counted, then a new connection
          ::close(fd);
          fd = -1;
          buffer.clear();
        }
        latency[i] = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
        status[i] = s;
      }
      if (fd >= 0) ::close(fd);
    });
  }
  for (auto& t : threads) t.join();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wall_seconds %.6f\n", wall);
  for (std::size_t i = 0; i < messages.size(); ++i) std::printf("%.1f %d\n", latency[i], status[i]);
  return 0;
}
