#pragma once
// Runs the auvballast executable and captures exit code, stdout and stderr.
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace auv::testing {

struct CliResult {
  int code = -1;
  std::string out;
  std::string err;
};

inline CliResult runCli(const std::string& args) {
  // One file per call: ctest runs several CLI tests in parallel processes.
  static int calls = 0;
  const std::string errFile =
      ::testing::TempDir() + "cli_stderr_" + std::to_string(getpid()) + "_" + std::to_string(++calls) + ".txt";
  const std::string cmd = std::string(AUVBALLAST_EXE) + " " + args + " 2>" + errFile;
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(errFile);
  std::stringstream ss;
  ss << e.rdbuf();
  r.err = ss.str();
  std::remove(errFile.c_str());
  return r;
}

}  // namespace auv::testing
