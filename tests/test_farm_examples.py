#!/usr/bin/env python3
"""examples/farm/ in the farm managers' own formats, checked without the managers
(none is in Debian): each file parses, carries the fields its manager requires,
asks grotto for the parts docs/farm.md describes, and is the text the docs show.
The Flamenco job types run under Node.js, where it is installed, against a
stand-in for Flamenco's `author` API: the tasks they make are checked.
    test_farm_examples.py SOURCE_DIR
"""
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import yaml

source = Path(sys.argv[1]).resolve()
farm = source / "examples" / "farm"
doc = (source / "docs" / "farm.md").read_text()
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
    return condition


def doc_block(tag):
    """The fenced block of docs/farm.md whose info string is `tag`."""
    m = re.search(r"^```" + re.escape(tag) + r"\n(.*?)^```$", doc, re.S | re.M)
    return m.group(1) if m else None


# --- Open Job Description -----------------------------------------------------
def check_openjd(path, step_names):
    t = yaml.safe_load(path.read_text())
    name = path.relative_to(source)
    check(t.get("specificationVersion") == "jobtemplate-2023-09", f"{name}: specificationVersion")
    check(isinstance(t.get("name"), str) and t["name"], f"{name}: name")
    params = {p["name"]: p for p in t.get("parameterDefinitions", [])}
    for p in params.values():
        check(p.get("type") in ("STRING", "INT", "FLOAT", "PATH"), f"{name}: parameter {p['name']}'s type")
        if p["type"] == "PATH":
            check(p.get("objectType") in ("FILE", "DIRECTORY"), f"{name}: PATH {p['name']}'s objectType")
    steps = t.get("steps", [])
    check([s.get("name") for s in steps] == step_names, f"{name}: steps {[s.get('name') for s in steps]}")
    for step in steps:
        where = f"{name}: step {step.get('name')}"
        task_params = {p["name"]: p for p in step.get("parameterSpace", {}).get("taskParameterDefinitions", [])}
        for p in task_params.values():
            check(p.get("type") in ("INT", "FLOAT", "STRING", "PATH") and "range" in p, f"{where}: {p['name']}")
        for d in step.get("dependencies", []):
            check(d.get("dependsOn") in step_names[: step_names.index(step["name"])], f"{where}: depends on {d}")
        run = step.get("script", {}).get("actions", {}).get("onRun", {})
        if not check(isinstance(run.get("command"), str), f"{where}: script.actions.onRun.command"):
            continue
        text = json.dumps(step)
        for ref in re.findall(r"\{\{\s*Param\.(\w+)\s*\}\}", text):
            check(ref in params, f"{where}: {{{{Param.{ref}}}}} is not a job parameter")
        for ref in re.findall(r"\{\{\s*Task\.Param\.(\w+)\s*\}\}", text):
            check(ref in task_params, f"{where}: {{{{Task.Param.{ref}}}}} is not a task parameter")
    return t, params


flythrough, params = check_openjd(farm / "openjd" / "flythrough.yaml", ["Render"])
render = flythrough["steps"][0]
check(render["parameterSpace"]["taskParameterDefinitions"][0]["range"] == "1-{{Param.Chunks}}",
      "openjd/flythrough.yaml: chunks 1 to Chunks")
check("{{Task.Param.Chunk}}/{{Param.Chunks}}" in render["script"]["actions"]["onRun"]["args"],
      "openjd/flythrough.yaml: --chunk K/N")
bake, _ = check_openjd(farm / "openjd" / "bake.yaml", ["BakeParts", "Merge"])
check(bake["steps"][1].get("dependencies") == [{"dependsOn": "BakeParts"}], "openjd/bake.yaml: Merge after BakeParts")
check("--merge" in " ".join(bake["steps"][1]["script"]["actions"]["onRun"]["args"]), "openjd/bake.yaml: Merge merges")


# --- Kubernetes ---------------------------------------------------------------
def check_indexed_job(path):
    job = yaml.safe_load(path.read_text())
    name = path.relative_to(source)
    check(job.get("apiVersion") == "batch/v1" and job.get("kind") == "Job", f"{name}: a batch/v1 Job")
    check(bool(job.get("metadata", {}).get("name")), f"{name}: metadata.name")
    spec = job.get("spec", {})
    check(spec.get("completionMode") == "Indexed", f"{name}: completionMode Indexed")
    check(isinstance(spec.get("completions"), int) and spec["completions"] >= 1, f"{name}: completions")
    pod = spec.get("template", {}).get("spec", {})
    check(pod.get("restartPolicy") in ("Never", "OnFailure"), f"{name}: restartPolicy Never or OnFailure")
    containers = pod.get("containers", [])
    check(len(containers) == 1 and containers[0].get("name") and containers[0].get("image"), f"{name}: a container")
    command = " ".join(containers[0].get("command", []) + containers[0].get("args", []))
    # The chunk count is written twice, in completions and --chunks: they must agree.
    chunks = re.search(r"--chunk\s+auto\s+--chunks\s+(\d+)", command)
    if check(chunks is not None, f"{name}: --chunk auto --chunks N"):
        check(int(chunks.group(1)) == spec.get("completions"), f"{name}: --chunks {chunks.group(1)} but "
                                                                  f"completions {spec.get('completions')}")
    return job, command


walk_file = farm / "kubernetes" / "walk-job.yaml"
check_indexed_job(walk_file)
check(doc_block("yaml walk-job.yaml") == walk_file.read_text(),
      "docs/farm.md's walk-job.yaml block is not examples/farm/kubernetes/walk-job.yaml")
bake_file = farm / "kubernetes" / "bake-job.yaml"
_, bake_command = check_indexed_job(bake_file)
check("part$((JOB_COMPLETION_INDEX + 1)).gfc" in bake_command, "kubernetes/bake-job.yaml: a part per index")
excerpt = doc_block("yaml bake-job.yaml")
check(excerpt is not None and excerpt in bake_file.read_text(),
      "docs/farm.md's bake-job.yaml block is not in examples/farm/kubernetes/bake-job.yaml")

# --- Flamenco -----------------------------------------------------------------
# Flamenco runs a job type's compileJob(job) with `author` in scope; this
# stand-in records the tasks, their commands and dependencies as JSON.
FLAMENCO_STANDIN = r"""
const fs = require("fs");
const vm = require("vm");
const [file, settingsJson] = process.argv.slice(1);  // node -e: no script name
const tasks = [];
const author = {
  Task(name, type) {
    const task = { name, type, commands: [], dependsOn: [] };
    return { _t: task, addCommand(c) { task.commands.push(c); }, addDependency(o) { task.dependsOn.push(o._t.name); } };
  },
  Command(type, parameters) { return { type, parameters }; },
};
const job = { settings: {}, addTask(t) { tasks.push(t._t); } };
const context = vm.createContext({ author });
vm.runInContext(fs.readFileSync(file, "utf8") + "\n;this.JOB_TYPE = JOB_TYPE; this.compileJob = compileJob;", context);
for (const s of context.JOB_TYPE.settings) if ("default" in s) job.settings[s.key] = s.default;
Object.assign(job.settings, JSON.parse(settingsJson));
context.compileJob(job);
console.log(JSON.stringify({ jobType: context.JOB_TYPE, tasks }));
"""


def check_flamenco(path, settings):
    name = path.relative_to(source)
    text = path.read_text()
    check(re.search(r"^const JOB_TYPE = \{", text, re.M), f"{name}: const JOB_TYPE")
    check(re.search(r"^function compileJob\(job\) \{", text, re.M), f"{name}: function compileJob(job)")
    node = shutil.which("node") or shutil.which("nodejs")
    if not node:
        print(f"{name}: Node.js is not installed; its tasks are not checked")
        return None
    check(subprocess.run([node, "--check", str(path)]).returncode == 0, f"{name}: node --check")
    r = subprocess.run([node, "-e", FLAMENCO_STANDIN, str(path), json.dumps(settings)], capture_output=True, text=True)
    if not check(r.returncode == 0, f"{name}: compileJob failed: {r.stderr.strip()}"):
        return None
    out = json.loads(r.stdout)
    job_type = out["jobType"]
    check(isinstance(job_type.get("label"), str), f"{name}: JOB_TYPE.label")
    for s in job_type["settings"]:
        check(s.get("type") in ("string", "int32", "float", "bool"), f"{name}: setting {s.get('key')}'s type")
    for t in out["tasks"]:
        check(t["commands"] and all(c["type"] == "exec" and c["parameters"].get("exe") and
                                    isinstance(c["parameters"].get("args"), list) for c in t["commands"]),
              f"{name}: task {t['name']} runs exec commands with exe and args")
    return out["tasks"]


def chunk_of(args):
    return args[args.index("--chunk") + 1] if "--chunk" in args else None


tasks = check_flamenco(farm / "flamenco" / "grotto-flythrough.js",
                       {"world": "/w/caves.json", "output": "/w/walk", "chunks": 3})
if tasks is not None:
    check([chunk_of(t["commands"][0]["parameters"]["args"]) for t in tasks] == ["1/3", "2/3", "3/3"],
          "flamenco/grotto-flythrough.js: chunks 1/3 to 3/3")
    check(all(t["commands"][0]["parameters"]["args"][:2] == ["flythrough", "/w/caves.json"] for t in tasks),
          "flamenco/grotto-flythrough.js: flythrough WORLD")
tasks = check_flamenco(farm / "flamenco" / "grotto-bake.js",
                       {"world": "/w/big.json", "parts_dir": "/w/bake", "output": "/w/big.gfc", "chunks": 3})
if tasks is not None:
    parts, merge = tasks[:-1], tasks[-1]
    check([chunk_of(t["commands"][0]["parameters"]["args"]) for t in parts] == ["1/3", "2/3", "3/3"],
          "flamenco/grotto-bake.js: parts 1/3 to 3/3")
    check(sorted(merge["dependsOn"]) == sorted(t["name"] for t in parts), "flamenco/grotto-bake.js: merge after parts")
    merge_args = merge["commands"][0]["parameters"]["args"]
    check(merge_args[:2] == ["bake", "--merge"] and merge_args[-2:] == ["-o", "/w/big.gfc"] and
          [a for a in merge_args if a.endswith(".gfc")][:-1] ==
          [t["commands"][0]["parameters"]["args"][-1] for t in parts], "flamenco/grotto-bake.js: merges every part")

for f in failures:
    print(f, file=sys.stderr)
sys.exit(1 if failures else 0)
