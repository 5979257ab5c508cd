"""`motorbench claims` as scripts/reproduce.sh runs it in a clone without ../shared: the corpus
folder points nowhere, the real-file rows read the committed inputs of results/ (corpus-graph.json,
corpus/report.json, corpus/skin-volumes.json; results/inputs.json gives their provenance), and
every verdict equals the committed results/claims.json, the real-file rows' figures included.
"""
import json
import os
import subprocess
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RESULTS = os.environ.get("MB_RESULTS_DIR", os.path.join(REPO, "results"))
EXE = os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench"))
# The rows judged on real files a clone does not have, read from the committed inputs.
REAL_FILE_ROWS = ("animated_scale_corpus", "nonuniform_scale_leaves", "skinning_volume_file")


def results(*parts):
    return os.path.join(RESULTS, *parts)


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


@unittest.skipUnless(os.path.exists(EXE), "no motorbench built at " + EXE)
class ClaimsWithoutShared(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        out = cls.tmp.name
        # The same options as reproduce.sh's claims step where ../shared/corpus is absent.
        cmd = [EXE, "claims", "--report", results("report.json"), "--bench-json", results("bench.json"),
               "--isa", results("isa.json"), "--corpus", os.path.join(out, "no-corpus-here"),
               "--skin-volumes", results("corpus", "skin-volumes.json"),
               "--scene-graphs", results("corpus-graph.json"), "--corpus-report", results("corpus", "report.json"),
               "-o", os.path.join(out, "claims.md"), "--json", os.path.join(out, "claims.json")]
        cls.claims_run = subprocess.run(cmd, env=dict(os.environ, MB_GL_BACKEND="none"), capture_output=True, text=True,
                                 timeout=300, cwd=out)
        cls.committed = {c["id"]: c for c in load(results("claims.json"))["claims"]}
        path = os.path.join(out, "claims.json")
        cls.rows = {c["id"]: c for c in load(path)["claims"]} if os.path.exists(path) else {}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_runs(self):
        self.assertEqual(self.claims_run.returncode, 0, self.claims_run.stderr[-2000:])

    def test_every_verdict_equals_the_committed_one(self):
        self.assertEqual(sorted(self.rows), sorted(self.committed))
        differ = {cid: (self.committed[cid]["verdict"], row["verdict"]) for cid, row in self.rows.items()
                  if row["verdict"] != self.committed[cid]["verdict"]}
        self.assertEqual(differ, {}, "verdicts (committed, without ../shared)")

    def test_real_file_rows_are_measured_from_the_committed_inputs(self):
        for cid in REAL_FILE_ROWS:
            self.assertNotEqual(self.rows[cid]["verdict"], "not measurable here", cid)
        # The scale rows judge the same models: the kinds (test fixtures left out) travel in
        # corpus-graph.json, not in ../shared's MANIFEST.tsv. (Each kind's full inspect aggregate
        # is compared by scripts/results_diff.py after a run.)
        for cid in ("animated_scale_corpus", "nonuniform_scale_leaves"):
            now, committed = self.rows[cid]["measuredValue"], self.committed[cid]["measuredValue"]
            for key in committed:
                if key == "byKind":
                    self.assertEqual(sorted(now[key] or {}), sorted(committed[key] or {}), cid)
                elif not isinstance(committed[key], dict):
                    self.assertEqual(now[key], committed[key], f"{cid}: {key}")
            self.assertEqual(self.rows[cid]["verdictText"], self.committed[cid]["verdictText"], cid)
        # Read, not measured: the skinned-file volumes are the committed row's, value for value,
        # and the file is named in the row's method.
        row = self.rows["skinning_volume_file"]
        self.assertEqual(row["measuredValue"], self.committed["skinning_volume_file"]["measuredValue"])
        self.assertIn(results("corpus", "skin-volumes.json"), row["method"])
        volumes = load(results("corpus", "skin-volumes.json"))
        self.assertEqual(sorted(m["id"] for m in volumes["meshes"]), sorted(row["measuredValue"]["meshes"]))

    def test_each_committed_input_has_its_provenance(self):
        inputs = {e["name"]: e for e in load(results("inputs.json"))["inputs"]}
        self.assertEqual(set(inputs), {"corpus", "corpus-graph", "morph-corpus-wide"})
        for name, e in inputs.items():
            for output in e["outputs"]:
                self.assertTrue(os.path.exists(results(output)), f"{name}: {output} missing")
            src = e["sourceFiles"]
            self.assertTrue(e["source"].startswith("../shared/"), name)
            self.assertEqual(len(src["sha256"]), 64, name)
            self.assertGreater(src["count"], 0, name)
            self.assertTrue(e["measuredWith"] and e["date"] and e["command"], name)
        # The skinned-file volumes were measured over the corpus folder the provenance names.
        self.assertEqual(load(results("corpus", "skin-volumes.json"))["folder"], inputs["corpus"]["source"])
        # morph.json counts every scene of the committed corpus-wide morph figures.
        morph = {s["scene"] for s in load(results("morph.json"))["scenes"]}
        wide = {s["scene"] for s in load(results("morph-corpus-wide.json"))["scenes"]}
        self.assertLessEqual(wide, morph)
        self.assertEqual(sorted(f["file"] for f in inputs["morph-corpus-wide"]["usedFiles"]), sorted(wide))


if __name__ == "__main__":
    unittest.main()
