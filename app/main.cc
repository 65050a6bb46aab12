// pcsg: generate and show the point-contact state space of two strictly curved objects.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>

#include "app/command.h"
#include "engine/core/error.h"

namespace pcsg::app {

std::vector<CommandRegistration>& command_registry() {
  static std::vector<CommandRegistration> registry;
  return registry;
}

}  // namespace pcsg::app

int main(int argc, char** argv) {
  using namespace pcsg;
  CLI::App cli{
      "pcsg: point-contact state graphs of strictly curved objects (Tang & Xiao, RSS 2006)",
      "pcsg"};
  cli.set_version_flag("--version", std::string("pcsg ") + PCSG_VERSION);
  cli.require_subcommand(1);
  cli.fallthrough(false);

  auto& registry = app::command_registry();
  std::stable_sort(registry.begin(), registry.end(),
                   [](const auto& a, const auto& b) { return a.rank < b.rank; });
  for (const auto& reg : registry) reg.setup(cli);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    // One clear line and exit code 2 for any malformed command line.
    std::fprintf(stderr, "pcsg: error: %s\nRun 'pcsg --help' for usage.\n", e.what());
    return 2;
  } catch (const app::CommandExit& e) {
    return e.code;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "pcsg: error: %s\n", e.what());
    return 2;
  } catch (const Error& e) {
    std::fprintf(stderr, "pcsg: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pcsg: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
