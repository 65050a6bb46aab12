#pragma once
// Subcommands register themselves: a file app/cmd_<name>.cc defines a setup function that adds
// its CLI11 subcommand and sets its callback, and registers it with PCSG_REGISTER_COMMAND.
// Commands are listed in `pcsg --help` in the order of their `rank`.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace pcsg::app {

struct CommandRegistration {
  int rank;
  std::function<void(CLI::App&)> setup;
};

std::vector<CommandRegistration>& command_registry();

struct CommandRegistrar {
  CommandRegistrar(int rank, std::function<void(CLI::App&)> setup) {
    command_registry().push_back({rank, std::move(setup)});
  }
};

// Exit code a command callback asks for by throwing CommandExit (the CLI's other codes:
// 0 success, 1 error in the input or the run, 2 bad command line).
struct CommandExit {
  int code;
};

}  // namespace pcsg::app

#define PCSG_CONCAT_INNER(a, b) a##b
#define PCSG_CONCAT(a, b) PCSG_CONCAT_INNER(a, b)
#define PCSG_REGISTER_COMMAND(rank, fn) \
  static ::pcsg::app::CommandRegistrar PCSG_CONCAT(pcsg_registrar_, __LINE__)(rank, fn)
