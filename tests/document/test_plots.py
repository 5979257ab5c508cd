"""scripts/plot.py: the plots are read from their data, the "bars" that
plots/index.json records for every bar drawn, never from pixels.

image_error: one bar per pipeline and scene (grouped: within a scene every pipeline at its own
x, inside the scene's slot), identical frames drawn as "identical" (no value, not 100 dB); one
colour per pipeline, the same in every plot, no two pipelines sharing one.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PLOT = os.path.join(REPO, "scripts", "plot.py")
# Debian's python3-matplotlib lives with /usr/bin/python3 (as motorbench report picks it).
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
PIPES = ["matrix", "affine", "qtangent", "motor", "motor_q", "hybrid"]


def has_matplotlib():
    return subprocess.run([PYTHON, "-c", "import matplotlib"], capture_output=True).returncode == 0


def metrics(psnr, over1):
    return {"psnr": psnr, "identical": psnr is None, "fractionOver1": over1, "maxError": 0.01}


def report():
    """Three scenes: box identical for every pipeline at every time; torus differs (PSNR per
    pipeline = 40 + index, worst of two times); tube identical for affine only."""
    scenes = []
    for sid in ["textured_box", "normal_torus", "skinned_tube"]:
        frames = []
        for t in range(2):
            m = {}
            for i, p in enumerate(PIPES[1:]):
                if sid == "textured_box" or (sid == "skinned_tube" and p == "affine"):
                    m[p] = metrics(None, 0.0)
                else:
                    m[p] = metrics(40.0 + i + t, 0.001 * (i + 1) * (t + 1))
            frames.append({"time": t, "metrics": m})
        pipelines = {p: {"memory": {"bytesPerVertex": 28 + 4 * i}} for i, p in enumerate(PIPES)}
        scenes.append({"id": sid, "frames": frames, "pipelines": pipelines,
                       "opsPerVertex": {p: {"counted": {"mul": 50 + i, "add": 40}} for i, p in enumerate(PIPES)},
                       "timing": {"ratio_motor_matrix": 0.9, "update": {"ratio_motor_matrix": 0.8}}})
    # The tube's motor pipeline drew with its exact skin fallback.
    scenes[2]["pipelines"]["motor"]["fallbacks"] = {"linearFallbackDraws": 0, "skinFallbackDraws": 1,
                                                    "skinFallbackJoints": 4, "fallbackVertices": 100}
    # A curved scene: compared by its space's pair (s3_motor against s3_matrix).
    scenes.append({"id": "s3_tiling", "frames": [{"time": 0, "metrics": {"s3_motor": metrics(70.0, 0.0)}}]})
    return {"settings": {"pipelines": PIPES, "baseline": "matrix"}, "scenes": scenes}


def run_plots(report_json, prefix):
    """Writes `report_json` to a scratch folder, runs plot.py on it; returns (folder, index.json,
    {name: plot})."""
    folder = tempfile.mkdtemp(prefix=prefix)
    src = os.path.join(folder, "report.json")
    with open(src, "w") as f:
        json.dump(report_json, f)
    run = subprocess.run([PYTHON, PLOT, src, os.path.join(folder, "plots")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    with open(os.path.join(folder, "plots", "index.json")) as f:
        index = json.load(f)
    return folder, index, {p["name"]: p for p in index["files"]}


@unittest.skipUnless(has_matplotlib(), "matplotlib not installed (python3-matplotlib)")
class Plots(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir, cls.index, cls.plots = run_plots(report(), "motorbench_plots_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_image_error_has_one_bar_per_pipeline_and_scene_at_distinct_x(self):
        self.assertIn("image_error", self.plots)
        self.assertTrue(os.path.exists(os.path.join(self.dir, "plots", "image_error.png")))
        bars = [b for b in self.plots["image_error"]["bars"] if b["panel"] == "psnr"]
        scenes = ["textured_box", "normal_torus", "skinned_tube"]
        self.assertEqual(sorted((b["series"], b["label"]) for b in bars),
                         sorted([(p, s) for p in PIPES[1:] for s in scenes] + [("s3_motor", "s3_tiling")]))
        for k, s in enumerate(scenes):
            xs = [b["x"] for b in bars if b["label"] == s]
            self.assertEqual(len(set(xs)), len(PIPES) - 1, f"{s}: bars share an x: {xs}")
            self.assertNotIn(3, [round(x) for x in xs])  # none in the curved scene's slot
            self.assertTrue(all(k - 0.5 < x < k + 0.5 for x in xs), f"{s}: bar outside its group: {xs}")
            # In pipeline order, left to right.
            order = [b["series"] for b in sorted((b for b in bars if b["label"] == s), key=lambda b: b["x"])]
            self.assertEqual(order, PIPES[1:])

    def test_identical_frames_are_marked_identical_not_a_number(self):
        bars = {(b["series"], b["label"]): b for b in self.plots["image_error"]["bars"] if b["panel"] == "psnr"}
        for p in PIPES[1:]:
            self.assertEqual(bars[(p, "textured_box")]["text"], "identical")
            self.assertIsNone(bars[(p, "textured_box")]["value"])
        self.assertEqual(bars[("affine", "skinned_tube")]["text"], "identical")
        # A differing scene shows its worst PSNR (the smaller of the two times): 40 + index.
        for i, p in enumerate(PIPES[1:]):
            self.assertIsNone(bars[(p, "normal_torus")]["text"])
            self.assertEqual(bars[(p, "normal_torus")]["value"], 40.0 + i)
        self.assertEqual(bars[("motor", "skinned_tube")]["value"], 42.0)

    def test_frame_time_ratio_names_the_motor_fallback_under_its_scene(self):
        labels = {b["label"] for b in self.plots["frame_time_ratio"]["bars"]}
        self.assertIn("skinned_tube\nmotor fallback: 1 draws, 4 joints, 100 vertices", labels)
        self.assertIn("normal_torus", labels)
        self.assertNotIn("skinned_tube", labels)

    def test_one_colour_per_pipeline_in_every_plot(self):
        seen = {}
        for plot in self.index["files"]:
            for b in plot["bars"]:
                seen.setdefault(b["series"], set()).add(b["colour"])
        for series, colours in seen.items():
            self.assertEqual(len(colours), 1, f"{series} has several colours: {colours}")
        by_colour = {}
        for series, colours in seen.items():
            by_colour.setdefault(next(iter(colours)), []).append(series)
        shared = {c: s for c, s in by_colour.items() if len(s) > 1}
        self.assertEqual(shared, {}, "series sharing a colour")
        for p in PIPES:
            self.assertIn(p, seen)


if __name__ == "__main__":
    unittest.main()
