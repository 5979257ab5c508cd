"""scripts/committed_inputs.py, the provenance of results/'s committed inputs, on small folders
made here: `record` hashes the source as its rule says (recomputed here with hashlib), lists the
files measured and keeps one entry per input; `check` reads an input whose source is absent
and refuses (exit 1, naming the file) when that input is missing; `markdown` says per input
whether this run measured it again or read it.
"""
import hashlib
import json
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SCRIPT = os.path.join(REPO, "scripts", "committed_inputs.py")


def run(*args, cwd):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True, cwd=cwd, timeout=60)


class CommittedInputs(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        os.makedirs(os.path.join(self.root, "src", "sub"))
        os.makedirs(os.path.join(self.root, "results"))
        self.files = {"a.gltf": b"{}", "sub/b.glb": b"glTF\x02", "MANIFEST.tsv": b"a.gltf\n"}
        for name, data in self.files.items():
            with open(os.path.join(self.root, "src", name), "wb") as f:
                f.write(data)
        with open(os.path.join(self.root, "results", "figures.json"), "w") as f:
            f.write("{}")

    def tearDown(self):
        self.tmp.cleanup()

    def record(self, name="graphs", *extra):
        r = run("record", "results", name, "--source", "src", "--outputs", "figures.json", "--command", "measure src",
                "--what", "figures over src", "--commit", "abc", "--date", "2026-01-01 00:00 UTC", *extra, cwd=self.root)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(self.root, "results", "inputs.json")) as f:
            return json.load(f)

    def test_record_hashes_the_source_by_its_rule(self):
        entry = self.record("graphs", "--used", "src/a.gltf")["inputs"][0]
        src = entry["sourceFiles"]
        sha = {n: hashlib.sha256(d).hexdigest() for n, d in self.files.items()}
        lines = "".join(f"{sha[n]}  {n}\n" for n in sorted(self.files))
        self.assertEqual(src["sha256"], hashlib.sha256(lines.encode()).hexdigest())
        self.assertEqual(src["count"], 3)
        self.assertEqual(src["bytes"], sum(len(d) for d in self.files.values()))
        self.assertEqual(src["manifest"], {"file": "MANIFEST.tsv", "sha256": sha["MANIFEST.tsv"]})
        self.assertEqual(sorted(f["file"] for f in src["files"]), sorted(self.files))
        self.assertEqual(entry["usedFiles"], [{"file": "src/a.gltf", "bytes": 2, "sha256": sha["a.gltf"]}])
        self.assertEqual((entry["measuredWith"], entry["date"]), ("abc", "2026-01-01 00:00 UTC"))
        # Recorded again: one entry per input, the newest.
        self.assertEqual(len(self.record("graphs")["inputs"]), 1)
        self.assertEqual(len(self.record("other")["inputs"]), 2)

    def test_check_reads_an_absent_source_and_refuses_a_missing_input(self):
        self.record()
        r = run("check", "results", cwd=self.root)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("src present: measured again", r.stdout)
        self.assertIn("regenerated in this run", run("markdown", "results", cwd=self.root).stdout)
        os.rename(os.path.join(self.root, "src"), os.path.join(self.root, "gone"))
        r = run("check", "results", cwd=self.root)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("src absent: read as committed (figures.json; 3 source files", r.stdout)
        self.assertIn("read as committed in this run", run("markdown", "results", cwd=self.root).stdout)
        os.remove(os.path.join(self.root, "results", "figures.json"))
        r = run("check", "results", cwd=self.root)
        self.assertEqual(r.returncode, 1)
        self.assertIn("results/figures.json missing", r.stderr)

    def test_record_refuses_an_absent_source(self):
        r = run("record", "results", "x", "--source", "nowhere", "--outputs", "figures.json", "--command", "c",
                "--what", "w", cwd=self.root)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("nowhere: not a folder", r.stderr)


if __name__ == "__main__":
    unittest.main()
