// Subcommands of `motorbench`. Each harness/cli/cmd_*.cpp registers one with MB_COMMAND; main()
// dispatches on argv[1]. Exit codes: 0 pass, 1 threshold exceeded, 2 bad input / error.
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

std::vector<Command>& commands();

struct CommandRegistrar {
  explicit CommandRegistrar(Command c) { commands().push_back(c); }
};

}  // namespace mb

#define MB_COMMAND(ident, name, usage, summary, fn) \
  static ::mb::CommandRegistrar mb_command_##ident({name, usage, summary, fn})
