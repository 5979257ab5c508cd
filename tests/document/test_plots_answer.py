"""scripts/plot.py: the frame-time bars are report.json's figures with their IQR
as error bars, every ratio follows one convention (< 1: motor side cheaper, kernel plot included),
identical frames are a short stub not a tall bar, the design space has one point per pipeline in
two family colours. Read from index.json's "bars" (the data as drawn), never from pixels.
"""
import os
import shutil
import sys
import unittest

sys.path.insert(0, os.path.dirname(__file__))
from test_plots import REPO, has_matplotlib, run_plots  # noqa: E402

sys.path.insert(0, os.path.join(REPO, "scripts"))


def fig(value, unit="x", q1=None, q3=None, device="CPU rasterizer (llvmpipe), wall clock"):
    f = {"value": value, "unit": unit, "device": device, "n": 3}
    if q1 is not None:
        f["spread"] = {"q1": q1, "q3": q3, "kind": "interquartile range"}
    return f


def report():
    pipes = ["matrix", "motor", "qtangent"]
    figures = {"frame_time.motor_over_matrix": fig(0.95, q1=0.9, q3=1.0),
               "frame_time.a.motor_over_matrix": fig(0.8, q1=0.7, q3=0.9),
               "frame_time.b.motor_over_matrix": fig(1.1, q1=1.05, q3=1.2),
               "vertex_fetch.bytes_per_vertex.matrix": fig(48, "bytes"),
               "vertex_fetch.bytes_per_vertex.motor": fig(36, "bytes"),
               "vertex_fetch.bytes_per_vertex.qtangent": fig(28, "bytes"),
               "isa.instructions.rigid.gfx1100.matrix": fig(153, "instructions"),
               "isa.instructions.rigid.gfx1100.motor": fig(162, "instructions"),
               "isa.instructions.rigid.gfx1100.qtangent": fig(156, "instructions")}
    identical = {"psnr": None, "identical": True, "fractionOver1": 0.0}
    scenes = [{"id": sid, "timing": {"ratio_motor_matrix": 0.5},  # the old ratio of medians: not drawn
               "frames": [{"time": 0, "metrics": {"motor": identical, "qtangent": identical}}]} for sid in "ab"]
    return {"settings": {"pipelines": pipes, "baseline": "matrix"}, "scenes": scenes, "figures": figures,
            "pipelineFamilies": {"matrix": "matrix", "motor": "motor", "qtangent": "matrix"},
            "isa": {"families": [{"id": "tahiti"}, {"id": "gfx1100"}]},
            "machine": {"gl": {"renderer": "llvmpipe", "realGpu": False}},
            # The shim pair at 2x the throughput, the fastest implementations at 4x: the plot shows
            # the fastest against the fastest (summary.kernelRatios, the figure the text quotes).
            "kernels": {"pairs": [{"pair": "compose", "kernel": "compose", "size": None, "ratio_motor_matrix": 2.0,
                                   "ratio_motor_fastest_matrix": 4.0}]},
            "summary": {"kernelRatios": {"compose": {"motorOverMatrixTime": 0.25, "fastestMotor": "simd_motor",
                                                     "fastestMatrix": "simd_affine"}}}}


@unittest.skipUnless(has_matplotlib(), "matplotlib not installed (python3-matplotlib)")
class AnswerPlots(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir, _, cls.plots = run_plots(report(), "motorbench_plots_answer_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_frame_bars_are_the_figures_with_their_iqr(self):
        bars = {b["label"]: b for b in self.plots["frame_time_ratio"]["bars"] if b["series"] == "frame"}
        self.assertEqual(bars["a"]["value"], 0.8)
        self.assertEqual(bars["a"]["iqr"], [0.7, 0.9])
        self.assertEqual(bars["b"]["value"], 1.1)
        self.assertEqual(bars["b"]["iqr"], [1.05, 1.2])

    def test_kernel_ratio_is_time_motor_over_matrix(self):
        # 4x the throughput of the fastest matrix = a quarter of the time: 0.25, below 1 as motor
        # is cheaper; the sides are named with the kernel.
        (bar,) = self.plots["kernel_ratios"]["bars"]
        self.assertEqual(bar["value"], 0.25)
        self.assertEqual(bar["label"], "compose")
        self.assertIn("fastest motor implementation over the fastest matrix", self.plots["kernel_ratios"]["caption"])

    def test_device_and_convention_in_titles_and_captions(self):
        import plot
        self.assertEqual(plot.CONVENTION, "< 1: motor side cheaper")
        self.assertGreaterEqual(plot.FONT * plot.DPI / 72, 10)  # labels >= 10 px at the saved dpi
        self.assertIn("no error bars", self.plots["kernel_ratios"]["caption"])

    def test_identical_frames_are_stubs_not_tall_bars(self):
        # PSNR: no value (infinite); changed pixels: 0 %. Either way drawn as a stub of 4 % of
        # the axis, not the tallest bar.
        for b in self.plots["image_error"]["bars"]:
            self.assertEqual(b["text"], "identical")
            self.assertIn(b["value"], (None, 0.0))
            self.assertLessEqual(b["height"], 0.05 * b["axisTop"])

    def test_design_space_one_point_per_pipeline_in_family_colours(self):
        bars = self.plots["design_space"]["bars"]
        self.assertEqual(sorted(b["label"] for b in bars), ["matrix", "motor", "qtangent"])
        points = {b["label"]: (b["x"], b["value"], b["series"]) for b in bars}
        motors, matrices = "motor family: motors on the CPU and the GPU", "matrix family: matrices on the CPU and the GPU"
        self.assertEqual(points["motor"], (36, 162, motors))
        self.assertEqual(points["qtangent"], (28, 156, matrices))  # the newest ISA family
        colours = {b["series"]: b["colour"] for b in bars}
        self.assertNotEqual(colours[motors], colours[matrices])
        self.assertTrue(all(b["text"] is None for b in bars))  # no GPU timed: no time labels

    def test_a_pipeline_with_another_familys_gpu_side_has_its_own_entry(self):
        # hybrid poses with motors (its family) and draws as qtangent: not a motor-family point.
        r = report()
        r["settings"]["pipelines"].append("hybrid")
        r["pipelineFamilies"]["hybrid"] = "motor"
        r["pipelineGpuSides"] = {"hybrid": "qtangent"}
        r["figures"]["vertex_fetch.bytes_per_vertex.hybrid"] = fig(28, "bytes")
        r["figures"]["isa.instructions.rigid.gfx1100.hybrid"] = fig(156, "instructions")
        folder, _, plots = run_plots(r, "motorbench_plots_hybrid_")
        shutil.rmtree(folder, ignore_errors=True)
        series = {b["label"]: b["series"] for b in plots["design_space"]["bars"]}
        colours = {b["series"]: b["colour"] for b in plots["design_space"]["bars"]}
        self.assertEqual(series["hybrid"], "hybrid: motors on the CPU, qtangent on the GPU")
        self.assertEqual(series["motor"], "motor family: motors on the CPU and the GPU")
        self.assertEqual(len(set(colours.values())), 3)  # three entries, three colours
        self.assertIn("hybrid: motors on the CPU, qtangent on the GPU", plots["design_space"]["caption"])
        self.assertIn("modelled", plots["design_space"]["caption"])
        self.assertIn("compiled", plots["design_space"]["caption"])

    def test_kernel_caption_says_how_each_time_was_taken(self):
        # The sides' recorded repetitions (Google Benchmark's medians), else that they are unknown.
        self.assertIn("not recorded", self.plots["kernel_ratios"]["caption"])
        r = report()
        r["kernels"]["pairs"][0]["simd_motor"] = {"items_per_second": 4.0, "repetitions": 3}
        r["kernels"]["pairs"][0]["simd_affine"] = {"items_per_second": 1.0, "repetitions": 3}
        folder, _, plots = run_plots(r, "motorbench_plots_reps_")
        shutil.rmtree(folder, ignore_errors=True)
        caption = plots["kernel_ratios"]["caption"]
        self.assertIn("the median of 3 repetitions", caption)
        self.assertNotIn("one run per kernel", caption)

    def test_design_space_labels_gpu_time_where_a_gpu_measured_it(self):
        r = report()
        r["machine"]["gl"] = {"renderer": "NVIDIA H100", "realGpu": True}
        r["figures"]["frame_time_vertex_bound.motor_over_matrix"] = fig(0.8, device="NVIDIA H100")
        r["figures"]["frame_time.qtangent_over_matrix"] = fig(0.9, device="NVIDIA H100")
        folder, _, plots = run_plots(r, "motorbench_plots_gpu_")
        shutil.rmtree(folder, ignore_errors=True)
        texts = {b["label"]: b["text"] for b in plots["design_space"]["bars"]}
        # Vertex-bound where measured, else the whole frame; none where neither was timed.
        self.assertEqual(texts, {"motor": "0.80x", "qtangent": "0.90x", "matrix": None})


def kinds_report():
    """Files 40 % normal-mapped (motor 0.75x the bytes, 1.1x the ops), 60 % skinned without a
    normal map (1.125x the bytes, 0.72x the ops); the built-in scenes 0.75x the bytes."""
    r = report()
    figs = r["figures"]
    for kind, vertices, share, prims, b, om, ob in (("all", 500, None, None, 0.9375, 122, 148),
                                                   ("normal_mapped", 200, 40, 25, 0.75, 110, 100),
                                                   ("not_normal_mapped", 300, 60, 75, 1.125, 130, 180),
                                                   ("morph", 0, 0, 0, None, None, None),
                                                   ("built_in", 50, None, None, 0.75, 110, 100)):
        figs["kind.vertices." + kind] = fig(vertices, "vertices")
        if share is not None:
            figs["kind.share_vertices." + kind] = fig(share, "%")
            figs["kind.share_primitives." + kind] = fig(prims, "%")
        if b is not None:
            figs["kind.fetched_over_baseline.%s.motor" % kind] = fig(b)
            figs["kind.ops_counted.%s.motor" % kind] = fig(om, "ops")
            figs["kind.ops_counted.%s.matrix" % kind] = fig(ob, "ops")
    return r


@unittest.skipUnless(has_matplotlib(), "matplotlib not installed (python3-matplotlib)")
class ContentKindPlot(unittest.TestCase):
    def test_one_bar_per_kind_and_cost_with_its_share_under_it(self):
        folder, _, plots = run_plots(kinds_report(), "motorbench_plots_kinds_")
        shutil.rmtree(folder, ignore_errors=True)
        bars = plots["content_kinds"]["bars"]
        got = {(b["kind"], b["series"]): b["value"] for b in bars}
        self.assertEqual(got[("normal_mapped", "bytes fetched per frame")], 0.75)
        self.assertEqual(got[("not_normal_mapped", "bytes fetched per frame")], 1.125)
        self.assertAlmostEqual(got[("not_normal_mapped", "ops counted per vertex")], 130 / 180)
        self.assertAlmostEqual(got[("normal_mapped", "ops counted per vertex")], 1.1)
        self.assertEqual(got[("built_in", "bytes fetched per frame")], 0.75)
        self.assertNotIn("morph", {b["kind"] for b in bars})  # a kind the content does not draw
        labels = {b["kind"]: b["label"] for b in bars}
        self.assertEqual(labels["normal_mapped"], "normal-mapped\n40 % of vertices\n25 % of primitives")
        self.assertIn("controlled cases", labels["built_in"])
        self.assertEqual(len({b["x"] for b in bars}), len(bars))  # never two bars at one x

    def test_no_kind_figures_no_plot(self):
        folder, index, _ = run_plots(report(), "motorbench_plots_nokinds_")
        shutil.rmtree(folder, ignore_errors=True)
        self.assertIn("content_kinds", index["skipped"])


if __name__ == "__main__":
    unittest.main()
