"""report.json's figures against the scenes they come from, recomputed
here from results/report.json's own per-scene numbers: one statistic for a frame-time ratio (the
median over scenes of each scene's median of per-frame paired ratios, not a ratio of medians and
not the upper of two middle values), and the compact pipelines' image figures from the frames that
draw their own vertex format only (the teapot draws patches), each frame against its own reference
(a skinned frame of another skinning method than the baseline's against that method's). A report.json older than the figures
layer fails the test: regenerate results/ (scripts/reproduce.sh).
"""
import json
import os
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def median(values):
    v = sorted(values)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


class ReportFiguresRecomputed(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # MB_REPORT_JSON: check another report.json (e.g. a fresh `motorbench report` run).
        path = os.environ.get("MB_REPORT_JSON", os.path.join(REPO, "results", "report.json"))
        with open(path, encoding="utf-8") as f:
            cls.report = json.load(f)
        cls.euclidean = [s for s in cls.report["scenes"] if s.get("space", "Euclidean") == "Euclidean"]

    def figure(self, name):
        figures = self.report.get("figures")
        self.assertIsNotNone(figures, "results/report.json predates the figures layer: regenerate results/")
        self.assertIn(name, figures)
        return figures[name]

    def test_frame_time_is_the_median_of_paired_ratios(self):
        paired = [s["timing"]["paired_ratio_motor_matrix"] for s in self.euclidean
                  if (s.get("timing") or {}).get("paired_ratio_motor_matrix") is not None]
        f = self.figure("frame_time.motor_over_matrix")
        self.assertEqual(f["n"], len(paired))
        self.assertAlmostEqual(f["value"], median(paired), places=12)
        self.assertIn("paired", f["statistic"])
        self.assertAlmostEqual(self.report["summary"]["frameTimeRatio"]["median"], median(paired), places=12)

    def test_frame_time_range_is_over_the_same_scenes(self):
        # The range printed beside the median is over the scenes it is taken over, not over the
        # other pipelines' frame_time.<p>_over_matrix figures (matrix_over_matrix is 1 by
        # definition). Both committed reports: results/ and results/corpus/.
        reports = [self.report]
        corpus = os.path.join(REPO, "results", "corpus", "report.json")
        if "MB_REPORT_JSON" not in os.environ and os.path.exists(corpus):
            with open(corpus, encoding="utf-8") as f:
                reports.append(json.load(f))
        for r in reports:
            paired = [s["timing"]["paired_ratio_motor_matrix"] for s in r["scenes"]
                      if s.get("space", "Euclidean") == "Euclidean"
                      and (s.get("timing") or {}).get("paired_ratio_motor_matrix") is not None]
            self.assertAlmostEqual(r["summary"]["frameTimeRatio"]["min"], min(paired), places=12)
            self.assertAlmostEqual(r["summary"]["frameTimeRatio"]["max"], max(paired), places=12)

    def test_every_pipeline_ratio_is_a_true_median(self):
        for p in self.report["settings"]["pipelines"][1:]:
            per_scene = [s["timing"]["pipelines"][p]["pairedRatioToMatrix"]["median"] for s in self.euclidean
                         if "pairedRatioToMatrix" in ((s.get("timing") or {}).get("pipelines") or {}).get(p, {})]
            if not per_scene:
                continue
            f = self.figure("frame_time.%s_over_matrix" % p)
            self.assertAlmostEqual(f["value"], median(per_scene), places=12, msg=p)
            self.assertEqual(f["n"], len(per_scene), p)

    def test_compact_images_come_from_their_own_vertex_format(self):
        base = self.report["settings"]["pipelines"][0]
        for p in ("matrix_c", "motor_c", "motor_cf", "motor_q"):
            if p not in self.report["settings"]["pipelines"]:
                continue
            psnr, over1 = [], []
            for s in self.report["scenes"]:
                ps = s.get("pipelines") or {}
                if not ((ps.get(p) or {}).get("memory") or {}).get("bytesPerVertex"):
                    continue  # no mesh vertex of its own drawn (the teapot's patches)
                skinned = (s.get("vertexMix") or {}).get("skinned", 0) > 0
                blends = {(ps.get(q) or {}).get("skinBlend", "") for q in (p, base)}
                methods_differ = skinned and "" not in blends and len(blends) == 2
                for fr in s.get("frames", []):
                    m = (fr.get("metrics") or {}).get(p)
                    if m is None:
                        continue
                    # A skinned frame of another skinning method than the baseline's is judged
                    # against its own method's reference; one not judged so is counted apart.
                    judgement = (fr.get("skinJudgement") or {}).get(p)
                    if judgement is not None or methods_differ:
                        m = (fr.get("referenceMetrics") or {}).get(p) if (judgement or {}).get("judged") else None
                        if m is None:
                            continue
                    if not m.get("identical") and m.get("psnr") is not None:
                        psnr.append(m["psnr"])
                    if m.get("fractionOver1") is not None:
                        over1.append(m["fractionOver1"])
            got = self.report["summary"]["vertexFormatImages"][p]
            if psnr:
                self.assertAlmostEqual(got["psnr"]["min"], min(psnr), places=9, msg=p)
                # The figure the README's and report's compact tables quote.
                figure = self.figure("image.worst_psnr_own_format.%s" % p)
                self.assertAlmostEqual(figure["value"], min(psnr), places=9, msg=p)
                self.assertEqual(figure["n"], len(psnr), p)
            if over1:
                self.assertAlmostEqual(got["fractionOver1"]["max"], max(over1), places=12, msg=p)


if __name__ == "__main__":
    unittest.main()
