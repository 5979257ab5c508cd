"""The scope ladder (report.json's and claims.json's "scopeLadder") recomputed from report.json's
"figures" and "pipelineFamilies" alone, and the answer block's ops and ISA lines checked against
it. Each cell is motor / baseline per sample (a figure pair per ISA family; the CPU kernel cells
are the kernel_time ratio figures of the two working sets); occupancy is a cost, baseline waves /
motor waves; the strongest baseline is, per sample, the cheapest matrix-family pipeline (the one
with the most waves for occupancy). A cell is "as cheap" when every ratio is at most 1.1,
"dearer" when none is, "split" otherwise. Every cell the answer lines quote (claims.json
answer.lines[*].cells) is the ladder's cell of the same stage, measure and baseline, and the
line's text and claims.md's answer table print it. MB_RESULTS_DIR checks another results folder.
"""
import json
import os
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RESULTS = os.environ.get("MB_RESULTS_DIR", os.path.join(REPO, "results"))
LIMIT = 1.10
WORLD, CLIP, WHOLE = "transform to world", "transform to clip", "whole vertex shader"
# measure -> {stage: figure pattern}; {p} the pipeline, {f} the ISA family.
PATTERNS = {
    "counted ops": {WORLD: "ops_per_vertex.rigid.counted.{p}", CLIP: "ops_per_vertex.to_clip.counted.{p}"},
    "SPIR-V probe": {WORLD: "ops_per_vertex.rigid.spirv_probe.{p}", CLIP: "ops_per_vertex.to_clip.spirv_probe.{p}"},
    "SPIR-V whole shader": {WHOLE: "ops_per_vertex.rigid.spirv_whole_shader.{p}"},
    "ISA instructions": {WHOLE: "isa.instructions.rigid.{f}.{p}"},
    "ISA inverse throughput": {WHOLE: "isa.inverse_throughput.rigid.{f}.{p}"},
    "VGPRs": {WHOLE: "isa.vgprs.rigid.{f}.{p}"},
    "occupancy": {WHOLE: "isa.waves.rigid.{f}.{p}"},
}
CPU_RATIO = {"paper": "shim_motor_over_shim_matrix", "strongest": "fastest_motor_over_fastest_matrix"}


def load(name):
    with open(os.path.join(RESULTS, name), encoding="utf-8") as f:
        return f.read() if name.endswith(".md") else json.load(f)


def g3(v):
    return "%.3g" % v


class LadderRecomputed(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.report = load("report.json")
        cls.claims = load("claims.json")
        cls.claims_md = load("claims.md")
        for name, j in (("report.json", cls.report), ("claims.json", cls.claims)):
            if "scopeLadder" not in j:
                raise AssertionError(name + " predates the scope ladder: regenerate results/ (scripts/reproduce.sh)")
        cls.figures = cls.report["figures"]
        cls.matrix_family = sorted(p for p, fam in cls.report["pipelineFamilies"].items() if fam == "matrix")
        head, tail = "isa.instructions.rigid.", ".motor"
        cls.families = sorted(n[len(head):-len(tail)] for n in cls.figures if n.startswith(head) and n.endswith(tail))
        cls.ladder = {(c["stage"], c["measure"], c["baseline"]): c for c in cls.report["scopeLadder"]}

    def value(self, name):
        """The figure's value, or None (absent, not measured, disturbed)."""
        f = self.figures.get(name)
        if f is None or not isinstance(f.get("value"), (int, float)):
            return None
        d = f.get("disturbed")
        return None if isinstance(d, dict) and d.get("disturbed") else f["value"]

    def expected_ratios(self, stage, measure, baseline):
        """[(ratio, baseline side, side's value)] of the measured samples, recomputed."""
        out = []
        if measure == "CPU kernel":
            for working_set in ("in_cache", "out_of_cache"):
                r = self.value("kernel_time.vertex_frame/%s.%s" % (working_set, CPU_RATIO[baseline]))
                if r is not None:
                    out.append((r, None, None))
            return out
        pattern = PATTERNS[measure][stage]
        for fam in self.families if "{f}" in pattern else [""]:
            name = lambda p: pattern.replace("{p}", p).replace("{f}", fam)
            motor = self.value(name("motor"))
            if baseline == "paper":
                sides = {"matrix": self.value(name("matrix"))}
            else:
                sides = {p: self.value(name(p)) for p in self.matrix_family}
            sides = {p: v for p, v in sides.items() if v is not None}
            if not sides:
                continue
            # the strongest: fewest ops / instructions / cycles / VGPRs, most waves
            best = (max if measure == "occupancy" else min)(sides.values())
            if not motor or not best:
                continue
            out.append((best / motor if measure == "occupancy" else motor / best, sides, best))
        return out

    def test_the_ladder_has_every_stage_and_measure_that_reaches_it(self):
        want = set()
        for baseline in ("paper", "strongest"):
            want.add((WORLD, "CPU kernel", baseline))
            for measure, stages in PATTERNS.items():
                want |= {(stage, measure, baseline) for stage in stages}
        self.assertEqual(set(self.ladder), want)
        for (stage, _, baseline), c in self.ladder.items():
            self.assertEqual(c["paperScope"], stage == WORLD and baseline == "paper")
        self.assertTrue(self.families, "report.json has no ISA figures")

    def test_every_cell_recomputed_from_the_figures(self):
        for key, c in self.ladder.items():
            got = self.expected_ratios(*key)
            ratios = [r for r, _, _ in got]
            self.assertEqual(len(c["ratios"]), len(ratios), key)
            for a, b in zip(c["ratios"], ratios):
                self.assertAlmostEqual(a, b, places=12, msg=key)
            self.assertEqual(c["n"], len(ratios), key)
            for side, (_, sides, best) in zip(c["baselineSides"], got):
                if sides is not None:  # the side named is a matrix-family pipeline with the best value
                    self.assertEqual(sides.get(side), best, (key, side))
            if not ratios:
                self.assertEqual((c["verdict"], c["text"]), ("-", "-"), key)
                continue
            worst, best = max(ratios), min(ratios)
            verdict = "as cheap" if worst <= LIMIT else "dearer" if best > LIMIT else "split"
            text = g3(worst) + "x" if worst == best else g3(best) + ".." + g3(worst) + "x"
            self.assertEqual((c["verdict"], c["text"]), (verdict, text), key)
            self.assertAlmostEqual(c["worst"], worst, places=12)
            self.assertAlmostEqual(c["best"], best, places=12)

    def test_claims_prints_the_report_s_ladder(self):
        self.assertEqual(self.claims["scopeLadder"], self.report["scopeLadder"])

    def test_the_answer_s_ops_and_isa_cells_are_ladder_cells(self):
        lines = {line["evidence"]: line for line in self.claims["answer"]["lines"]}
        wanted = {"ops counted and SPIR-V": {(s, m, "paper") for s in (WORLD, CLIP) for m in ("counted ops", "SPIR-V probe")},
                  "AMD ISA per family": {(WHOLE, m, "paper") for m in ("ISA instructions", "ISA inverse throughput",
                                                                        "occupancy")}}
        for evidence, cells in wanted.items():
            line = lines[evidence]
            quoted = {(c["stage"], c["measure"], c["baseline"]): c for c in line["cells"]}
            measured = {k for k in cells if self.ladder[k]["verdict"] != "-"}
            self.assertEqual(set(quoted), measured, evidence)
            for key, c in quoted.items():
                ladder = self.ladder[key]
                self.assertEqual((c["text"], c["verdict"]), (ladder["text"], ladder["verdict"]), key)
                self.assertIn(c["text"] + " " + c["verdict"], line["text"], key)
            row = next(r for r in self.claims_md.splitlines() if r.startswith("| [" + evidence + "]"))
            for c in quoted.values():
                self.assertIn(c["text"] + " " + c["verdict"], row, evidence)
        # The other lines quote no ladder cell.
        for evidence, line in lines.items():
            if evidence not in wanted:
                self.assertEqual(line["cells"], [], evidence)

    def test_claims_rows_on_ladder_figures_read_the_ladder_s_ratios(self):
        # (motor figure, baseline figure or None) -> the ratio the ladder took from it
        sample_ratio = {}
        for c in self.report["scopeLadder"]:
            measured = [s for s in c["samples"] if self.value(s["motor"]) is not None and
                        (s["baseline"] is None or self.value(s["baseline"]) is not None)]
            self.assertEqual(len(measured), len(c["ratios"]), (c["stage"], c["measure"], c["baseline"]))
            for s, r in zip(measured, c["ratios"]):
                sample_ratio[(s["motor"], s["baseline"])] = r
        strip = lambda ref: ref[len("report:"):] if ref and ref.startswith("report:") else None
        read = 0
        for row in self.claims["claims"]:
            for e in row["evidence"]:
                key = (strip(e["value"]), strip(e["over"]))
                if key in sample_ratio and e["leftOut"] is None:
                    read += 1
                    self.assertEqual(e["read"], sample_ratio[key], (row["id"], e["label"]))
        self.assertGreater(read, 10)
        # The paper's sentence: the row's verdict is the ladder's first row (to world, the 4x4).
        cells = [self.ladder[(WORLD, m, "paper")]["verdict"] for m in ("counted ops", "SPIR-V probe", "CPU kernel")]
        cells = [v for v in cells if v != "-"]
        want = ("reproduced" if all(v == "as cheap" for v in cells) else
                "differs" if all(v == "dearer" for v in cells) else "inconclusive")
        row = next(r for r in self.claims["claims"] if r["id"] == "as_fast_as_matrices")
        self.assertEqual(row["verdict"], want, (cells, row["verdictText"]))


if __name__ == "__main__":
    unittest.main()
