#pragma once
// Helpers shared by the tests: scratch directories and running the grotto CLI.
#include <filesystem>
#include <string>

namespace grotto::test {

// A fresh, empty directory under the system temp dir, removed on destruction.
struct ScratchDir {
    std::filesystem::path path;
    ScratchDir();
    ~ScratchDir();
    std::filesystem::path operator/(const std::string& name) const { return path / name; }
};

struct RunResult {
    int exitCode = -1;
    std::string out, err;
};

// Runs the grotto executable with the given arguments (shell-quoted here),
// with `env` ("NAME=value ...") added to its environment.
RunResult runGrotto(const std::string& args, const std::string& env = "");

// The source tree's worlds/ directory.
std::filesystem::path worldsDir();

}  // namespace grotto::test
