// Subcommands of `motorbench`. Each harness/cli/cmd_*.cpp registers one with MB_COMMAND and its
// longer help (options, example) with MB_COMMAND_HELP; main() dispatches on argv[1]. Exit codes:
// 0 pass, 1 threshold exceeded, 2 bad input / error.
#pragma once
#include <string>
#include <vector>

namespace mb {

struct Command {
  const char* name;
  const char* usage;    // one line: arguments
  const char* summary;  // one line: what it does
  int (*run)(const std::vector<std::string>& args);  // args exclude "motorbench <name>"
};

// What `motorbench CMD --help` (and `motorbench help CMD`) prints after the usage line.
struct CommandHelp {
  const char* name;
  const char* options;  // one option per line: "--key VALUE   what it does"
  const char* example;  // one command line, run from the repository root
  bool pipelines;       // the command takes pipeline names: list the registered ones
};

std::vector<Command>& commands();
std::vector<CommandHelp>& commandHelps();

// The usage line, summary, options, pipeline names (where the command takes them) and the
// example of `c`, on stdout.
void printCommandHelp(const Command& c);

struct CommandRegistrar {
  explicit CommandRegistrar(Command c) { commands().push_back(c); }
  explicit CommandRegistrar(CommandHelp h) { commandHelps().push_back(h); }
};

}  // namespace mb

#define MB_COMMAND(ident, name, usage, summary, fn) \
  static ::mb::CommandRegistrar mb_command_##ident(::mb::Command{name, usage, summary, fn})
#define MB_COMMAND_HELP(ident, name, options, example, pipelines) \
  static ::mb::CommandRegistrar mb_command_help_##ident(::mb::CommandHelp{name, options, example, pipelines})
