"""scripts/corpus-check.sh on a subset of ../shared/corpus-wide.

Sixteen real files chosen to cover what broke before: multi-primitive meshes, skins (per-joint
scales, inner non-uniform scale under a skin), inner non-uniform scale, Draco, WebP, morph
targets, texture transform, GPU instancing, and files with nothing to draw. The script must run
them all without a crash and write a row per file x pipeline; whether each passes the image
rules is the full run's business (README: Corpus check), not this test's. Skipped when
../shared/corpus-wide is absent (a user's clone).
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import time
import unittest
import xml.etree.ElementTree as ET

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CORPUS = os.path.join(REPO, "..", "shared", "corpus-wide")
EXE = os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench"))

PIPELINES = ["matrix", "motor", "affine", "qtangent", "motor_q", "hybrid", "matrix_c", "motor_c", "motor_cf"]

SUBSET = [  # path under corpus-wide: what it covers
    "vpenades+SharpGLTF/examples/Example1.glb",  # multi-primitive
    "KhronosGroup+glTF-Blender-IO/tests/roundtrip/22_material_slot_merge/22_material_slot_merge.gltf",  # 36 primitives
    "KhronosGroup+glTF-Blender-IO/tests/roundtrip/23_multi_prim_vertex_attribute/23_multi_prim_vertex_attribute.gltf",  # multi-primitive, morph targets
    "KhronosGroup+glTF-Blender-IO/tests/roundtrip/01_cs_morph/01_cs_morph.gltf",  # morph targets, animated
    "trebeljahr+quaternius-showcase/public/glb/fish_pack/Fish1.glb",  # skinned, multi-primitive
    "mgsx-dev+gdx-gltf/demo/android/assets/models/PBRTest/glTF/pbrTest.gltf",  # skinned
    "trebeljahr+quaternius-showcase/public/glb/cute_fish_pack/Piranha.glb",  # skinned, inner non-uniform scale
    "trebeljahr+quaternius-showcase/public/glb/cyberpunk_pack/Enemy_2Legs_Gun.glb",  # the skinned multi-primitive file
    "pmndrs+examples/demos/space-game/src/3d/ship.gltf",  # inner non-uniform scale
    "donmccurdy+glTF-Transform/packages/extensions/test/in/DracoSparseMesh.gltf",  # Draco
    "pmndrs+examples/demos/magic-box/src/aobox-transformed.glb",  # Draco, WebP
    "pmndrs+examples/demos/portal-shapes/public/journey-transformed.glb",  # Draco, WebP, 3 primitives
    "KenneyNL+Starter-Kit-City-Builder/models/pavement.glb",  # texture transform
    "vpenades+SharpGLTF/tests/Assets/gltf-GpuMeshInstancing/InstanceTest.glb",  # GPU instancing
    "mgsx-dev+gdx-gltf/gltf/testRes/nominal/gltf/empty.gltf",  # no meshes: no data, not a failure
    "mgsx-dev+gdx-gltf/gltf/testRes/nominal/gltf/points.gltf",  # points only: nothing to draw
]


@unittest.skipUnless(os.path.isdir(CORPUS), "../shared/corpus-wide absent (a clone without ../shared)")
@unittest.skipUnless(os.access(EXE, os.X_OK), f"{EXE}: motorbench not built")
class CorpusCheckSubset(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = tempfile.mkdtemp(prefix="corpus-check-")
        files = [os.path.join(CORPUS, p) for p in SUBSET]
        t0 = time.monotonic()
        cls.proc = subprocess.run([os.path.join(REPO, "scripts", "corpus-check.sh"), *files, "--out", cls.out,
                                  "--jobs", "2", "--size", "96x96", "--exe", EXE],
                                 capture_output=True, text=True, timeout=300)
        cls.seconds = time.monotonic() - t0
        with open(os.path.join(cls.out, "corpus-check.json"), encoding="utf-8") as f:
            cls.doc = json.load(f)

    def test_subset_is_small_and_present(self):
        self.assertLessEqual(len(SUBSET), 20)
        for p in SUBSET:
            self.assertTrue(os.path.isfile(os.path.join(CORPUS, p)), p)

    def test_runs_without_a_crash_in_time(self):
        s = self.doc["summary"]
        self.assertEqual(s["crashed"], 0, s["crashes"])
        self.assertEqual(s["files"], len(SUBSET))
        self.assertIn(self.proc.returncode, (0, 1), self.proc.stderr[-2000:])  # 1: an image rule failed
        self.assertLess(self.seconds, 120, "the CI subset must run in under 2 minutes")
        crash_rule = self.doc["rules"][0]
        self.assertTrue(crash_rule["pass"], crash_rule["failures"])

    def test_a_row_per_file_and_pipeline(self):
        rows = {(r["file"], r["pipeline"]) for r in self.doc["rows"]}
        drawable = [f["file"] for f in self.doc["files"] if f["status"] not in ("no-data", "load-failed")]
        self.assertGreaterEqual(len(drawable), len(SUBSET) - 2)
        for f in drawable:
            for p in PIPELINES:
                self.assertIn((f, p), rows)
        self.assertEqual(len(self.doc["rows"]), len(drawable) * len(PIPELINES))

    def test_files_without_data_are_not_load_failures(self):
        by_file = {f["file"]: f for f in self.doc["files"]}
        for p in SUBSET[-2:]:
            f = by_file[p]  # rows name files under the files' common folder: corpus-wide here
            self.assertEqual(f["status"], "no-data", f)
            self.assertTrue(f["error"], "a file without data says why")

    def test_rules_and_summary_are_printed(self):
        for rule in self.doc["rules"]:
            self.assertIn(("PASS: " if rule["pass"] else "FAIL: ") + rule["rule"], self.proc.stdout)
        self.assertIn("| pipeline | rows | drawn |", self.proc.stdout)
        self.assertEqual(self.proc.returncode, 0 if all(r["pass"] for r in self.doc["rules"]) else 1)


@unittest.skipUnless(os.access(EXE, os.X_OK), f"{EXE}: motorbench not built")
class SurveyPositionBound(unittest.TestCase):
    """The 16-byte bound `survey` states, recomputed by hand for textured_box: a unit box (half
    extent 0.5) centred on the origin under a rotation, so 0.5 / 32767 world units, projected at
    its nearest possible depth |eye| - sqrt(3) 0.5 with the frustum's corner slope."""

    def survey(self, size):
        run = subprocess.run([EXE, "survey", "textured_box", "--size", size, "--pipelines", "matrix_c"],
                             capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stderr)
        return json.loads(run.stdout)

    def test_bound_in_world_units_and_pixels(self):
        for size, height in (("128x128", 128), ("64x96", 96)):
            frame = self.survey(size)["frames"][0]
            bound, view = frame["positionBound"], frame["view"]
            self.assertAlmostEqual(bound["worldUnits"], 0.5 / 32767, delta=1e-12)
            tan_y = math.tan(view["yfov"] / 2)
            tan_x = tan_y * view["aspect"]
            depth = max(math.hypot(*view["eye"]) - math.sqrt(3) * 0.5, view["znear"])
            pixels = 0.5 / 32767 * math.sqrt(1 + tan_x ** 2 + tan_y ** 2) / depth * (height / 2) / tan_y
            self.assertAlmostEqual(bound["pixels"], pixels, delta=pixels * 1e-4)
            self.assertEqual(bound["envelopeRadius"], round(pixels) + 1)


@unittest.skipUnless(os.path.isdir(CORPUS), "../shared/corpus-wide absent (a clone without ../shared)")
@unittest.skipUnless(os.access(EXE, os.X_OK), f"{EXE}: motorbench not built")
class CorpusCheckCrash(unittest.TestCase):
    """A worker killed by a signal is recorded, pinned on its pipeline, and the run goes on."""

    def test_a_crashing_pipeline_is_named_and_the_others_keep_their_rows(self):
        with tempfile.TemporaryDirectory() as tmp:
            fake = os.path.join(tmp, "motorbench")
            with open(fake, "w", encoding="utf-8") as f:  # motor_cf "crashes": whole-file runs and its own
                f.write("#!/bin/sh\ncase \"$*\" in *--pipelines*motor_cf*) kill -SEGV $$;; *--pipelines*) ;; "
                        f"*) kill -SEGV $$;; esac\nexec {EXE} \"$@\"\n")
            os.chmod(fake, 0o755)
            files = [os.path.join(CORPUS, p) for p in SUBSET[:2]]
            run = subprocess.run([os.path.join(REPO, "scripts", "corpus-check.sh"), *files, "--out", tmp,
                                  "--jobs", "2", "--size", "64x64", "--exe", EXE, "--worker-exe", fake],
                                 capture_output=True, text=True, timeout=300)
            with open(os.path.join(tmp, "corpus-check.json"), encoding="utf-8") as f:
                doc = json.load(f)
        self.assertEqual(run.returncode, 1, run.stderr[-2000:])
        self.assertIn("FAIL: 0 crashes, signals or timeouts", run.stdout)
        self.assertEqual(doc["summary"]["crashed"], 2)
        for f in doc["files"]:
            self.assertEqual(f["status"], "crashed")
            self.assertEqual(f["crashedPipelines"], ["motor_cf"])
            self.assertIn("SIGSEGV", f["error"])
        for p in SUBSET[:2]:
            rows = {r["pipeline"]: r for r in doc["rows"] if r["file"] == p}
            self.assertEqual(sorted(rows), sorted(PIPELINES))
            self.assertEqual(rows["motor_cf"]["signal"], "SIGSEGV")
            self.assertTrue(all(r["drawn"] for n, r in rows.items() if n != "motor_cf"))


@unittest.skipUnless(os.access(EXE, os.X_OK), f"{EXE}: motorbench not built")
class SurveyTiePixels(unittest.TestCase):
    """The tie probe on real frames: few on a scene without coplanar surfaces, and on court.glb the
    z-fighting line pixels that fail motor's 50 dB are all ties."""

    COURT = os.path.join(CORPUS, "pmndrs+examples/demos/sport-hall/src/court.glb")
    court = None

    def survey(self, scene, *extra):
        run = subprocess.run([EXE, "survey", scene, "--size", "128x128", *extra], capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stderr)
        return json.loads(run.stdout)

    def court_survey(self):
        # One survey of court.glb for both court tests: each pipeline's document and the frames'
        # tie sets are the same as in a survey of motor alone or of matrix_c,motor_cf alone
        # (compared once), and it loads the file, renders matrix and probes the ties once.
        if SurveyTiePixels.court is None:
            SurveyTiePixels.court = self.survey(self.COURT, "--pipelines", "motor,matrix_c,motor_cf")
        return SurveyTiePixels.court

    def test_normal_torus_has_at_most_a_handful(self):
        doc = self.survey("normal_torus", "--pipelines", "motor")
        ties = doc["frames"][0]["ties"]
        motor = doc["pipelines"]["motor"]["frames"][0]
        # The probe's jitter is 16 float steps of each primitive's rounding magnitude
        # (harness/render/rounding_magnitude.h), at most 3e-4 px here: it may flip only pixels that
        # rounding decides, a sliver of the drawn ones (measured: 17 of 3412).
        self.assertLessEqual(ties["pixels"], motor["drawnPixels"] // 100)
        self.assertEqual(len(ties["set"]), ties["pixels"])
        self.assertTrue(all(0 <= i < 128 * 128 for i in ties["set"]))
        self.assertLessEqual(motor["differingNotTies"], motor["differingPixels"])

    @unittest.skipUnless(os.path.isdir(CORPUS), "../shared/corpus-wide absent (a clone without ../shared)")
    def test_court_z_fighting_is_ties(self):
        doc = self.court_survey()
        motor = doc["pipelines"]["motor"]["frames"][0]
        self.assertLess(motor["psnr"], 50)
        self.assertGreaterEqual(motor["psnrNotTies"] or math.inf, 50)

    @unittest.skipUnless(os.path.isdir(CORPUS), "../shared/corpus-wide absent (a clone without ../shared)")
    def test_court_16_byte_rule_in_the_geometry_view(self):
        # court.glb: motor_cf's interpolated rotor shades the normal-mapped roof differently (lit
        # PSNR about 32 dB against matrix) while its int16 positions draw what matrix_c's do: in the
        # geometry view every pixel outside the int16-cell ties lies inside the envelope.
        doc = self.court_survey()
        frame = doc["frames"][0]
        self.assertEqual(frame["int16Ties"]["renders"], 5)  # two antithetic pairs of cell corners, the int16 grid
        self.assertEqual(len(frame["int16Ties"]["set"]), frame["int16Ties"]["pixels"])
        cf = doc["pipelines"]["motor_cf"]["frames"][0]
        self.assertLess(cf["psnr"], 40)
        self.assertGreater(cf["geometryPsnr"], cf["psnr"] + 5)
        for name in ("matrix_c", "motor_cf"):
            self.assertEqual(doc["pipelines"][name]["frames"][0]["outsideEnvelopeNotTies"], 0, name)

    def test_skinned_tube_motor_blend_reference(self):
        # The motor blend's CPU reference (GLM dual quaternions, drawn by matrix): motor draws it
        # (identical or >= 60 dB, the same drawn pixels within 1 %), hybrid's linear blend does not
        # (measured: 43.6 dB at the bent frames), so the reference is not matrix's method again.
        doc = self.survey("skinned_tube", "--pipelines", "motor,hybrid")
        self.assertTrue(doc["motorBlendReference"]["available"])
        for k, frame in enumerate(doc["frames"]):
            ref = frame["motorBlendReference"]["drawnPixels"]
            motor = doc["pipelines"]["motor"]["frames"][k]
            self.assertTrue(motor["motorBlend"]["identical"] or motor["motorBlend"]["psnr"] >= 60, k)
            self.assertLessEqual(abs(motor["drawnPixels"] - ref), 0.01 * ref, k)
        bent = [f["motorBlend"] for f in doc["pipelines"]["hybrid"]["frames"][1:]]
        self.assertTrue(all(not b["identical"] and b["psnr"] < 50 for b in bent), bent)

    @unittest.skipUnless(os.path.isdir(CORPUS), "../shared/corpus-wide absent (a clone without ../shared)")
    def test_robot_morph_then_skin_reference(self):
        # robot-draco.glb: skinned primitives with morph targets; the reference morphs at the
        # frame's weights, then skins (glTF order): motor draws it (measured: identical).
        doc = self.survey(os.path.join(CORPUS, "pmndrs+examples/demos/staging-and-camerashake/src/robot-draco.glb"),
                          "--pipelines", "motor")
        self.assertTrue(doc["motorBlendReference"]["available"], doc["motorBlendReference"])
        for k, f in enumerate(doc["pipelines"]["motor"]["frames"]):
            self.assertTrue(f["motorBlend"]["identical"] or f["motorBlend"]["psnr"] >= 60, (k, f["motorBlend"]))


SYSTEM_PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
# Validates argv[2] against the schema argv[1], prints junitparser's tests, failures and errors.
JUNIT_READER = """import sys
try:
    import xmlschema, junitparser
except ImportError as e:
    print('SKIP', e); sys.exit(0)
xmlschema.XMLSchema(sys.argv[1]).validate(sys.argv[2])
x = junitparser.JUnitXml.fromfile(sys.argv[2])
print(x.tests, x.failures, x.errors)
"""


@unittest.skipUnless(os.access(EXE, os.X_OK), f"{EXE}: motorbench not built")
class CorpusCheckFailing(unittest.TestCase):
    """Files that do not load: the rule fails naming each file and its reason, exit 1; the JUnit
    file holds one failing case per file; --quiet prints the failing rule and one summary line."""

    def test_broken_files_fail_the_load_rule(self):
        with tempfile.TemporaryDirectory() as tmp:
            folder = os.path.join(tmp, "assets")
            os.makedirs(os.path.join(folder, "sub"))
            with open(os.path.join(folder, "empty.glb"), "wb"):
                pass
            with open(os.path.join(folder, "sub", "broken.gltf"), "w", encoding="utf-8") as f:
                f.write("{not json")
            junit = os.path.join(tmp, "ci", "rules.xml")
            cmd = [os.path.join(REPO, "scripts", "corpus-check.sh"), folder, "--out", os.path.join(tmp, "out"),
                   "--jobs", "2", "--exe", EXE, "--junit", junit]
            # --quiet on the empty file alone, beside the full run (one survey worker more).
            quiet = subprocess.Popen([cmd[0], os.path.join(folder, "empty.glb"), "--out", os.path.join(tmp, "quiet"),
                                      "--exe", EXE, "--quiet"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
            quiet.stdout_text, quiet.stderr_text = quiet.communicate(timeout=120)
            with open(os.path.join(tmp, "out", "corpus-check.json"), encoding="utf-8") as f:
                doc = json.load(f)
            suite = ET.parse(junit).getroot()
            # As CI reads it: the project's JUnit schema (tests/cli/junit_schema.xsd) and junitparser,
            # from the system python that setup.sh installs them for.
            read = subprocess.run([SYSTEM_PYTHON, "-c", JUNIT_READER, os.path.join(REPO, "tests", "cli", "junit_schema.xsd"),
                                   junit], capture_output=True, text=True, timeout=60)
        self.assertEqual(run.returncode, 1, run.stderr[-2000:])
        self.assertIn("- FAIL: every file loads (files without data excepted) (2)\n", run.stdout)
        self.assertRegex(run.stdout, r"\n  - empty\.glb: .*empty file \(0 bytes\)")
        self.assertIn("  - sub/broken.gltf: ", run.stdout)
        self.assertIn("- PASS: 0 crashes, signals or timeouts", run.stdout)
        self.assertEqual((doc["summary"]["files"], doc["summary"]["loadFailed"], doc["rows"]), (2, 2, []))
        cases = suite.findall(".//testcase")
        self.assertEqual([c.get("classname") for c in cases], ["check.rules.empty.glb", "check.rules.sub/broken.gltf"])
        self.assertTrue(all(c.find("failure") is not None for c in cases))
        self.assertRegex(cases[0].find("failure").get("message"), r"^every file loads: .*empty file \(0 bytes\)")
        if not read.stdout.startswith("SKIP"):
            self.assertEqual(read.stdout.split(), ["2", "2", "0"], read.stdout + read.stderr)
        self.assertEqual(quiet.returncode, 1)
        lines = quiet.stdout_text.splitlines()
        self.assertEqual(lines[0], "FAIL: every file loads (files without data excepted) (1)")
        self.assertRegex(lines[1], r"^  - empty\.glb: .*empty file \(0 bytes\)")
        self.assertEqual(len(lines), 3, quiet.stdout_text)
        self.assertTrue(lines[-1].startswith("check --rules: FAIL: 1 of 6 rules failed; 1 files"), quiet.stdout_text)
        self.assertNotIn("check --rules: [", quiet.stderr_text)  # no progress lines


if __name__ == "__main__":
    unittest.main()
