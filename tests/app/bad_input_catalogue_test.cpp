// The bad-input catalogue (tests/data/bad/catalogue.tsv, written by
// scripts/make-bad-inputs.py): every damaged or hostile input is run through
// the real CLI and must be refused on one line with exit code 2, naming the
// file (or flag) and position and the key words of the fix, within 2 s and
// 200 MB of peak memory (the child's own getrusage). One table, one test;
// the summary line printed at the end gives the counts for the issue note.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Case {
  std::string name, args;
  std::vector<std::string> expect;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  return out;
}

std::vector<Case> readCatalogue(const std::string& file) {
  std::vector<Case> cases;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto cols = split(line, '\t');
    if (cols.size() != 3) continue;
    cases.push_back({cols[0], cols[1], split(cols[2], '|')});
  }
  return cases;
}

void replaceAll(std::string& s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
}

// Whitespace-separated arguments; none of the catalogue's contain spaces.
std::vector<std::string> argv(const std::string& args) {
  std::vector<std::string> out;
  std::istringstream in(args);
  for (std::string a; in >> a;) out.push_back(a);
  return out;
}

struct ChildRun {
  int code = -1;  // -1: killed (timeout) or did not exit normally
  std::string err;
  double seconds = 0.0;
  long peak_kb = 0;
};

// fork/exec in `cwd`, stderr to a file; wait4 gives the child's own peak RSS.
// A child still running after 20 s is killed (a FIFO that blocks, say).
ChildRun runChild(const std::vector<std::string>& args, const std::string& cwd, const std::string& errFile,
        const std::string& history) {
  ChildRun r;
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(cwd.c_str()) != 0) _exit(120);
    const int fd = open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int nul = open("/dev/null", O_RDWR);
    dup2(nul, 0);
    dup2(nul, 1);
    dup2(fd, 2);
    setenv("AUVBALLAST_HISTORY", history.c_str(), 1);
    std::vector<char*> a;
    std::string exe = AUVBALLAST_EXE;
    a.push_back(exe.data());
    std::vector<std::string> copy = args;
    for (auto& s : copy) a.push_back(s.data());
    a.push_back(nullptr);
    execv(exe.c_str(), a.data());
    _exit(121);
  }
  int status = 0;
  rusage ru{};
  for (;;) {
    const pid_t w = wait4(pid, &status, WNOHANG, &ru);
    if (w == pid) break;
    if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(20)) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &ru);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.peak_kb = ru.ru_maxrss;
  std::ifstream e(errFile);
  std::stringstream ss;
  ss << e.rdbuf();
  r.err = ss.str();
  return r;
}

TEST(BadInputCatalogue, EveryInputIsRefusedClearlyQuicklyAndSmall) {
  const std::string src = std::string(AUV_TEST_DATA_DIR) + "/bad";
  const std::vector<Case> cases = readCatalogue(src + "/catalogue.tsv");
  ASSERT_GE(cases.size(), 150u) << "the catalogue must hold at least 150 inputs";

  // A copy, so that nothing (a history's -wal file, an output) lands in the source tree.
  const fs::path work = fs::path(::testing::TempDir()) / ("bad_catalogue_" + std::to_string(getpid()));
  fs::remove_all(work);
  fs::create_directories(work / "tmp");
  fs::copy(src, work / "bad", fs::copy_options::recursive);
  const std::string fifo = (work / "fifo").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);

  int refused = 0, named = 0;
  long peak_kb = 0;
  double slowest = 0.0;
  for (const Case& c : cases) {
    std::string args = c.args;
    replaceAll(args, "{bad}", (work / "bad").string());
    replaceAll(args, "{tmp}", (work / "tmp").string());
    replaceAll(args, "{res}", AUV_RESOURCE_DIR);
    replaceAll(args, "{fifo}", fifo);
    const ChildRun r = runChild(argv(args), (work / "bad").string(), (work / "stderr.txt").string(),
                      (work / "tmp" / "default.sqlite").string());
    SCOPED_TRACE(c.name + ": auvballast " + args + "\n  stderr: " + r.err);
    EXPECT_EQ(r.code, 2) << "bad input must exit 2 (0 = silently accepted, 1 = internal error)";
    EXPECT_LT(r.seconds, 2.0);
    EXPECT_LT(r.peak_kb, 200L * 1024) << "peak RSS " << r.peak_kb / 1024 << " MB";
    // The refusal is the last line: "auvballast: <where>: <field>: <problem>; <fix>"
    // (a warning may come before it).
    std::string last = r.err;
    while (!last.empty() && last.back() == '\n') last.pop_back();
    last = last.substr(last.rfind('\n') == std::string::npos ? 0 : last.rfind('\n') + 1);
    EXPECT_EQ(last.rfind("auvballast: ", 0), 0u);
    EXPECT_NE(last.find("; "), std::string::npos) << "the message must end with a fix after '; '";
    bool all = true;
    for (const std::string& e : c.expect) {
      if (e.empty()) continue;
      EXPECT_NE(r.err.find(e), std::string::npos) << "missing '" << e << "'";
      all = all && r.err.find(e) != std::string::npos;
    }
    refused += r.code == 2;
    named += r.code == 2 && all;
    peak_kb = std::max(peak_kb, r.peak_kb);
    slowest = std::max(slowest, r.seconds);
  }
  std::printf("bad-input catalogue: %zu inputs, %d refused with exit 2, %d naming file/flag, position and fix as "
              "listed; peak RSS %.1f MB; slowest %.2f s\n",
              cases.size(), refused, named, static_cast<double>(peak_kb) / 1024.0, slowest);
  fs::remove_all(work);
}

}  // namespace
