// popen-based runner: stdout and stderr go to temp files so both can be checked.
#include "tests/support/run_command.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mdrsim::test {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string make_temp_dir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "mdrsim-test-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

CommandResult run_mdrsim(const std::string& args, const std::string& input) {
  const std::filesystem::path dir = make_temp_dir();
  const std::string command = "cd '" MDRSIM_SOURCE_DIR "' && '" MDRSIM_BINARY "' " + args + " >'" +
                              (dir / "out").string() + "' 2>'" + (dir / "err").string() + "' <'" +
                              input + "'";
  const int status = std::system(command.c_str());
  CommandResult r{WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
                  slurp(dir / "out"), slurp(dir / "err")};
  std::filesystem::remove_all(dir);
  return r;
}

}  // namespace mdrsim::test
