#!/usr/bin/env python3
"""Differences between two results/ folders in every figure that is not a timing.

    scripts/results_diff.py                  committed results/ (git HEAD) vs the working tree's
    scripts/results_diff.py git:REV results  results/ at commit REV vs the folder results
    scripts/results_diff.py OLD NEW          two folders

Every *.json below each folder is read; timings and the run's circumstances (what a rerun of
scripts/reproduce.sh changes by itself) are left out by the rules below, everything else is
compared value for value: op counts, bytes, ISA statistics, image metrics, scene statistics,
claims on those. Prints one line per difference and exits 1 when there is one (0: the same).
"""
import json
import re
import subprocess
import sys
from pathlib import Path

# A key whose value is a timing, derived from one, or the run's circumstances (machine, load,
# date) is left out whole. Keys are split into words (camelCase, snake_case); these words mark
# a timing: ...Ms, ..._time, seconds, per_second, fps, ratios of times, disturbance, load.
TIMING_WORDS = {"ms", "time", "seconds", "second", "timing", "fps", "iterations", "ratio", "ratios",
                "spread", "disturbance", "disturbed", "runnable", "load", "mhz", "gbps", "bps", "bw"}
# Keys derived from a timing whose words do not say so: a bandwidth's share of the copy bandwidth;
# claims' tallies of verdicts, some of which are judged on timings; which implementation of a
# kernel pair ran fastest.
TIMING_DERIVED = {"copy_fraction", "bw_fraction", "counts", "paperCounts", "ownCounts", "fastest_matrix",
                  "fastest_motor"}
# Keys left out by name: the run's circumstances (a report made whole or merged from shards), and
# a count calibrated on the clock.
TIMING_NAMES = {"machine", "context", "date", "host_name", "cpu", "cpuOverReal", "bestOf", "best_of",
                "warmup", "update_calls_per_block", "shard"}
# Keys with a timing word that are not timings: animation times (of a frame, of a scene's
# frames, where a skin is thinnest) and counts of keyframe times.
NOT_TIMING = {"time", "times", "lbsTime", "motorTime", "timeWidth", "timeHeight"}
# Figures (report.json "figures", keyed by name) that are timings: frame and kernel times, and
# Pipeline::update's times per scene (update.<scene>.<pipeline>, update.hierarchy....).
TIMING_FIGURE = re.compile(r"(^|\.)(frame_time|kernel_time)|^update\.")
# What a claims evidence entry or a scope-ladder cell read from its figures: left out where those
# figures are timings (the references themselves are still compared).
READ_FROM_FIGURES = ("read", "passes", "leftOut", "figures", "ratios", "baselineSides", "worst", "best", "verdict",
                     "text", "n")
# A claim or answer line judged on a timing: its sentence, verdict and measured values move with
# the machine's load (a timing marked disturbed leaves the verdict and drops its kind); its id,
# origin, quote and method are still compared, and its non-timing inputs are compared where they
# are measured (ops.json, isa.json, report.json).
JUDGED_TEXT = ("measured", "measuredValue", "verdict", "verdictText", "text")


def words(key):
    return {w.lower() for w in re.findall(r"[A-Z]+(?![a-z])|[A-Z]?[a-z]+|[0-9]+", key)}


def is_timing_key(key):
    return key not in NOT_TIMING and (key in TIMING_NAMES or key in TIMING_DERIVED or
                                      bool(words(key) & TIMING_WORDS))


def judged_on_time(value):
    """Whether a claim or an answer line is judged on a timing."""
    return (
        # a claim whose measured value held a timing, or that names time or speed
        ("measuredValue" in value and (strip(value["measuredValue"]) != value["measuredValue"] or
                                       value.get("section") == "Speed" or
                                       bool(words(str(value.get("id", ""))) & {"time", "update"})))
        # a claim with evidence read from a timing figure
        or any(isinstance(e, dict) and (is_timing_reference(e.get("value")) or is_timing_reference(e.get("over")))
               for e in value.get("evidence", []) or [] if isinstance(value.get("evidence"), list))
        # an answer line quoting a timing figure
        or any(isinstance(f, str) and TIMING_FIGURE.search(f) for f in value.get("figures", []) or []
               if isinstance(value.get("figures"), list)))


def is_timing_reference(ref):
    """Whether "<source>:<figure name>" (a claims evidence's reference) names a timing figure."""
    return isinstance(ref, str) and ":" in ref and bool(TIMING_FIGURE.search(ref.split(":", 1)[1]))


def reads_timing(value):
    """A claims evidence entry whose figures are timings, or a scope-ladder cell of a measured
    (timed) kind."""
    if "label" in value and "value" in value and "read" in value:
        return is_timing_reference(value["value"]) or is_timing_reference(value.get("over"))
    return "samples" in value and value.get("kind") == "measured"


def timed_claims(value, found):
    """Adds to `found` the id of every claim in `value` judged on a timing."""
    if isinstance(value, list):
        for v in value:
            timed_claims(v, found)
    elif isinstance(value, dict):
        if "id" in value and judged_on_time(value):
            found.add(value["id"])
        for v in value.values():
            timed_claims(v, found)
    return found


def strip(value, key="", timed=frozenset(), under_timed=False):
    """value without its timing parts; `timed`: ids of claims judged on a timing in either run
    (a timing marked disturbed in one run can leave a claim with no timed kind there);
    `under_timed`: value is a part of such a claim or answer line (its kinds' texts move too)."""
    if isinstance(value, list):
        # plots/index.json: a plot of timings (frame_time_ratio, kernel_ratios) is left out whole.
        return [strip(v, key, timed, under_timed) for v in value
                if not (key == "files" and isinstance(v, dict) and is_timing_key(str(v.get("name", ""))))]
    if not isinstance(value, dict) or key == "glossary":  # the glossary's meanings are text
        return value
    under_timed = under_timed or judged_on_time(value) or value.get("id") in timed
    if reads_timing(value):
        value = {k: v for k, v in value.items() if k not in READ_FROM_FIGURES}
    out = {}
    for k, v in value.items():
        if is_timing_key(k) or (key == "figures" and TIMING_FIGURE.search(k)):
            continue
        out[k] = strip(v, k, timed, under_timed)
    if under_timed:
        for k in JUDGED_TEXT:
            out.pop(k, None)
    return out


# Keys that name a list entry (a claim's id, a scene, a pipeline, a benchmark, a shader variant):
# entries are matched by the values of those of these keys every entry has, so one entry added
# in the middle of a list is one difference, not a shift of every entry after it.
IDENTITY_KEYS = ("id", "name", "scene", "file", "pipeline", "variant", "shader", "stage", "kernel",
                 "gpu", "label", "anim", "method", "space", "kind", "run_type", "aggregate_name",
                 "repetition_index")


def identities(entries):
    """[identity of each entry], or None when the entries are not dicts named uniquely."""
    if not entries or not all(isinstance(e, dict) for e in entries):
        return None
    def named_by(k):  # every entry that has k has a name or number there (a missing one reads "-")
        present = [e[k] for e in entries if k in e]
        return present and all(isinstance(v, (str, int)) and not isinstance(v, bool) for v in present)

    # The naming keys in order, then (a shader per pipeline, variant and GPU family) the other
    # text fields every entry has, in sorted order: the shortest run of them that names every
    # entry once.
    candidates = [k for k in IDENTITY_KEYS if named_by(k)]
    candidates += sorted(k for k in entries[0] if k not in candidates and all(isinstance(e.get(k), str) for e in entries))
    for n in range(1, len(candidates) + 1):
        ids = ["/".join(str(e.get(k, "-")) for k in candidates[:n]) for e in entries]
        if len(set(ids)) == len(ids):
            return ids
    return None


def matched(a, b, names, path, out):
    """Compares two {name: value} maps entry by entry; `names` is the order of the lines."""
    for k in names:
        where = path(k)
        if k not in a:
            out.append(f"{where}: only in the new results")
        elif k not in b:
            out.append(f"{where}: only in the old results")
        else:
            differences(a[k], b[k], where, out)


def differences(a, b, path, out):
    if isinstance(a, dict) and isinstance(b, dict):
        matched(a, b, sorted(set(a) | set(b)), lambda k: f"{path}.{k}" if path else k, out)
    elif isinstance(a, list) and isinstance(b, list):
        ids_a, ids_b = identities(a), identities(b)
        if ids_a is not None and ids_b is not None:
            by_a, by_b = dict(zip(ids_a, a)), dict(zip(ids_b, b))
            matched(by_a, by_b, ids_a + [i for i in ids_b if i not in by_a], lambda i: f"{path}[{i}]", out)
            if [i for i in ids_a if i in ids_b] != [i for i in ids_b if i in ids_a]:
                out.append(f"{path}: the entries present in both are in another order")
            return
        if len(a) != len(b):
            out.append(f"{path}: {len(a)} entries before, {len(b)} now")
        for i, (x, y) in enumerate(zip(a, b)):
            differences(x, y, f"{path}[{i}]", out)
    elif a != b:
        out.append(f"{path}: {json.dumps(a)[:80]} -> {json.dumps(b)[:80]}")


def load_tree(spec):
    """{relative path: parsed JSON} of every .json in a folder or in git:REV's results/."""
    files = {}
    if spec.startswith("git:"):
        rev = spec[4:]
        names = subprocess.run(["git", "ls-tree", "-r", "--name-only", rev, "results/"],
                               check=True, capture_output=True, text=True).stdout.split()
        for name in names:
            if name.endswith(".json"):
                text = subprocess.run(["git", "show", f"{rev}:{name}"], check=True,
                                      capture_output=True, text=True).stdout
                files[name[len("results/"):]] = json.loads(text)
    else:
        root = Path(spec)
        if not root.is_dir():
            sys.exit(f"results_diff: {spec}: not a folder (or git:REV)")
        for p in sorted(root.rglob("*.json")):
            files[str(p.relative_to(root))] = json.loads(p.read_text())
    return files


def compare(old, new):
    """Lines naming each non-timing difference between two {path: JSON} trees."""
    out = []
    timed = frozenset(timed_claims(list(old.values()) + list(new.values()), set()))
    differences({k: strip(v, "", timed) for k, v in old.items()}, {k: strip(v, "", timed) for k, v in new.items()},
                "", out)
    return out


def main(argv):
    if len(argv) > 2 or any(a in ("-h", "--help") for a in argv):
        print(__doc__.strip())
        return 0 if argv and argv[0] in ("-h", "--help") else 2
    old_spec = argv[0] if argv else "git:HEAD"
    new_spec = argv[1] if len(argv) > 1 else "results"
    lines = compare(load_tree(old_spec), load_tree(new_spec))
    for line in lines:
        print(line)
    print(f"results_diff: {len(lines)} difference(s) outside timings between {old_spec} and {new_spec}",
          file=sys.stderr)
    return 1 if lines else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
