#pragma once
// Runs untrusted parsing in a forked child under memory and CPU limits, so a
// damaged or hostile file that claims huge sizes costs a bounded amount of the
// machine and ends in a clear error instead of a hang or an exhausted host.
#include <cstddef>
#include <functional>
#include <string>

namespace grotto {

struct ChildLimits {
    size_t memoryBytes = size_t(512) << 20;  // address space the child may add to what it inherits
    int cpuSeconds = 1;                      // CPU time before the child is stopped
};

// Raises the calling child's memory limit to at least `bytes` beyond what it
// inherited (never above a hard limit set from outside). For `work` to call once
// it knows, from trusted checks, that the input legitimately needs more.
void allowChildMemory(size_t bytes);

// Runs work() in a child process under `limits` and waits for it. Returns when
// work returned; rethrows a grotto::Error it threw (kind, where, what and hint
// kept); throws grotto::Error (input) naming `where` when work ran out of memory,
// out of CPU time, threw something else or crashed.
void runInLimitedChild(const std::string& where, const ChildLimits& limits, const std::function<void()>& work);

}  // namespace grotto
