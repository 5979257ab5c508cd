"""claims.json against its JSON inputs: the speed row, the tally, the minimum of work and the
scene-graph row (the ops ranking line: test_ops_ranking_recomputed.py) recomputed here from
results/report.json, isa.json and ops.json with the rule the row prints, never by calling
motorbench's own formula. results/ is what
`motorbench claims` wrote from those inputs (scripts/reproduce.sh); a claims.json whose rows
carry no "quote" field fails the test.
"""
import json
import os
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RESULTS = os.path.join(REPO, "results")
TOLERANCE = 0.10  # the rule's "as fast": at most 10 % costlier


def load(name):
    with open(os.path.join(RESULTS, name), encoding="utf-8") as f:
        return json.load(f)


def motor_side(p):
    return p.startswith("motor") or p.startswith("simd_motor") or p.startswith("lanes_motor")


class ClaimsRecomputed(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.claims = load("claims.json")
        cls.report = load("report.json")
        cls.isa = load("isa.json")
        cls.ops = load("ops.json")
        cls.rows = {c["id"]: c for c in cls.claims["claims"]}

    def row(self, cid):
        self.assertIn(cid, self.rows, "no row " + cid)
        return self.rows[cid]

    def test_claims_json_is_of_issue_35(self):
        self.assertTrue(all("quote" in c for c in self.claims["claims"]),
                        "results/claims.json has rows without a quote field: regenerate it with motorbench claims")

    # Speed: the paper's row is the rigid vertex with its frame, motor against the 4x4 matrix.
    def isa_ratio(self, program, stat):
        per_family = {}
        for s in self.isa["shaders"]:
            if s["stage"] != "vertex" or s["program"] not in (program, program + "_normalmap"):
                continue
            fam = s["family"] + (" (NGG)" if s.get("ngg") else "")
            slot = per_family.setdefault(fam, {})
            # the normal-mapped form wins where the family has one
            if s["program"] == program + "_normalmap" or s["pipeline"] not in slot:
                slot[s["pipeline"]] = s
        ratios = []
        for fam, by in per_family.items():
            if "motor" in by and "matrix" in by:
                m, x = by["motor"], by["matrix"]
                ratios.append(x["wavesPerSimd"] / m["wavesPerSimd"] if stat == "waves"
                              else m["instructions"] / x["instructions"])
        return max(ratios)

    def ops_ratio(self, figure, source):
        per = {r["pipeline"]: r for r in self.ops["per_pipeline"]}
        return per["motor"][figure][source]["total"] / per["matrix"][figure][source]["total"]

    def cpu_ratio(self, kernel):
        worst = []
        for p in self.report["kernels"]["pairs"]:
            if p.get("kernel") != kernel:
                continue
            sides = {k: v["items_per_second"] for k, v in p.items()
                     if isinstance(v, dict) and v.get("items_per_second", 0) > 0}
            motor = max(v for k, v in sides.items() if motor_side(k))
            matrix = max(v for k, v in sides.items() if not motor_side(k))
            worst.append(matrix / motor)
        return max(worst)

    def check_scope(self, cid, figure, program, kernel):
        row = self.row(cid)
        kinds = row["measuredValue"]["kinds"]
        expected = {
            "counted": self.ops_ratio(figure, "counted"),
            "SPIR-V (probe)": self.ops_ratio(figure, "spirv"),
            "AMD ISA instructions": self.isa_ratio(program, "instructions"),
            "AMD ISA occupancy": self.isa_ratio(program, "waves"),
            "CPU kernel": self.cpu_ratio(kernel),
        }
        for key, value in expected.items():
            found = [k for k in kinds if key in k]
            self.assertEqual(len(found), 1, key)
            kind = kinds[found[0]]
            if kind["costRatio"] is None:  # a timing taken while other work shared the cores: no ratio, no vote
                self.assertFalse(kind["usable"], key)
                self.assertIn("disturbed", kind.get("caveat", ""), key)
                continue
            self.assertAlmostEqual(kind["costRatio"], value, places=9, msg=key)
        # The verdict by the printed rule over the usable kinds.
        self.assertIn("at most 10 % more", row["measuredValue"]["rule"])
        usable = [k["costRatio"] for k in kinds.values() if k["usable"]]
        agree = [r for r in usable if r <= 1 + TOLERANCE]
        verdict = ("not measurable here" if not usable else "reproduced" if len(agree) == len(usable)
                   else "differs" if not agree else "inconclusive")
        self.assertEqual(row["verdict"], verdict)
        return row

    def test_as_fast_is_judged_on_the_rigid_vertex_against_4x4(self):
        row = self.check_scope("as_fast_as_matrices", "rigid", "rigid", "vertex_frame")
        self.assertIn("just as fast as 4x4 matrices", row["quote"])
        self.assertNotIn("skinned", " ".join(row["measuredValue"]["kinds"]))

    def test_skinned_evidence_is_its_own_row(self):
        row = self.check_scope("as_fast_as_matrices_skinned", "skinned", "skinned", "skinned_vertex")
        self.assertIsNone(row["quote"])
        self.assertTrue(row["origin"].startswith("own"))

    def test_isa_vgprs_are_judged_through_occupancy_and_both_shaders_are_quoted(self):
        for cid, program in (("ops_clip_vs_strongest_isa", "rigid"), ("ops_skinned_vs_strongest_isa", "skinned")):
            v = self.row(cid)["measuredValue"]
            self.assertIn("vgprs", v)
            self.assertIn("occupancyCost", v)

    # The tally recomputed from the rows: a row quoting the paper is the paper's, a pair
    # printed as one table row counts once.
    def test_tally_counts_quoted_rows_once_per_table_row(self):
        paper, own, seen = {}, {}, set()
        for c in self.claims["claims"]:
            key = c["tallyAs"]
            if key in seen:
                continue
            seen.add(key)
            side = paper if c["quote"] else own
            side[c["verdict"]] = side.get(c["verdict"], 0) + 1
        for verdict in ("reproduced", "differs", "inconclusive", "not measurable here", "baseline"):
            self.assertEqual(self.claims["paperCounts"][verdict], paper.get(verdict, 0), verdict)
            self.assertEqual(self.claims["ownCounts"][verdict], own.get(verdict, 0), verdict)
        for cid in ("skinning_volume", "skinning_volume_file", "blend_vs_slerp"):
            self.assertIsNone(self.row(cid)["quote"], cid)
            self.assertTrue(self.row(cid)["origin"].startswith("own"), cid)
        self.assertEqual(self.row("fragment_rotor")["origin"], "paper")
        self.assertEqual(self.row("gp_rt")["tallyAs"], self.row("gp_tr")["tallyAs"])
        for c in self.claims["claims"]:
            self.assertEqual(c["origin"] == "paper", c["quote"] is not None, c["id"])

    # The minimum of work as printed, per timed block (R update calls), over the scenes.
    def test_update_minimum_applies_per_timed_block(self):
        row = self.row("cpu_update_vs_strongest")
        self.assertIn("50 us per timed block", row["method"])
        counted = []
        for s in self.report["scenes"]:
            t = s.get("timing") or {}
            ps = t.get("pipelines") or {}
            if s.get("space", "Euclidean") != "Euclidean" or "matrix" not in ps:
                continue
            blocks = []
            for p in ps.values():
                per_call = p.get("updateMedianMs")
                if not per_call:
                    continue
                r = p.get("updateCallsPerBlock") or min(1000, max(1, -(-0.25 // per_call)))
                blocks.append(per_call * r)
            drawn = (s.get("stats") or {}).get("geometry", {}).get("drawnVertices")
            if min(blocks) >= 0.05 and (drawn is None or drawn >= 1000):
                counted.append(s["id"])
        for sid in counted:
            self.assertNotIn(sid + " (", row["measured"] + row["verdictText"], "counted scene listed as left out")
        self.assertIn("over %d scenes" % len(counted), row["measured"] + row["method"] + row["verdictText"])

    # The scene-graph row times the hierarchy phase; no unconditional "under load".
    def test_scene_graph_update_is_the_hierarchy_phase(self):
        row = self.row("scene_graph_update")
        self.assertNotIn("under load", row["measured"])
        crowd = next(s for s in self.report["scenes"] if s["id"] == "crowd")["timing"]["pipelines"]
        h = {p: v["updatePhasesMedianMs"]["hierarchy"] for p, v in crowd.items()
             if v.get("updatePhasesMedianMs", {}).get("hierarchy")}
        best = min(v for p, v in h.items() if not p.startswith("motor") and p != "hybrid")
        ratio = h["motor"] / best
        ev = row["measuredValue"]["hierarchy phase of Pipeline::update on crowd"]
        self.assertAlmostEqual(ev["costRatio"], ratio, places=9)
        comp = self.row("composition")
        if "bench" in comp["measuredValue"]:
            self.assertNotIn("in-process timing", comp["measured"])
    # The ops ranking line: tests/claims/test_ops_ranking_recomputed.py.


if __name__ == "__main__":
    unittest.main()
