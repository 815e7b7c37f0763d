#pragma once
// Which part of a farm's work a task does: --chunk K/N, or --chunk auto, which
// reads K and N from the scheduler that started the task (a Slurm job array or
// a Kubernetes Indexed Job), so a job script cannot pass the wrong part.
#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>

namespace grotto::app {

// The K-th (1-based) of N parts.
struct ChunkOfN {
    int k = 1, n = 1;
    std::string text() const { return std::to_string(k) + "/" + std::to_string(n); }
};

// The most parts a run may be split into.
inline constexpr int kMaxChunks = 1'000'000;

// "K/N" with 1 <= K <= N <= kMaxChunks; throws grotto::Error (input) naming --chunk.
ChunkOfN parseKOfN(const std::string& text);

// A variable of the environment, or null when unset (std::getenv by default).
using Environment = std::function<const char*(const char*)>;
const char* processEnvironment(const char* name);

// --chunk and --chunks as flythrough and bake take them.
struct ChunkFlags {
    std::string chunk;          // "K/N" or "auto"; empty when not given
    std::optional<int> chunks;  // --chunks N: the count for --chunk auto
};
void addChunkOptions(CLI::App* cmd, ChunkFlags& flags, const std::string& what);

// The part `flags` name, or none without --chunk. "auto" reads
//   Slurm:      SLURM_ARRAY_TASK_ID with SLURM_ARRAY_TASK_MIN and MAX (or COUNT):
//               K = ID - MIN + 1 of N = MAX - MIN + 1, for an array numbered
//               from 0 or 1 without gaps (--chunks N, when given, must agree);
//   Kubernetes: JOB_COMPLETION_INDEX (from 0): K = index + 1, of N from --chunks
//               or GROTTO_CHUNKS (the Job's completions).
// Anything else throws grotto::Error (input) naming what is missing or wrong.
std::optional<ChunkOfN> resolveChunk(const ChunkFlags& flags, const Environment& env = processEnvironment);

}  // namespace grotto::app
