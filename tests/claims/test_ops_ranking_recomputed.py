"""The ops ranking: where counted ops, SPIR-V (probe) ops and AMD ISA instructions order the
pipelines differently, report.md says so in one line, read from report.json's "opsRanking", and
the claims rows ops_ranking_<kind> read the number of pairs ordered both ways as a figure.
Recomputed here from report.json's raw measures (the ops room's variants, the embedded isa JSON)
by sorting the pipelines by each measure and comparing the orders, never with motorbench's own
formula. MB_RESULTS_DIR checks another results folder (a scratch `motorbench report` + `claims`
run); a report.json without "opsRanking" fails.
"""
import json
import os
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RESULTS = os.environ.get("MB_RESULTS_DIR", os.path.join(REPO, "results"))
SCOPES = ("rigid", "skinned")


def load(name):
    with open(os.path.join(RESULTS, name), encoding="utf-8") as f:
        return f.read() if name.endswith(".md") else json.load(f)


def median(values):
    v = sorted(values)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def total(ops):
    return sum(ops.get(k, 0) for k in ("mul", "add", "div", "sqrt", "other")) if ops else 0


def measures(report, label):
    """{measure: {pipeline: value}} from the raw inputs (values > 0: 0 means not joined)."""
    out = {"counted": {}, "spirv_probe": {}, "isa": {}}
    for v in report["opsPerVertex"]["detail"]["variants"]:
        if v["variant"] != label:
            continue
        out["counted"][v["pipeline"]] = total(v["counted"])
        out["spirv_probe"][v["pipeline"]] = total(v.get("spirv_kernel_probes"))
    per = {}
    for s in report.get("isa", {}).get("shaders", []):
        if s["stage"] == "vertex" and s["program"] == label:  # the isa room's program of that variant
            per.setdefault(s["pipeline"], []).append(s["instructions"])
    out["isa"] = {p: median(v) for p, v in per.items()}
    return {m: {p: x for p, x in v.items() if x > 0} for m, v in out.items() if v}


def rank_positions(values):
    """Position in the ascending sort; equal values take the first position of their value."""
    order = sorted(values, key=lambda p: values[p])
    return {p: next(i for i, q in enumerate(order) if values[q] == values[p]) for p in values}


def reversed_pairs(ms, pipelines):
    positions = {m: rank_positions(v) for m, v in ms.items()}
    out = set()
    for i, a in enumerate(pipelines):
        for b in pipelines[i + 1:]:
            signs = {(pos[a] > pos[b]) - (pos[a] < pos[b]) for pos in positions.values() if a in pos and b in pos} - {0}
            if signs == {1, -1}:
                out.add((a, b))
    return out


class OpsRankingRecomputed(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.report = load("report.json")
        cls.claims = {c["id"]: c for c in load("claims.json")["claims"]}
        cls.report_md = load("report.md")

    def ranking(self, label):
        self.assertIn("opsRanking", self.report, "report.json predates the ops ranking: regenerate results/")
        return self.report["opsRanking"][label]

    def test_the_line_says_disagree_exactly_when_the_orders_differ(self):
        for label in SCOPES:
            r = self.ranking(label)
            ms = measures(self.report, label)
            self.assertEqual(len(ms), 3, label)  # results/ has all three measures
            for m, values in ms.items():
                for p, x in values.items():
                    self.assertEqual(r["table"][p][m], x, (label, m, p))
            expected = reversed_pairs(ms, r["pipelines"])
            self.assertEqual({(x["a"], x["b"]) for x in r["reversed"]}, expected, label)
            self.assertEqual("disagree" in r["line"], bool(expected), r["line"])
            for a, b in expected:
                self.assertIn(f"{a} vs {b}:", r["line"])
            figure = self.report["figures"][f"ops_ranking.{label}.pairs_reversed"]
            self.assertEqual(figure["value"], len(expected))

    def test_the_rigid_ranking_shows_the_issue_s_swaps(self):
        # The issue's observation on these shaders: counted puts matrix_c below motor, ISA motor below matrix_c.
        ms = measures(self.report, "rigid")
        self.assertLess(ms["counted"]["matrix_c"], ms["counted"]["motor"])
        self.assertLess(ms["isa"]["motor"], ms["isa"]["matrix_c"])
        self.assertIn(("motor", "matrix_c"), {(x["a"], x["b"]) for x in self.ranking("rigid")["reversed"]})

    def test_report_prints_the_line_and_claims_reads_the_recomputed_count(self):
        for label in SCOPES:
            r = self.ranking(label)
            self.assertIn(r["line"], self.report_md)
            expected = reversed_pairs(measures(self.report, label), r["pipelines"])
            # The claims row is a baseline on report.json's figure, whose value is the count here.
            row = self.claims[f"ops_ranking_{label}"]
            self.assertEqual(row["rule"]["kind"], "baseline")
            [evidence] = row["evidence"]
            self.assertEqual(evidence["value"], f"report:ops_ranking.{label}.pairs_reversed")
            self.assertEqual(evidence["read"], len(expected), label)
            self.assertEqual(row["verdict"], "baseline")

if __name__ == "__main__":
    unittest.main()
