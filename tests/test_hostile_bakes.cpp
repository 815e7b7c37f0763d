// Hostile and mismatched bakes (.gfc): a header that claims millions of faces of
// another world, or of a bigger one, over a sparse file of the size it claims, is
// refused from its header by render --bake and bake --merge, within the hostile
// caps, naming the file at fault; parts baked with other settings are refused
// naming the part and the setting; and what a killed bake, merge or export left
// behind is removed by the next run writing that output, unless its process lives.
#include "tests/hostile_fixture.h"

#include <sys/file.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstring>

namespace grotto::test {
namespace {

// The header fields a test rewrites, at the offsets grotto bake writes them.
constexpr size_t kTexelsPerSideAt = 12, kHashAt = 16, kTotalFacesAt = 72, kFirstFaceAt = 80, kFaceCountAt = 88;
constexpr uint64_t kTexelBytes = 24;

template <class T> T peek(const std::string& bytes, size_t at) {
    T v;
    std::memcpy(&v, bytes.data() + at, sizeof v);
    return v;
}
template <class T> void poke(std::string& bytes, size_t at, T v) { std::memcpy(bytes.data() + at, &v, sizeof v); }

class HostileBakes : public HostileInputs {
protected:
    std::string bake(const fs::path& out, const std::string& more = "", int rays = 4) {
        return "bake " + good_.string() + " -o " + out.string() + " --sun-rays 1 --rays " + std::to_string(rays) + " " + more;
    }
    fs::path baked(const std::string& name, const std::string& more = "", int rays = 4) {
        const RunResult r = runGrotto(bake(dir_ / name, more, rays));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return dir_ / name;
    }
    // `real`'s header claiming faces [first, first + count) of `total`, its voxel
    // hash changed when `otherWorld`, over a sparse body of exactly the size the
    // claim needs: only the header says it is not this world's.
    fs::path claiming(const std::string& name, const fs::path& real, uint64_t total, uint64_t first, uint64_t count,
                      bool otherWorld) {
        const std::string bytes = bytesOf(real);
        const uint64_t k = peek<uint32_t>(bytes, kTexelsPerSideAt), texel = k * k * kTexelBytes;
        std::string header = bytes.substr(0, bytes.size() - peek<uint64_t>(bytes, kFaceCountAt) * texel);
        if (otherWorld) poke(header, kHashAt, peek<uint64_t>(header, kHashAt) ^ 0x5a5a);
        poke(header, kTotalFacesAt, total), poke(header, kFirstFaceAt, first), poke(header, kFaceCountAt, count);
        const fs::path file = writeBytes(name, header);
        fs::resize_file(file, header.size() + count * texel);
        return file;
    }
};

constexpr uint64_t kMillions = 5'000'000;  // 1.08 GB of texels at 3 x 3 a face

TEST_F(HostileBakes, RenderRefusesAHugeBakeFromItsHeader) {
    const fs::path real = baked("real.gfc");
    const uint64_t faces = peek<uint64_t>(bytesOf(real), kTotalFacesAt);
    const std::string render = "render " + good_.string() + " --size 16x8 -o " + out().string() + " --bake ";
    const fs::path other = claiming("other.gfc", real, kMillions, 0, kMillions, true);
    expectCommandRefusedWithinCaps(render + other.string(), "other.gfc: baked for other voxels", out());
    const fs::path bigger = claiming("bigger.gfc", real, kMillions, 0, kMillions, false);  // this world's hash
    expectCommandRefusedWithinCaps(render + bigger.string(), "bigger.gfc: baked for other voxels", out());
    const fs::path part = claiming("part.gfc", real, faces, 0, faces / 2, false);  // a part, half the size
    expectCommandRefusedWithinCaps(render + part.string(), "part.gfc: a part of a bake", out());
    EXPECT_GT(fs::file_size(other), uint64_t(1) << 30);
}

TEST_F(HostileBakes, MergeRefusesAHugePartFromItsHeaderNamingIt) {
    std::vector<std::string> parts;
    for (int k = 1; k <= 3; ++k)
        parts.push_back(baked("p" + std::to_string(k) + ".gfc", "--chunk " + std::to_string(k) + "/3").string());
    const fs::path out = dir_ / "joined.gfc";
    const fs::path other = claiming("other.gfc", parts[0], kMillions, 0, kMillions, true);
    const fs::path bigger = claiming("bigger.gfc", parts[0], kMillions, 0, kMillions, false);
    for (const fs::path& huge : {other, bigger}) {
        // First or among the others, the one part unlike the rest is blamed.
        const std::string name = huge.filename().string();
        expectCommandRefusedWithinCaps("bake --merge " + huge.string() + " " + parts[0] + " " + parts[1] + " " + parts[2] +
                                           " -o " + out.string(), name + ":", out);
        expectCommandRefusedWithinCaps("bake --merge " + parts[0] + " " + parts[1] + " " + huge.string() + " " + parts[2] +
                                           " -o " + out.string(), name + ":", out);
    }
}

// docs/face-cache.md: parts baked with other settings are refused, naming the
// part and the setting.
TEST_F(HostileBakes, MergeRefusesAPartBakedWithOtherSettings) {
    const fs::path p1 = baked("p1.gfc", "--chunk 1/3"), p3 = baked("p3.gfc", "--chunk 3/3");
    const fs::path out = dir_ / "joined.gfc";
    struct Other {
        const char* flags;
        int rays;
        const char* setting;
    };
    for (const Other& o : {Other{"", 8, "rays 8"}, Other{"--radius 2", 4, "AO radius 2"}, Other{"--texels 2", 4, "texels per side 2"}}) {
        const fs::path p2 = baked("p2.gfc", std::string("--chunk 2/3 ") + o.flags, o.rays);
        fs::remove(out);  // what an accepted mix wrote
        expectRefused("bake --merge " + p1.string() + " " + p2.string() + " " + p3.string() + " -o " + out.string(),
                      "p2.gfc: " + std::string(o.setting), out);
    }
    const fs::path p2 = baked("p2.gfc", "--chunk 2/3");  // alike: joined
    const RunResult r = runGrotto("bake --merge " + p1.string() + " " + p2.string() + " " + p3.string() + " -o " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

// A process that has ended: a child of ours, reaped.
pid_t deadPid() {
    const pid_t child = fork();
    if (child == 0) _exit(0);
    int status = 0;
    waitpid(child, &status, 0);
    return child;
}

// The temporary a run with process id `pid` writes `target` under.
fs::path temporaryOf(const fs::path& target, pid_t pid) {
    const fs::path tmp = target.parent_path() / ("." + target.stem().string() + ".tmp" + std::to_string(pid) + "-0" +
                                                 target.extension().string());
    std::ofstream(tmp) << "what a killed run was writing";
    return tmp;
}

TEST_F(HostileBakes, TheNextRunRemovesTheTemporariesOfKilledRuns) {
    const fs::path p1 = baked("p1.gfc", "--chunk 1/2"), p2 = baked("p2.gfc", "--chunk 2/2");
    const fs::path runs = dir_ / "runs";
    fs::create_directory(runs);
    const std::pair<std::string, fs::path> writers[] = {
        {bake(runs / "whole.gfc"), runs / "whole.gfc"},
        {"bake --merge " + p1.string() + " " + p2.string() + " -o " + (runs / "joined.gfc").string(), runs / "joined.gfc"},
        {"export-mesh " + good_.string() + " -o " + (runs / "mesh.ply").string(), runs / "mesh.ply"}};
    for (const auto& [command, target] : writers) {
        SCOPED_TRACE(command);
        const fs::path killed = temporaryOf(target, deadPid());
        const fs::path living = temporaryOf(target, getpid());  // a run still writing it
        const fs::path held = temporaryOf(target, deadPid());
        const int fd = open(held.c_str(), O_RDONLY);  // a dead id, but its file held: someone writes it
        ASSERT_EQ(flock(fd, LOCK_EX), 0);
        const RunResult r = runGrotto(command);
        close(fd);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(fs::exists(target));
        EXPECT_FALSE(fs::exists(killed));
        EXPECT_TRUE(fs::exists(living));
        EXPECT_TRUE(fs::exists(held));
    }
}

}  // namespace
}  // namespace grotto::test
