"""README.md, pipelines/compact/README.md, harness/cli/README.md, results/report.md,
results/claims.md and results/curved/README.md quote one value per figure: every value a
document quotes is read back by name (the <span title="NAME">TEXT</span> marks motorbench and
scripts/document_figures.py write, and claims.md's rows by id as claims.<id>), and a name quoted
twice, in one document or in two, must read the same; a figure of report.json (its "figures" and
the morph figures it embeds) must read as report.json's text. claims.md's answer lines must be
report.md's. A column that says SPIR-V says which (probe or whole shader) and quotes only that
one. A copy with one value edited by hand fails (shown below).
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
DOCS = ("README.md", "pipelines/compact/README.md", "harness/cli/README.md", "results/report.md", "results/claims.md",
        "results/curved/README.md")
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
    # claims.md's section tables: | id | origin | claim | ... | measured | ... | verdict |
    for header, cells in table_rows(text):
        column = measured_column(header)
        if column is not None and len(cells) > column:
            out.setdefault("claims." + cells[0], []).append(cells[column])
    return out


def table_rows(text):
    """(header, cells) of every body row of every Markdown table."""
    header = None
    for line in text.splitlines():
        if not line.startswith("|"):
            header = None
            continue
        cells = split_row(line)
        if header is None:
            header = cells
        elif not cells[0].startswith("-") and not set("".join(cells)) <= set("-: "):
            yield header, cells


def measured_column(header):
    """The "measured" column of a claims.md section table (its first columns id, origin), else None."""
    return header.index("measured") if header[:2] == ["id", "origin"] and "measured" in header else None


def spirv_scope_problems(doc, text):
    """Every column whose header says SPIR-V must name its scope (probe or whole shader) and quote
    only figures of that scope (ops_per_vertex.*.spirv_probe.* or *.spirv_whole_shader.*)."""
    problems = []
    for header, cells in table_rows(text):
        for title, cell in zip(header, cells):
            if "SPIR-V" not in title:
                continue
            scopes = [k for k, words in (("spirv_probe", "SPIR-V probe"), ("spirv_whole_shader", "SPIR-V whole shader"))
                      if words in title]
            names = [n for n, _ in SPAN.findall(cell) if ".spirv" in n]
            if len(scopes) != 1 and names:
                problems.append(f"{doc}: column '{title}' quotes SPIR-V figures without one scope: {names}")
            for n in names:
                if scopes and scopes[0] not in n:
                    problems.append(f"{doc}: column '{title}' quotes {n}")
    return problems


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
    figures = dict((report.get("morph") or {}).get("figures") or {})
    figures.update(report.get("figures", {}))
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
    problems = [p for doc in texts for p in spirv_scope_problems(doc, texts[doc])]
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
    # The ops ranking line: report.md prints report.json's line as it is, and claims.md, where it
    # quotes it, too: no start or end of it is left once its exact copies are taken out.
    for label, ranking in sorted((report.get("opsRanking") or {}).items()):
        line = ranking["line"]
        start, end = "op ranking of the " + ranking["scope"] + ": ", line[-40:]
        for doc in ("results/report.md", "results/claims.md"):
            if doc not in texts or (doc == "results/claims.md" and start not in texts[doc]):
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
        header = next(h for h, cells in table_rows(read(claims)) if cells[0] == "curved_floats_per_instance")
        row = next(l for l in read(claims).splitlines(True) if l.startswith("| curved_floats_per_instance |"))
        measured = split_row(row)[measured_column(header)]
        self.edit(claims, row, row.replace(measured, measured.replace("16", "15"), 1))
        self.assertTrue(any(p.startswith("claims.curved_floats_per_instance:") for p in disagreements(tmp)))

    def test_an_edited_ranking_line_fails(self):
        tmp = self.copy()
        with open(os.path.join(tmp, "results", "report.json"), encoding="utf-8") as f:
            ranking = json.load(f).get("opsRanking")
        self.assertIsNotNone(ranking, "results/report.json predates the ops ranking: regenerate results/")
        line = ranking["rigid"]["line"]
        self.edit(os.path.join(tmp, "results", "report.md"), line, line.replace(" pipeline pairs", " pairs", 1))
        self.assertTrue(any(p.startswith("opsRanking.rigid: results/report.md") for p in disagreements(tmp)),
                        disagreements(tmp))

    def test_a_spirv_column_of_the_other_scope_fails(self):
        tmp = self.copy()
        readme = os.path.join(tmp, "README.md")
        self.edit(readme, '<span title="ops_per_vertex.rigid.spirv_probe.motor">',
                  '<span title="ops_per_vertex.rigid.spirv_whole_shader.motor">')
        self.assertTrue(any("quotes ops_per_vertex.rigid.spirv_whole_shader.motor" in p for p in disagreements(tmp)),
                        disagreements(tmp))
        compact = os.path.join(tmp, "pipelines", "compact", "README.md")
        self.edit(compact, "rigid to clip (counted / SPIR-V probe)", "rigid to clip (counted / SPIR-V)")
        self.assertTrue(any("without one scope" in p for p in disagreements(tmp)), disagreements(tmp))

    def test_an_edited_answer_line_fails(self):
        tmp = self.copy()
        claims = os.path.join(tmp, "results", "claims.md")
        self.edit(claims, "inconclusive: a CPU rasterizer cannot discriminate", "motor side faster")
        self.assertIn("claims.md's answer lines differ from report.md's", disagreements(tmp))


if __name__ == "__main__":
    unittest.main()
