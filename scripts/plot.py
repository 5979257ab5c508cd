#!/usr/bin/env python3
"""Plots of a motorbench report: reads report.json, writes PNGs and index.json to OUTDIR.

    python3 scripts/plot.py results/report.json results/plots

index.json lists what was written: {"files": [{"name", "file", "title", "caption"}], "error"}.
When matplotlib is missing it still writes index.json (with the reason in "error") and exits
0, so `motorbench report` can say so in the report and go on. A plot whose data is absent
(e.g. no bench run) is skipped and named in "skipped".
"""
import json
import math
import os
import sys

COLOURS = {"matrix": "#4c72b0", "motor": "#dd8452", "glm": "#8c8c8c", "matrix-affine": "#55a868"}


def colour(name, i=0):
    return COLOURS.get(name, ["#937860", "#da8bc3", "#8172b3"][i % 3])


def num(x):
    return x if isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) else None


def scenes_with(report, pred):
    return [s for s in report.get("scenes", []) if pred(s)]


def save(fig, outdir, name):
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, name + ".png"), dpi=90, metadata={"Software": None})


def grouped_bars(ax, labels, series, ylabel, colours=None, digits=3, reference=None):
    """series: [(name, [values or None])]; None values are left out. colours: one per series
    (default: the pipeline colours by name); reference: a horizontal line (e.g. ratio 1)."""
    n = max(1, len(series))
    width = 0.8 / n
    for i, (name, values) in enumerate(series):
        xs = [k + (i - (n - 1) / 2) * width for k in range(len(labels))]
        pts = [(x, v) for x, v in zip(xs, values) if v is not None]
        if not pts:
            continue
        col = colours[i] if colours else colour(name, i)
        bars = ax.bar([p[0] for p in pts], [p[1] for p in pts], width, label=name, color=col)
        for b, (_, v) in zip(bars, pts):
            ax.annotate(f"{v:.{digits}g}", (b.get_x() + b.get_width() / 2, b.get_height()),
                        ha="center", va="bottom", fontsize=7)
    if reference is not None:
        ax.axhline(reference, color="black", lw=0.8)
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=8)


def plot_bytes_per_vertex(plt, report, outdir):
    pipes = report["settings"]["pipelines"]
    scenes = scenes_with(report, lambda s: any(
        num(s.get("pipelines", {}).get(p, {}).get("memory", {}).get("bytesPerVertex")) for p in pipes))
    if not scenes:
        return None
    fig, ax = plt.subplots(figsize=(8, 3.6))
    series = [(p, [num(s["pipelines"].get(p, {}).get("memory", {}).get("bytesPerVertex")) for s in scenes])
              for p in pipes]
    grouped_bars(ax, [s["id"] for s in scenes], series, "bytes / vertex")
    ax.set_title("Vertex attribute bytes per vertex (position + frame + uv, from the uploads)", fontsize=9)
    save(fig, outdir, "bytes_per_vertex")
    return ("bytes_per_vertex", "Bytes per vertex",
            "Shading attributes uploaded per vertex (PipelineStats.vertexBytes / vertices); "
            "skin weights/joints and optional streams excluded.")


def plot_ops_per_vertex(plt, report, outdir):
    scenes = scenes_with(report, lambda s: isinstance(s.get("opsPerVertex"), dict))
    if not scenes:
        return None
    pipes = [p for p in report["settings"]["pipelines"]
             if any(p in s["opsPerVertex"] for s in scenes)]
    fig, ax = plt.subplots(figsize=(8, 3.6))
    series = []
    for p in pipes:
        vals = []
        for s in scenes:
            c = (s["opsPerVertex"].get(p) or {}).get("counted")
            vals.append(num(c.get("mul", 0) + c.get("add", 0)) if c else None)
        series.append((p, vals))
    grouped_bars(ax, [s["id"] for s in scenes], series, "mul + add per vertex")
    ax.set_title("Counted ops per drawn vertex (vertex shader incl. world to clip, "
                 "weighted rigid/skinned)", fontsize=9)
    save(fig, outdir, "ops_per_vertex")
    return ("ops_per_vertex", "Ops per vertex",
            "Multiplications + additions of one drawn vertex, counted by executing the shaders' "
            "GLSL through the op-counting shim; each scene weights the rigid, skinned and "
            "scaled-fallback variants by the vertices it draws.")


def plot_kernel_ratios(plt, report, outdir):
    pairs = [p for p in report.get("kernels", {}).get("pairs", []) if num(p.get("ratio_motor_matrix"))]
    if not pairs:
        return None
    kernels = []
    for p in pairs:
        if p["kernel"] not in kernels:
            kernels.append(p["kernel"])
    # Bars per kernel: in cache above, out of cache below; unsized kernels centred.
    sizes = [("in_cache", "in cache", "#4c72b0", -0.2), ("out_of_cache", "out of cache (>= 256 MiB)", "#c44e52", 0.2),
             (None, "one working set", "#8c8c8c", 0.0)]
    fig, ax = plt.subplots(figsize=(8, 0.45 * len(kernels) + 1.4))
    for size, label, col, offset in sizes:
        pts = [(k, p["ratio_motor_matrix"]) for k, name in enumerate(kernels) for p in pairs
               if p["kernel"] == name and p.get("size") == size]
        if not pts:
            continue
        ys = [k + offset for k, _ in pts]
        ax.barh(ys, [v for _, v in pts], 0.4, label=label, color=col)
        for y, (_, v) in zip(ys, pts):
            ax.annotate(f"{v:.2f}", (v, y), va="center", fontsize=7)
    ax.axvline(1.0, color="black", lw=0.8)
    ax.set_yticks(range(len(kernels)))
    ax.set_yticklabels(kernels, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("motor / matrix throughput (items/s; > 1: motor faster)")
    ax.set_title("CPU kernel throughput ratios (Google Benchmark, shim-compiled shader source)", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, outdir, "kernel_ratios")
    return ("kernel_ratios", "Kernel throughput ratios",
            "motorbench bench: items/s of the motor kernel over the matrix kernel of each pair, in "
            "cache and out of cache.")


def plot_frame_time_ratio(plt, report, outdir):
    scenes = scenes_with(report, lambda s: num((s.get("timing") or {}).get("ratio_motor_matrix")))
    if not scenes:
        return None
    fig, ax = plt.subplots(figsize=(8, 3.4))
    labels = [s["id"] for s in scenes]
    series = [("frame", [s["timing"]["ratio_motor_matrix"] for s in scenes])]
    vb = [num((s["timing"].get("vertexBound") or {}).get("ratio_motor_matrix")) for s in scenes]
    if any(v is not None for v in vb):
        series.append(("64x64 viewport (vertex-bound)", vb))
    cpu = [num((s["timing"].get("update") or {}).get("ratio_motor_matrix")) for s in scenes]
    if any(v is not None for v in cpu):
        series.append(("CPU update", cpu))
    grouped_bars(ax, labels, series, "motor / matrix time (< 1: motor faster)",
                 colours=["#4c72b0", "#c44e52", "#55a868"], digits=2, reference=1.0)
    ax.set_title("Frame-time ratios (median wall clock around glFinish)", fontsize=9)
    save(fig, outdir, "frame_time_ratio")
    return ("frame_time_ratio", "Frame-time ratios",
            "Median frame time of the motor pipeline over the matrix pipeline's (curved scenes: their "
            "space's pair, e.g. s3_motor / s3_matrix), both measured in one process with frames "
            "interleaved; the CPU update (hierarchy, animation, skin palette) timed apart.")


def plot_image_error(plt, report, outdir):
    pipes = report["settings"]["pipelines"][1:]
    scenes = scenes_with(report, lambda s: any(f.get("metrics") for f in s.get("frames", [])))
    if not scenes or not pipes:
        return None
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(9, 3.4))
    labels = [s["id"] for s in scenes]
    for i, p in enumerate(pipes):
        psnr, frac = [], []
        for s in scenes:
            ms = [f["metrics"][p] for f in s.get("frames", []) if p in f.get("metrics", {})]
            ps = [m["psnr"] for m in ms if num(m.get("psnr"))]
            psnr.append(min(ps) if ps else (100.0 if ms else None))  # identical: drawn at 100 dB
            fr = [m["fractionOver1"] for m in ms if num(m.get("fractionOver1")) is not None]
            frac.append(100 * max(fr) if fr else None)
        grouped_bars(a1, labels, [(p, psnr)], "worst PSNR [dB]")
        grouped_bars(a2, labels, [(p, frac)], "% pixels off by > 1/255")
    a1.set_title("Image agreement with %s (worst time; identical = 100)" % report["settings"]["baseline"],
                 fontsize=9)
    a2.set_title("Changed pixels (worst time)", fontsize=9)
    save(fig, outdir, "image_error")
    return ("image_error", "Image error per scene",
            "Worst PSNR and largest fraction of pixels differing by more than one 8-bit step, "
            "over the scene's animation times. On skinned scenes a pipeline that blends joint motors "
            "differs from the LBS baseline by design (the methods' expected difference, not an error).")


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
        for fn in (plot_bytes_per_vertex, plot_ops_per_vertex, plot_kernel_ratios,
                   plot_frame_time_ratio, plot_image_error):
            got = fn(plt, report, outdir)
            plt.close("all")
            if got is None:
                index["skipped"].append(fn.__name__[5:])
                continue
            name, title, caption = got
            index["files"].append({"name": name, "file": name + ".png", "title": title, "caption": caption})
    with open(os.path.join(outdir, "index.json"), "w") as f:
        json.dump(index, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
