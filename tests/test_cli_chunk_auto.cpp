// --chunk auto in the scheduler's environment, set in the child process as Slurm
// and Kubernetes set it: a task renders (or bakes) the part --chunk K/N names, and
// outside a scheduler it is refused with nothing written.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace grotto::test {
namespace {

// The scheduler's variables this process may have (a test run inside a Slurm job).
const std::string kNoScheduler = "-u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX -u GROTTO_CHUNKS";

std::string slurmTask(int id, int first, int last) {
    return kNoScheduler + " SLURM_ARRAY_JOB_ID=7 SLURM_ARRAY_TASK_ID=" + std::to_string(id) +
           " SLURM_ARRAY_TASK_MIN=" + std::to_string(first) + " SLURM_ARRAY_TASK_MAX=" + std::to_string(last) +
           " SLURM_ARRAY_TASK_COUNT=" + std::to_string(last - first + 1) + " SLURM_ARRAY_TASK_STEP=1";
}

class ChunkAutoRuns : public CliErrors {
protected:
    std::string flythrough(const fs::path& out, const std::string& chunk) {
        return "flythrough " + writeFlyWorld().string() + " --path p --size 16x8 --fps 8 --warmup 0 --quiet " + chunk +
               " -o " + out.string();
    }
    std::string bake(const fs::path& out, const std::string& chunk) {
        return "bake " + good_.string() + " --rays 4 --sun-rays 1 --texels 1 " + chunk + " -o " + out.string();
    }
};

TEST_F(ChunkAutoRuns, SlurmArrayTaskRendersItsChunk) {
    // Task 2 of --array=1-3 is chunk 2/3 of 9 frames: frames 4 to 6, no others.
    const fs::path out = dir_ / "walk";
    const RunResult r = runGrotto(flythrough(out, "--chunk auto"), slurmTask(2, 1, 3));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (int i = 1; i <= 9; ++i)
        EXPECT_EQ(fs::exists(out / ("frame.000" + std::to_string(i) + ".png")), i >= 4 && i <= 6) << "frame " << i;
}

TEST_F(ChunkAutoRuns, KubernetesIndexBakesTheSamePartAsKOfN) {
    const fs::path byIndex = dir_ / "index.gfc", byHand = dir_ / "hand.gfc";
    const RunResult r = runGrotto(bake(byIndex, "--chunk auto --chunks 3"), kNoScheduler + " JOB_COMPLETION_INDEX=1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(runGrotto(bake(byHand, "--chunk 2/3")).exitCode, 0);
    EXPECT_EQ(fileBytes(byIndex), fileBytes(byHand));
    EXPECT_GT(fileBytes(byIndex).size(), 0u);
}

TEST_F(ChunkAutoRuns, RefusedOutsideAScheduler) {
    const fs::path out = dir_ / "walk", part = dir_ / "part.gfc";
    expectRefused(flythrough(out, "--chunk auto"), "SLURM_ARRAY_TASK_ID", out, kNoScheduler);
    expectRefused(bake(part, "--chunk auto"), "JOB_COMPLETION_INDEX", part, kNoScheduler);
    expectRefused(bake(part, "--chunk auto"), "--chunks", part, kNoScheduler + " JOB_COMPLETION_INDEX=0");
    expectRefused(flythrough(out, "--chunk auto"), "starts at 2", out, slurmTask(2, 2, 3));
}

}  // namespace
}  // namespace grotto::test
