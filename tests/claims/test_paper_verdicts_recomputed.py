"""Every verdict in claims.json, the paper's rows and our own, recomputed from the row's declared
rule (claims.json's "rule" and "evidence") and the run's source JSON files alone, never by calling
motorbench: each evidence reference "<source>:<name>" is looked up in the file claims.json's
"sources" names for that source (read relative to the results folder) as that file's
["figures"][name]; the value claims.json says it read must be that figure's (a ratio: value /
over), the evidence left out exactly when the figure is missing, not measured, disturbed, from too
few samples (n < minN) or, under the GPU rule, timed on a CPU rasterizer; then the rule kinds are
applied here (the paper's columns, ours or the printed listing, an undefined expansion, at most /
at least, a baseline) and combined (every kind passes: reproduced, none: differs, some:
inconclusive; none left: not measurable here). A rule kind this file does not know fails the test
until it is recomputed here. MB_RESULTS_DIR checks another results folder (a scratch
`motorbench claims --results DIR` run).
"""
import json
import os
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RESULTS = os.environ.get("MB_RESULTS_DIR", os.path.join(REPO, "results"))
COLUMNS = ("mul", "add", "div", "sqrt", "other")
COLUMN_KINDS = {"paper_columns", "paper_columns_or_listing", "paper_columns_undefined"}
KINDS = COLUMN_KINDS | {"at_most", "at_least", "baseline"}
VERDICTS = {"reproduced", "differs", "inconclusive", "not measurable here", "baseline"}


def load_sources(claims):
    """{source: its "figures" object, or None when claims.json names the file as missing}."""
    sources = claims["sources"]
    # The results folder as the claims run named it: the folder of its report.json.
    base = os.path.dirname(sources["report"])
    out = {}
    for source, path in sources.items():
        if "; made by " in path:  # "<path>: not found; made by motorbench ..."
            out[source] = None
            continue
        with open(os.path.join(RESULTS, os.path.relpath(path, base)), encoding="utf-8") as f:
            out[source] = json.load(f)["figures"]
    return out


class Reading:
    """One evidence as recomputed here: what it read, whether it passes, why it is left out."""

    def __init__(self):
        self.read = None
        self.passes = None
        self.left_out = None  # "missing", "not measured", "disturbed", "cpu rasterizer", "few", "zero"
        self.reference = None  # the figure it was left out for


def why_left_out(figure, rule):
    if figure is None:
        return "missing"
    if figure.get("value") is None:
        return "not measured"
    disturbed = figure.get("disturbed")
    if isinstance(disturbed, dict) and disturbed.get("disturbed"):
        return "disturbed"
    if rule["gpuTimed"] and "CPU rasterizer" in figure.get("device", ""):
        return "cpu rasterizer"
    n = figure.get("n", 0)
    if rule["minN"] > 0 and 0 < n < rule["minN"]:
        return "few"
    return None


class VerdictsRecomputed(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(os.path.join(RESULTS, "claims.json"), encoding="utf-8") as f:
            cls.claims = json.load(f)
        cls.rows = cls.claims["claims"]
        if not all("rule" in row for row in cls.rows):
            raise AssertionError("claims.json predates the declared table (no \"rule\"): regenerate results/ "
                                 "(scripts/reproduce.sh)")
        cls.figures = load_sources(cls.claims)

    def figure(self, reference):
        source, name = reference.split(":", 1)
        self.assertIn(source, self.figures, reference)
        figures = self.figures[source]
        return None if figures is None else figures.get(name)

    def read_one(self, reading, reference, rule):
        """The figure's value, or None with reading.left_out set."""
        f = self.figure(reference)
        why = why_left_out(f, rule)
        if why:
            reading.left_out, reading.reference = why, reference
            return None
        return f["value"]

    def recompute(self, row, evidence):
        rule, r = row["rule"], Reading()
        kind = rule["kind"]
        if kind in COLUMN_KINDS:
            paper = row["paperValue"]
            read = {}
            for c in COLUMNS:
                reference = evidence["value"] + "." + c
                if self.figure(reference) is None and c not in paper:
                    continue  # an unstated column may be absent
                v = self.read_one(r, reference, rule)
                if r.left_out:
                    return r
                read[c] = v
            r.read = read
            r.passes = all(read[c] == v for c, v in paper.items())
            return r
        a = self.read_one(r, evidence["value"], rule)
        if r.left_out:
            return r
        if evidence["over"] is None:
            r.read = a
        else:
            b = self.read_one(r, evidence["over"], rule)
            if r.left_out:
                return r
            if b == 0:
                r.left_out, r.reference = "zero", evidence["over"]
                return r
            r.read = a / b
        if kind == "at_most":
            r.passes = r.read <= rule["limit"]
        elif kind == "at_least":
            r.passes = r.read >= rule["limit"]
        return r

    def readings(self, row):
        return [self.recompute(row, e) for e in row["evidence"]]

    def test_every_rule_kind_is_recomputed_here(self):
        kinds = {row["rule"]["kind"] for row in self.rows}
        self.assertEqual(kinds - KINDS, set(), "a rule kind this test does not recompute: add it here")
        self.assertEqual({row["verdict"] for row in self.rows} - VERDICTS, set())

    def test_the_sources_are_files_of_the_results_folder(self):
        for source, path in self.claims["sources"].items():
            self.assertTrue(self.figures[source] is not None or "; made by motorbench " in path, (source, path))
        self.assertIsNotNone(self.figures["report"])

    def test_every_figure_claims_quotes_is_its_source_s(self):
        for row in self.rows:
            for e in row["evidence"]:
                for quoted in e["figures"]:
                    f = self.figure(quoted["reference"])
                    self.assertIsNotNone(f, (row["id"], quoted["reference"]))
                    # A key the figure lacks reads as its default (an older room's JSON has no "kind").
                    for key, default in (("value", None), ("n", 0), ("device", ""), ("statistic", ""), ("scope", ""),
                                         ("kind", "")):
                        if key in quoted:
                            self.assertEqual(quoted[key], f.get(key, default), (row["id"], quoted["reference"], key))

    def test_every_evidence_reads_what_its_figures_give(self):
        for row in self.rows:
            baseline = row["rule"]["kind"] == "baseline"
            for e, r in zip(row["evidence"], self.readings(row)):
                where = (row["id"], e["label"])
                self.assertEqual(e["leftOut"] is not None, r.left_out is not None, (where, e["leftOut"], r.left_out))
                if r.left_out:
                    self.assertIsNone(e["read"], where)
                    self.assertIsNone(e["passes"], where)
                    continue
                # Columns as {column: count}; a ratio is the same double division on both sides.
                self.assertEqual(e["read"], r.read, where)
                self.assertEqual(e["passes"], None if baseline else r.passes, where)

    def test_left_out_evidence_names_its_figure_and_why(self):
        words = {"missing": "no figure {ref}", "not measured": "{ref} not measured", "disturbed": "{ref} disturbed",
                 "cpu rasterizer": "{ref} was timed on a CPU rasterizer", "few": "{ref}: n = ", "zero": "{ref} is 0"}
        seen = 0
        for row in self.rows:
            for e, r in zip(row["evidence"], self.readings(row)):
                if not r.left_out:
                    continue
                seen += 1
                self.assertIsNotNone(e["leftOut"], (row["id"], e["label"], r.left_out))
                self.assertIn(words[r.left_out].format(ref=r.reference), e["leftOut"], (row["id"], e["label"]))
                if r.left_out == "few":
                    self.assertIn("< %d" % row["rule"]["minN"], e["leftOut"])
                self.assertIn(e["label"] + ": " + e["leftOut"], row["verdictText"], row["id"])
        # results/ is timed on a CPU rasterizer: the GPU-only frame-time rows leave their evidence out.
        self.assertGreater(seen, 0, "no evidence left out: the GPU rule and the missing-figure path are untested here")

    def test_every_verdict_follows_its_rule(self):
        for row in self.rows:
            kind = row["rule"]["kind"]
            rs = self.readings(row)
            judged = [r for r in rs if not r.left_out]
            if not judged:
                want = "not measurable here"
            elif kind == "baseline":
                want = "baseline"
            elif kind == "paper_columns_or_listing":
                # Either ours (the first evidence) or the paper's printed listing (the second).
                either = any(not r.left_out and r.passes for r in rs[:2])
                want = "reproduced" if either else "differs"
            else:
                passed = sum(1 for r in judged if r.passes)
                if passed == len(judged):
                    want = "reproduced"
                elif passed == 0:
                    want = "inconclusive" if kind == "paper_columns_undefined" else "differs"
                else:
                    want = "inconclusive"
            self.assertEqual(row["verdict"], want, (row["id"], row["verdictText"]))

    def test_the_tally_counts_every_row_once(self):
        counts, seen = {v: 0 for v in VERDICTS}, set()
        paper = {v: 0 for v in VERDICTS}
        for row in self.rows:
            if row["tallyAs"] in seen:  # a table row printed as a pair (gp_rt / gp_tr) counts once
                continue
            seen.add(row["tallyAs"])
            counts[row["verdict"]] += 1
            if row["origin"] == "paper":
                paper[row["verdict"]] += 1
        self.assertEqual(self.claims["counts"], counts)
        self.assertEqual(self.claims["paperCounts"], paper)


if __name__ == "__main__":
    unittest.main()
