// Flamenco 3 job type: a Grotto face-cache bake split by region, then merged.
// Put this file in the Manager's scripts/ directory. Task K of N runs
// `grotto bake WORLD --chunk K/N -o DIR/partK.gfc`; the merge task depends on
// every part and joins them into the file one machine's bake writes, byte for
// byte (docs/farm.md). Each part uses every core of its Worker.

const JOB_TYPE = {
    label: "Grotto Bake",
    description: "Bake a Grotto world's face cache in parts, then merge them",
    settings: [
        { key: "grotto", type: "string", required: true, default: "/shared/grotto/build/grotto",
          description: "The grotto program, at the same path on every Worker" },
        { key: "world", type: "string", subtype: "file_path", required: true,
          description: "World file (.json or .vdb) on the shared mount" },
        { key: "parts_dir", type: "string", subtype: "dir_path", required: true,
          description: "Directory for the parts, on the shared mount" },
        { key: "output", type: "string", subtype: "file_path", required: true,
          description: "The merged face cache (.gfc)" },
        { key: "chunks", type: "int32", required: true, default: 8, propargs: { min: 1, max: 10000 },
          description: "How many parts" },
    ],
};

function compileJob(job) {
    const settings = job.settings;
    const parts = [];
    const partTasks = [];
    for (let k = 1; k <= settings.chunks; k++) {
        const part = `${settings.parts_dir}/part${k}.gfc`;
        const task = author.Task(`part-${k}`, "misc");
        task.addCommand(author.Command("exec", {
            exe: settings.grotto,
            args: ["bake", settings.world, "--chunk", `${k}/${settings.chunks}`, "-o", part],
        }));
        job.addTask(task);
        parts.push(part);
        partTasks.push(task);
    }
    const merge = author.Task("merge", "misc");
    merge.addCommand(author.Command("exec", {
        exe: settings.grotto,
        args: ["bake", "--merge"].concat(parts, ["-o", settings.output]),
    }));
    for (const task of partTasks) merge.addDependency(task);
    job.addTask(merge);
}
