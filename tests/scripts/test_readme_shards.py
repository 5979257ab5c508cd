"""harness/report/README.md "Sharded runs": the three recipes are real.

The GNU parallel recipe is run as written (with the built motorbench and a scratch folder for
out/), and its merged report must hold every scene once; the Slurm script must pass `bash -n`
and cut as many shards as its array has tasks; the Kubernetes Job must parse as YAML, be an
Indexed Job, and turn the 0-based completion index into shards 1..completions.
"""
import json
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import yaml

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench"))


def section_blocks():
    with open(os.path.join(REPO, "harness", "report", "README.md"), encoding="utf-8") as f:
        text = f.read()
    start = text.index("## Sharded runs")
    end = text.find("\n## ", start + 1)
    end = len(text) if end < 0 else end
    return re.findall(r"```(\w+)\n(.*?)```", text[start:end], re.S)


def block(lang):
    found = [body for kind, body in section_blocks() if kind == lang]
    assert len(found) == 1, f"expected one ```{lang} block in README 'Sharded runs'"
    return found[0]


class ReadmeShards(unittest.TestCase):
    def test_slurm_script_is_valid_bash_and_cuts_one_shard_per_task(self):
        script = block("bash")
        run = subprocess.run(["bash", "-n"], input=script, capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        first, last = map(int, re.search(r"#SBATCH --array=(\d+)-(\d+)", script).groups())
        shards = int(re.search(r'--shard "\$\{SLURM_ARRAY_TASK_ID\}/(\d+)"', script).group(1))
        self.assertEqual((first, last), (1, shards))

    def test_kubernetes_job_is_an_indexed_job_over_every_shard(self):
        job = yaml.safe_load(block("yaml"))
        self.assertEqual(job["kind"], "Job")
        spec = job["spec"]
        self.assertEqual(spec["completionMode"], "Indexed")
        container = spec["template"]["spec"]["containers"][0]
        arg = container["args"][0]
        shards = int(re.search(r"--shard \$\(\(JOB_COMPLETION_INDEX \+ 1\)\)/(\d+)", arg).group(1))
        self.assertEqual(spec["completions"], shards)
        for index in (0, shards - 1):  # the shell arithmetic the container runs
            out = subprocess.run(["sh", "-c", "echo " + arg.replace("motorbench ", "", 1)],
                                 env={"JOB_COMPLETION_INDEX": str(index), "PATH": os.environ["PATH"]},
                                 capture_output=True, text=True).stdout
            self.assertIn(f"--shard {index + 1}/{shards}", out)

    @unittest.skipUnless(shutil.which("parallel"), "GNU parallel not installed (scripts/setup.sh installs it)")
    def test_gnu_parallel_recipe_runs_and_merges(self):
        if not os.path.exists(EXE):
            self.skipTest(f"{EXE} not built")
        lines = [l for l in block("sh").splitlines() if l.strip()]
        with tempfile.TemporaryDirectory() as tmp:
            for line in lines:
                cmd = line.replace("build/harness/motorbench", EXE).replace("out/", tmp + "/")
                run = subprocess.run(cmd, shell=True, capture_output=True, text=True, cwd=REPO)
                self.assertEqual(run.returncode, 0, cmd + "\n" + run.stdout + run.stderr)
            with open(os.path.join(tmp, "merged", "report.json"), encoding="utf-8") as f:
                merged = json.load(f)
            ids = [s["id"] for s in merged["scenes"]]
            self.assertEqual(ids, ["textured_box", "normal_torus", "skinned_tube"])
            self.assertTrue(all(s["status"] == "ok" for s in merged["scenes"]))
            self.assertEqual(merged["settings"]["shard"]["count"], 3)


if __name__ == "__main__":
    unittest.main()
