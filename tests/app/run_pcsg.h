#pragma once
// Runs the built `pcsg` executable (PCSG_EXE) in the app tests and captures what it prints.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace pcsg::testing {

struct ExeRun {
  int exit_code = -1;
  std::string out;
};

// Runs pcsg with `args`, capturing stdout; stderr is merged into it when asked, else dropped.
inline ExeRun run_pcsg(const std::string& args, bool merge_stderr = false) {
  const std::string cmd =
      std::string(PCSG_EXE) + " " + args + (merge_stderr ? " 2>&1" : " 2>/dev/null");
  ExeRun r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace pcsg::testing
