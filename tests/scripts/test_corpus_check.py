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

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CORPUS = os.path.join(REPO, "..", "shared", "corpus-wide")
EXE = os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench"))
sys.path.insert(0, os.path.join(REPO, "scripts"))
import corpus_check  # noqa: E402  (the judging functions, on synthetic survey documents)

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
                                  "--jobs", "2", "--size", "64x64", "--exe", fake],
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


def synthetic_result(motor=None, matrix_c=None, ties=16, int16_ties=9):
    """file_result() of a made-up one-frame rigid survey: matrix plus the given pipelines' frames."""
    frame = {"animation": None, "time": 0.0, "kind": "rigid",
             "positionBound": {"worldUnits": 1e-5, "pixels": 0.01, "envelopeRadius": 1, "shadeTolerance": 4}}
    if ties is not None:
        frame["ties"] = {"pixels": ties, "renders": 2, "set": list(range(ties))}
    if int16_ties is not None:
        frame["int16Ties"] = {"pixels": int16_ties, "renders": 5, "set": list(range(int16_ties))}
    pipelines = {"matrix": {"error": None, "frames": [{"drawnPixels": 5000}], "fallbacks": {}, "seconds": 0.1}}
    for name, f in (("motor", motor), ("matrix_c", matrix_c)):
        if f is not None:
            pipelines[name] = {"error": None, "frames": [dict({"drawnPixels": 5000}, **f)], "fallbacks": {}, "seconds": 0.1}
    doc = {"status": "ok", "baseline": "matrix", "pipelineOrder": list(pipelines), "frames": [frame],
           "pipelines": pipelines, "scene": {}, "loaderFallbacks": {}}
    rec = {"exit": 0, "signal": None, "timeout": False, "stderr": "", "doc": doc, "seconds": 1.0}
    return corpus_check.file_result("x.glb", "x.glb", rec, "")


def rule(rules, start):
    return next((fails, ties) for name, fails, ties in rules if name.startswith(start))


class TieRule(unittest.TestCase):
    """The rigid and 16-byte rules judged outside the tie pixels (survey: pixels matrix itself draws
    differently from jittered vertex positions), on synthetic survey documents."""

    def test_a_frame_whose_failing_pixels_are_all_ties_passes_with_the_mark(self):
        # court.glb's case: 42.4 dB, 16 differing pixels, every one a tie.
        res = synthetic_result(motor={"identical": False, "psnr": 42.4, "differingPixels": 16, "differingNotTies": 0,
                                      "identicalNotTies": True, "psnrNotTies": None})
        rules = corpus_check.evaluate([res])
        fails, ties = rule(rules, "rigid frames of motor")
        self.assertEqual(fails, [])
        self.assertEqual(len(ties), 1)
        self.assertIn("x.glb [motor] rest: 42.40 dB; identical dB outside the 16 tie pixels", ties[0])
        lines = "\n".join(corpus_check.rule_lines(rules))
        self.assertIn("PASS: rigid frames of motor", lines)
        self.assertIn("(1 frames pass on ties)", lines)
        self.assertIn("PASS (ties: undetermined by the transform): x.glb [motor] rest", lines)
        per = corpus_check.totals([res], ["matrix", "motor"])
        self.assertEqual(per["motor"]["rigidTieFrames"], 1)
        self.assertEqual(per["motor"]["rigidFilesFailing"], 0)
        self.assertEqual(per["motor"]["rigidFilesBelow50dB"], 1)  # the raw figure stays visible

    def test_rounding_outside_the_ties_that_the_50_dB_rule_allows_anyway_still_passes(self):
        # motor on court.glb also differs by one byte in 8 non-tie pixels: 66 dB outside the ties.
        res = synthetic_result(motor={"identical": False, "psnr": 42.4, "differingPixels": 37, "differingNotTies": 8,
                                      "identicalNotTies": False, "psnrNotTies": 66.0})
        fails, ties = rule(corpus_check.evaluate([res]), "rigid frames of motor")
        self.assertEqual(fails, [])
        self.assertIn("66.0 dB outside the 16 tie pixels (37 px differ, 8 of them not ties)", ties[0])

    def test_a_frame_with_a_failing_pixel_outside_the_tie_set_still_fails(self):
        res = synthetic_result(motor={"identical": False, "psnr": 42.0, "differingPixels": 17, "differingNotTies": 1,
                                      "identicalNotTies": False, "psnrNotTies": 43.5})
        rules = corpus_check.evaluate([res])
        fails, ties = rule(rules, "rigid frames of motor")
        self.assertEqual(ties, [])
        self.assertEqual(fails, ["x.glb [motor]: 42.00 dB, 43.5 dB outside the tie pixels"])
        self.assertIn("FAIL: rigid frames of motor", "\n".join(corpus_check.rule_lines(rules)))
        self.assertEqual(corpus_check.totals([res], ["motor"])["motor"]["rigidFilesFailing"], 1)

    def test_a_survey_without_tie_data_is_judged_on_every_pixel(self):
        res = synthetic_result(motor={"identical": False, "psnr": 42.0}, ties=None)
        fails, ties = rule(corpus_check.evaluate([res]), "rigid frames of motor")
        self.assertEqual((len(fails), ties), (1, []))

    def test_a_counted_morph_omission_is_listed_not_judged(self):
        # qtangent draws a morphed node in its base shape and counts it (morphNotDrawnNodes): no
        # image rule judges that frame; it is listed apart with its count and PSNR.
        res = synthetic_result(motor={"identical": False, "psnr": 22.0, "fallbacks": {"morphNotDrawnNodes": 1}})
        rules = corpus_check.evaluate([res])
        fails, _ = rule(rules, "rigid frames of motor")
        self.assertEqual(fails, [])
        _, listed = rule(rules, "frames judged by no image rule")
        self.assertEqual(listed, [("counted omission: motor does not morph (issue 37)",
                                   "x.glb [motor] rest: 1 morphed node(s) drawn in their base shape, 22.0 dB against matrix")])
        self.assertIn("- COUNTED: frames judged by no image rule: a feature the pipeline counts as not drawn (1)",
                      corpus_check.rule_lines(rules))
        # The same frame without the count is a failure.
        fails, _ = rule(corpus_check.evaluate([synthetic_result(motor={"identical": False, "psnr": 22.0})]), "rigid frames of motor")
        self.assertEqual(len(fails), 1)

    def test_the_16_byte_rule_both_ways(self):
        ok = synthetic_result(matrix_c={"identical": False, "psnr": 45.0, "outsideEnvelope": 2, "envelopeExcess": 90,
                                        "outsideEnvelopeNotTies": 0, "envelopeExcessNotTies": 3})
        fails, ties = rule(corpus_check.evaluate([ok]), "rigid frames of matrix_c")
        self.assertEqual(fails, [])
        self.assertEqual(ties, ["x.glb [matrix_c] rest: 2 px outside the envelope, every one of them an int16-cell tie pixel (9 in the frame)"])
        self.assertEqual(corpus_check.totals([ok], ["matrix_c"])["matrix_c"]["compactTieFrames"], 1)
        bad = synthetic_result(matrix_c={"identical": False, "psnr": 45.0, "outsideEnvelope": 3, "envelopeExcess": 90,
                                         "outsideEnvelopeNotTies": 1, "envelopeExcessNotTies": 40})
        fails, ties = rule(corpus_check.evaluate([bad]), "rigid frames of matrix_c")
        self.assertEqual(ties, [])
        self.assertEqual(len(fails), 1)
        self.assertIn("3 px outside the envelope (1 not tie pixels)", fails[0])


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


class SkinnedRule(unittest.TestCase):
    """The skinned rule on synthetic surveys: each pipeline against its skinning method's reference."""

    @staticmethod
    def result(motor_drawn, reference_drawn, matrix_drawn=1000):
        frame = {"animation": 0, "time": 0.5, "kind": "skinned", "motorBlendReference": {"drawnPixels": reference_drawn}}
        pipelines = {"matrix": {"error": None, "frames": [{"drawnPixels": matrix_drawn}], "fallbacks": {}, "seconds": 0.1},
                     "motor": {"error": None, "frames": [{"drawnPixels": motor_drawn, "psnr": 40.0,
                                                          "motorBlend": {"identical": False, "psnr": 90.0}}],
                               "fallbacks": {}, "seconds": 0.1}}
        doc = {"status": "ok", "baseline": "matrix", "pipelineOrder": list(pipelines), "frames": [frame],
               "pipelines": pipelines, "scene": {}, "loaderFallbacks": {},
               "motorBlendReference": {"available": True, "why": None}}
        rec = {"exit": 0, "signal": None, "timeout": False, "stderr": "", "doc": doc, "seconds": 1.0}
        return corpus_check.file_result("s.glb", "s.glb", rec, "")

    def test_motor_judged_against_the_motor_blend(self):
        # 2 % from matrix but on its own method's reference: passes, listed as a method difference.
        fails, marked = rule(corpus_check.evaluate([self.result(1020, 1020)]), "skinned frames")
        self.assertEqual(fails, [])
        self.assertEqual(len(marked), 1)
        self.assertIn("s.glb [motor]: t=0.5 2.0 % apart from matrix; from its own method's reference t=0.5 0.0 %, 90.0 dB",
                      marked[0])
        # Within 1 % of matrix but 2 % from its own reference: a failure naming the reference.
        fails, _ = rule(corpus_check.evaluate([self.result(1000, 1020)]), "skinned frames")
        self.assertEqual(len(fails), 1)
        self.assertIn("apart from motor blend (GLM dual quaternions, drawn by matrix) by t=0.5 2.0 %", fails[0])


if __name__ == "__main__":
    unittest.main()
