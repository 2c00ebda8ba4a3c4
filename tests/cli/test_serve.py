#!/usr/bin/python3
"""Black-box tests of `casteljau serve` (docs/cli.md, "casteljau serve"): the HTTP contract.

Usage: test_serve.py PATH_TO_CASTELJAU [unittest options]

The expected answers come from the command line program itself (the server must answer
the same bytes as `casteljau COMMAND` for the same request), from its `--help` (the command
list), and from the statuses the contract states. Standard library only.
"""
import http.client
import json
import os
import socket
import subprocess
import sys
import threading
import time
import unittest

BINARY = None  # set from argv in __main__

# Small limits so that the limit tests are fast: 1/4 s of CPU per request (every request
# below but the slow one takes milliseconds), a 128 KiB body (the slow request is 55 KB).
TIME_LIMIT = 0.25
MAX_BODY = 128 * 1024
JOBS = 2  # compute processes

CUBIC = {"type": "bezier", "points": [[0, 0], [1, 2], [3, 2], [4, 0]]}


def cli(command, body):
    """`casteljau COMMAND` on body (bytes): (exit status, stdout bytes, stderr text)."""
    p = subprocess.run([BINARY, command], input=body, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=30)
    return p.returncode, p.stdout, p.stderr.decode()


class Server:
    """A `casteljau serve` on a free loopback port."""

    def __init__(self, *args):
        self.proc = subprocess.Popen([BINARY, "serve", "--port", "0", *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        line = self.proc.stdout.readline().decode()
        if not line.startswith("casteljau serve: http://"):
            self.proc.kill()
            raise RuntimeError("the server did not start: " + line + self.proc.stderr.read().decode())
        hostport = line.split("http://")[1].split("/")[0]
        self.host, port = hostport.rsplit(":", 1)
        self.port = int(port)

    def request(self, method, path, body=None, headers=None):
        """(status, content type, body bytes)."""
        c = http.client.HTTPConnection(self.host, self.port, timeout=30)
        try:
            c.request(method, path, body=body, headers=headers or {})
            r = c.getresponse()
            return r.status, r.getheader("Content-Type"), r.read()
        finally:
            c.close()

    def post(self, command, body):
        if isinstance(body, dict):
            body = json.dumps(body).encode()
        return self.request("POST", "/api/" + command, body, {"Content-Type": "application/json"})

    def stop(self):
        self.proc.terminate()
        self.proc.wait(timeout=10)
        self.proc.stdout.close()
        self.proc.stderr.close()


def descendants(pid):
    """{pid: CPU seconds (user + system)} of every process below pid (from /proc)."""
    children, cpu = {}, {}
    tick = os.sysconf("SC_CLK_TCK")
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                stat = f.read()
        except OSError:
            continue
        fields = stat.rsplit(")", 1)[1].split()
        children.setdefault(int(fields[1]), []).append(int(entry))
        cpu[int(entry)] = (int(fields[11]) + int(fields[12])) / tick
    out, todo = {}, [pid]
    while todo:
        for c in children.get(todo.pop(), []):
            out[c] = cpu[c]
            todo.append(c)
    return out


class ServeTest(unittest.TestCase):
    server = None

    @classmethod
    def setUpClass(cls):
        cls.server = Server("--time-limit", str(TIME_LIMIT), "--max-body", str(MAX_BODY), "--jobs", str(JOBS))

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()

    def assert_error(self, status, ctype, body, expected_status, contains=""):
        self.assertEqual(status, expected_status, body)
        self.assertTrue(ctype.startswith("application/json"), ctype)
        error = json.loads(body)["error"]
        self.assertIsInstance(error, str)
        self.assertIn(contains, error)
        return error

    def test_page(self):
        status, ctype, body = self.server.request("GET", "/")
        self.assertEqual(status, 200)
        self.assertTrue(ctype.startswith("text/html"), ctype)
        self.assertIn(b"casteljau explorer", body)
        for asset, kind in (("/explorer.js", "text/javascript"), ("/explorer.css", "text/css")):
            status, ctype, body = self.server.request("GET", asset)
            self.assertEqual(status, 200, asset)
            self.assertTrue(ctype.startswith(kind), ctype)
            self.assertGreater(len(body), 100)

    def test_listing_is_the_registry(self):
        status, ctype, body = self.server.request("GET", "/api")
        self.assertEqual(status, 200)
        self.assertTrue(ctype.startswith("application/json"))
        listing = json.loads(body)
        names = [c["name"] for c in listing["commands"]]
        # The command line's commands, in its --help order (COMMANDS section), but glyph,
        # whose font is a file: not served without --font-dir.
        help_text = subprocess.run([BINARY, "--help"], stdout=subprocess.PIPE, check=True).stdout.decode()
        section = help_text.split("Commands:", 1)[1].split("\n\n", 1)[0]
        cli_names = [line.split()[0] for line in section.splitlines() if line.startswith("  ") and line.split()]
        self.assertEqual(names, [n for n in cli_names if n != "glyph"])
        for c in listing["commands"]:
            self.assertEqual(set(c), {"name", "summary", "fields"}, c["name"])
            self.assertIn(c["summary"], help_text, c["name"])
            # Each field as `casteljau NAME --help` documents it.
            cmd_help = subprocess.run([BINARY, c["name"], "--help"], stdout=subprocess.PIPE, check=True).stdout.decode()
            for f in c["fields"]:
                self.assertIn(f["name"], cmd_help, (c["name"], f["name"]))
                self.assertIn(f["type"], cmd_help, (c["name"], f["name"]))

    def test_same_bytes_as_the_command_line(self):
        cases = [
            ("eval", {"curve": CUBIC, "t": [0, 0.25, 0.5, 1], "derivatives": 2, "curvature": True}),
            ("split", {"curve": CUBIC, "t": 0.3}),
            ("insert_knot", {"curve": {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 0.5, 1, 1, 1], "points": [[0, 0], [1, 1], [2, 0], [3, 1]]}, "knot": 0.25}),
            ("flatten", {"curve": {"type": "circle", "center": [0, 0], "radius": 1}, "tolerance": 1e-3}),
            ("to_bspline", {"curve": {"type": "circle", "center": [4.5, 2.5], "radius": 2}}),
            ("basis", {"kind": "bernstein", "degree": 3, "t": [0.1, 0.7]}),
        ]
        for command, request in cases:
            body = json.dumps(request).encode()
            rc, out, err = cli(command, body)
            self.assertEqual(rc, 0, err)
            status, ctype, answer = self.server.post(command, body)
            self.assertEqual(status, 200, answer)
            self.assertTrue(ctype.startswith("application/json"), ctype)
            self.assertEqual(answer, out, command)

    def test_render_is_svg(self):
        body = json.dumps({"curve": CUBIC}).encode()
        rc, out, err = cli("render", body)
        self.assertEqual(rc, 0, err)
        status, ctype, answer = self.server.post("render", body)
        self.assertEqual(status, 200)
        self.assertTrue(ctype.startswith("image/svg+xml"), ctype)
        self.assertEqual(answer, out)

    def test_bad_input_is_400_with_the_command_lines_message(self):
        cases = [
            ("eval", b'{"curve": '),  # malformed JSON
            ("eval", json.dumps({"curve": CUBIC, "t": "half"}).encode()),  # wrong type
            ("eval", json.dumps({"curve": CUBIC}).encode()),  # missing field
            ("split", json.dumps({"curve": CUBIC, "t": 0.5, "tt": 1}).encode()),  # unknown field
            ("insert_knot", json.dumps({"curve": {"type": "bspline", "degree": 1, "knots": [0, 0, 2, 1, 1], "points": [[0], [1], [2]]}, "knot": 0.5}).encode()),
            ("eval", b""),
        ]
        for command, body in cases:
            rc, out, err = cli(command, body)
            self.assertEqual(rc, 2, err)
            status, ctype, answer = self.server.post(command, body)
            error = self.assert_error(status, ctype, answer, 400)
            # The command line's one line, "error: <where>: <what>".
            self.assertEqual("error: " + error + "\n", err, body)

    def test_not_found(self):
        status, ctype, body = self.server.post("no_such_command", {"curve": CUBIC})
        self.assert_error(status, ctype, body, 404, "unknown command")
        # glyph's font is a path on the server's file system: not served without --font-dir.
        status, ctype, body = self.server.post("glyph", {"font": "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "text": "l"})
        self.assert_error(status, ctype, body, 404, "glyph")
        for method, path in (("GET", "/nope"), ("GET", "/api/eval"), ("POST", "/"), ("POST", "/api"), ("GET", "/index.html/x"),
                             ("POST", "/api/eval/x")):
            status, ctype, body = self.server.request(method, path, b"{}" if method == "POST" else None)
            self.assert_error(status, ctype, body, 404)

    def test_path_traversal(self):
        # Raw request lines, so that no client library normalises the path.
        paths = ["/../../../../etc/passwd", "/%2e%2e/%2e%2e/%2e%2e/etc/passwd", "/api/../../../etc/passwd",
                 "/explorer.js/../../../../etc/passwd", "/..%2f..%2f..%2fetc%2fpasswd", "//etc/passwd",
                 "/%2e%2e%5c%2e%2e%5cetc%5cpasswd", "/etc/passwd", "/proc/self/environ"]
        for path in paths:
            with socket.create_connection((self.server.host, self.server.port), timeout=10) as s:
                s.sendall(f"GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n".encode())
                data = b""
                while chunk := s.recv(65536):
                    data += chunk
            head, _, body = data.partition(b"\r\n\r\n")
            self.assertTrue(head.startswith(b"HTTP/1.1 404"), (path, head[:40]))
            self.assertIn(b'"error"', body)
            self.assertNotIn(b"root:", body)
            self.assertNotIn(b"PATH=", body)

    def test_body_limit(self):
        # Exactly the limit is read (a valid request padded with spaces); one byte more is 413.
        request = json.dumps({"curve": CUBIC, "t": [0.5]}).encode()
        padded = request + b" " * (MAX_BODY - len(request))
        status, ctype, body = self.server.post("eval", padded)
        self.assertEqual(status, 200, body)
        status, ctype, body = self.server.post("eval", padded + b" ")
        self.assert_error(status, ctype, body, 413)

    def test_chunked_body_limit(self):
        # A chunked body has no length up front: refused once it passes the limit, without
        # being kept (read and dropped up to 1 MiB more, so this one, twice the limit, gets
        # its 413 on a connection still in step).
        with socket.create_connection((self.server.host, self.server.port), timeout=30) as s:
            block = b"%x\r\n%s\r\n" % (32 * 1024, b" " * (32 * 1024))
            s.sendall(b"POST /api/eval HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\nConnection: close\r\n\r\n" +
                      block * (2 * MAX_BODY // (32 * 1024)) + b"0\r\n\r\n")
            data = b""
            while chunk := s.recv(65536):
                data += chunk
        head, _, body = data.partition(b"\r\n\r\n")
        self.assertTrue(head.startswith(b"HTTP/1.1 413"), head[:40])
        self.assertIn(b'"error"', body)
        # 64 MiB more: the connection is dropped after about 1 MiB, and the server's peak
        # memory stays far below what it was sent.
        with socket.create_connection((self.server.host, self.server.port), timeout=30) as s:
            s.sendall(b"POST /api/eval HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n")
            block = b"%x\r\n%s\r\n" % (1 << 20, b" " * (1 << 20))
            try:
                for _ in range(64):
                    s.sendall(block)
            except OSError:
                pass  # dropped: what is wanted
        with open(f"/proc/{self.server.proc.pid}/status") as f:
            peak_kb = int(next(l for l in f if l.startswith("VmHWM")).split()[1])
        self.assertLess(peak_kb, 48 * 1024)

    def test_time_limit_stops_the_work(self):
        slow = SLOW_REQUEST
        start = time.monotonic()
        status, ctype, body = self.server.post(*slow)
        elapsed = time.monotonic() - start
        self.assert_error(status, ctype, body, 503, "time limit")
        self.assertLess(elapsed, 4 * TIME_LIMIT + 3)
        # Its work stopped: below the server, the spawner and the two workers (the one that
        # ran it replaced), none of them computing.
        deadline = time.monotonic() + 3  # the killed worker may take a moment to leave /proc
        while len(descendants(self.server.proc.pid)) != 1 + JOBS and time.monotonic() < deadline:
            time.sleep(0.05)
        before = descendants(self.server.proc.pid)
        time.sleep(0.3)
        after = descendants(self.server.proc.pid)
        self.assertEqual(len(after), 1 + JOBS, after)
        # 0.05 s: far below the 0.3 s a process still computing would add; above the clock
        # tick (0.01 s) an idle process may be charged.
        self.assertLess(sum(after.values()) - sum(v for p, v in before.items() if p in after), 0.05, (before, after))
        # And the server still answers.
        status, _, body = self.server.post("eval", {"curve": CUBIC, "t": [0.5]})
        self.assertEqual(status, 200, body)

    def test_concurrent_requests(self):
        # 16 clients at once, each with its own request, answered as the command line does;
        # a slow request among them does not hold the others.
        requests = [json.dumps({"curve": CUBIC, "t": [i / 16, 0.5], "derivatives": 1}).encode() for i in range(16)]
        expected = [cli("eval", r)[1] for r in requests]
        results = [None] * len(requests)

        def client(i):
            results[i] = [self.server.post("eval", requests[i]) for _ in range(3)]

        slow = threading.Thread(target=lambda: self.server.post(*SLOW_REQUEST))
        slow.start()
        threads = [threading.Thread(target=client, args=(i,)) for i in range(len(requests))]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        slow.join()
        for i, rs in enumerate(results):
            for status, _, body in rs:
                self.assertEqual(status, 200, body)
                self.assertEqual(body, expected[i])

    def test_batch_answers_as_jsonl(self):
        # POST /batch: one {"command", "request"} line per request; each answer line is the
        # command line's `--jsonl` line for the same request (bad ones too), in order.
        requests = [
            ("eval", {"curve": CUBIC, "t": [0, 0.3, 1], "derivatives": 1}),
            ("split", {"curve": CUBIC, "t": 0.3}),
            ("eval", {"curve": CUBIC, "t": "half"}),  # wrong type: its error line
            ("basis", {"kind": "bernstein", "degree": 3, "t": [0.1, 0.7]}),
            ("render", {"curve": CUBIC}),  # as --jsonl writes it: {"svg": ...}
        ]
        expected = []
        for command, request in requests:
            p = subprocess.run([BINARY, command, "--jsonl"], input=json.dumps(request).encode() + b"\n",
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=30)
            expected.append(p.stdout)
        body = b"".join(json.dumps({"command": c, "request": r}).encode() + b"\n" for c, r in requests)
        status, ctype, answer = self.server.request("POST", "/batch", body)
        self.assertEqual(status, 200, answer)
        self.assertTrue(ctype.startswith("application/x-ndjson"), ctype)
        self.assertEqual(answer, b"".join(expected))
        # Lines that are not requests: an error line each, in place; the others answered.
        body = (b'[1]\n\n{"command": "nope", "request": {}}\n{"command": "eval"}\n{"command": "eval", "request": {}, "x": 1}\n' +
                json.dumps({"command": "split", "request": {"curve": CUBIC, "t": 0.3}}).encode())  # no final newline
        status, _, answer = self.server.request("POST", "/batch", body)
        self.assertEqual(status, 200, answer)
        lines = [json.loads(l) for l in answer.decode().splitlines()]
        self.assertEqual(len(lines), 6)
        self.assertTrue(lines[0]["error"].startswith("batch line: "), lines[0])
        self.assertTrue(lines[1]["error"].startswith("batch line: empty line"), lines[1])
        self.assertEqual(lines[2]["error"], "command: unknown command 'nope'")
        self.assertEqual(lines[3]["error"], "request: required field is missing")
        self.assertTrue(lines[4]["error"].startswith("x: unknown field"), lines[4])
        self.assertEqual(answer.decode().splitlines()[5] + "\n", expected[1].decode())
        # The contract's routes are unchanged: /api/batch names no command.
        status, ctype, body = self.server.post("batch", {})
        self.assert_error(status, ctype, body, 404, "unknown command")
        # One time limit for the whole batch: 503, and the server still answers.
        slow = json.dumps({"command": SLOW_REQUEST[0], "request": json.loads(SLOW_REQUEST[1])}).encode()
        status, ctype, body = self.server.request("POST", "/batch", slow)
        self.assert_error(status, ctype, body, 503, "time limit")
        status, _, _ = self.server.request("POST", "/batch", body=b'{"command": "eval", "request": {"curve": {"type": "bezier", "points": [[0]]}, "t": [0]}}')
        self.assertEqual(status, 200)

    def test_slow_client_does_not_block_others(self):
        # A client that sends its body a byte at a time (about 0.5 s in all) holds one
        # connection; 20 requests from other clients meanwhile are answered at once.
        request = json.dumps({"curve": CUBIC, "t": [0.5]}).encode()
        expected = cli("eval", request)[1]
        done = {}

        def slow_client():
            with socket.create_connection((self.server.host, self.server.port), timeout=30) as s:
                s.sendall(b"POST /api/eval HTTP/1.1\r\nHost: x\r\nConnection: close\r\nContent-Length: %d\r\n\r\n" % len(request))
                for i in range(len(request)):
                    s.sendall(request[i:i + 1])
                    time.sleep(0.5 / len(request))
                data = b""
                while chunk := s.recv(65536):
                    data += chunk
            done["slow"] = (time.monotonic(), data)

        t = threading.Thread(target=slow_client)
        t.start()
        time.sleep(0.1)  # the slow client is sending
        for _ in range(20):
            status, _, body = self.server.post("eval", request)
            self.assertEqual((status, body), (200, expected))
        others_done = time.monotonic()
        t.join()
        finished, data = done["slow"]
        self.assertLess(others_done, finished)  # not queued behind it
        head, _, body = data.partition(b"\r\n\r\n")
        self.assertTrue(head.startswith(b"HTTP/1.1 200"), head[:40])
        self.assertEqual(body, expected)

    def test_http_fuzz_seeds(self):
        # The http fuzz target's seeds (tests/fuzz/corpus/http: raw bytes of a connection,
        # pipelined requests, chunked and malformed bodies, Range, Expect, HEAD...) sent to
        # the real server, all at once: every response is HTTP/1.1 with a status of the
        # contract (or HTTP's 100 and 414), and the server still answers afterwards.
        import glob
        import re
        seeds = sorted(glob.glob(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fuzz", "corpus", "http", "*")))
        self.assertGreater(len(seeds), 10)
        answers = {}

        def send(path):
            with open(path, "rb") as f:
                data = f.read()
            with socket.create_connection((self.server.host, self.server.port), timeout=10) as s:
                s.sendall(data)
                s.settimeout(0.4)  # after the last byte, 0.4 s of silence ends the reading
                out = b""
                try:
                    while chunk := s.recv(65536):
                        out += chunk
                except (socket.timeout, ConnectionResetError):
                    pass
            answers[path] = out

        threads = [threading.Thread(target=send, args=(p,)) for p in seeds]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for path, out in answers.items():
            self.assertTrue(out.startswith(b"HTTP/1.1 "), (path, out[:60]))
            for status in re.findall(rb"HTTP/1\.1 (\d\d\d) ", out):
                self.assertIn(int(status), (100, 200, 400, 404, 413, 414), (path, out[:200]))
        status, _, body = self.server.post("eval", {"curve": CUBIC, "t": [0.5]})
        self.assertEqual(status, 200, body)

    def test_many_idle_connections(self):
        # 1000 connections opened at once and left idle do not exhaust the server: a request
        # on a new connection is answered (with a fixed pool of 32 connection threads it
        # waited for the idle ones' 2 s timeouts, about a minute), then they are closed.
        import resource
        soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
        if soft < 1200:
            resource.setrlimit(resource.RLIMIT_NOFILE, (min(hard, 4096), hard))
        idle = []
        try:
            for _ in range(1000):
                idle.append(socket.create_connection((self.server.host, self.server.port), timeout=30))
            start = time.monotonic()
            status, _, body = self.server.post("eval", {"curve": CUBIC, "t": [0.5]})
            elapsed = time.monotonic() - start
            self.assertEqual(status, 200, body)
            # 5 s: the server accepts the 1000 connections first, starting a thread for
            # each (about 1.3 ms apiece on this loaded 2-core machine: 1.3 s in all, then
            # a request takes milliseconds again); far below the minute a fixed pool took.
            self.assertLess(elapsed, 5)
        finally:
            for s in idle:
                s.close()
        status, _, body = self.server.post("eval", {"curve": CUBIC, "t": [0.5]})
        self.assertEqual(status, 200, body)


class FontDirTest(unittest.TestCase):
    """glyph with --font-dir: fonts by file name inside the directory, nothing else."""

    FONTS = "/usr/share/fonts/truetype/dejavu"  # fonts-dejavu-core (scripts/install-deps.sh)

    def test_glyph(self):
        server = Server("--font-dir", self.FONTS)
        try:
            status, _, body = server.request("GET", "/api")
            self.assertIn("glyph", [c["name"] for c in json.loads(body)["commands"]])
            rc, out, err = cli("glyph", json.dumps({"font": self.FONTS + "/DejaVuSans.ttf", "text": "l"}).encode())
            self.assertEqual(rc, 0, err)
            status, _, body = server.post("glyph", {"font": "DejaVuSans.ttf", "text": "l"})
            self.assertEqual((status, body), (200, out))
            for font in ("../../../etc/passwd", "/etc/passwd", ".hidden", "", "a/b.ttf", "..\\x.ttf"):
                status, ctype, body = server.post("glyph", {"font": font, "text": "l"})
                self.assertEqual(status, 400, (font, body))
                self.assertTrue(json.loads(body)["error"].startswith("font: "), body)
        finally:
            server.stop()


# A request known to take seconds: the self-intersections of a cubic B-spline through 4000
# points on a Lissajous-like figure (thousands of crossings; about 2 s of CPU, measured with
# the command line, eight times the limit; under the library's work limit for intersect).
SLOW_REQUEST = None


def make_slow_request():
    import math
    n = 4000
    points = [[round(100 * math.cos(i * 0.37)), round(100 * math.sin(i * 0.53))] for i in range(n)]
    curve = {"type": "bspline", "degree": 3, "knots": list(range(n + 4)), "points": points}
    return ("intersect", json.dumps({"curves": [curve]}, separators=(",", ":")).encode())


if __name__ == "__main__":
    BINARY = sys.argv.pop(1)
    SLOW_REQUEST = make_slow_request()
    unittest.main()
