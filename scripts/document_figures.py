#!/usr/bin/env python3
"""The figure tables of README.md and pipelines/compact/README.md and results/curved/README.md,
written from the run's figures.

Every value is a figure of report.json ("figures", quoted by name as its "text") or the
"measured" text of a claims.json row (quoted as claims.<id>), never typed by hand. Each value
is written as <span title="NAME">TEXT</span>, as motorbench writes report.md and claims.md, so
tests/document/test_documents_agree.py can read every document's values back by name.

  scripts/document_figures.py [--results DIR] [--readme FILE] [--check]

rewrites the regions of the README (--readme) and of pipelines/compact/README.md between "<!-- figures: TABLE -->" and "<!-- /figures -->" and the
generated part of DIR/curved/README.md; --check writes nothing and exits 1 when a document
differs from what the figures give (a hand edit, or figures regenerated without the documents).
"""
import argparse
import json
import os
import re
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
REGION = re.compile(r"(<!-- figures: ([a-z_]+) -->\n)(.*?)(<!-- /figures -->)", re.S)
ISA_FAMILIES = ("polaris10", "gfx1100")


def quote(name, text):
    text = text.replace("|", "\\|")  # inside a table cell
    return f'<span title="{name}">{text}</span>'


class Figures:
    """report.json's figures and claims.json's rows, by name."""

    def __init__(self, report, claims):
        self.figures = report.get("figures", {})
        self.claims = {c["id"]: c for c in (claims or {}).get("claims", [])}

    def fig(self, name):
        f = self.figures.get(name)
        return quote(name, f["text"]) if f and f.get("value") is not None else "-"

    def claim(self, cid):
        c = self.claims.get(cid)
        return quote("claims." + cid, c["measured"]) if c else "-"


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines) + "\n"


def ops_cell(F, p):
    kinds = ("rigid", "skinned", "to_clip")
    counted = " / ".join(F.fig(f"ops_per_vertex.{k}.counted.{p}") for k in kinds)
    spirv = " / ".join(F.fig(f"ops_per_vertex.{k}.spirv_probe.{p}") for k in kinds)
    return f"{counted} ({spirv})"


def frame_cell(F, p):
    return f"{F.fig(f'frame_time.{p}_over_matrix')} ({F.fig(f'frame_time_vertex_bound.{p}_over_matrix')})"


def isa_cell(F, p):
    return ", ".join(F.fig(f"isa.instructions.rigid.{fam}.{p}") for fam in ISA_FAMILIES)


def pipelines_table(F, report, results=None):
    pipes = [p for p in report.get("settings", {}).get("pipelines", []) if f"bytes_per_vertex.{p}" in F.figures]
    header = ["pipeline", "bytes/vertex uploaded", "bytes fetched/vertex", "floats/transform",
              "ops rigid / skinned / to clip, counted (SPIR-V)", "ISA rigid VS instr. " + " / ".join(ISA_FAMILIES),
              "frame time vs matrix (vertex-bound)", "worst PSNR vs matrix", "worst mean FLIP"]
    rows = [[p, F.fig(f"bytes_per_vertex.{p}"), F.fig(f"vertex_fetch.bytes_per_vertex.{p}"),
             F.fig(f"floats_per_transform.{p}"), ops_cell(F, p), isa_cell(F, p), frame_cell(F, p),
             F.fig(f"image.worst_psnr.{p}"), F.fig(f"image.flip_mean_worst.{p}")] for p in pipes]
    return table(header, rows)


def compact_table(F, report, results=None):
    pipes = [p for p in ("matrix", "qtangent", "motor_q", "matrix_c", "motor_c", "motor_cf")
             if f"bytes_per_vertex.{p}" in F.figures]
    header = ["pipeline", "bytes/vertex (uploads)", "worst PSNR vs matrix, own vertex format",
              "rigid to clip (counted / SPIR-V)", "ISA rigid VS instr. " + " / ".join(ISA_FAMILIES),
              "vertex-bound frame time / matrix"]
    rows = [[p, F.fig(f"bytes_per_vertex.{p}"), F.fig(f"image.worst_psnr_own_format.{p}"),
             F.fig(f"ops_per_vertex.to_clip.counted.{p}") + " / " + F.fig(f"ops_per_vertex.to_clip.spirv_probe.{p}"),
             isa_cell(F, p), F.fig(f"frame_time_vertex_bound.{p}_over_matrix")] for p in pipes]
    return table(header, rows)


def curved_table(F, report, results=None):
    rows = [[cid.replace("curved_", "").replace("_", " "), F.claim(cid)]
            for cid in ("curved_floats_per_instance", "curved_ops_per_vertex", "curved_frame_time", "curved_drift")]
    for p in ("s3_matrix", "s3_motor", "h3_matrix", "h3_motor"):
        rows.append([f"ops per vertex {p}: rigid counted / SPIR-V probe",
                     F.fig(f"ops_per_vertex.rigid.counted.{p}") + " / " + F.fig(f"ops_per_vertex.rigid.spirv_probe.{p}")])
    return table(["figure", "measured"], rows)


SPAN = re.compile(r'<span title="[^"]*">(.*?)</span>')
LINK = re.compile(r"\[([^\]]*)\]\([^)]*\)")


def answer_of(path):
    """The answer block of a report.md: its headline paragraph, its evidence -> verdict rows and
    its scene count line, as plain text (figure marks and links dropped)."""
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        text = f.read()
    start = text.find("## The answer")
    block = text[start:text.find("**Design space**", start)] if start >= 0 else ""
    plain = lambda t: LINK.sub(r"\1", SPAN.sub(r"\1", t)).strip()
    paragraphs = [p for p in block.split("\n\n")[1:] if p.strip() and not p.lstrip().startswith("|")]
    headline = plain(paragraphs[1]) if len(paragraphs) > 1 else ""
    rows = {}
    for line in block.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if line.startswith("| [") and len(cells) >= 3:
            rows[plain(cells[0])] = plain(cells[-1])
    line = next((plain(l) for l in text.splitlines() if " scene(s): " in l), "")
    counts = re.match(r"(\d+) scene\(s\).*?(\d+) built-in.*?(\d+) from files", line)
    count = f"{counts[1]} scenes: {counts[2]} built-in, {counts[3]} from files" if counts else ""
    return {"headline": headline, "rows": rows, "count": count}


def answer_table(F, report, results):
    """The answer of the last run on the built-in scenes (results/report.md) and on the real files
    of results/corpus (results/corpus/report.md), each verdict as that report prints it."""
    sides = [("built-in scenes", "report.md"), ("real files", os.path.join("corpus", "report.md"))]
    answers = [(label, rel, answer_of(os.path.join(results, rel))) for label, rel in sides]
    answers = [a for a in answers if a[2]]
    out = []
    for label, rel, a in answers:
        out.append(f"- **{label}** (results/{rel.replace(os.sep, '/')}; {a['count'] or 'no scene count'}): {a['headline']}")
    evidence = list(dict.fromkeys(k for _, _, a in answers for k in a["rows"]))
    rows = [[e] + [a["rows"].get(e, "-") for _, _, a in answers] for e in evidence]
    return "\n".join(out) + "\n\n" + table(["evidence"] + [label for label, _, _ in answers], rows)


TABLES = {"pipelines": pipelines_table, "compact": compact_table, "curved": curved_table, "answer": answer_table}

CURVED_README = """# results/curved — curved space

Images at t = 2.7 s of each scene's camera path, 512x384, one per pipeline (`motorbench render
<scene> --pipeline <p> --time 2.7 --size 512x384 -o results/curved/<scene>.<p>.png`):

| scene | matrix | motor |
|---|---|---|
| s3_tiling | ![](s3_tiling.s3_matrix.png) | ![](s3_tiling.s3_motor.png) |
| h3_tiling | ![](h3_tiling.h3_matrix.png) | ![](h3_tiling.h3_motor.png) |

Other files, each written by the command named:
- `ops.txt`: the curved rows of `motorbench ops` (pga_kappa kernels per curvature, per-vertex
  kernels and whole shader variants, counted and SPIR-V).
- `drift.json`: `motorbench drift --json` (10^6 float camera steps, raw and renormalised).
- `time.json`: `motorbench time s3_tiling h3_tiling --frames 20 --json` (llvmpipe, 2 shared
  cores: the ratios are noisy at the few-percent level).

The figures of the last run (`scripts/reproduce.sh`), written by `scripts/document_figures.py`
from ../claims.json (its "Curved space" rows, hover a value for its name) and ../report.json's
figures; image equivalence per frame: ../report.md, section "Curved space".

<!-- figures: curved -->
<!-- /figures -->
"""


def fill(text, F, report, results):
    def region(m):
        make = TABLES.get(m.group(2))
        if not make:
            raise SystemExit(f"document_figures: unknown table '{m.group(2)}'")
        return m.group(1) + make(F, report, results) + m.group(4)
    return REGION.sub(region, text)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--results", default=os.path.join(REPO, "results"))
    ap.add_argument("--readme", default=os.path.join(REPO, "README.md"))
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args(argv)
    with open(os.path.join(a.results, "report.json"), encoding="utf-8") as f:
        report = json.load(f)
    claims_path = os.path.join(a.results, "claims.json")
    claims = None
    if os.path.exists(claims_path):
        with open(claims_path, encoding="utf-8") as f:
            claims = json.load(f)
    F = Figures(report, claims)
    curved = os.path.join(a.results, "curved", "README.md")
    stale = []
    compact = os.path.join(REPO, "pipelines", "compact", "README.md")
    for path, template in ((a.readme, None), (compact, None), (curved, CURVED_README)):
        old = ""
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                old = f.read()
        new = fill(template if template is not None else old, F, report, a.results)
        if new == old:
            continue
        stale.append(path)
        if not a.check:
            with open(path, "w", encoding="utf-8") as f:
                f.write(new)
    for path in stale:
        print(f"document_figures: {path} {'differs from' if a.check else 'rewritten from'} the figures", file=sys.stderr)
    return 1 if a.check and stale else 0


if __name__ == "__main__":
    sys.exit(main())
