#!/usr/bin/env python3
"""scripts/results_diff.py: timings may differ, every other figure may not."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "results_diff.py")


def report(frame_ms, psnr, verdict, bytes_per_vertex=36, time=0.5):
    """A report.json and claims.json shaped like motorbench's (the keys results_diff judges by)."""
    return {
        "report.json": {
            "machine": {"date": "2026-11-27T17:09:02Z", "cpu": "AMD EPYC"},
            "scenes": [{"id": "teapot", "frames": [{"time": time, "metrics": {"psnr": psnr}}],
                        "timing": {"paired_ratio_motor_matrix": frame_ms / 2},
                        "pipelines": {"motor": {"stats": {"conversionMs": frame_ms / 7,
                                                          "bytesPerVertex": bytes_per_vertex}}}}],
            "figures": {"frame_time.motor_over_matrix": {"value": frame_ms / 3},
                        "bytes_per_vertex.motor": {"value": bytes_per_vertex}},
            "glossary": {"conversionMs": {"meaning": "load-time conversion"}},
        },
        "claims.json": {"claims": [
            {"id": "as_fast_as_matrices", "section": "Speed", "measured": f"{frame_ms} ms",
             "measuredValue": {"costRatio": frame_ms}, "verdict": verdict},
            {"id": "floats_per_vertex", "section": "Memory", "measured": f"{bytes_per_vertex} bytes",
             "measuredValue": {"motor": bytes_per_vertex}, "verdict": "reproduced"},
        ]},
        "bench.json": {"context": {"load_avg": [frame_ms]},
                       "benchmarks": [{"name": "compose/motor", "real_time": frame_ms, "iterations": 7}]},
    }


def write(root, files):
    for name, doc in files.items():
        os.makedirs(os.path.dirname(os.path.join(root, name)) or root, exist_ok=True)
        with open(os.path.join(root, name), "w") as f:
            json.dump(doc, f)


def diff(old, new):
    with tempfile.TemporaryDirectory() as a, tempfile.TemporaryDirectory() as b:
        write(a, old)
        write(b, new)
        p = subprocess.run([sys.executable, SCRIPT, a, b], capture_output=True, text=True)
        return p.returncode, p.stdout


class ResultsDiff(unittest.TestCase):
    def test_timings_and_their_verdicts_may_differ(self):
        rc, out = diff(report(10.0, 50.0, "reproduced"), report(13.0, 50.0, "differs"))
        self.assertEqual((rc, out), (0, ""))

    def test_a_changed_image_metric_is_found(self):
        rc, out = diff(report(10.0, 50.0, "reproduced"), report(10.0, 49.5, "reproduced"))
        self.assertEqual(rc, 1)
        self.assertIn("report.json.scenes[teapot].frames[0].metrics.psnr: 50.0 -> 49.5", out)

    def test_bytes_in_stats_figure_and_claim_are_found(self):
        rc, out = diff(report(10.0, 50.0, "reproduced"), report(10.0, 50.0, "reproduced", bytes_per_vertex=48))
        self.assertEqual(rc, 1)
        for path in ("stats.bytesPerVertex", "figures.bytes_per_vertex.motor.value",
                     "claims[floats_per_vertex].measured", "claims[floats_per_vertex].measuredValue.motor"):
            self.assertIn(path, out)
        self.assertNotIn("claims[as_fast_as_matrices]", out)

    def test_animation_time_is_not_a_timing(self):
        rc, out = diff(report(10.0, 50.0, "reproduced"), report(10.0, 50.0, "reproduced", time=0.75))
        self.assertEqual(rc, 1)
        self.assertIn("frames[0].time: 0.5 -> 0.75", out)

    def test_a_missing_file_or_benchmark_is_found(self):
        old = report(10.0, 50.0, "reproduced")
        new = report(10.0, 50.0, "reproduced")
        del new["claims.json"]
        new["bench.json"]["benchmarks"].append({"name": "compose/matrix", "real_time": 1.0})
        rc, out = diff(old, new)
        self.assertEqual(rc, 1)
        self.assertIn("claims.json: only in the old results", out)
        self.assertIn("bench.json.benchmarks[compose/matrix]: only in the new results", out)

    def test_an_entry_inserted_in_the_middle_is_one_difference(self):
        # Entries are matched by their names, not their places: the claims after the new one
        # are not reported as changed.
        old = report(10.0, 50.0, "reproduced")
        new = report(10.0, 50.0, "reproduced")
        new["claims.json"]["claims"].insert(1, {"id": "isa_vgprs", "section": "Memory",
                                                "measured": "24 VGPRs", "verdict": "reproduced"})
        rc, out = diff(old, new)
        self.assertEqual(rc, 1)
        self.assertEqual(out.splitlines(), ["claims.json.claims[isa_vgprs]: only in the new results"])

    def test_entries_without_unique_names_are_compared_by_place(self):
        old = report(10.0, 50.0, "reproduced")
        new = report(10.0, 50.0, "reproduced")
        for doc in (old, new):
            doc["report.json"]["scenes"].append(dict(doc["report.json"]["scenes"][0]))
        new["report.json"]["scenes"][1] = dict(new["report.json"]["scenes"][1], frames=[])
        rc, out = diff(old, new)
        self.assertEqual(rc, 1)
        self.assertIn("report.json.scenes[1].frames: 1 entries before, 0 now", out)

    def test_a_timed_claim_left_unmeasured_by_a_disturbed_run_is_a_timing(self):
        # A disturbed bench leaves the CPU claim "not measurable here" with no measured value:
        # the claim is judged on a timing in the other run, so its verdict is not compared.
        old = report(10.0, 50.0, "reproduced")
        new = report(10.0, 50.0, "reproduced")
        old["claims.json"]["claims"].append({"id": "cpu_vertex_frame_vs_strongest", "section": "Against",
                                             "measuredValue": {"in_cache": {"real_time": 2.0}},
                                             "verdict": "reproduced"})
        new["claims.json"]["claims"].append({"id": "cpu_vertex_frame_vs_strongest", "section": "Against",
                                             "measuredValue": None, "verdict": "not measurable here"})
        self.assertEqual(diff(old, new), (0, ""))

    def test_a_claim_read_from_timing_figures_is_a_timing(self):
        # Evidence read from a kernel-time figure (a label without a timing word): its reads,
        # pass and the claim's verdict move with the machine; evidence read from a byte count
        # is still compared.
        def claim(kernel_ratio, bytes_ratio):
            return {"id": "cpu_vertex_frame_vs_strongest", "section": "Against the strongest baseline",
                    "measured": f"in cache {kernel_ratio}x", "measuredValue": {"in cache": kernel_ratio},
                    "verdict": "reproduced" if kernel_ratio < 1 else "differs",
                    "evidence": [{"label": "in cache", "read": kernel_ratio, "passes": kernel_ratio < 1,
                                  "value": "report:kernel_time.vertex_frame/in_cache.fastest_motor_over_fastest_matrix",
                                  "over": None},
                                 {"label": "bytes", "read": bytes_ratio, "passes": True,
                                  "value": "report:bytes_per_vertex.motor", "over": None}]}
        old = report(10.0, 50.0, "reproduced")
        new = report(10.0, 50.0, "reproduced")
        old["claims.json"]["claims"].append(claim(0.95, 0.75))
        new["claims.json"]["claims"].append(claim(1.56, 0.75))
        self.assertEqual(diff(old, new), (0, ""))
        new["claims.json"]["claims"][-1] = claim(1.56, 0.8)
        rc, out = diff(old, new)
        self.assertEqual(rc, 1)
        self.assertIn("claims[cpu_vertex_frame_vs_strongest].evidence[bytes].read: 0.75 -> 0.8", out)

    def test_reordered_entries_are_reported(self):
        old = report(10.0, 50.0, "reproduced")
        new = report(10.0, 50.0, "reproduced")
        new["claims.json"]["claims"].reverse()
        rc, out = diff(old, new)
        self.assertEqual(rc, 1)
        self.assertEqual(out.splitlines(), ["claims.json.claims: the entries present in both are in another order"])


if __name__ == "__main__":
    unittest.main()
