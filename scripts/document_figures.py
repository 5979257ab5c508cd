#!/usr/bin/env python3
"""The figure tables of README.md, pipelines/compact/README.md, harness/cli/README.md and
results/curved/README.md, written from the run's figures.

Every value is a figure of report.json ("figures", and the morph figures it embeds as
morph.figures, quoted by name as its "text"), a figure of DIR/corpus/report.json (quoted as
corpus/<name>) or the "measured" text of a claims.json row (quoted as claims.<id>), never typed
by hand. Each value is written as <span title="NAME">TEXT</span>, as motorbench writes report.md
and claims.md, so tests/document/test_documents_agree.py can read every document's values back
by name.

  scripts/document_figures.py [--results DIR] [--readme FILE] [--check]

rewrites the regions between "<!-- figures: TABLE -->" and "<!-- /figures -->" of the README
(--readme), pipelines/compact/README.md and harness/cli/README.md, and DIR/curved/README.md;
--check writes nothing and exits 1 when a document differs from what the figures give (a hand
edit, or figures regenerated without the documents).
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


def report_figures(report):
    """report.json's figures with the morph figures it embeds (report.json morph.figures)."""
    out = dict((report.get("morph") or {}).get("figures") or {})
    out.update(report.get("figures") or {})
    return out


class Figures:
    """report.json's figures, the corpus report's (corpus/<name>) and claims.json's rows, by name."""

    def __init__(self, report, claims, corpus=None):
        self.figures = report_figures(report)
        self.corpus = (corpus or {}).get("figures") or {}
        self.claims = {c["id"]: c for c in (claims or {}).get("claims", [])}

    def fig(self, name):
        f = self.figures.get(name)
        return quote(name, f["text"]) if f and f.get("value") is not None else "-"

    def corpus_fig(self, name):
        f = self.corpus.get(name)
        return quote("corpus/" + name, f["text"]) if f and f.get("value") is not None else "-"

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
              "ops rigid / skinned / to clip, counted (SPIR-V probe)", "ISA rigid VS instr. " + " / ".join(ISA_FAMILIES),
              "frame time vs matrix (vertex-bound)", "worst PSNR vs matrix", "worst mean FLIP"]
    rows = [[p, F.fig(f"bytes_per_vertex.{p}"), F.fig(f"vertex_fetch.bytes_per_vertex.{p}"),
             F.fig(f"floats_per_transform.{p}"), ops_cell(F, p), isa_cell(F, p), frame_cell(F, p),
             F.fig(f"image.worst_psnr.{p}"), F.fig(f"image.flip_mean_worst.{p}")] for p in pipes]
    return table(header, rows)


def compact_table(F, report, results=None):
    pipes = [p for p in ("matrix", "qtangent", "motor_q", "matrix_c", "motor_c", "motor_cf")
             if f"bytes_per_vertex.{p}" in F.figures]
    header = ["pipeline", "bytes/vertex (uploads)", "worst PSNR vs matrix, own vertex format",
              "rigid to clip (counted / SPIR-V probe)", "ISA rigid VS instr. " + " / ".join(ISA_FAMILIES),
              "vertex-bound frame time / matrix"]
    rows = [[p, F.fig(f"bytes_per_vertex.{p}"), F.fig(f"image.worst_psnr_own_format.{p}"),
             F.fig(f"ops_per_vertex.to_clip.counted.{p}") + " / " + F.fig(f"ops_per_vertex.to_clip.spirv_probe.{p}"),
             isa_cell(F, p), F.fig(f"frame_time_vertex_bound.{p}_over_matrix")] for p in pipes]
    return table(header, rows)


def fragment_rotor_table(F, report, results=None):
    """motor_c against motor_cf, the rotor unpacked per fragment: where the frame is unpacked and
    what each stage runs."""
    pipes = ("motor_c", "motor_cf")
    both = lambda fn: [fn(p) for p in pipes]
    slash = lambda *names: " / ".join(F.fig(n) for n in names)
    isa = lambda stage: lambda p: ", ".join(slash(f"isa.{stage}instructions.rigid.{fam}.{p}", f"isa.{stage}vgprs.rigid.{fam}.{p}")
                                             for fam in ISA_FAMILIES)
    fams = " / ".join(ISA_FAMILIES)
    rows = [
        ["varyings (vec4 slots / components)"] + both(lambda p: slash(f"varyings.slots.{p}", f"varyings.components.{p}")),
        ["rigid vertex to clip (counted / SPIR-V probe)"] + both(
            lambda p: slash(f"ops_per_vertex.to_clip.counted.{p}", f"ops_per_vertex.to_clip.spirv_probe.{p}")),
        ["shading normal per fragment, normal-mapped (counted)"] + both(
            lambda p: F.fig(f"ops_per_fragment.shading_normal.normal_mapped.{p}")),
        ["shading normal per fragment, no normal map (counted)"] + both(
            lambda p: F.fig(f"ops_per_fragment.shading_normal.no_normal_map.{p}")),
        [f"ISA vertex shader {fams} (instructions / VGPRs)"] + both(isa("")),
        [f"ISA fragment shader {fams} (instructions / VGPRs)"] + both(isa("fragment_")),
        ["vertex-bound frame time / matrix (median over scenes)"] + both(
            lambda p: F.fig(f"frame_time_vertex_bound.{p}_over_matrix")),
        ["worst PSNR vs matrix, own vertex format: built-in scenes / ../shared/corpus"] + both(
            lambda p: F.fig(f"image.worst_psnr_own_format.{p}") + " / " + F.corpus_fig(f"image.worst_psnr_own_format.{p}")),
    ]
    return table([""] + list(pipes), rows)


def morph_table(F, report, results=None):
    """Each morph method of the run's morph figures (report.json morph): bytes, the morphing rigid
    shader's SPIR-V beside the rigid one's, and its worst frame against matrix."""
    methods = (report.get("morph") or {}).get("methods") or []
    rows = []
    for m in methods:
        mid, pipe, label = m.get("id", ""), m.get("pipeline", ""), m.get("program", "")
        baseline = mid == "matrix"
        rows.append([f"{mid}: {m.get('method', '')}", F.fig(f"morph.bytes_per_vertex.{mid}"),
                     F.fig(f"morph.bytes_per_target_vertex.{mid}"),
                     F.fig(f"ops_per_vertex.{label}.spirv_whole_shader.{pipe}") + " (rigid " +
                     F.fig(f"ops_per_vertex.rigid.spirv_whole_shader.{pipe}") + ")",
                     "baseline" if baseline else F.fig(f"morph.worst_psnr.rigid.{mid}"),
                     "-" if baseline else F.fig(f"morph.max_error.rigid.{mid}"),
                     F.fig(f"morph.worst_psnr.skinned.{mid}")])
    return table(["method", "bytes / vertex", "bytes / target vertex", "SPIR-V whole shader, morphing rigid (rigid)",
                  "worst PSNR vs matrix (unskinned)", "max error (unskinned)", "worst PSNR vs skin reference (skinned)"],
                 rows)


CURVED = (("s3_tiling", "S3", "s3_matrix", "s3_motor"), ("h3_tiling", "H3", "h3_matrix", "h3_motor"))


def curved_table(F, report, results=None):
    """Curved space, each figure with its scope: floats per instance; ops per vertex of the instance
    transform alone (counted and SPIR-V probe: position and normal by camera * instance, the
    projection left out) and of the whole vertex shader (SPIR-V whole shader, the projection
    included); frame time; camera drift; the claims rows that judge them."""
    rows = []
    for scene, space, matrix, motor in CURVED:
        for p in (matrix, motor):
            rows.append([f"{scene} {p}", F.fig(f"curved.floats_per_instance.{scene}.{p}"),
                         F.fig(f"ops_per_vertex.rigid.counted.{p}") + " / " + F.fig(f"ops_per_vertex.rigid.spirv_probe.{p}"),
                         F.fig(f"ops_per_vertex.{space} instance.spirv_whole_shader.{p}")])
    out = table(["scene and pipeline", "floats per instance", "ops per vertex, transform only (counted / SPIR-V probe)",
                 "ops per vertex, whole shader with the projection (SPIR-V whole shader)"], rows)
    rows = [[scene, F.fig(f"curved.frame_time.{scene}.motor_over_matrix"),
             F.fig(f"curved.frame_time_vertex_bound.{scene}.motor_over_matrix")] for scene, _, _, _ in CURVED]
    device = (F.figures.get(f"curved.frame_time.{CURVED[0][0]}.motor_over_matrix") or {}).get("device", "not timed")
    out += "\n" + table([f"scene", f"frame time motor / matrix (median of per-frame paired ratios; {device})",
                         "vertex-bound (the small viewport)"], rows)
    rows = [[f"{space} {side}", F.fig(f"curved.drift.{space}.{side}.raw"), F.fig(f"curved.drift.{space}.{side}.renormalised")]
            for _, space, _, _ in CURVED for side in ("matrix", "motor")]
    out += "\n" + table(["camera (float steps)", "distance from the group, raw", "renormalised after every step"], rows)
    scope = lambda c: (c.get("scope") or {}).get("stage", "-") if isinstance(c.get("scope"), dict) else "-"
    rows = [[cid, scope(F.claims[cid]), F.claim(cid), F.claims[cid].get("verdict", "-")]
            for cid in ("curved_floats_per_instance", "curved_ops_per_vertex", "curved_frame_time", "curved_update",
                        "curved_drift") if cid in F.claims]
    if rows:
        out += "\n" + table(["claims row (../claims.md)", "scope", "measured", "verdict"], rows)
    return out


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


TABLES = {"pipelines": pipelines_table, "compact": compact_table, "fragment_rotor": fragment_rotor_table,
          "morph": morph_table, "curved": curved_table, "answer": answer_table}

CURVED_README = """# results/curved — curved space

The curved-space figures of the last run (`scripts/reproduce.sh`), written by
`scripts/document_figures.py` from ../report.json's figures (the report's s3_tiling and h3_tiling
scenes and its camera-drift run) and ../claims.json's "Curved space" rows; hover a value for its
name. Images and image equivalence per frame: ../report.md, section "Curved space". What each
pipeline uploads and runs: pipelines/curved/README.md.

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
    corpus_path = os.path.join(a.results, "corpus", "report.json")
    corpus = None
    if os.path.exists(corpus_path):
        with open(corpus_path, encoding="utf-8") as f:
            corpus = json.load(f)
    F = Figures(report, claims, corpus)
    curved = os.path.join(a.results, "curved", "README.md")
    stale = []
    compact = os.path.join(REPO, "pipelines", "compact", "README.md")
    cli = os.path.join(REPO, "harness", "cli", "README.md")
    for path, template in ((a.readme, None), (compact, None), (cli, None), (curved, CURVED_README)):
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
