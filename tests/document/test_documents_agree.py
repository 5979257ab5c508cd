"""README.md, pipelines/compact/README.md, results/report.md, results/claims.md and results/curved/README.md quote one value
per figure: every value a document quotes is read back by name (the
<span title="NAME">TEXT</span> marks motorbench and scripts/document_figures.py write, and
claims.md's rows by id as claims.<id>), and a name quoted twice, in one document or in two,
must read the same; a figure of report.json must read as report.json's text. claims.md's
answer lines must be report.md's. A copy with one value edited by hand fails (shown below).
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DOCS = ("README.md", "pipelines/compact/README.md", "results/report.md", "results/claims.md", "results/curved/README.md")
SPAN = re.compile(r'<span title="([^"]+)">([^<]*)</span>')


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def split_row(line):
    """A Markdown table row's cells ("\\|" is a pipe inside a cell)."""
    cells = re.split(r"(?<!\\)\|", line.strip())[1:-1]
    return [c.strip().replace("\\|", "|") for c in cells]


def quoted(text):
    """{name: [value, ...]} of one document."""
    out = {}
    for name, value in SPAN.findall(text):
        out.setdefault(name, []).append(value.replace("\\|", "|"))
    # claims.md's section tables: | id | origin | claim | paper | measured | how | verdict |
    header = None
    for line in text.splitlines():
        if not line.startswith("|"):
            header = None
            continue
        cells = split_row(line)
        if header is None:
            header = cells
            continue
        if header[:5] == ["id", "origin", "claim", "paper", "measured"] and len(cells) >= 5 and not cells[0].startswith("-"):
            out.setdefault("claims." + cells[0], []).append(cells[4])
    return out


def answer_rows(text):
    """The answer table's rows (evidence without its link | figures | verdict)."""
    m = re.search(r"## The answer\n(.*?)(\n## |\Z)", text, re.S)
    if not m:
        return []
    return [re.sub(r"^\[([^\]]*)\]\([^)]*\)", r"\1", cells[0]) + " | " + " | ".join(cells[1:])
            for cells in (split_row(l) for l in m.group(1).splitlines() if l.startswith("| ["))]


def canonical(name, value, figures):
    """A value without its figure's unit ("125 instructions" and "125" quote one figure)."""
    unit = (figures.get(name) or {}).get("unit", "")
    return value[: -len(unit) - 1] if unit and unit != "x" and value.endswith(" " + unit) else value


def disagreements(root):
    """Every name read differently, each with where; [] when the documents agree."""
    with open(os.path.join(root, "results", "report.json"), encoding="utf-8") as f:
        report = json.load(f)
    figures = report.get("figures", {})
    seen = {}  # name -> {canonical value: [document, ...]}
    texts = {}
    for doc in DOCS:
        path = os.path.join(root, doc)
        if not os.path.exists(path):
            continue
        texts[doc] = read(path)
        for name, values in quoted(texts[doc]).items():
            for v in values:
                seen.setdefault(name, {}).setdefault(canonical(name, v, figures), []).append(doc)
    problems = []
    for name, values in sorted(seen.items()):
        fig = figures.get(name)
        if fig and fig.get("value") is not None:
            values = dict(values)
            expected = canonical(name, fig["text"], figures)
            for v, docs in values.items():
                if v != expected:
                    problems.append(f"{name}: {sorted(set(docs))} quote '{v}', report.json '{fig['text']}'")
        elif len(values) > 1:
            problems.append(f"{name}: " + "; ".join(f"'{v}' in {sorted(set(d))}" for v, d in values.items()))
    # The ops ranking line: report.md and claims.md print report.json's line as it
    # is, wherever they print it: no start or end of it is left once its exact copies are taken out.
    for label, ranking in sorted((report.get("opsRanking") or {}).items()):
        line = ranking["line"]
        start, end = "op ranking of the " + ranking["scope"] + ": ", line[-40:]
        for doc in ("results/report.md", "results/claims.md"):
            if doc not in texts:
                continue
            rest = texts[doc].replace(line, "")
            if line not in texts[doc] or start in rest or end in rest:
                problems.append(f"opsRanking.{label}: {doc} does not print report.json's line '{line}'")
    if "results/report.md" in texts and "results/claims.md" in texts:
        if answer_rows(texts["results/claims.md"]) != answer_rows(texts["results/report.md"]):
            problems.append("claims.md's answer lines differ from report.md's")
    return problems


def shared_names(root):
    per_doc = [set(quoted(read(os.path.join(root, d)))) for d in DOCS
               if os.path.exists(os.path.join(root, d))]
    return {n for i, a in enumerate(per_doc) for b in per_doc[i + 1:] for n in a & b}


class DocumentsAgree(unittest.TestCase):
    def copy(self):
        tmp = tempfile.mkdtemp(prefix="mb_docs_")
        self.addCleanup(shutil.rmtree, tmp)
        for rel in DOCS + ("results/report.json", "results/claims.json"):
            src = os.path.join(REPO, rel)
            if os.path.exists(src):
                os.makedirs(os.path.dirname(os.path.join(tmp, rel)), exist_ok=True)
                shutil.copy(src, os.path.join(tmp, rel))
        return tmp

    def edit(self, path, old, new):
        text = read(path)
        self.assertIn(old, text)
        open(path, "w", encoding="utf-8").write(text.replace(old, new, 1))

    def test_the_documents_quote_one_value_per_figure(self):
        self.assertEqual(disagreements(REPO), [])
        # They do share figures: the answer's (report.md, claims.md, README) and the claims' curved rows.
        shared = shared_names(REPO)
        for name in ("bytes_per_vertex.motor", "frame_time.motor_over_matrix", "claims.curved_drift"):
            self.assertIn(name, shared)
        self.assertEqual(len(answer_rows(read(os.path.join(REPO, "results/report.md")))), 5)

    def test_the_generated_tables_are_the_figures(self):
        # scripts/document_figures.py --check: the README's and the curved README's tables are what
        # the figures give now (no hand edit since the last regeneration).
        run = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "document_figures.py"), "--check"],
                             capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)

    def test_a_hand_edited_value_fails(self):
        tmp = self.copy()
        readme = os.path.join(tmp, "README.md")
        self.edit(readme, '<span title="bytes_per_vertex.motor">36 bytes</span>', '<span title="bytes_per_vertex.motor">35 bytes</span>')
        self.assertTrue(any(p.startswith("bytes_per_vertex.motor:") for p in disagreements(tmp)), disagreements(tmp))
        self.assertEqual(subprocess.run([sys.executable, os.path.join(REPO, "scripts", "document_figures.py"), "--check",
                                         "--results", os.path.join(tmp, "results"), "--readme", readme],
                                        capture_output=True).returncode, 1)

    def test_a_hand_edited_claims_row_fails(self):
        tmp = self.copy()
        claims = os.path.join(tmp, "results", "claims.md")
        row = next(l for l in read(claims).splitlines(True) if l.startswith("| curved_floats_per_instance |"))
        measured = split_row(row)[4]
        self.edit(claims, row, row.replace(measured, measured.replace("16", "15"), 1))
        self.assertTrue(any(p.startswith("claims.curved_floats_per_instance:") for p in disagreements(tmp)))

    def test_an_edited_ranking_line_fails(self):
        tmp = self.copy()
        with open(os.path.join(tmp, "results", "report.json"), encoding="utf-8") as f:
            ranking = json.load(f).get("opsRanking")
        self.assertIsNotNone(ranking, "results/report.json predates the ops ranking: regenerate results/")
        line = ranking["rigid"]["line"]
        self.edit(os.path.join(tmp, "results", "claims.md"), line, line.replace(" pipeline pairs", " pairs", 1))
        self.assertTrue(any(p.startswith("opsRanking.rigid: results/claims.md") for p in disagreements(tmp)),
                        disagreements(tmp))

    def test_an_edited_answer_line_fails(self):
        tmp = self.copy()
        claims = os.path.join(tmp, "results", "claims.md")
        self.edit(claims, "inconclusive: a CPU rasterizer cannot discriminate", "motor side faster")
        self.assertIn("claims.md's answer lines differ from report.md's", disagreements(tmp))


if __name__ == "__main__":
    unittest.main()
