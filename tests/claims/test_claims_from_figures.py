"""`motorbench claims` is a function of a run's JSON files: run on the results folder's source
files (with MB_GL_BACKEND=none, so that a GL context would fail it), it writes claims.json and
claims.md byte for byte as committed, and again when every source but report.json is cut down to
its "figures" object. Changing one figure of report.json changes exactly the rows whose
evidence references that figure, and no other row (a figure a paper row reads, one only
baselines read, one no row reads). Without report.json it fails naming the command that writes
it; without ops.json the rows that read ops figures are not measurable and stderr names
`motorbench ops --json`.

The committed files are read from MB_RESULTS_DIR (default results/); the runs use the same
--results argument as the committed claims.json names (its "sources"), in a scratch folder with
the same relative layout, so that claims.md's link to report.md is the same.
"""
import copy
import json
import os
import shutil
import subprocess
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RESULTS = os.environ.get("MB_RESULTS_DIR", os.path.join(REPO, "results"))
EXE = os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench"))
COLUMNS = ("mul", "add", "div", "sqrt", "other")
COLUMN_KINDS = {"paper_columns", "paper_columns_or_listing", "paper_columns_undefined"}


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def references(row):
    """Every figure reference the row's declared evidence reads."""
    out = set()
    for e in row["evidence"]:
        if row["rule"]["kind"] in COLUMN_KINDS:
            out |= {e["value"] + "." + c for c in COLUMNS}
        else:
            out |= {e["value"]} | ({e["over"]} if e["over"] else set())
    return out


def start(cwd, results, out, extra=()):
    """A claims run on `results` (relative to `cwd`) writing out/claims.{md,json}."""
    env = dict(os.environ, MB_GL_BACKEND="none")
    cmd = [EXE, "claims", "--results", results, "-o", os.path.join(out, "claims.md"),
           "--json", os.path.join(out, "claims.json"), *extra]
    return subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def finish(proc):
    out, err = proc.communicate(timeout=120)
    return proc.returncode, out + err


class ClaimsFromFigures(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.committed = load(os.path.join(RESULTS, "claims.json"))
        if not all("rule" in row for row in cls.committed["claims"]):
            raise AssertionError("claims.json predates the declared table: regenerate results/ (scripts/reproduce.sh)")
        sources = cls.committed["sources"]
        cls.arg = os.path.dirname(sources["report"])  # --results as the committed run gave it
        # source -> its path under the results folder ("ops.json", "corpus/report.json")
        cls.files = {s: os.path.relpath(p, cls.arg) for s, p in sources.items() if "; made by " not in p}
        cls.tmp = tempfile.mkdtemp(prefix="mb_claims_figures_")
        # Every source cut down to its "figures" object, written once.
        cls.stripped = {}
        for source, rel in cls.files.items():
            cls.stripped[source] = os.path.join(cls.tmp, "stripped", rel)
            os.makedirs(os.path.dirname(cls.stripped[source]), exist_ok=True)
            with open(cls.stripped[source], "w", encoding="utf-8") as f:
                json.dump({"figures": load(os.path.join(RESULTS, rel))["figures"]}, f)
        real = {s: os.path.abspath(os.path.join(RESULTS, rel)) for s, rel in cls.files.items()}
        cls.runs = {
            "as_committed": cls.layout("as_committed", real),
            # report.json whole (the answer block and the scope ladder read more than its figures)
            "figures_only": cls.layout("figures_only", dict(cls.stripped, report=real["report"])),
            "no_ops": cls.layout("no_ops", {s: p for s, p in cls.stripped.items() if s != "ops"}),
        }
        # One figure of report.json changed at a time, on the figures alone: the rows must read
        # nothing else of it.
        cls.report = load(os.path.join(RESULTS, cls.files["report"]))
        cls.changed = cls.pick_figures()
        base = cls.layout("stripped_sources", cls.stripped, run=False)
        for what, name in cls.changed.items():
            figures = copy.deepcopy(cls.report["figures"])
            figures[name]["value"] = figures[name]["value"] * 2 + 1
            out = os.path.join(cls.tmp, "changed_" + what)
            os.makedirs(out)
            with open(os.path.join(out, "report.json"), "w", encoding="utf-8") as fh:
                json.dump({"figures": figures}, fh)
            cls.runs["changed_" + what] = (out, start(cls.tmp, base, out, ["--report", os.path.join(out, "report.json")]))
        cls.done = {k: (out, *finish(p)) for k, (out, p) in cls.runs.items()}

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @classmethod
    def layout(cls, name, files, run=True):
        """tmp/name/<arg>: the results folder's layout with each source linked to `files`[source]
        (a source not there is absent), and a claims run on it from tmp/name."""
        root = os.path.join(cls.tmp, name)
        folder = os.path.join(root, cls.arg)
        os.makedirs(folder, exist_ok=True)
        for source, path in files.items():
            dst = os.path.join(folder, cls.files[source])
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            os.symlink(path, dst)
        return folder if not run else (folder, start(root, cls.arg, folder))

    @classmethod
    def pick_figures(cls):
        """report.json figures with a value: the one most rows read among those a paper row
        reads, one only baseline rows read, and one no row reads."""
        readers = {}
        for row in cls.committed["claims"]:
            for ref in references(row):
                if ref.startswith("report:"):
                    readers.setdefault(ref[len("report:"):], []).append(row)
        valued = {n for n, f in cls.report["figures"].items() if isinstance(f.get("value"), (int, float))}
        paper = sorted((n for n in readers if n in valued and any(r["origin"] == "paper" for r in readers[n])),
                       key=lambda n: (-len(readers[n]), n))
        baseline = sorted(n for n in readers if n in valued and all(r["rule"]["kind"] == "baseline" for r in readers[n]))
        unread = sorted(valued - set(readers))
        assert paper and baseline and unread, (len(paper), len(baseline), len(unread))
        return {"paper": paper[0], "baseline": baseline[0], "unread": unread[0]}

    def result(self, name):
        out, rc, log = self.done[name]
        self.assertEqual(rc, 0, log)
        with open(os.path.join(out, "claims.json"), "rb") as f:
            raw_json = f.read()
        with open(os.path.join(out, "claims.md"), "rb") as f:
            raw_md = f.read()
        return raw_json, raw_md, log

    def test_claims_rewrites_the_committed_files_byte_for_byte(self):
        self.assertFalse(os.path.isabs(self.arg), "the committed claims.json was run with --results " + self.arg +
                         ": regenerate it with scripts/reproduce.sh (--results results)")
        with open(os.path.join(RESULTS, "claims.json"), "rb") as f:
            committed_json = f.read()
        with open(os.path.join(RESULTS, "claims.md"), "rb") as f:
            committed_md = f.read()
        for run in ("as_committed", "figures_only"):
            raw_json, raw_md, _ = self.result(run)
            self.assertTrue(raw_json == committed_json, run + ": claims.json differs from the committed one")
            self.assertTrue(raw_md == committed_md, run + ": claims.md differs from the committed one")

    def test_one_changed_figure_changes_exactly_the_rows_that_read_it(self):
        before = {row["id"]: row for row in json.loads(self.result("figures_only")[0])["claims"]}
        for what, name in self.changed.items():
            after = {row["id"]: row for row in json.loads(self.result("changed_" + what)[0])["claims"]}
            self.assertEqual(set(after), set(before), what)
            ref = "report:" + name
            readers = {i for i, row in before.items() if ref in references(row)}
            changed = {i for i in before if after[i] != before[i]}
            self.assertEqual(changed, readers, (what, name))
            self.assertEqual(bool(readers), what != "unread", (what, name))
            for i in readers:  # the evidence that reads it read the new value (or quotes it, left out)
                for e0, e1 in zip(before[i]["evidence"], after[i]["evidence"]):
                    quoted = {q["reference"] for q in e0["figures"]}
                    if ref in quoted and e0["leftOut"] is None:
                        self.assertNotEqual(e1["read"], e0["read"], (what, i, e0["label"]))
                    elif ref in quoted:
                        self.assertNotEqual(e1["figures"], e0["figures"], (what, i, e0["label"]))

    def test_without_report_json_it_names_the_command_that_writes_it(self):
        empty = os.path.join(self.tmp, "empty")
        os.makedirs(empty)
        rc, log = finish(start(self.tmp, empty, empty))
        self.assertNotEqual(rc, 0, log)
        self.assertIn("report.json", log)
        self.assertIn("motorbench report -o DIR", log)
        self.assertEqual(os.listdir(empty), [], "claims wrote files without its inputs")

    def test_without_ops_json_the_ops_rows_are_not_measurable(self):
        raw_json, _, log = self.result("no_ops")
        self.assertIn("motorbench ops --json", log)
        claims = json.loads(raw_json)
        self.assertIn("motorbench ops --json", claims["sources"]["ops"])
        only_ops = 0
        for row in claims["claims"]:
            refs = references(row)
            for e in row["evidence"]:
                if e["value"].startswith("ops:") or (e["over"] or "").startswith("ops:"):
                    self.assertIn("motorbench ops --json", e["leftOut"] or "", (row["id"], e["label"]))
            if refs and all(r.startswith("ops:") for r in refs):
                only_ops += 1
                self.assertEqual(row["verdict"], "not measurable here", row["id"])
        self.assertGreater(only_ops, 10)  # the op-count rows


if __name__ == "__main__":
    unittest.main()
