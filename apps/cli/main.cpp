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
#include "request.hpp"
#include "serve.hpp"

namespace {

using casteljau::InvalidArgument;
using casteljau::cli::Answer;
using casteljau::cli::clipped;
using casteljau::cli::exit_bad_input;
using casteljau::cli::exit_internal;
using casteljau::cli::exit_ok;
using casteljau::cli::max_message;
using casteljau::cli::one_line;
using casteljau::cli::where_what;
using casteljau::io::Command;
using casteljau::io::OrderedJson;

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

int run_single(const Command& command, const std::string& file) {
  std::string text;
  try {
    Input in(file);
    text = in.read_all();
  } catch (const InvalidArgument& e) {
    print_error(where_what(e));
    return exit_bad_input;
  }
  const Answer a = casteljau::cli::answer(command, text, false);
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
      const Answer a = casteljau::cli::answer(command, line, true);
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
  // `casteljau serve`: the HTTP server and the explorer page (serve.cpp).
  casteljau::cli::ServeOptions serve_options;
  CLI::App* serve = app.add_subcommand("serve", "Serve the explorer page and every command over HTTP (POST /api/COMMAND)");
  serve->group("Server");
  serve->add_option("--host", serve_options.host, "Address to bind (default: the loopback address)")->capture_default_str();
  serve->add_option("--port", serve_options.port, "Port to listen on (0: any free port, printed)")->capture_default_str()->check(CLI::Range(0, 65535));
  serve->add_option("--max-body", serve_options.max_body, "Largest request body in bytes (larger: 413)")->capture_default_str()->check(CLI::PositiveNumber);
  serve->add_option("--time-limit", serve_options.time_limit, "Seconds of computing one request may take (more: 503, its work stopped)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  serve->add_option("--jobs", serve_options.jobs, "Requests computed at once (default: the number of cores)");
  serve->add_option("--font-dir", serve_options.font_dir,
                    "Directory whose font files the glyph command may read, by file name (default: none, glyph is refused)");

  // An unknown command reads better as such than as CLI11's "arguments were not expected".
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a.empty() || a.front() != '-' || a == "-") {
      if (a != "serve" && !casteljau::io::find_command(a)) {
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
  if (chosen.front() == serve) {
    try {
      return casteljau::cli::serve_through_module(serve_options);
    } catch (const std::exception& e) {
      print_error(std::string("serve: ") + e.what());
      return exit_internal;
    }
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
