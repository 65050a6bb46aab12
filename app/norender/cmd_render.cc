// pcsg render, when pcsg is built without the renderer (-DPCSG_WITH_RENDER=OFF): the command
// exists, so that scripts get a clear message and a distinct exit code (3) instead of
// "unknown subcommand".
#include <cstdio>

#include "app/command.h"

namespace pcsg::app {
namespace {

void setup(CLI::App& cli) {
  CLI::App* cmd = cli.add_subcommand("render", "Draw the objects to a PNG (not in this build)");
  cmd->allow_extras();  // accept the renderer's arguments, whatever they are
  cmd->callback([] {
    std::fprintf(stderr, "pcsg was built without the renderer (-DPCSG_WITH_RENDER=OFF)\n");
    throw CommandExit{3};
  });
}

}  // namespace

PCSG_REGISTER_COMMAND(40, setup);

}  // namespace pcsg::app
