// pcsg figures, when pcsg is built without the renderer (-DPCSG_WITH_RENDER=OFF): the command
// exists, so that scripts (scripts/main.sh) get a clear message and a distinct exit code (3)
// instead of "unknown subcommand".
#include <cstdio>

#include "app/command.h"

namespace pcsg::app {
namespace {

void setup(CLI::App& cli) {
  CLI::App* cmd = cli.add_subcommand("figures", "Draw the paper's figures (not in this build)");
  cmd->allow_extras();  // accept the renderer's arguments, whatever they are
  cmd->callback([] {
    std::fprintf(stderr, "pcsg was built without the renderer (-DPCSG_WITH_RENDER=OFF)\n");
    throw CommandExit{3};
  });
}

}  // namespace

PCSG_REGISTER_COMMAND(50, setup);

}  // namespace pcsg::app
