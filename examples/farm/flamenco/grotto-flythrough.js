// Flamenco 3 job type: a Grotto flythrough split into chunks, one task each.
// Put this file in the Manager's scripts/ directory; each task runs
// `grotto flythrough WORLD --path NAME --chunk K/N -o DIR` on a Worker. The
// tasks share DIR (a mount every Worker sees at the same path) and may run in
// any order, at once or not; a task run again resumes (docs/farm.md).
// Chunks, not frames: grotto knows the path's length, and a chunk past the
// last frame has nothing to do and succeeds.

const JOB_TYPE = {
    label: "Grotto Flythrough",
    description: "Render a Grotto camera path to numbered frames, in chunks",
    settings: [
        { key: "grotto", type: "string", required: true, default: "/shared/grotto/build/grotto",
          description: "The grotto program, at the same path on every Worker" },
        { key: "world", type: "string", subtype: "file_path", required: true,
          description: "World file (.json or .vdb) on the shared mount" },
        { key: "path", type: "string", required: true, default: "walk", description: "The world's camera path" },
        { key: "size", type: "string", required: true, default: "1920x1080", description: "Image size WxH" },
        { key: "output", type: "string", subtype: "dir_path", required: true,
          description: "Output directory on the shared mount, shared by every chunk" },
        { key: "chunks", type: "int32", required: true, default: 8, propargs: { min: 1, max: 10000 },
          description: "How many tasks split the path" },
        { key: "bake", type: "string", subtype: "file_path", required: false, default: "",
          description: "A face cache from grotto bake (optional): frames then match one machine's bit for bit" },
    ],
};

function compileJob(job) {
    const settings = job.settings;
    for (let k = 1; k <= settings.chunks; k++) {
        const args = [settings.world, "--path", settings.path, "--size", settings.size,
                      "--chunk", `${k}/${settings.chunks}`, "-o", settings.output];
        if (settings.bake) args.push("--bake", settings.bake);
        const task = author.Task(`chunk-${k}`, "misc");
        task.addCommand(author.Command("exec", { exe: settings.grotto, args: ["flythrough"].concat(args) }));
        job.addTask(task);
    }
}
