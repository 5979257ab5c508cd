#!/usr/bin/env python3
"""Plots of a motorbench report: reads report.json, writes PNGs and index.json to OUTDIR.

    python3 scripts/plot.py results/report.json results/plots

index.json lists what was written: {"files": [{"name", "file", "title", "caption", "bars"}], "error"};
"bars" is each plot's data as drawn: one entry per bar {"panel", "series" (a pipeline or
configuration, which fixes its colour), "label" (the scene or kernel), "x", "value" (null where
"text" is drawn instead, e.g. "identical"), "text", "colour"}.
When matplotlib is missing it still writes index.json (with the reason in "error") and exits
0, so `motorbench report` can say so in the report and go on. A plot whose data is absent
(e.g. no bench run) is skipped and named in "skipped".
"""
import json
import math
import os
import sys

# The one colour table of every plot: each pipeline keeps its colour in every figure, and the
# other series (timing configurations, cache sizes) have their own, none shared.
COLOURS = {
    "matrix": "#1f77b4", "affine": "#2ca02c", "qtangent": "#17becf", "hybrid": "#9467bd",
    "motor": "#ff7f0e", "motor_q": "#d62728", "glm": "#7f7f7f", "matrix-affine": "#bcbd22",
    "s3_matrix": "#8c564b", "s3_motor": "#e377c2", "h3_matrix": "#393b79", "h3_motor": "#ad494a",
    "frame": "#3182bd", "64x64 viewport (vertex-bound)": "#e6550d", "CPU update": "#31a354",
    "in cache": "#6baed6", "out of cache (>= 256 MiB)": "#fd8d3c", "one working set": "#969696",
    "matrix family: matrices on the CPU and the GPU": "#08519c", "motor family: motors on the CPU and the GPU": "#e6550d",
    "bytes fetched per frame": "#756bb1", "ops counted per vertex": "#de9ed6",
}
# Every label is at least 10 px high at the plots' 90 dpi: 8 pt = 8 * 90 / 72 = 10 px.
DPI = 90
FONT = 8
# One convention in every plot: ratios are cost motor side / matrix side, < 1 = motor side cheaper.
CONVENTION = "< 1: motor side cheaper"
SPARE = ["#637939", "#8c6d31", "#843c39", "#7b4173", "#5254a3", "#cedb9c"]


def colour(name, i=0):
    """The table's colour of `name`; names outside it take spare colours in order."""
    if name not in COLOURS:
        COLOURS[name] = SPARE[len([k for k in COLOURS if COLOURS[k] in SPARE]) % len(SPARE)]
    return COLOURS[name]


def num(x):
    return x if isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) else None


def figure(report, name):
    """The figure `name` of report.json's "figures" or None; plots quote figures,
    never recompute them."""
    f = (report.get("figures") or {}).get(name)
    return f if isinstance(f, dict) and num(f.get("value")) is not None else None


def iqr(f):
    """(q1, q3) of a figure's spread, or None."""
    sp = (f or {}).get("spread") or {}
    return (sp["q1"], sp["q3"]) if num(sp.get("q1")) is not None and num(sp.get("q3")) is not None else None


def frame_device(report):
    """Where frame times were measured, as the figures name it (else machine.gl)."""
    f = figure(report, "frame_time.motor_over_matrix")
    if f and f.get("device"):
        return f["device"]
    gl = (report.get("machine") or {}).get("gl") or {}
    return gl.get("renderer", "unknown device") + ("" if gl.get("realGpu") else " (a CPU rasterizer)")


def scenes_with(report, pred):
    return [s for s in report.get("scenes", []) if pred(s)]


def save(fig, outdir, name, right=1.0):
    """Writes the figure; `right` is the share of its width the axes may use (a legend beside them).
    A legend above the axes keeps them (and their titles) under it; the image is cut to what was
    drawn, so no title, label or value is clipped at its edge."""
    top = 0.94
    fig.tight_layout(rect=(0, 0, right, top))
    above = [lg for lg in fig.legends if getattr(lg, "above_axes", False)]
    if above:
        fig.canvas.draw()
        bottom = min(lg.get_window_extent().transformed(fig.transFigure.inverted()).y0 for lg in above)
        fig.tight_layout(rect=(0, 0, right, min(top, bottom - 0.01)))
    fig.savefig(os.path.join(outdir, name + ".png"), dpi=DPI, metadata={"Software": None},
                bbox_inches="tight", pad_inches=0.1)


def grouped_bars(ax, labels, series, ylabel, digits=3, reference=None, bars=None, panel=None, texts=None,
                 spreads=None):
    """Bars grouped per label: one bar per series in each group, side by side (never at the same
    x), coloured by the series' name (COLOURS), values written vertically above each bar so that
    neighbours do not overlap. series: [(name, [value or None])]; None values are left out.
    texts: {(series, label): text} drawn instead of a value (a bar of full axis height, hatched:
    e.g. "identical" where a PSNR is infinite): a short hatched stub at the foot of the axis,
    never a tall bar. spreads: {(series, label): (q1, q3)} drawn as error bars (the IQR). Every
    bar drawn is appended to `bars` (the plot's data in index.json): series, label, x, value,
    text, colour, panel, iqr."""
    n = max(1, len(series))
    width = 0.8 / n
    texts = texts or {}
    spreads = spreads or {}
    finite = [v for _, vs in series for v in vs if v is not None] + [q[1] for q in spreads.values()]
    top = max(finite) * 1.25 if finite else 1.0
    for i, (name, values) in enumerate(series):
        col = colour(name)
        for k, (label, v) in enumerate(zip(labels, values)):
            x = k + (i - (n - 1) / 2) * width
            text = texts.get((name, label))
            if v is None and text is None:
                continue
            spread = spreads.get((name, label))
            height = top * 0.04 if text is not None else v
            if text is not None:
                ax.bar(x, top * 0.04, width, color=col, alpha=0.35, hatch="//", edgecolor=col)
                ax.annotate(text, (x, top * 0.05), ha="center", va="bottom", rotation=90, fontsize=FONT)
            else:
                ax.bar(x, v, width, color=col)
                if spread:
                    ax.errorbar(x, v, yerr=[[max(0.0, v - spread[0])], [max(0.0, spread[1] - v)]],
                                color="black", capsize=2, lw=0.8)
                ax.annotate(f"{v:.{digits}g}", (x, max(v, spread[1] if spread else v)), ha="center", va="bottom",
                            rotation=90, fontsize=FONT, xytext=(0, 2), textcoords="offset points")
            if bars is not None:
                bars.append({"panel": panel, "series": name, "label": label, "x": round(x, 6),
                             "value": v, "text": text, "colour": col, "iqr": list(spread) if spread else None,
                             "height": height, "axisTop": top})
    if reference is not None:
        ax.axhline(reference, color="black", lw=0.8)
    ax.set_ylim(0, top * 1.15 if finite or texts else 1.0)
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=FONT)
    ax.tick_params(axis="y", labelsize=FONT)
    ax.set_ylabel(ylabel, fontsize=FONT + 1)


def legend(fig, names, title, markers=False, extra=()):
    """One legend for the figure, above the axes (it never hides a bar), a patch of each
    series' colour from the table (markers: the series' point marker in its colour, for scatter
    plots); `title` says what the colours mean, `extra` adds handles (e.g. a hatched stub)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    if markers:  # beside the axes, one entry a line: the figure keeps its height
        handles = [Line2D([], [], linestyle="none", marker=marker(n), color=colour(n), label=n) for n in names]
        fig.legend(handles=handles, loc="center right", ncol=1, fontsize=FONT, frameon=False, title=title,
                   title_fontsize=FONT)
        return
    handles = [Patch(facecolor=colour(n), label=n) for n in names] + list(extra)
    fig.legend(handles=handles, loc="upper center", ncol=min(len(handles), 6), fontsize=FONT,
               bbox_to_anchor=(0.5, 1.0), frameon=False, title=title, title_fontsize=FONT).above_axes = True


def width_for(groups, per_group):
    return max(8.0, min(24.0, 1.2 + 0.28 * groups * max(1, per_group)))


def plot_bytes_per_vertex(plt, report, outdir):
    pipes = report["settings"]["pipelines"]
    scenes = scenes_with(report, lambda s: any(
        num(s.get("pipelines", {}).get(p, {}).get("memory", {}).get("bytesPerVertex")) for p in pipes))
    if not scenes:
        return None
    fig, ax = plt.subplots(figsize=(width_for(len(scenes), len(pipes)), 4.0))
    series = [(p, [num(s["pipelines"].get(p, {}).get("memory", {}).get("bytesPerVertex")) for s in scenes])
              for p in pipes]
    bars = []
    grouped_bars(ax, [s["id"] for s in scenes], series, "bytes / vertex", bars=bars)
    ax.set_title("Vertex attribute bytes per vertex (position + frame + uv; device: the buffers uploaded)",
                 fontsize=9, pad=24)
    legend(fig, pipes, "colour: pipeline")
    save(fig, outdir, "bytes_per_vertex")
    return ("bytes_per_vertex", "Bytes per vertex",
            "Shading attributes uploaded per vertex (PipelineStats.vertexBytes / vertices); "
            "skin weights/joints and optional streams excluded.", bars)


def plot_ops_per_vertex(plt, report, outdir):
    scenes = scenes_with(report, lambda s: isinstance(s.get("opsPerVertex"), dict))
    if not scenes:
        return None
    pipes = [p for p in report["settings"]["pipelines"]
             if any(p in s["opsPerVertex"] for s in scenes)]
    fig, ax = plt.subplots(figsize=(width_for(len(scenes), len(pipes)), 4.0))
    series = []
    for p in pipes:
        vals = []
        for s in scenes:
            c = (s["opsPerVertex"].get(p) or {}).get("counted")
            vals.append(num(c.get("mul", 0) + c.get("add", 0)) if c else None)
        series.append((p, vals))
    bars = []
    grouped_bars(ax, [s["id"] for s in scenes], series, "mul + add per vertex", bars=bars)
    ax.set_title("Counted ops per drawn vertex (vertex shader incl. world to clip, weighted rigid/skinned; "
                 "device: op-counting scalar)", fontsize=9, pad=24)
    legend(fig, pipes, "colour: pipeline")
    save(fig, outdir, "ops_per_vertex")
    return ("ops_per_vertex", "Ops per vertex",
            "Multiplications + additions of one drawn vertex, counted by executing the shaders' "
            "GLSL through the op-counting shim; each scene weights the rigid, skinned and "
            "scaled-fallback variants by the vertices it draws.", bars)


def plot_kernel_ratios(plt, report, outdir):
    # Time per item, fastest motor implementation / fastest matrix implementation: report.json's
    # summary.kernelRatios, the figure report.md and claims quote (not the shim sources
    # against each other); < 1 = motor side cheaper, as in every other plot. Each side's time is
    # the median of the bench's repetitions; the ratio of two medians carries no spread to draw.
    ratios = (report.get("summary") or {}).get("kernelRatios") or {}
    pairs = [dict(p, time_ratio=ratios[p["pair"]]["motorOverMatrixTime"],
                  sides="%s / %s" % (ratios[p["pair"]].get("fastestMotor"), ratios[p["pair"]].get("fastestMatrix")))
             for p in report.get("kernels", {}).get("pairs", [])
             if num((ratios.get(p.get("pair")) or {}).get("motorOverMatrixTime"))]
    if not pairs:
        return None
    kernels, sides = [], {}
    for p in pairs:
        if p["kernel"] not in kernels:
            kernels.append(p["kernel"])
        sides.setdefault(p["kernel"], set()).add(p["sides"])
    # Bars per kernel: in cache above, out of cache below; unsized kernels centred.
    sizes = [("in_cache", "in cache", -0.2), ("out_of_cache", "out of cache (>= 256 MiB)", 0.2),
             (None, "one working set", 0.0)]
    fig, ax = plt.subplots(figsize=(8, 0.45 * len(kernels) + 1.4))
    bars = []
    for size, label, offset in sizes:
        pts = [(k, p["time_ratio"]) for k, name in enumerate(kernels) for p in pairs
               if p["kernel"] == name and p.get("size") == size]
        if not pts:
            continue
        ys = [k + offset for k, _ in pts]
        ax.barh(ys, [v for _, v in pts], 0.4, label=label, color=colour(label))
        for y, (k, v) in zip(ys, pts):
            ax.annotate(f"{v:.2f}", (v, y), va="center", fontsize=FONT)
            bars.append({"panel": None, "series": label, "label": kernels[k], "x": round(y, 6), "value": v,
                         "text": None, "colour": colour(label)})
    ax.axvline(1.0, color="black", lw=0.8)
    values = [p["time_ratio"] for p in pairs]
    if max(values) / min(values) > 10:  # one far ratio (load_frames) would flatten every other bar
        ax.set_xscale("log")
        ticks = [t for t in (0.25, 0.5, 1, 2, 5, 10, 20, 50, 100) if min(values) / 2 <= t <= max(values) * 2]
        ax.set_xticks(ticks)
        ax.set_xticklabels(["%g" % t for t in ticks])
    ax.set_yticks(range(len(kernels)))
    ax.set_yticklabels(["%s (%s)" % (k, ", ".join(sorted(sides[k]))) for k in kernels], fontsize=FONT)
    ax.tick_params(axis="x", labelsize=FONT)
    ax.invert_yaxis()
    ax.set_xlabel("time per item motor / matrix (%s)" % CONVENTION, fontsize=FONT + 1)
    ctx = report.get("kernels", {}).get("context") or {}
    cpu = ctx.get("cpu_model") or (report.get("machine") or {}).get("cpu", "unnamed CPU")
    reps = repetitions(report)
    short = reps if len(reps) < 40 else "repetitions not recorded"
    ax.set_title("CPU kernel time ratios on %s (Google Benchmark)\neach side's time: %s; no spread drawn" % (cpu, short),
                 fontsize=9)
    ax.legend(fontsize=FONT, title="colour: working set", title_fontsize=FONT)
    save(fig, outdir, "kernel_ratios")
    return ("kernel_ratios", "Kernel time ratios",
            "motorbench bench: time per item of the fastest motor implementation over the fastest matrix "
            "implementation of each pair (named beside the kernel; the inverse of the throughput ratio; "
            "< 1: motor faster), in cache and out of cache, on the CPU in the title; each side's time is %s "
            "(bench.json keeps every repetition and their coefficient of variation); a ratio of two medians has no "
            "spread of its own, so no error bars; a logarithmic axis when the ratios span more than 10x." % reps, bars)


def fallback_label(scene):
    """The scene's id, and under it the motor pipeline's exact fallback when it took one."""
    fb = ((scene.get("pipelines") or {}).get("motor") or {}).get("fallbacks") or {}
    draws = (fb.get("linearFallbackDraws") or 0) + (fb.get("skinFallbackDraws") or 0)
    if not draws:
        return scene["id"]
    return "%s\nmotor fallback: %d draws, %d joints, %d vertices" % (
        scene["id"], draws, fb.get("skinFallbackJoints") or 0, fb.get("fallbackVertices") or 0)


def plot_frame_time_ratio(plt, report, outdir):
    """Per scene, the figures the text quotes (frame_time.<scene>.motor_over_matrix and the
    vertex-bound one: medians of per-frame paired ratios) with their IQR as error bars."""
    scenes = [s for s in report.get("scenes", [])
              if figure(report, "frame_time.%s.motor_over_matrix" % s.get("id"))
              or num((s.get("timing") or {}).get("ratio_motor_matrix"))]
    if not scenes:
        return None
    labels = [fallback_label(s) for s in scenes]
    series, spreads = [], {}
    for name, key in (("frame", "frame_time"), ("64x64 viewport (vertex-bound)", "frame_time_vertex_bound")):
        vals = []
        for s, label in zip(scenes, labels):
            f = figure(report, "%s.%s.motor_over_matrix" % (key, s["id"]))
            if f is None and key == "frame_time":  # a report.json before the figures layer
                vals.append(num((s.get("timing") or {}).get("ratio_motor_matrix")))
                continue
            vals.append(f["value"] if f else None)
            if f and iqr(f):
                spreads[(name, label)] = iqr(f)
        if any(v is not None for v in vals):
            series.append((name, vals))
    cpu = [num((s["timing"].get("update") or {}).get("ratio_motor_matrix")) for s in scenes]
    if any(v is not None for v in cpu):
        series.append(("CPU update", cpu))
    fig, ax = plt.subplots(figsize=(width_for(len(scenes), len(series)), 4.0))
    bars = []
    grouped_bars(ax, labels, series, "motor / matrix time (%s)" % CONVENTION, digits=3, reference=1.0, bars=bars,
                 spreads=spreads)
    ax.set_title("Frame-time ratios on %s" % frame_device(report), fontsize=9, pad=24)
    legend(fig, [name for name, _ in series], "colour: what is timed, motor / matrix")
    save(fig, outdir, "frame_time_ratio")
    return ("frame_time_ratio", "Frame-time ratios",
            "Per scene, frame time motor / matrix: the median of per-frame paired ratios (both pipelines "
            "render each frame back to back), error bars the interquartile range of those ratios; the values "
            "are report.json's figures, the same the text quotes. CPU update: ratio of medians, timed apart "
            "(no spread recorded). A scene whose motor pipeline drew with its exact fallback says so under "
            "its name (the most draws, joints and vertices in any frame drawn). On a CPU rasterizer these "
            "times cannot discriminate GPU costs.", bars)


def image_error_series(report, scenes, pipes):
    """Per pipeline: worst PSNR and largest % of pixels over 1/255 per scene, and the scenes whose
    frames were all identical to the baseline (PSNR infinite: drawn as "identical")."""
    psnr, frac, identical = [], [], {}
    for p in pipes:
        ps_row, fr_row = [], []
        for s in scenes:
            ms = [f["metrics"][p] for f in s.get("frames", []) if p in f.get("metrics", {})]
            ps = [m["psnr"] for m in ms if num(m.get("psnr"))]
            ps_row.append(min(ps) if ps else None)
            if ms and not ps:
                identical[(p, s["id"])] = "identical"
            fr = [m["fractionOver1"] for m in ms if num(m.get("fractionOver1")) is not None]
            fr_row.append(100 * max(fr) if fr else None)
        psnr.append((p, ps_row))
        frac.append((p, fr_row))
    return psnr, frac, identical


def plot_image_error(plt, report, outdir):
    baseline = report["settings"].get("baseline", report["settings"]["pipelines"][0])
    scenes = scenes_with(report, lambda s: any(f.get("metrics") for f in s.get("frames", [])))
    # Every compared pipeline: the glTF ones in settings order, then those of curved scenes
    # (s3_motor against s3_matrix, ...), each with its own colour.
    pipes = [p for p in report["settings"]["pipelines"] if p != baseline]
    for s in scenes:
        for f in s.get("frames", []):
            pipes += [p for p in f.get("metrics", {}) if p not in pipes]
    if not scenes or not pipes:
        return None
    labels = [s["id"] for s in scenes]
    psnr, frac, identical = image_error_series(report, scenes, pipes)
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(width_for(len(scenes), len(pipes)), 7.5))
    bars = []
    grouped_bars(a1, labels, psnr, "worst PSNR [dB]", digits=3, bars=bars, panel="psnr", texts=identical)
    grouped_bars(a2, labels, frac, "% pixels off by > 1/255", digits=2, bars=bars, panel="fractionOver1",
                 texts={k: "identical" for k in identical})
    a1.set_title("Worst PSNR against %s (curved scenes: their space's matrix); hatched stub: identical; "
                 "device: images rendered on %s" % (baseline, frame_device(report)), fontsize=9, pad=24)
    a2.set_title("Changed pixels (worst time); hatched stub: identical (0 %)", fontsize=9)
    from matplotlib.patches import Patch
    stub = Patch(facecolor="#cccccc", hatch="//", edgecolor="#777777", label="identical to %s (hatched stub)" % baseline)
    legend(fig, pipes, "colour: pipeline, against %s" % baseline, extra=[stub])
    save(fig, outdir, "image_error")
    return ("image_error", "Image error per scene",
            "Worst PSNR and largest fraction of pixels differing by more than one 8-bit step, "
            "over the scene's animation times, one bar per pipeline and scene; a scene whose frames "
            "are identical to the baseline shows a short hatched stub marked \"identical\" (never a tall bar). On skinned scenes "
            "a pipeline that blends joint motors differs from the LBS baseline by design (the methods' "
            "expected difference, not an error).", bars)


PLURAL = {"matrix": "matrices", "motor": "motors"}


def design_series(p, families, gpu_sides):
    """The design-space series of pipeline p: its family, which transforms with its own maths on the
    CPU and the GPU, or, where its GPU side is another family's pipeline (report.json
    pipelineGpuSides), an entry of its own that says both ("hybrid: motors on the CPU, qtangent
    on the GPU")."""
    fam = families.get(p, "matrix")
    if p in gpu_sides:
        return "%s: %s on the CPU, %s on the GPU" % (p, PLURAL.get(fam, fam), gpu_sides[p])
    return "%s family: %s on the CPU and the GPU" % (fam, PLURAL.get(fam, fam))


def marker(series):
    """A family's points are discs; a pipeline with another family's GPU side a diamond."""
    return "o" if " family: " in series else "D"


def apart_text(points):
    apart = sorted({p["family"] for p in points if " family: " not in p["family"]})
    return ("; marked apart (a diamond): " + "; ".join(apart)) if apart else ""


def repetitions(report):
    """How each kernel time was taken: "the median of 3 repetitions" from the pairs' recorded
    repetitions (report.json kernels.pairs[].<side>.repetitions), else what is known."""
    seen = sorted({v["repetitions"] for p in (report.get("kernels") or {}).get("pairs", []) for v in p.values()
                   if isinstance(v, dict) and isinstance(v.get("repetitions"), int)})
    if not seen:
        return "one run or the median of repetitions (not recorded in this report.json)"
    if seen == [1]:
        return "one run"
    return "the median of %s repetitions" % " or ".join(str(n) for n in seen)


def design_space_points(report):
    """One point per pipeline: x = bytes fetched per vertex, y = ISA instructions of the rigid
    vertex shader on the newest AMD family measured (else counted ops to clip, said on the axis),
    family and the GPU frame time over the baseline where a GPU measured it. All figures."""
    pipes = (report.get("settings") or {}).get("pipelines", [])
    families = report.get("pipelineFamilies") or {}
    gpu_sides = report.get("pipelineGpuSides") or {}
    isa = [f.get("id") for f in ((report.get("isa") or {}).get("families") or [])]
    fam = isa[-1] if isa else None
    gpu = bool(((report.get("machine") or {}).get("gl") or {}).get("realGpu"))
    if fam:
        ylabel = "ISA instr., rigid VS (RADV %s; compiled)" % fam
    else:
        ylabel = "ops per vertex, rigid to clip (counted; no ISA in this report)"
    points = []
    for p in pipes:
        x = figure(report, "vertex_fetch.bytes_per_vertex." + p)
        y = figure(report, ("isa.instructions.rigid.%s.%s" % (fam, p)) if fam else "ops_per_vertex.to_clip.counted." + p)
        if not x or not y:
            continue
        # The vertex-bound viewport's paired ratio where measured (the GPU question), else the frame's.
        t = (figure(report, "frame_time_vertex_bound.%s_over_matrix" % p)
             or figure(report, "frame_time.%s_over_matrix" % p)) if gpu else None
        points.append({"pipeline": p, "family": design_series(p, families, gpu_sides), "x": x["value"],
                       "y": y["value"], "time": t["value"] if t else None})
    return points, ylabel, gpu


def plot_design_space(plt, report, outdir):
    points, ylabel, gpu = design_space_points(report)
    if not points:
        return None
    fig, ax = plt.subplots(figsize=(9.5, 3.0))  # 3 in high: the answer block and it above the fold
    bars = []
    seen = {}
    for pt in points:
        col = colour(pt["family"])
        # Pipelines at the same point: one label, and each later marker smaller so every
        # family's colour shows.
        key = (round(pt["x"], 3), round(pt["y"], 3))
        seen.setdefault(key, []).append(pt)
        ax.scatter([pt["x"]], [pt["y"]], color=col, s=60 / len(seen[key]), zorder=2 + len(seen[key]),
                   marker=marker(pt["family"]))
        bars.append({"panel": None, "series": pt["family"], "label": pt["pipeline"], "x": pt["x"], "value": pt["y"],
                     "text": None if pt["time"] is None else "%.2fx" % pt["time"], "colour": col, "iqr": None})
    xs = [p["x"] for p in points]
    ys = [p["y"] for p in points]
    close_y = (max(ys) - min(ys)) * 0.08
    close_x = max(xs) * 0.03  # 16.0 and 16.01 bytes fetched are one column
    placed = []  # (x, y, side) of the labels so far
    for (x, y), pts in sorted(seen.items(), key=lambda kv: -kv[0][1]):
        text = ", ".join(p["pipeline"] + ("" if p["time"] is None else " %.2fx" % p["time"]) for p in pts)
        # A label near one already placed in the same column goes to the other side of its point,
        # then below it, so no two labels overlap.
        taken = {side for px, py, side in placed if abs(px - x) <= close_x and abs(py - y) <= close_y}
        side = next((sd for sd in ("right", "left", "below") if sd not in taken), "below")
        offset, ha = {"right": ((5, 3), "left"), "left": ((-5, 3), "right"), "below": ((5, -11), "left")}[side]
        ax.annotate(text, (x, y), xytext=offset, textcoords="offset points", fontsize=FONT, ha=ha)
        placed.append((x, y, side))
    ax.set_xlim(0, max(xs) * 1.35)
    ax.set_ylim(min(ys) * 0.9, max(ys) * 1.1)
    ax.set_xlabel("bytes fetched per vertex (meshoptimizer's model: modelled, not timed)", fontsize=FONT + 1)
    ax.set_ylabel(ylabel, fontsize=FONT)
    ax.tick_params(labelsize=FONT)
    ax.grid(alpha=0.3)
    ax.set_title("Design space; labels: frame time / matrix on %s (vertex-bound where measured)" % frame_device(report) if gpu else
                 "Design space (no GPU timed: no frame times shown)", fontsize=9, pad=18)
    legend(fig, sorted({p["family"] for p in points}), "colour and marker: family", markers=True)
    save(fig, outdir, "design_space", right=0.66)
    return ("design_space", "Design space",
            "One point per pipeline: bytes fetched per vertex in meshoptimizer's fetch model with its layout "
            "(modelled, not timed; median over scenes) against its vertex shader's ISA instructions (compiled by "
            "RADV on its null device, not timed); lower left is cheaper on both. Colours: the matrix family and the "
            "motor family, each transforming with its own maths on the CPU and the GPU" + apart_text(points) + ".", bars)

# The kinds of content the answer splits the report into (harness/document/report_kind_figures.h).
CONTENT_KINDS = [("all", "all content"), ("normal_mapped", "normal-mapped"), ("not_normal_mapped", "not normal-mapped"),
                 ("skinned", "skinned"), ("morph", "morph"), ("rigid", "rigid"), ("built_in", "built-in scenes")]


def content_kind_ratios(report):
    """Per kind the content draws: (kind, label with its share, bytes ratio, ops ratio), motor over
    the baseline, from the kind figures the answer quotes (kind.fetched_over_baseline.K.motor,
    kind.ops_counted.K.<p>, kind.share_vertices.K)."""
    pipes = (report.get("settings") or {}).get("pipelines") or []
    if len(pipes) < 2:
        return []
    base = pipes[0]
    motor = "motor" if "motor" in pipes else next((p for p in pipes[1:] if "motor" in p), pipes[1])
    out = []
    for kind, label in CONTENT_KINDS:
        count = figure(report, "kind.vertices." + kind)
        if count is None or not count["value"] > 0:
            continue
        share = figure(report, "kind.share_vertices." + kind)
        shares = figure(report, "kind.share_primitives." + kind)
        if share is not None:
            label += "\n%.3g %% of vertices" % share["value"]
            if shares is not None:
                label += "\n%.3g %% of primitives" % shares["value"]
        elif kind == "built_in":
            label += "\n(controlled cases)"
        b = figure(report, "kind.fetched_over_baseline.%s.%s" % (kind, motor))
        om, ob = figure(report, "kind.ops_counted.%s.%s" % (kind, motor)), figure(report, "kind.ops_counted.%s.%s" % (kind, base))
        ops = om["value"] / ob["value"] if om and ob and ob["value"] > 0 else None
        out.append((kind, label, b["value"] if b else None, ops))
    return out


def plot_content_kinds(plt, report, outdir):
    """The answer by kind of content: cost motor / matrix (bytes fetched per frame, ops counted
    per vertex by the variant each vertex draws) per kind, each kind's share under its name."""
    kinds = content_kind_ratios(report)
    if not kinds:
        return None
    labels = [label for _, label, _, _ in kinds]
    series = [(name, vals) for name, vals in (("bytes fetched per frame", [k[2] for k in kinds]),
                                              ("ops counted per vertex", [k[3] for k in kinds]))
              if any(v is not None for v in vals)]
    if not series:
        return None
    fig, ax = plt.subplots(figsize=(max(12.0, 1.7 * len(kinds)), 4.4))  # room for the shares under each kind
    bars = []
    grouped_bars(ax, labels, series, "motor / matrix (%s)" % CONVENTION, digits=3, reference=1.0, bars=bars)
    ax.set_xticklabels(labels, rotation=0, ha="center", fontsize=FONT)
    kind_of = {label: kind for kind, label, _, _ in kinds}
    for b in bars:  # the kind's figure key beside its printed label
        b["kind"] = kind_of[b["label"]]
    ax.set_title("Cost motor / matrix by kind of content (modelled: meshoptimizer's fetch model; counted: the op "
                 "counts; not timed)", fontsize=9, pad=24)
    legend(fig, [name for name, _ in series], "colour: cost compared")
    save(fig, outdir, "content_kinds")
    return ("content_kinds", "Cost by kind of content",
            "Per kind of content the report draws, cost motor / matrix (< 1: motor side cheaper): bytes fetched "
            "per frame in meshoptimizer's fetch model (modelled, not timed; each pipeline's stride) and arithmetic ops counted per "
            "vertex, each vertex by the shader variant its primitive draws with (exact fallback included); under each "
            "kind its share of the content's drawn vertices and primitives. The values are report.json's kind "
            "figures, the same the answer quotes; the built-in scenes are controlled cases beside the files.", bars)


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    src, outdir = sys.argv[1], sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    index = {"files": [], "skipped": [], "error": None}
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except Exception as e:  # missing package: say so, let the report go on
        index["error"] = "matplotlib is not available (%s): no plots; install python3-matplotlib" % e
        plt = None
    if plt is not None:
        with open(src) as f:
            report = json.load(f)
        for fn in (plot_design_space, plot_content_kinds, plot_bytes_per_vertex, plot_ops_per_vertex, plot_kernel_ratios,
                   plot_frame_time_ratio, plot_image_error):
            got = fn(plt, report, outdir)
            plt.close("all")
            if got is None:
                index["skipped"].append(fn.__name__[5:])
                continue
            name, title, caption, bars = got
            index["files"].append({"name": name, "file": name + ".png", "title": title, "caption": caption,
                                   "bars": bars})
    with open(os.path.join(outdir, "index.json"), "w") as f:
        json.dump(index, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
