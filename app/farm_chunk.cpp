#include "app/farm_chunk.h"

#include "app/options.h"
#include "grotto/error.h"

#include <algorithm>
#include <cstdlib>

namespace grotto::app {
namespace {

constexpr const char* kAccepted = "accepted: K/N with 1 <= K <= N <= 1000000, e.g. 2/8, or auto in a Slurm job array "
                                  "or a Kubernetes Indexed Job";

bool isWholeNumber(const std::string& t) {
    return !t.empty() && t.size() <= 9 && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

ChunkOfN parseKOfN(const std::string& text) {
    const size_t slash = text.find('/');
    if (slash == std::string::npos || !isWholeNumber(text.substr(0, slash)) || !isWholeNumber(text.substr(slash + 1)))
        throw Error("--chunk", "'" + text + "' is not a chunk", kAccepted);
    const ChunkOfN c{std::stoi(text.substr(0, slash)), std::stoi(text.substr(slash + 1))};
    if (c.n < 1 || c.n > kMaxChunks || c.k < 1 || c.k > c.n)
        throw Error("--chunk", "'" + text + "' is out of range", kAccepted);
    return c;
}

namespace {

// A variable holding a whole number, or none when unset.
std::optional<int> wholeVariable(const Environment& env, const char* name) {
    const char* value = env(name);
    if (!value) return std::nullopt;
    if (!isWholeNumber(value))
        throw Error(name, std::string("'") + value + "' is not a whole number", "set by the scheduler: 0, 1, 2, ...");
    return std::stoi(value);
}

ChunkOfN fromSlurm(int id, const ChunkFlags& flags, const Environment& env) {
    const std::optional<int> min = wholeVariable(env, "SLURM_ARRAY_TASK_MIN");
    const std::optional<int> max = wholeVariable(env, "SLURM_ARRAY_TASK_MAX");
    const std::optional<int> count = wholeVariable(env, "SLURM_ARRAY_TASK_COUNT");
    const int first = min.value_or(1);
    if (!max && !count)
        throw Error("--chunk auto", "SLURM_ARRAY_TASK_ID is set but neither SLURM_ARRAY_TASK_MAX nor SLURM_ARRAY_TASK_COUNT",
                    "run it as a task of sbatch --array=1-N, or give --chunk K/N");
    // A rerun of some tasks (--array=3,5) numbers its tasks from 3: K = 1 there
    // would be the wrong part, so only the whole array is taken.
    if (first > 1)
        throw Error("--chunk auto", "the job array starts at " + std::to_string(first) + " (SLURM_ARRAY_TASK_MIN)",
                    "auto needs the whole array, --array=1-N; rerun some tasks with scontrol requeue JOBID_K, "
                    "or give them --chunk K/N");
    const int n = max ? *max - first + 1 : *count;
    if (count && *count != n)
        throw Error("--chunk auto",
                    "the job array has gaps or a step: " + std::to_string(*count) + " tasks (SLURM_ARRAY_TASK_COUNT) from " +
                        std::to_string(first) + " to " + std::to_string(*max),
                    "auto needs a whole array, --array=1-N");
    if (id < first || id > first + n - 1)
        throw Error("SLURM_ARRAY_TASK_ID", std::to_string(id) + " is outside the array, " + std::to_string(first) +
                                               " to " + std::to_string(first + n - 1), "set by Slurm");
    if (flags.chunks && *flags.chunks != n)
        throw Error("--chunks", std::to_string(*flags.chunks) + " differs from the job array's " + std::to_string(n) +
                                    " tasks", "keep --array=1-N and --chunks N in step, or drop --chunks");
    return {id - first + 1, n};
}

ChunkOfN fromKubernetes(int index, const ChunkFlags& flags, const Environment& env) {
    const std::optional<int> n = flags.chunks ? flags.chunks : wholeVariable(env, "GROTTO_CHUNKS");
    if (!n)
        throw Error("--chunk auto", "JOB_COMPLETION_INDEX is set but not the number of chunks",
                    "give --chunks N, or set GROTTO_CHUNKS, to the Job's completions");
    if (*n < 1 || *n > kMaxChunks)
        throw Error(flags.chunks ? "--chunks" : "GROTTO_CHUNKS", std::to_string(*n) + " is out of range",
                    "accepted: 1 to 1000000, the Job's completions");
    if (index >= *n)
        throw Error("JOB_COMPLETION_INDEX", std::to_string(index) + " is not below the " + std::to_string(*n) + " chunks",
                    "the Job's completions and --chunks (or GROTTO_CHUNKS) must agree");
    return {index + 1, *n};
}

}  // namespace

const char* processEnvironment(const char* name) { return std::getenv(name); }

void addChunkOptions(CLI::App* cmd, ChunkFlags& flags, const std::string& what) {
    cmd->add_option("--chunk", flags.chunk,
                    "K/N: " + what + " (1 <= K <= N), for a farm; auto: K and N from the Slurm job array or "
                    "Kubernetes Indexed Job running it");
    cmd->add_option("--chunks", flags.chunks, "N for --chunk auto in a Kubernetes Indexed Job (its completions)")
        ->check(wholeRange(1, kMaxChunks));
}

std::optional<ChunkOfN> resolveChunk(const ChunkFlags& flags, const Environment& env) {
    if (flags.chunks && flags.chunk != "auto")
        throw Error("--chunks", "applies to --chunk auto only", "with --chunk K/N, N is the count");
    if (flags.chunk.empty()) return std::nullopt;
    if (flags.chunk != "auto") return parseKOfN(flags.chunk);
    const std::optional<int> slurm = wholeVariable(env, "SLURM_ARRAY_TASK_ID");
    const std::optional<int> kubernetes = wholeVariable(env, "JOB_COMPLETION_INDEX");
    if (slurm && kubernetes)
        throw Error("--chunk auto", "both SLURM_ARRAY_TASK_ID and JOB_COMPLETION_INDEX are set", "give --chunk K/N");
    if (slurm) return fromSlurm(*slurm, flags, env);
    if (kubernetes) return fromKubernetes(*kubernetes, flags, env);
    throw Error("--chunk auto",
                "no task index: neither SLURM_ARRAY_TASK_ID (a Slurm job array) nor JOB_COMPLETION_INDEX (a Kubernetes "
                "Indexed Job) is set",
                "give --chunk K/N outside a scheduler");
}

}  // namespace grotto::app
