// `casteljau COMMAND [FILE]`: the command line program of docs/cli.md. Reads
// requests, runs commands, writes responses; maps errors to exit statuses 2 (bad input)
// and 1 (internal error), always with exactly one `error: <where>: <what>` line on stderr.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "casteljau/io/commands.hpp"

namespace {

using casteljau::InvalidArgument;
using casteljau::io::Command;
using casteljau::io::Json;
using casteljau::io::OrderedJson;

constexpr int exit_ok = 0;
constexpr int exit_internal = 1;
constexpr int exit_bad_input = 2;

/// The length of the well-formed UTF-8 sequence starting at s[i] (RFC 3629), or 0.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n;
  unsigned char lo = 0x80, hi = 0xbf;  // range of the second byte
  if (c >= 0xc2 && c <= 0xdf) {
    n = 2;
  } else if (c >= 0xe0 && c <= 0xef) {
    n = 3;
    if (c == 0xe0) lo = 0xa0;  // no overlong forms
    if (c == 0xed) hi = 0x9f;  // no surrogates
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 4;
    if (c == 0xf0) lo = 0x90;
    if (c == 0xf4) hi = 0x8f;  // <= U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (b(i + k) < 0x80 || b(i + k) > 0xbf) return 0;
  }
  return n;
}

/// The message with control characters and bytes that are not UTF-8 escaped, so that it
/// stays one line of text (user input may appear in it).
std::string one_line(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char ch = s[i];
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x80) {
      if (const std::size_t n = utf8_length(s, i)) {
        out.append(s.substr(i, n));
        i += n - 1;
      } else {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\x%02x", c);
        out += buf;
      }
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out;
}

/// s cut to about `limit` bytes: its start and its end (whole UTF-8 characters) around an
/// ellipsis and the length. The io layer already cuts the user text it quotes; this keeps
/// every message bounded whatever its source (CLI11's messages echo arguments).
std::string clipped(std::string_view s, std::size_t limit) {
  if (s.size() <= limit) return std::string(s);
  const auto continuation = [&](std::size_t i) { return (static_cast<unsigned char>(s[i]) & 0xc0) == 0x80; };
  std::size_t head = limit * 2 / 3, tail = s.size() - limit / 3;
  while (head > 0 && continuation(head)) --head;
  while (tail < s.size() && continuation(tail)) ++tail;
  return std::string(s.substr(0, head)) + "\u2026 (" + std::to_string(s.size()) + " bytes) \u2026" + std::string(s.substr(tail));
}

/// Longest `<where>` and whole message written (bytes): far above any message the program
/// composes, far below what hostile input could make of one.
constexpr std::size_t max_where = 300;
constexpr std::size_t max_message = 800;

std::string where_what(const InvalidArgument& e) {
  return clipped(e.where().empty() ? std::string("request") : e.where(), max_where) + ": " + e.problem();
}

void print_error(std::string_view message) {
  const std::string line = "error: " + one_line(clipped(message, max_message)) + "\n";
  std::fwrite(line.data(), 1, line.size(), stderr);
  std::fflush(stderr);
}

/// Writes all of s to stdout and flushes; false on a write error.
bool write_stdout(std::string_view s) {
  if (std::fwrite(s.data(), 1, s.size(), stdout) != s.size()) return false;
  return std::fflush(stdout) == 0;
}

/// Input: a named file, or stdin for "" (no FILE argument) and "-".
class Input {
 public:
  explicit Input(const std::string& file) : name_(file.empty() || file == "-" ? "stdin" : file) {
    if (file.empty() || file == "-") {
      fp_ = stdin;
    } else {
      fp_ = std::fopen(file.c_str(), "rb");
      if (!fp_) throw InvalidArgument(file, std::string("cannot open file: ") + std::strerror(errno));
      owned_ = true;
    }
  }
  Input(const Input&) = delete;
  Input& operator=(const Input&) = delete;
  ~Input() {
    if (owned_) std::fclose(fp_);
  }

  /// Everything that is left.
  std::string read_all() {
    std::string s;
    char buf[1 << 16];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, fp_)) > 0) s.append(buf, n);
    check();
    return s;
  }

  /// The next line without its "\n" (and "\r" before it); false at the end.
  bool read_line(std::string& line) {
    line.clear();
    int c;
    bool any = false;
    while ((c = std::fgetc(fp_)) != EOF) {
      any = true;
      if (c == '\n') break;
      line += static_cast<char>(c);
    }
    if (c == EOF) check();
    if (!any) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }

 private:
  void check() {
    if (std::ferror(fp_)) throw InvalidArgument(name_, std::string("cannot read: ") + std::strerror(errno));
  }

  std::string name_;
  std::FILE* fp_ = nullptr;
  bool owned_ = false;
};

/// The outcome of one request: the text to write, or an error.
struct Answer {
  std::string text;  // response (JSON line or SVG), on success
  std::string error;  // "<where>: <what>", on failure
  int status = exit_ok;
};

Answer answer(const Command& command, std::string_view text, bool jsonl) {
  Answer a;
  try {
    // A blank line is not silently skipped: responses pair with input lines by position.
    if (jsonl && text.find_first_not_of(" \t") == std::string_view::npos) {
      throw InvalidArgument("request", "empty line (every line must hold one JSON request object)");
    }
    const Json request = casteljau::io::parse_json(text);
    const auto response = casteljau::io::run(command, request);
    if (response.is_svg && !jsonl) {
      a.text = response.svg;
    } else {
      a.text = response.json.dump(-1, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
    }
  } catch (const InvalidArgument& e) {
    a.error = where_what(e);
    a.status = exit_bad_input;
  } catch (const std::exception& e) {
    a.error = std::string("internal: ") + e.what();
    a.status = exit_internal;
  }
  return a;
}

int run_single(const Command& command, const std::string& file) {
  std::string text;
  try {
    Input in(file);
    text = in.read_all();
  } catch (const InvalidArgument& e) {
    print_error(where_what(e));
    return exit_bad_input;
  }
  const Answer a = answer(command, text, false);
  if (a.status != exit_ok) {
    print_error(a.error);
    return a.status;
  }
  if (!write_stdout(a.text)) {
    print_error(std::string("internal: cannot write the response: ") + std::strerror(errno));
    return exit_internal;
  }
  return exit_ok;
}

int run_jsonl(const Command& command, const std::string& file) {
  std::vector<std::size_t> bad_lines;
  std::size_t count = 0;
  int status = exit_ok;
  try {
    Input in(file);
    std::string line;
    while (in.read_line(line)) {
      ++count;
      const Answer a = answer(command, line, true);
      std::string out = a.text;
      if (a.status != exit_ok) {
        out = OrderedJson{{"error", clipped(a.error, max_message)}}.dump(-1, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
        bad_lines.push_back(count);
        if (status != exit_internal) status = a.status;
      }
      if (!write_stdout(out)) {
        print_error(std::string("internal: cannot write the response: ") + std::strerror(errno));
        return exit_internal;
      }
    }
  } catch (const InvalidArgument& e) {
    // The input itself failed (no such file, read error): the lines so far are answered.
    print_error(where_what(e));
    return exit_bad_input;
  }
  if (!bad_lines.empty()) {
    std::string where = bad_lines.size() == 1 ? "line " : "lines ";
    for (std::size_t i = 0; i < bad_lines.size() && i < 10; ++i) where += (i ? ", " : "") + std::to_string(bad_lines[i]);
    if (bad_lines.size() > 10) where += ", ...";
    print_error(where + ": " + std::to_string(bad_lines.size()) + " of " + std::to_string(count) +
                " requests failed; each has an {\"error\": ...} response line");
  }
  return status;
}

std::string command_list() {
  std::string s;
  for (const auto& c : casteljau::io::commands()) s += (s.empty() ? "" : ", ") + std::string(c.name);
  return s;
}

/// The program's description for --help: the curve types of the registry.
std::string description() {
  std::string types;
  for (const auto name : casteljau::io::curve_type_names()) types += (types.empty() ? "" : ", ") + std::string(name);
  return "casteljau " CASTELJAU_VERSION ": curves on the command line (" + types +
         ").\n"
         "Reads one JSON request from FILE (or stdin when FILE is absent or -), writes one JSON\n"
         "response to stdout. Errors: exit status 2 and one line 'error: <where>: <what>' on stderr.";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(description(), "casteljau");
  app.set_version_flag("--version", "casteljau " CASTELJAU_VERSION);
  app.footer("Run 'casteljau COMMAND --help' for a command's request, response and an example.\n"
             "Curve objects and the full contract: docs/cli.md.");
  app.require_subcommand(0, 1);
  app.get_formatter()->label("SUBCOMMAND", "COMMAND");

  bool jsonl = false;
  std::string file;
  std::vector<CLI::Option*> file_options;
  app.add_flag("--jsonl", jsonl, "One request per line in, one response per line out");
  for (const auto& c : casteljau::io::commands()) {
    CLI::App* sub = app.add_subcommand(std::string(c.name), std::string(c.summary));
    sub->group("Commands");
    sub->footer(casteljau::io::help(c));
    file_options.push_back(sub->add_option("FILE", file, "Request file (default: stdin; - for stdin)")->type_name(""));
    sub->add_flag("--jsonl", jsonl, "One request per line in, one response per line out");
  }

  // An unknown command reads better as such than as CLI11's "arguments were not expected".
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a.empty() || a.front() != '-' || a == "-") {
      if (!casteljau::io::find_command(a)) {
        print_error("command: unknown command " + casteljau::io::quoted(a) + " (commands: " + command_list() + ")");
        return exit_bad_input;
      }
      break;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    print_error(std::string("arguments: ") + e.what() + " (run casteljau --help)");
    return exit_bad_input;
  }

  const auto chosen = app.get_subcommands();
  if (chosen.empty()) {
    print_error("command: missing command (commands: " + command_list() + "; run casteljau --help)");
    return exit_bad_input;
  }
  const Command* command = casteljau::io::find_command(chosen.front()->get_name());
  // An empty FILE (a script's unset variable: casteljau eval "$f") must not quietly read
  // stdin, as a missing one does.
  for (const CLI::Option* o : file_options) {
    if (o->count() > 0 && file.empty()) {
      print_error("arguments: FILE is an empty string (give a file name, or - or no FILE to read stdin)");
      return exit_bad_input;
    }
  }
  try {
    return jsonl ? run_jsonl(*command, file) : run_single(*command, file);
  } catch (const std::exception& e) {
    print_error(std::string("internal: ") + e.what());
    return exit_internal;
  }
}
