"""report.md's layout, re-rendered from the committed report.json files (motorbench merge, no
measuring): the Scenes section is small tables (the scene facts, then one per quantity with the
scenes as rows), none wider than a page's dozen columns; the Summary has a shader variant's rows
only where some scene draws that variant (report.json's per-scene vertexMix).
"""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench"))
REPORTS = ("results", "results/corpus")
MOST_COLUMNS = 12


def tables(section):
    """[(heading, header cells, rows)] of the Markdown tables in `section`."""
    out, heading, lines = [], None, section.splitlines() + [""]
    for i, line in enumerate(lines):
        if line.startswith("### "):
            heading = line[4:]
        if line.startswith("| ") and not lines[i - 1].startswith("|"):
            out.append((heading, [c.strip() for c in line.strip().strip("|").split(" | ")], []))
        elif line.startswith("| "):
            out[-1][2].append(line)
    return out


def section(md, title):
    return md.split("## " + title + "\n", 1)[1].split("\n## ", 1)[0]


class ReportLayout(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = tempfile.mkdtemp(prefix="mb-layout-")
        cls.md, cls.json = {}, {}
        for folder in REPORTS:
            out = os.path.join(cls.scratch, folder.replace("/", "_"))
            subprocess.run([EXE, "merge", os.path.join(REPO, folder), "-o", out, "--no-plots"], check=True,
                           capture_output=True)
            with open(os.path.join(out, "report.md"), encoding="utf-8") as f:
                cls.md[folder] = f.read()
            with open(os.path.join(REPO, folder, "report.json"), encoding="utf-8") as f:
                cls.json[folder] = json.load(f)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.scratch, ignore_errors=True)

    def test_scene_tables_fit_a_page_each_under_its_heading(self):
        for folder in REPORTS:
            found = tables(section(self.md[folder], "Scenes"))
            self.assertGreaterEqual(len(found), 6, folder)
            euclidean = [s for s in self.json[folder]["scenes"] if s.get("space", "Euclidean") == "Euclidean"]
            for heading, head, rows in found:
                self.assertTrue(heading, f"{folder}: a table without its heading")
                self.assertLessEqual(len(head), MOST_COLUMNS, f"{folder}: {heading}")
                self.assertEqual(head[0], "scene", f"{folder}: {heading}")
                if not heading.startswith("Fallbacks"):
                    self.assertEqual(len(rows), len(euclidean), f"{folder}: {heading}: one row per scene")

    def test_the_fallback_table_names_every_pipeline_with_a_fallback_once_per_scene(self):
        for folder in REPORTS:
            found = [t for t in tables(section(self.md[folder], "Scenes")) if t[0].startswith("Fallbacks")]
            self.assertEqual(len(found), 1, folder)
            named = {}  # scene -> pipelines named in its rows
            for line in found[0][2]:
                cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
                if set(cells[0]) <= {"-"}:
                    continue  # the header's separator
                scene = cells[0].split("]")[0].lstrip("[")
                named.setdefault(scene, []).extend(p.strip() for p in cells[1].split(","))
            for s in self.json[folder]["scenes"]:
                if s.get("space", "Euclidean") != "Euclidean":
                    continue
                expected = [p for p, pj in s.get("pipelines", {}).items()
                            if any(isinstance(v, (int, float)) and v != 0 for v in (pj.get("fallbacks") or {}).values())]
                self.assertEqual(sorted(named.get(s["id"], [])), sorted(expected), f"{folder}: {s['id']}")

    def test_summary_has_a_variants_rows_only_where_a_scene_draws_it(self):
        for folder in REPORTS:
            summary = section(self.md[folder], "Summary")
            mix = [s.get("vertexMix") or {} for s in self.json[folder]["scenes"]]
            for label, key in (("bezier patch", "bezierPatch"), ("skinned", "skinned"), ("rigid", "rigid")):
                drawn = any(m.get(key, 0) > 0 for m in mix)
                rows = summary.count(f"| ops per vertex, {label} shader (")
                self.assertEqual(rows, 2 if drawn else 0, f"{folder}: {label}")

    def test_no_summary_row_is_empty_in_every_pipeline(self):
        for folder in REPORTS:
            for line in section(self.md[folder], "Summary").splitlines():
                if line.startswith("| ") and not line.startswith("| quantity"):
                    cells = line.strip()[2:-2].split(" | ")
                    self.assertTrue(any(c != "-" for c in cells[1:]), f"{folder}: {cells[0]}")


if __name__ == "__main__":
    unittest.main()
