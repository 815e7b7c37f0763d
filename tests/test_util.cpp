#include "tests/test_util.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace grotto::test {
namespace fs = std::filesystem;

ScratchDir::ScratchDir() {
    static std::atomic<int> counter{0};
    path = fs::temp_directory_path() /
           ("grotto-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
}

ScratchDir::~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
}

RunResult runGrotto(const std::string& args, const std::string& env) {
    ScratchDir dir;
    const fs::path out = dir / "stdout", err = dir / "stderr";
    const std::string cmd = (env.empty() ? "" : "env " + env + " ") + std::string(GROTTO_EXE) + " " + args + " >" + out.string() + " 2>" + err.string();
    RunResult r;
    const int status = std::system(cmd.c_str());
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    auto slurp = [](const fs::path& p) {
        std::ifstream in(p);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

fs::path worldsDir() { return fs::path(GROTTO_SOURCE_DIR) / "worlds"; }

}  // namespace grotto::test
