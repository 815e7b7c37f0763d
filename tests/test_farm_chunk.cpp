// --chunk auto (app/farm_chunk.h): K and N from the scheduler's variables, as
// Slurm sets them for a job array and Kubernetes for an Indexed Job; anything
// else refused naming what is missing or wrong.
#include "app/farm_chunk.h"
#include "tests/input_error_checks.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace grotto::app {
namespace {

using Variables = std::map<std::string, std::string>;

ChunkOfN resolve(const Variables& vars, std::optional<int> chunks = std::nullopt, const std::string& chunk = "auto") {
    const Environment env = [&](const char* name) -> const char* {
        const auto it = vars.find(name);
        return it == vars.end() ? nullptr : it->second.c_str();
    };
    const std::optional<ChunkOfN> c = resolveChunk({chunk, chunks}, env);
    return c.value_or(ChunkOfN{0, 0});
}

// What sbatch --array=FIRST-LAST sets in task `id`.
Variables slurmArray(int first, int last, int id) {
    return {{"SLURM_ARRAY_TASK_ID", std::to_string(id)},        {"SLURM_ARRAY_TASK_MIN", std::to_string(first)},
            {"SLURM_ARRAY_TASK_MAX", std::to_string(last)},     {"SLURM_ARRAY_TASK_COUNT", std::to_string(last - first + 1)},
            {"SLURM_ARRAY_TASK_STEP", "1"},                     {"SLURM_ARRAY_JOB_ID", "1234"}};
}

void expectChunk(const ChunkOfN& c, int k, int n) {
    EXPECT_EQ(c.k, k);
    EXPECT_EQ(c.n, n);
}

TEST(ChunkAuto, SlurmArrayFromOneOrZeroGivesEveryPartOnce) {
    for (int id = 1; id <= 8; ++id) expectChunk(resolve(slurmArray(1, 8, id)), id, 8);
    for (int id = 0; id <= 3; ++id) expectChunk(resolve(slurmArray(0, 3, id)), id + 1, 4);
    expectChunk(resolve(slurmArray(1, 4, 3), 4), 3, 4);  // --chunks, when given, agrees
    Variables countOnly = slurmArray(1, 5, 2);
    countOnly.erase("SLURM_ARRAY_TASK_MAX");
    expectChunk(resolve(countOnly), 2, 5);
}

TEST(ChunkAuto, KubernetesIndexCountsFromZero) {
    for (int i = 0; i < 8; ++i) expectChunk(resolve({{"JOB_COMPLETION_INDEX", std::to_string(i)}}, 8), i + 1, 8);
    expectChunk(resolve({{"JOB_COMPLETION_INDEX", "2"}, {"GROTTO_CHUNKS", "3"}}), 3, 3);
    expectChunk(resolve({{"JOB_COMPLETION_INDEX", "0"}, {"GROTTO_CHUNKS", "9"}}, 4), 1, 4);  // --chunks first
}

TEST(ChunkAuto, GivenKOfNIgnoresTheScheduler) {
    expectChunk(resolve(slurmArray(1, 8, 2), std::nullopt, "5/6"), 5, 6);
    EXPECT_FALSE(resolveChunk({}, [](const char*) -> const char* { return "1"; }));
}

TEST(ChunkAuto, RefusesWhatDoesNotNameOnePart) {
    using test::inputErrorOf;
    inputErrorOf([] { resolve({}); }, {"--chunk auto", "SLURM_ARRAY_TASK_ID", "JOB_COMPLETION_INDEX"});
    inputErrorOf([] { resolve({{"SLURM_ARRAY_TASK_ID", "2"}}); }, {"SLURM_ARRAY_TASK_MAX", "SLURM_ARRAY_TASK_COUNT"});
    inputErrorOf([] { resolve(slurmArray(3, 5, 3)); }, {"starts at 3", "SLURM_ARRAY_TASK_MIN"});  // a rerun of 3-5
    Variables gaps = slurmArray(1, 5, 3);
    gaps["SLURM_ARRAY_TASK_COUNT"] = "3";  // --array=1,3,5
    inputErrorOf([&] { resolve(gaps); }, {"gaps", "SLURM_ARRAY_TASK_COUNT"});
    inputErrorOf([] { resolve(slurmArray(1, 4, 7)); }, {"SLURM_ARRAY_TASK_ID", "outside"});
    inputErrorOf([] { resolve(slurmArray(1, 4, 2), 8); }, {"--chunks", "8", "4"});
    inputErrorOf([] { resolve({{"SLURM_ARRAY_TASK_ID", "x1"}, {"SLURM_ARRAY_TASK_MAX", "4"}}); },
                 {"SLURM_ARRAY_TASK_ID", "'x1'"});
    inputErrorOf([] { resolve({{"JOB_COMPLETION_INDEX", "0"}}); }, {"JOB_COMPLETION_INDEX", "--chunks", "GROTTO_CHUNKS"});
    inputErrorOf([] { resolve({{"JOB_COMPLETION_INDEX", "4"}}, 4); }, {"JOB_COMPLETION_INDEX", "4"});
    inputErrorOf([] { resolve({{"JOB_COMPLETION_INDEX", "0"}, {"GROTTO_CHUNKS", "0"}}); }, {"GROTTO_CHUNKS"});
    inputErrorOf([] { resolve({{"JOB_COMPLETION_INDEX", "-1"}}, 4); }, {"JOB_COMPLETION_INDEX", "'-1'"});
    Variables both = slurmArray(1, 2, 1);
    both["JOB_COMPLETION_INDEX"] = "0";
    inputErrorOf([&] { resolve(both); }, {"SLURM_ARRAY_TASK_ID", "JOB_COMPLETION_INDEX"});
    inputErrorOf([] { resolve({}, 4, "2/4"); }, {"--chunks", "auto"});
}

}  // namespace
}  // namespace grotto::app
