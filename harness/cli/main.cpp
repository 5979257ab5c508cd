// motorbench: renders glTF scenes through interchangeable pipelines and measures them.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "harness/cli/command.h"
#include "mb_version.h"  // generated: MB_VERSION, MB_GIT_COMMIT (harness/cli/version.cmake)

namespace mb {
std::vector<Command>& commands() {
  static std::vector<Command> list;
  return list;
}
}  // namespace mb

static void usage() {
  std::printf("usage: motorbench <command> [options]   (motorbench --version; motorbench <command> --help or "
              "motorbench help <command>: options, pipeline names, an example)\n\ncommands:\n");
  auto cmds = mb::commands();
  std::sort(cmds.begin(), cmds.end(),
            [](const mb::Command& a, const mb::Command& b) { return std::strcmp(a.name, b.name) < 0; });
  for (const auto& c : cmds) std::printf("  %-9s %s\n            %s\n", c.name, c.usage, c.summary);
}

static const mb::Command* findCommand(const char* name) {
  for (const auto& c : mb::commands())
    if (!std::strcmp(name, c.name)) return &c;
  return nullptr;
}

int main(int argc, char** argv) {
  // `motorbench help CMD`: that command's help, as `motorbench CMD --help`.
  if (argc == 3 && !std::strcmp(argv[1], "help")) {
    if (!std::strcmp(argv[2], "help")) {  // help about help: how to ask, and the commands
      std::printf("usage: motorbench help <command>\n  the command's usage, options, pipeline names and an example "
                  "(the same as motorbench <command> --help); motorbench help alone lists the commands\n\n");
      usage();
      return 0;
    }
    const mb::Command* c = findCommand(argv[2]);
    if (!c) {
      std::fprintf(stderr, "motorbench help: unknown command '%s' (motorbench --help lists them)\n", argv[2]);
      return 2;
    }
    mb::printCommandHelp(*c);
    return 0;
  }
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
      !std::strcmp(argv[1], "help")) {
    usage();
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version") || !std::strcmp(argv[1], "version")) {
    std::printf("motorbench %s (git %s)\n", MB_VERSION, *MB_GIT_COMMIT ? MB_GIT_COMMIT : "commit unknown");
    return 0;
  }
  for (const auto& c : mb::commands()) {
    if (std::strcmp(argv[1], c.name) != 0) continue;
    std::vector<std::string> args(argv + 2, argv + argc);
    // No command takes --help as a value, so it always asks for this command's usage.
    if (std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; })) {
      mb::printCommandHelp(c);
      return 0;
    }
    try {
      return c.run(args);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "motorbench %s: error: %s\n", c.name, e.what());
      return 2;
    }
  }
  std::fprintf(stderr, "motorbench: unknown command '%s' (try --help)\n", argv[1]);
  return 2;
}
