#!/usr/bin/env python3
"""Every glTF file x every pipeline, judged (scripts/corpus-check.sh runs this; README: Corpus check).

One `motorbench survey` process per file (load once, every pipeline of the file's space on one GL
context, at rest and at 1/3 and 2/3 of animation 0), --jobs at a time. A worker that dies by a
signal or runs past --timeout is recorded and its pipelines are retried one process each, so the
crash is pinned on a pipeline; the run goes on. Writes OUT/corpus-check.json (a row per file x
pipeline, totals, the rules) and OUT/corpus-check.md (the summary tables), prints the rules as
PASS/FAIL lines naming the failing files, and exits 1 when a rule fails (2: bad arguments). The
rigid rule is judged outside each frame's tie pixels (the survey's: pixels matrix itself draws
differently when its vertex positions are jittered by ~1e-6 of their magnitude); the 16-byte rule
in the survey's geometry view (base colour alone: positions and uv decide a pixel, not how a
pipeline shades) outside its int16-cell ties (pixels matrix draws differently with its positions
moved to corners of their int16 quantisation cells). Frames that pass only so are listed under
their rule as "PASS (ties: ...)" and counted.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
DEFAULT_DIR = os.path.join(REPO, "..", "shared", "corpus-wide")
FULL_PRECISION = ["motor", "affine", "qtangent", "motor_q", "hybrid"]
COMPACT = ["matrix_c", "motor_c", "motor_cf"]
# Pipelines that skin by blending joint motors (dual quaternion linear blending); the others blend
# matrices (linear blend skinning), as matrix does. Their skinned frames are judged against the
# survey's reference of that method (harness/render/skin_reference.h: GLM dual quaternions on the CPU,
# drawn by matrix).
MOTOR_BLEND = ["motor", "motor_q", "motor_c", "motor_cf"]
MIN_PSNR = 50.0          # dB: rigid frames of the full-precision pipelines against matrix
MAX_DRAWN_DIFF = 0.01    # skinned frames: drawn-pixel counts at most 1 % apart
FALLBACKS = ["linearFallbackDraws", "skinFallbackDraws", "skinFallbackJoints", "fallbackVertices",
             "nonUniformScaleNodes", "negativeScaleNodes", "shearMatrixNodes", "scaleFallbackInstances",
             "zeroScalarFrames", "biasedFrames", "rotorSplitVertices", "rotorUnresolvedTriangles", "morphNotDrawnNodes"]


def gltf_files(paths):
    """Files as given, folders as their .gltf/.glb files (recursively, sorted)."""
    out = []
    for p in paths:
        if os.path.isdir(p):
            found = []
            for root, _, names in os.walk(p):
                found += [os.path.join(root, n) for n in names if n.lower().endswith((".gltf", ".glb"))]
            out += sorted(found)
        else:
            out.append(p)
    return out


def manifest_features(paths):
    """{absolute path: features} from the MANIFEST.tsv of each folder given (corpus-wide has one)."""
    features = {}
    for p in paths:
        tsv = os.path.join(p, "MANIFEST.tsv")
        if os.path.isdir(p) and os.path.isfile(tsv):
            with open(tsv, encoding="utf-8") as f:
                for row in csv.DictReader(f, delimiter="\t"):
                    features[os.path.abspath(os.path.join(p, row["path"]))] = row.get("features", "")
    return features


def run_survey(exe, path, size, timeout, pipelines=None):
    """One worker: {"exit", "signal", "timeout", "stderr", "doc", "seconds"}."""
    with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as tmp:
        out = tmp.name
    cmd = [exe, "survey", path, "--size", size, "-o", out]
    if pipelines:
        cmd += ["--pipelines", ",".join(pipelines)]
    t0 = time.monotonic()
    rec = {"exit": None, "signal": None, "timeout": False, "stderr": "", "doc": None}
    try:
        # Own session: a timeout kills the worker and whatever it started, nothing else.
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                                errors="replace", start_new_session=True)
        try:
            _, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            _, err = proc.communicate()
            rec["timeout"] = True
        rec["stderr"] = err[-2000:]
        if proc.returncode < 0:
            rec["signal"] = signal.Signals(-proc.returncode).name
        else:
            rec["exit"] = proc.returncode
        if os.path.getsize(out) > 0 and not rec["timeout"] and rec["signal"] is None:
            with open(out, encoding="utf-8") as f:
                rec["doc"] = json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        rec["stderr"] += f"\n{e}"
    finally:
        if os.path.exists(out):
            os.unlink(out)
    rec["seconds"] = time.monotonic() - t0
    return rec


def psnr_of(frame):
    """A frame's PSNR against the baseline, inf when identical, None when not compared."""
    if frame.get("identical"):
        return math.inf
    return frame.get("psnr")


def judge_rigid_frame(frame, tie_pixels):
    """One rigid frame of a full-precision pipeline against matrix: {"verdict": "pass" | "ties" |
    "fail", ...}. pass: PSNR >= MIN_PSNR or identical. ties: below that, but at MIN_PSNR or identical
    once the frame's tie pixels (those matrix itself draws differently when the vertex positions are
    jittered by ~1e-6 of their magnitude: undetermined by the transform, see survey_probe.h) are
    counted as equal: every pixel that makes it fail is a tie. fail: the pixels outside the tie set
    alone stay below MIN_PSNR (or the survey gave no tie data)."""
    psnr = psnr_of(frame)
    out = {"psnr": psnr, "tiePixels": tie_pixels, "differingPixels": frame.get("differingPixels"),
           "differingNotTies": frame.get("differingNotTies"),
           "psnrNotTies": math.inf if frame.get("identicalNotTies") else frame.get("psnrNotTies")}
    if psnr is not None and psnr >= MIN_PSNR:
        out["verdict"] = "pass"
        if out["psnrNotTies"] is None:
            out["psnrNotTies"] = psnr
    elif out["psnrNotTies"] is not None and out["psnrNotTies"] >= MIN_PSNR:
        out["verdict"] = "ties"
    else:
        out["verdict"] = "fail"
        if out["psnrNotTies"] is None:
            out["psnrNotTies"] = psnr
    return out


def pipeline_row(file, name, doc, rec, kinds, bounds):
    """The row of one file x pipeline from its survey document."""
    p = doc["pipelines"][name]
    base = doc["pipelines"][doc["baseline"]]["frames"]
    frames = p["frames"]
    # Frames where this pipeline drew morphed nodes in their base shape (a counted omission,
    # PipelineStats::morphNotDrawnNodes; issue 37) are judged by no image rule: listed apart.
    omitted = [(f.get("fallbacks") or {}).get("morphNotDrawnNodes", 0) for f in frames]
    omissions = [{"frame": i, "kind": k, "nodes": n, "psnr": psnr_of(f)}
                 for i, (f, k, n) in enumerate(zip(frames, kinds, omitted)) if n]
    first_kind = kinds[0] if kinds else None
    kinds = [("omitted" if n else k) for k, n in zip(kinds, omitted)] + list(kinds[len(omitted):])
    row = {"file": file, "pipeline": name, "exit": rec["exit"], "signal": rec["signal"], "status": "ok",
           "error": p.get("error"), "seconds": round(p.get("seconds", 0.0), 3),
           "drawnPixels": [f["drawnPixels"] for f in frames], "kind": first_kind,
           "fallbacks": p.get("fallbacks", {}), "omittedFrames": omissions}
    if row["error"]:
        row["status"] = "error"
    # Drawn: some pixel in every frame where the baseline drew some, and in one frame at least.
    drawn = [f["drawnPixels"] for f in frames]
    base_drawn = [f["drawnPixels"] for f in base]
    row["drawn"] = (not row["error"] and any(d > 0 for d in drawn)
                    and all(d > 0 or b == 0 for d, b in zip(drawn, base_drawn)))
    rigid = [psnr_of(f) for f, k in zip(frames, kinds) if k == "rigid" and psnr_of(f) is not None]
    row["worstRigidPsnr"] = min(rigid) if rigid else None
    row["rigidIdentical"] = bool(rigid) and min(rigid) == math.inf
    # The same rules outside each frame's tie pixels (pixels the transform does not determine).
    ties = [(f.get("ties") or {}).get("pixels") for f in doc["frames"]]
    row["tiePixels"] = ties
    judged = [dict(judge_rigid_frame(f, t), frame=i) for i, (f, k, t) in enumerate(zip(frames, kinds, ties))
              if k == "rigid" and psnr_of(f) is not None]
    row["rigidTieFrames"] = [j for j in judged if j["verdict"] == "ties"]
    row["rigidFailFrames"] = sum(1 for j in judged if j["verdict"] == "fail")
    not_ties = [j["psnrNotTies"] for j in judged]
    row["worstRigidPsnrNotTies"] = min(not_ties) if not_ties else None
    row["drawnDiff"] = [abs(d - b) / max(d, b) if max(d, b) else 0.0 for d, b in zip(drawn, base_drawn)]
    skinned = [x for x, k in zip(row["drawnDiff"], kinds) if k == "skinned"]
    row["worstSkinnedDrawnDiff"] = max(skinned) if skinned else None
    # The skinned rule's reference: matrix (linear blend) or, for the motor blend, the survey's
    # CPU reference of that method when it could be made (else matrix: the strict reading).
    reference = doc.get("motorBlendReference") or {}
    ref_drawn = [(fr.get("motorBlendReference") or {}).get("drawnPixels") for fr in doc["frames"]]
    if name in MOTOR_BLEND and reference.get("available") and None not in ref_drawn:
        row["skinReference"] = "motor blend (GLM dual quaternions, drawn by matrix)"
        row["referenceDrawnDiff"] = [abs(d - b) / max(d, b) if max(d, b) else 0.0 for d, b in zip(drawn, ref_drawn)]
        blend = [f.get("motorBlend") or {} for f in frames]
        psnrs = [math.inf if b.get("identical") else b.get("psnr") for b, k in zip(blend, kinds) if k == "skinned"]
        psnrs = [p for p in psnrs if p is not None]
        row["worstSkinnedPsnrReference"] = min(psnrs) if psnrs else None
    else:
        row["skinReference"] = "matrix" + ("" if name not in MOTOR_BLEND or not skinned else
                                           f" (motor blend reference unavailable: {reference.get('why')})")
        row["referenceDrawnDiff"] = row["drawnDiff"]
    against = [x for x, k in zip(row["referenceDrawnDiff"], kinds) if k == "skinned"]
    row["worstSkinnedReferenceDrawnDiff"] = max(against) if against else None
    # The 16-byte rule, judged by survey in the geometry view (positions and uv alone, no light).
    outside = [f["outsideEnvelope"] for f, k in zip(frames, kinds) if k == "rigid" and "outsideEnvelope" in f]
    row["outsideEnvelope"] = max(outside) if outside else None
    # Outside the tie set (surveys without tie data: every pixel counts).
    outside_nt = [f.get("outsideEnvelopeNotTies", f["outsideEnvelope"]) for f, k in zip(frames, kinds)
                  if k == "rigid" and "outsideEnvelope" in f]
    row["outsideEnvelopeNotTies"] = max(outside_nt) if outside_nt else None
    # The 16-byte rule's ties: pixels matrix draws differently with its positions moved within
    # their int16 cells (the geometry view; survey_probe.h).
    int16_ties = [(f.get("int16Ties") or {}).get("pixels") for f in doc["frames"]]
    row["compactTieFrames"] = [{"frame": i, "outsideEnvelope": f["outsideEnvelope"], "tiePixels": t}
                               for i, (f, k, t) in enumerate(zip(frames, kinds, int16_ties))
                               if k == "rigid" and f.get("outsideEnvelope") and f.get("outsideEnvelopeNotTies") == 0]
    excess = [f["envelopeExcess"] for f, k in zip(frames, kinds) if k == "rigid" and "envelopeExcess" in f]
    row["envelopeExcess"] = max(excess) if excess else None
    row["boundPixels"] = max(bounds) if bounds else None
    return row


def file_result(path, rel, rec, features):
    """{"file", "status", ...} and its rows (one per pipeline) from a worker's record."""
    doc = rec["doc"]
    res = {"file": rel, "features": features, "seconds": round(rec["seconds"], 3), "exit": rec["exit"],
           "signal": rec["signal"], "timeout": rec["timeout"], "rows": []}
    if rec["signal"] or rec["timeout"]:
        res["status"] = "crashed"
        res["error"] = f"worker killed by {rec['signal']}" if rec["signal"] else "worker ran past --timeout"
        return res
    if doc is None:
        res["status"] = "worker-error"
        res["error"] = f"exit {rec['exit']}, no JSON: {rec['stderr'].strip()[-400:]}"
        return res
    res["status"] = doc["status"]
    res["error"] = doc.get("error")
    res["loaderFallbacks"] = doc.get("loaderFallbacks", {})
    res["scene"] = doc.get("scene")
    if doc["status"] in ("load-failed", "no-data"):
        return res
    kinds = [f["kind"] for f in doc["frames"]]
    bounds = [f["positionBound"]["pixels"] for f in doc["frames"] if "positionBound" in f]
    res["kind"] = kinds[0]
    res["boundPixels"] = max(bounds) if bounds else None
    res["boundWorld"] = max((f["positionBound"]["worldUnits"] for f in doc["frames"] if "positionBound" in f), default=None)
    res["envelopeRadius"] = max((f["positionBound"]["envelopeRadius"] for f in doc["frames"] if "positionBound" in f), default=None)
    res["frames"] = [{"animation": f["animation"], "time": f["time"]} for f in doc["frames"]]
    res["gl"] = doc.get("gl")
    for name in doc["pipelineOrder"]:
        res["rows"].append(pipeline_row(rel, name, doc, rec, kinds, bounds))
    return res


def survey_file(exe, path, rel, size, timeout, features):
    rec = run_survey(exe, path, size, timeout)
    res = file_result(path, rel, rec, features)
    if res["status"] != "crashed":
        return res
    # Pin the crash on pipelines: each one alone (with the matrix baseline it is compared against).
    res["crashedPipelines"] = []
    for name in ["matrix"] + FULL_PRECISION + COMPACT:
        one = run_survey(exe, path, size, timeout, [name])
        sub = file_result(path, rel, one, features)
        if sub["status"] == "crashed":
            res["crashedPipelines"].append(name)
            res["rows"].append({"file": rel, "pipeline": name, "exit": one["exit"], "signal": one["signal"] or "timeout",
                                "status": "crashed", "error": sub["error"], "seconds": round(one["seconds"], 3),
                                "drawn": False, "fallbacks": {}})
        else:
            res["rows"] += [r for r in sub["rows"] if r["pipeline"] == name]
            for k in ("kind", "boundPixels", "boundWorld", "envelopeRadius", "frames", "loaderFallbacks", "scene"):
                res.setdefault(k, sub.get(k))
    res["error"] += " (alone: " + (", ".join(res["crashedPipelines"]) or "none") + " crashed)"
    return res


def fmt_psnr(v):
    if v is None:
        return "-"
    return "identical" if v == math.inf else f"{v:.1f}"


def evaluate(files):
    """The acceptance rules: [(name, failures)] with one line per failing file."""
    crashed = [f"{f['file']}: {f['error']}" for f in files if f["status"] in ("crashed", "worker-error")]
    crashed += [f"{f['file']} [{r['pipeline']}]: {r['signal']}" for f in files for r in f["rows"] if r.get("status") == "crashed"]
    load = [f"{f['file']}: {f['error']}" for f in files if f["status"] == "load-failed"]
    drawn, rigid, compact, skinned, rigid_ties, compact_ties, skinned_method = [], [], [], [], [], [], []
    omitted_lines = []  # frames no image rule judges: a feature the pipeline counts as not drawn
    for f in files:
        by_name = {r["pipeline"]: r for r in f["rows"]}
        for r in f["rows"]:
            if r.get("status") == "crashed":
                continue
            name = f"{f['file']} [{r['pipeline']}]"
            if not r["drawn"]:
                drawn.append(f"{name}: " + (r["error"] or f"drawn pixels {r['drawnPixels']}"))
            if r["pipeline"] in FULL_PRECISION and r.get("worstRigidPsnr") is not None and r["worstRigidPsnr"] < MIN_PSNR:
                if r.get("rigidFailFrames", 1):
                    rigid.append(f"{name}: {r['worstRigidPsnr']:.2f} dB"
                                 + ("" if r.get("worstRigidPsnrNotTies") is None else
                                    f", {fmt_psnr(r['worstRigidPsnrNotTies'])} dB outside the tie pixels"))
                else:
                    rigid_ties += [f"{name} {frame_name(f, t['frame'])}: {t['psnr']:.2f} dB; {fmt_psnr(t['psnrNotTies'])} dB outside "
                                   f"the {t['tiePixels']} tie pixels ({t['differingPixels']} px differ, "
                                   f"{t['differingNotTies']} of them not ties)" for t in r["rigidTieFrames"]]
            if r["pipeline"] in COMPACT and r.get("outsideEnvelope") and not r.get("outsideEnvelopeNotTies"):
                compact_ties += [f"{name} {frame_name(f, t['frame'])}: {t['outsideEnvelope']} px outside the envelope, every one "
                                 f"of them an int16-cell tie pixel ({t['tiePixels']} in the frame)" for t in r["compactTieFrames"]]
            elif r["pipeline"] in COMPACT and r.get("outsideEnvelope"):
                compact.append(f"{name}: {r['outsideEnvelope']} px outside the envelope"
                               + ("" if r.get("outsideEnvelopeNotTies") in (None, r["outsideEnvelope"]) else
                                  f" ({r['outsideEnvelopeNotTies']} not tie pixels)")
                               + f", by up to {r['envelopeExcess']}/255 "
                               f"(bound {f['boundPixels']:.2g} px, radius {f['envelopeRadius']}; "
                               f"PSNR {fmt_psnr(r['worstRigidPsnr'])}"
                               + ("" if r["pipeline"] == "matrix_c" or "matrix_c" not in by_name else
                                  f"; matrix_c, the same positions through matrix math: "
                                  f"{by_name['matrix_c'].get('outsideEnvelope') or 0} px") + ")")
            omitted_lines += [(f"counted omission: {r['pipeline']} does not morph (issue 37)",
                               f"{name} {frame_name(f, o['frame'])}: {o['nodes']} morphed node(s) drawn in their base shape"
                               + ("" if o["psnr"] is None else f", {fmt_psnr(o['psnr'])} dB against matrix"))
                              for o in r.get("omittedFrames") or []]
            when = lambda diffs: ", ".join(("rest" if fr["animation"] is None else f"t={fr['time']:.3g}") + f" {100 * x:.1f} %"
                                           for fr, x in zip(f["frames"], diffs))
            if r.get("worstSkinnedReferenceDrawnDiff") is not None and r["worstSkinnedReferenceDrawnDiff"] > MAX_DRAWN_DIFF:
                skinned.append(f"{name}: drawn pixels apart from {r['skinReference']} by {when(r['referenceDrawnDiff'])}")
            elif r.get("worstSkinnedDrawnDiff") is not None and r["worstSkinnedDrawnDiff"] > MAX_DRAWN_DIFF:
                psnr = r.get("worstSkinnedPsnrReference")
                skinned_method.append(f"{name}: {when(r['drawnDiff'])} apart from matrix; from its own method's reference "
                                      f"{when(r['referenceDrawnDiff'])}" + ("" if psnr is None else f", {fmt_psnr(psnr)} dB"))
    return [("0 crashes, signals or timeouts", crashed, []),
            ("every file loads (files without data excepted)", load, []),
            ("every drawable file drawn by every pipeline", drawn, []),
            (f"rigid frames of {', '.join(FULL_PRECISION)} vs matrix >= {MIN_PSNR:.0f} dB or identical "
             "(outside the tie pixels)", rigid, rigid_ties),
            (f"rigid frames of {', '.join(COMPACT)} within their position bound (geometry view, envelope; "
             "int16-cell tie pixels excepted)",
             compact, compact_ties),
            (f"skinned frames: drawn pixels within {100 * MAX_DRAWN_DIFF:.0f} % of their skinning method's reference "
             f"(matrix; for {', '.join(MOTOR_BLEND)} the motor blend by GLM dual quaternions, drawn by matrix)",
             skinned, skinned_method),
            ("frames judged by no image rule: a feature the pipeline counts as not drawn", [], omitted_lines)]


def frame_name(f, i):
    """A frame of file result `f` by index: "rest" or "t=0.4"."""
    fr = (f.get("frames") or [])[i] if i < len(f.get("frames") or []) else None
    return "rest" if fr is None or fr["animation"] is None else f"t={fr['time']:.3g}"


def rule_lines(rules):
    """The rules as PASS/FAIL lines (markdown list): failures, then frames passed on ties, marked."""
    out = []
    for name, fails, ties in rules:
        method = name.startswith("skinned")  # its marked passes: the motor blend apart from matrix by design
        if name.startswith("frames judged by no"):  # a list, not a rule
            out.append(f"- COUNTED: {name} ({len(ties)})")
            out += [f"  - {label}: {line}" for label, line in ties]
            continue
        out.append(f"- {'PASS' if not fails else 'FAIL'}: {name}" + (f" ({len(fails)})" if fails else "")
                   + (f" ({len(ties)} more than {100 * MAX_DRAWN_DIFF:.0f} % from matrix's linear blend)" if ties and method else
                      f" ({len(ties)} frames pass on ties)" if ties else ""))
        out += [f"  - {line}" for line in fails]
        mark = "the skinning method differs from matrix's" if method else "ties: undetermined by the transform"
        out += [f"  - PASS ({mark}): {line}" for line in ties]
    return out


def totals(files, pipelines):
    """Per pipeline: drawn, worst rigid PSNR, skinned files over 1 %, fallback totals and files."""
    per = {}
    for name in pipelines:
        rows = [(f, r) for f in files for r in f["rows"] if r["pipeline"] == name]
        rigid = [(r["worstRigidPsnr"], f["file"]) for f, r in rows if r.get("worstRigidPsnr") is not None]
        worst = min(rigid, key=lambda x: x[0]) if rigid else (None, None)
        fb = {}
        for key in FALLBACKS:
            vals = [r.get("fallbacks", {}).get(key, 0) for _, r in rows]
            fb[key] = {"total": sum(vals), "files": sum(1 for v in vals if v)}
        per[name] = {"rows": len(rows), "drawn": sum(1 for _, r in rows if r.get("drawn")),
                     "errors": sum(1 for _, r in rows if r.get("status") in ("error", "crashed")),
                     "worstRigidPsnr": worst[0], "worstRigidFile": worst[1],
                     "worstRigidIdentical": worst[0] == math.inf,  # JSON writes the PSNR null then
                     "rigidFilesBelow50dB": sum(1 for v, _ in rigid if v < MIN_PSNR),
                     "skinnedFilesOver1Percent": sum(1 for _, r in rows if (r.get("worstSkinnedDrawnDiff") or 0) > MAX_DRAWN_DIFF),
                     "skinnedFilesOver1PercentOfReference":
                         sum(1 for _, r in rows if (r.get("worstSkinnedReferenceDrawnDiff") or 0) > MAX_DRAWN_DIFF),
                     "compactFilesOutsideEnvelope": sum(1 for _, r in rows if r.get("outsideEnvelope")),
                     "compactFilesOutsideEnvelopeNotTies": sum(1 for _, r in rows if r.get("outsideEnvelopeNotTies")),
                     "rigidFilesFailing": sum(1 for _, r in rows if r.get("rigidFailFrames")),
                     "rigidTieFrames": sum(len(r.get("rigidTieFrames") or []) for _, r in rows)
                     if name in FULL_PRECISION else 0,
                     "compactTieFrames": sum(len(r.get("compactTieFrames") or []) for _, r in rows
                                             if not r.get("outsideEnvelopeNotTies")) if name in COMPACT else 0,
                     "fallbacks": fb, "seconds": round(sum(r.get("seconds", 0) for _, r in rows), 1)}
    return per


def markdown(summary, files, per, rules):
    s = summary
    out = [f"# corpus-check: {s['folder']}", "",
           f"{s['files']} files, {s['size']}, {s['jobs']} jobs, {s['wallSeconds']:.0f} s wall "
           f"({s['workerSeconds']:.0f} s in workers); drawn on {s.get('gl') or 'no context'}", "",
           "| files | ok | no data | load failed | crashed | pipeline errors | rigid | skinned |",
           "|---|---|---|---|---|---|---|---|",
           f"| {s['files']} | {s['ok']} | {s['noData']} | {s['loadFailed']} | {s['crashed']} | {s['pipelineErrors']} "
           f"| {s['rigidFiles']} | {s['skinnedFiles']} |", "",
           f"Frames passed on ties (every pixel that fails the rule undetermined by the transform): "
           f"{s['framesPassedOnTies']['rigid']} rigid (full precision), {s['framesPassedOnTies']['compact']} compact.", ""]
    for what, key in (("No data (not failures)", "notDrawable"), ("Load failures", "loadFailures"), ("Crashes", "crashes")):
        if s[key]:
            out += [f"{what}:", ""] + [f"- {f}: {why}" for f, why in s[key].items()] + [""]
    out += ["| pipeline | rows | drawn | errors | worst rigid PSNR (file) | rigid < 50 dB (outside ties) "
           "| compact outside bound (outside ties) | frames passed on ties | skinned > 1 % from matrix (from own method) | seconds |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for name, p in per.items():
        worst = "-" if p["worstRigidPsnr"] is None else f"{fmt_psnr(p['worstRigidPsnr'])} ({p['worstRigidFile']})"
        comp = f"{p['compactFilesOutsideEnvelope']} ({p['compactFilesOutsideEnvelopeNotTies']})" if name in COMPACT else "-"
        rig = f"{p['rigidFilesBelow50dB']} ({p['rigidFilesFailing']})"
        tie = str(p["rigidTieFrames"] + p["compactTieFrames"]) if name in FULL_PRECISION + COMPACT else "-"
        out.append(f"| {name} | {p['rows']} | {p['drawn']} | {p['errors']} | {worst} | {rig} "
                   f"| {comp} | {tie} | {p['skinnedFilesOver1Percent']} ({p['skinnedFilesOver1PercentOfReference']}) | {p['seconds']} |")
    out += ["", "Fallbacks (per file the largest value over its frames, summed over files; files taking it):", "",
            "| counter | " + " | ".join(per) + " |", "|---|" + "---|" * len(per)]
    for key in FALLBACKS:
        cells = [f"{p['fallbacks'][key]['total']} ({p['fallbacks'][key]['files']})" if p["fallbacks"][key]["total"] else "0"
                 for p in per.values()]
        out.append(f"| {key} | " + " | ".join(cells) + " |")
    lf = s["loaderFallbacks"]
    out += ["", "Loader fallbacks (total; files): " + (", ".join(f"{k} {v['total']} ({v['files']})" for k, v in lf.items()) or "none")]
    out += ["", "## Rules", ""] + rule_lines(rules)
    out += ["", "## Files", "",
            "Bound: the 16-byte pipelines' position error in pixels at this size (rigid files; int16 in each "
            "primitive's bounding cube: half extent / 32767 world units, projected at the nearest depth). The 16-byte "
            "pipelines are judged on it in the geometry view (base colour alone, no light); their lit images' PSNR "
            "against matrix is the cost of their quantised frame (and motor_cf's interpolated rotor).", "",
            "| file | status | kind | bound px | " + " | ".join(per) + " |", "|---|---|---|---|" + "---|" * len(per)]
    for f in files:
        cells = []
        rows = {r["pipeline"]: r for r in f["rows"]}
        for name in per:
            r = rows.get(name)
            if r is None:
                cells.append("-")
            elif r.get("status") != "ok" or not r.get("drawn"):
                cells.append("**" + (r.get("status") if r.get("status") != "ok" else "not drawn") + "**")
            elif f.get("kind") == "skinned":
                d = r.get("worstSkinnedDrawnDiff")
                cells.append("-" if d is None or name == "matrix" else f"{100 * d:.1f} %")
            else:
                cells.append("-" if name == "matrix" else fmt_psnr(r.get("worstRigidPsnr")))
        bound = "-" if f.get("boundPixels") is None else f"{f['boundPixels']:.2g}"
        status = f["status"] + ("" if f["status"] in ("ok",) else f": {f.get('error')}")
        out.append(f"| {f['file']} | {status} | {f.get('kind', '-')} | {bound} | " + " | ".join(cells) + " |")
    out += ["", "Cells: rigid files the worst PSNR (dB) against matrix over their frames; skinned files the largest "
            "drawn-pixel difference from matrix."]
    return "\n".join(out) + "\n"


def finite(v):
    """JSON has no infinity: an identical frame's PSNR is written null (rigidIdentical says so)."""
    if isinstance(v, float) and math.isinf(v):
        return None
    if isinstance(v, dict):
        return {k: finite(x) for k, x in v.items()}
    if isinstance(v, list):
        return [finite(x) for x in v]
    return v


def main(argv):
    ap = argparse.ArgumentParser(prog="corpus-check.sh", description=__doc__.split("\n")[0])
    ap.add_argument("paths", nargs="*", help="folders (searched recursively) and files; default ../shared/corpus-wide")
    ap.add_argument("--out", default=os.path.join(REPO, "build", "corpus-check"), help="folder for corpus-check.json/.md")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2, help="workers at a time (default: the CPUs)")
    ap.add_argument("--size", default="128x128", help="image size (default 128x128)")
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per worker before it is killed")
    ap.add_argument("--exe", default=os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench")))
    a = ap.parse_args(argv)
    paths = a.paths or [DEFAULT_DIR]
    for p in paths:
        if not os.path.exists(p):
            print(f"corpus-check: {p}: no such file or folder", file=sys.stderr)
            return 2
    if not os.access(a.exe, os.X_OK):
        print(f"corpus-check: {a.exe}: no motorbench executable (build it, or give --exe)", file=sys.stderr)
        return 2
    todo = gltf_files(paths)
    if not todo:
        print(f"corpus-check: no .gltf/.glb files under {', '.join(paths)}", file=sys.stderr)
        return 2
    features = manifest_features(paths)
    roots = [os.path.abspath(p) for p in paths]
    common = os.path.commonpath(roots) if len(roots) > 1 else (roots[0] if os.path.isdir(roots[0]) else os.path.dirname(roots[0]))
    if a.jobs > 1 and "LP_NUM_THREADS" not in os.environ:
        # llvmpipe: one thread per worker, so that --jobs workers share the CPUs without contention.
        os.environ["LP_NUM_THREADS"] = str(max(1, (os.cpu_count() or 1) // a.jobs))

    # The workers run a private copy: a rebuild during the run must not swap the binary under them.
    scratch = tempfile.mkdtemp(prefix="corpus-check-exe-")
    exe = os.path.join(scratch, "motorbench")
    shutil.copy2(a.exe, exe)
    t0 = time.monotonic()
    results = [None] * len(todo)
    done, lock = [0], threading.Lock()

    def one(i):
        path = todo[i]
        rel = os.path.relpath(os.path.abspath(path), common)
        res = survey_file(exe, path, rel, a.size, a.timeout, features.get(os.path.abspath(path), ""))
        with lock:
            done[0] += 1
            el = time.monotonic() - t0
            left = el / done[0] * (len(todo) - done[0])
            print(f"[{done[0]}/{len(todo)}] {el:.0f} s elapsed, ~{left:.0f} s left: {rel}: {res['status']}"
                  f"{'' if res['status'] == 'ok' else ' (' + str(res.get('error')) + ')'} {res['seconds']:.1f} s",
                  file=sys.stderr, flush=True)
        results[i] = res

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        list(pool.map(one, range(len(todo))))

    shutil.rmtree(scratch, ignore_errors=True)
    files = results
    pipelines = []
    for f in files:
        for r in f["rows"]:
            if r["pipeline"] not in pipelines:
                pipelines.append(r["pipeline"])
    rules = evaluate(files)
    per = totals(files, pipelines)
    tie_frames = {"rigid": sum(p["rigidTieFrames"] for p in per.values()),
                  "compact": sum(p["compactTieFrames"] for p in per.values())}
    lf = {}
    for f in files:
        for k, v in (f.get("loaderFallbacks") or {}).items():
            lf.setdefault(k, {"total": 0, "files": 0})
            lf[k]["total"] += v
            lf[k]["files"] += 1
    summary = {"folder": ", ".join(paths) if len(paths) <= 2 else f"{len(paths)} paths under {common}", "files": len(files), "size": a.size, "jobs": a.jobs,
               "wallSeconds": round(time.monotonic() - t0, 1), "workerSeconds": round(sum(f["seconds"] for f in files), 1),
               "gl": next((f["gl"] for f in files if f.get("gl")), None),
               "ok": sum(1 for f in files if f["status"] == "ok"),
               "noData": sum(1 for f in files if f["status"] == "no-data"),
               "loadFailed": sum(1 for f in files if f["status"] == "load-failed"),
               "crashed": sum(1 for f in files if f["status"] in ("crashed", "worker-error")),
               "pipelineErrors": sum(1 for f in files for r in f["rows"] if r.get("status") == "error"),
               "rigidFiles": sum(1 for f in files if f.get("kind") == "rigid"),
               "skinnedFiles": sum(1 for f in files if f.get("kind") == "skinned"),
               "rows": sum(len(f["rows"]) for f in files), "loaderFallbacks": lf,
               "framesPassedOnTies": tie_frames,
               "notDrawable": {f["file"]: f["error"] for f in files if f["status"] == "no-data"},
               "loadFailures": {f["file"]: f["error"] for f in files if f["status"] == "load-failed"},
               "crashes": {f["file"]: f["error"] for f in files if f["status"] in ("crashed", "worker-error")}}
    doc = {"summary": summary, "pipelines": per,
           "rules": [{"rule": n, "pass": not fails, "failures": fails, "passedOnTies": ties} for n, fails, ties in rules
                     if not n.startswith("frames judged by no")],
           "countedOmissions": [{"mark": m, "frame": line} for n, _, ties in rules if n.startswith("frames judged by no")
                                for m, line in ties],
           "files": [{k: v for k, v in f.items() if k != "rows"} for f in files],
           "rows": [r for f in files for r in f["rows"]]}
    os.makedirs(a.out, exist_ok=True)
    md = markdown(summary, files, per, rules)
    with open(os.path.join(a.out, "corpus-check.json"), "w", encoding="utf-8") as f:
        json.dump(finite(doc), f, indent=1)
        f.write("\n")
    with open(os.path.join(a.out, "corpus-check.md"), "w", encoding="utf-8") as f:
        f.write(md)
    print(md.split("\n## Files")[0])
    print(f"corpus-check: wrote {os.path.join(a.out, 'corpus-check.md')} and corpus-check.json", file=sys.stderr)
    return 1 if any(fails for _, fails, _ in rules) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
