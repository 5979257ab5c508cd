"""`motorbench claims` given its JSON inputs opens no GL context, renders and times nothing:
run twice on results/'s inputs with GL made unavailable (MB_GL_BACKEND=none makes
every GL context creation fail with a message naming it), it succeeds, writes byte-identical
claims.json and claims.md, no row carries the GL failure, and the upload rows hold report.json's
own figures (read here from report.json, not from motorbench's code).
"""
import json
import os
import subprocess
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RESULTS = os.path.join(REPO, "results")
EXE = os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench"))


def run_claims(out):
    env = dict(os.environ, MB_GL_BACKEND="none")
    cmd = [EXE, "claims", "--report", os.path.join(RESULTS, "report.json"),
           "--bench-json", os.path.join(RESULTS, "bench.json"), "--isa", os.path.join(RESULTS, "isa.json"),
           "--corpus", os.path.join(REPO, "..", "shared", "corpus"),
           "-o", os.path.join(out, "claims.md"), "--json", os.path.join(out, "claims.json")]
    for option, path in (("--scene-graphs", "corpus-graph.json"), ("--corpus-report", "corpus/report.json")):
        if os.path.exists(os.path.join(RESULTS, path)):
            cmd[2:2] = [option, os.path.join(RESULTS, path)]
    return subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=540)


def read(path, mode="rb"):
    with open(path, mode) as f:
        return f.read()


@unittest.skipUnless(os.path.exists(EXE), "no motorbench built at " + EXE)
class ClaimsWithoutGl(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.dirs = [os.path.join(cls.tmp.name, d) for d in ("one", "two")]
        cls.runs = [run_claims(d) for d in cls.dirs]
        cls.report = json.loads(read(os.path.join(RESULTS, "report.json"), "r"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_succeeds_without_gl(self):
        for r in self.runs:
            self.assertEqual(r.returncode, 0, r.stderr[-2000:])

    def test_same_inputs_same_bytes(self):
        for name in ("claims.json", "claims.md"):
            a, b = (read(os.path.join(d, name)) for d in self.dirs)
            self.assertEqual(a, b, name + " differs between two runs on the same inputs")

    def test_no_row_tried_gl(self):
        for name in ("claims.json", "claims.md"):
            text = read(os.path.join(self.dirs[0], name), "r")
            self.assertNotIn("MB_GL_BACKEND", text, name + ": some path tried to open a GL context")
            self.assertNotIn("cannot create a GL", text, name)
        self.assertNotIn("MB_GL_BACKEND", self.runs[0].stderr)

    def stats(self, scene, pipeline):
        for s in self.report["scenes"]:
            if s["id"] == scene:
                return s["pipelines"][pipeline]["stats"]
        self.fail("report.json has no scene " + scene)

    def test_upload_rows_are_the_reports(self):
        rows = {c["id"]: c for c in json.loads(read(os.path.join(self.dirs[0], "claims.json"), "r"))["claims"]}
        fpv = rows["floats_per_vertex"]["measuredValue"]
        for p in ("matrix", "motor"):
            self.assertEqual(fpv[p], self.stats("normal_torus", p)["floatsPerVertex"])
        fpj = rows["floats_per_joint"]["measuredValue"]
        for p in ("matrix", "motor"):
            self.assertEqual(fpj[p], self.stats("skinned_tube", p)["floatsPerJoint"])
        bpv = rows["bytes_per_vertex_vs_strongest"]["measuredValue"]["values"]
        for p, v in bpv.items():
            s = self.stats("normal_torus", p)
            self.assertAlmostEqual(v, s["vertexBytes"] / s["vertices"], places=9, msg=p)
        fpi = rows["curved_floats_per_instance"]["measuredValue"]
        self.assertEqual(fpi["S3"]["motor"], self.stats("s3_tiling", "s3_motor")["floatsPerTransform"])
        self.assertEqual(fpi["H3"]["matrix"], self.stats("h3_tiling", "h3_matrix")["floatsPerTransform"])


if __name__ == "__main__":
    unittest.main()
