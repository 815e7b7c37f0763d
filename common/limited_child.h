#pragma once
// Runs untrusted parsing in a separate process under memory and CPU limits, so a
// damaged or hostile file that claims huge sizes costs a bounded amount of the
// machine and ends in a clear error instead of a hang or an exhausted host.
//
// The reader is a program of its own that the library carries as bytes and
// starts fresh (exec, not a bare fork): a fork of a process with threads (TBB's,
// the Vulkan driver's) copies whatever locks they held at that instant, and a
// child that needed one of them waited forever.
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace grotto {

struct ChildLimits {
    size_t memoryBytes = size_t(512) << 20;  // address space the child may add to what it has at its start
    int cpuSeconds = 1;                      // CPU time before the child is stopped
};

// Runs `program` (an executable's bytes) as a new process with arguments `args`,
// the descriptor `input` as its descriptor 3 and stdout and stderr on /dev/null,
// under `limits`, and waits for it. The program calls serveAsLimitedChild.
// Returns when its work returned; rethrows a grotto::Error it threw (kind, where,
// what and hint kept); throws grotto::Error (input) naming `where` when it ran
// out of memory, out of CPU time, threw something else or crashed, and
// grotto::Error (internal) when it could not be started.
void runInLimitedChild(const std::string& where, const ChildLimits& limits, std::span<const unsigned char> program,
                       const std::vector<std::string>& args, int input);

// The child's side, its whole main(): applies the limits runInLimitedChild
// passed, runs work(args) (the arguments after them) and reports the outcome.
// Never returns.
[[noreturn]] void serveAsLimitedChild(int argc, char** argv,
                                      const std::function<void(const std::vector<std::string>& args)>& work);

// Raises the child's memory limit to at least `bytes` beyond what it had at its
// start (never above a hard limit set from outside). For `work` to call once it
// knows, from trusted checks, that the input legitimately needs more. Does
// nothing outside a child.
void allowChildMemory(size_t bytes);

}  // namespace grotto
