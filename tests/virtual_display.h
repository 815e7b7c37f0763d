#pragma once
// A virtual X server of a test's own, for `grotto view` in a real window. Xvfb
// picks a free display itself (-displayfd), so tests running side by side never
// collide; it stops with the test.
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace grotto::test {

class VirtualDisplay {
public:
    VirtualDisplay() {
        const std::filesystem::path file = std::filesystem::temp_directory_path() / ("grotto-xvfb-" + std::to_string(getpid()));
        pid_ = fork();
        if (pid_ == 0) {
            const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
            const int quiet = open("/dev/null", O_WRONLY);
            dup2(quiet, 1);
            dup2(quiet, 2);
            const std::string fdText = std::to_string(fd);
            execlp("Xvfb", "Xvfb", "-displayfd", fdText.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp",
                   static_cast<char*>(nullptr));
            _exit(127);
        }
        // The display number arrives once the server accepts connections.
        for (int i = 0; i < 200 && display_.empty(); ++i) {
            std::ifstream in(file);
            std::string n;
            if (std::getline(in, n) && !in.eof()) display_ = ":" + n;
            else std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        std::filesystem::remove(file);
    }
    ~VirtualDisplay() {
        if (pid_ > 0) {
            kill(pid_, SIGTERM);
            waitpid(pid_, nullptr, 0);
        }
    }
    // The environment a viewer run gets: this display, the validation layer on.
    std::string env() const { return "GROTTO_VALIDATION=1 DISPLAY=" + display_; }
    bool ready() const { return !display_.empty(); }

private:
    pid_t pid_ = -1;
    std::string display_;
};

inline bool haveXvfb() { return std::system("command -v Xvfb >/dev/null 2>&1") == 0; }

#define REQUIRE_XVFB()                                                                                         \
    if (!grotto::test::haveXvfb()) GTEST_SKIP() << "Xvfb is not installed (Debian: xvfb): no X server for the viewer's window"; \
    const grotto::test::VirtualDisplay x;                                                                                  \
    ASSERT_TRUE(x.ready()) << "Xvfb did not start";                                                           \
    const std::string kUnderXvfb = x.env()

}  // namespace grotto::test
