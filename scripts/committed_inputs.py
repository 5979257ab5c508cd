#!/usr/bin/env python3
"""The committed inputs of results/: figures measured over corpora a clone does not have
(../shared/corpus, ../shared/corpus-graph, ../shared/corpus-wide), kept in git with their
provenance in results/inputs.json. scripts/reproduce.sh regenerates an input where its source
folder is present (and records it here) and reads the committed one where it is not.

    scripts/committed_inputs.py record RESULTS NAME --source DIR --outputs PATH... --command CMD --what TEXT
                                       [--used FILE...] [--used-morph MORPH.json]
        (re)writes NAME's entry: the source folder's files (count, bytes, one sha256 over every
        file's sha256 and path, each file listed when there are at most 40; its MANIFEST's sha256),
        the files the figures were measured on when a part of it (--used, or the scenes of a
        motorbench morph JSON), the project commit that measured them, the date
    scripts/committed_inputs.py check RESULTS
        one line per input: regenerated from its source (present) or read as committed (absent);
        exit 1 naming the missing files when an input whose source is absent is not there
    scripts/committed_inputs.py markdown RESULTS
        the inputs as a Markdown list (results/README.md)

Relative source paths are taken from the repository root (where reproduce.sh runs).
"""
import argparse
import datetime
import hashlib
import json
import subprocess
import sys
from pathlib import Path

SCHEMA = "motorbench-inputs/1"
LISTED = 40  # at most this many source files are listed one by one
MANIFESTS = ("MANIFEST.tsv", "MANIFEST.md")


def load(results):
    path = Path(results) / "inputs.json"
    if not path.exists():
        return {"schema": SCHEMA, "inputs": []}
    doc = json.loads(path.read_text())
    if doc.get("schema") != SCHEMA:
        sys.exit(f"committed_inputs: {path}: not a {SCHEMA} file")
    return doc


def save(results, doc):
    (Path(results) / "inputs.json").write_text(json.dumps(doc, indent=1, sort_keys=True) + "\n")


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def source_files(folder):
    """{"count", "bytes", "sha256", "manifest", "files"?} of every file under `folder`."""
    root = Path(folder)
    files = sorted(p for p in root.rglob("*") if p.is_file())
    rows = [{"file": str(p.relative_to(root)), "bytes": p.stat().st_size, "sha256": sha256(p)} for p in files]
    digest = hashlib.sha256("".join(f"{r['sha256']}  {r['file']}\n" for r in rows).encode()).hexdigest()
    out = {"count": len(rows), "bytes": sum(r["bytes"] for r in rows), "sha256": digest,
           "sha256Rule": "sha256 of the lines '<file sha256>  <path>' of every file, sorted by path (sha256sum's format)"}
    manifest = next((m for m in MANIFESTS if (root / m).is_file()), None)
    out["manifest"] = {"file": manifest, "sha256": sha256(root / manifest)} if manifest else None
    if len(rows) <= LISTED:
        out["files"] = rows
    return out


def used_files(paths):
    """[{"file", "bytes", "sha256"}] of the files the input was measured on."""
    return [{"file": p, "bytes": Path(p).stat().st_size, "sha256": sha256(p)} for p in paths]


def project_commit():
    """The commit the measuring code was built from, '+modified' when the tree outside results/ differs."""
    def git(*args):
        return subprocess.run(["git", *args], capture_output=True, text=True).stdout.strip()
    commit = git("rev-parse", "HEAD")
    if not commit:
        return None
    changed = git("status", "--porcelain", "--untracked-files=no", "--", ".", ":(exclude)results")
    return commit + ("+modified" if changed else "")


def used(args):
    paths = list(args.used or [])
    if args.used_morph:
        paths += [s["scene"] for s in json.loads(Path(args.used_morph).read_text())["scenes"] if Path(s["scene"]).is_file()]
    return paths


def record(args):
    if not Path(args.source).is_dir():
        sys.exit(f"committed_inputs: {args.source}: not a folder (record runs where the source is present)")
    doc = load(args.results)
    entry = {"name": args.name, "what": args.what, "source": args.source, "outputs": args.outputs,
             "command": args.command, "sourceFiles": source_files(args.source),
             "usedFiles": used_files(used(args)) if used(args) else None,
             "measuredWith": args.commit or project_commit(),
             "date": args.date or datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")}
    doc["inputs"] = [e for e in doc["inputs"] if e["name"] != args.name] + [entry]
    doc["inputs"].sort(key=lambda e: e["name"])
    save(args.results, doc)


def missing_outputs(results, entry):
    return [o for o in entry["outputs"] if not (Path(results) / o).exists()]


def check(args):
    doc = load(args.results)
    bad = []
    for e in doc["inputs"]:
        if Path(e["source"]).is_dir():
            print(f"{e['name']}: {e['source']} present: measured again by this run")
            continue
        missing = missing_outputs(args.results, e)
        if missing:
            bad.append(f"{e['name']}: {e['source']} absent and the committed " +
                       ", ".join(f"{args.results}/{m}" for m in missing) + " missing (git checkout -- results/ restores it)")
            continue
        print(f"{e['name']}: {e['source']} absent: read as committed ({', '.join(e['outputs'])}; "
              f"{e['sourceFiles']['count']} source files, measured {e['date']})")
    for line in bad:
        print("committed_inputs: " + line, file=sys.stderr)
    return 1 if bad else 0


def markdown(args):
    for e in load(args.results)["inputs"]:
        src = e["sourceFiles"]
        part = f"; measured on {len(e['usedFiles'])} of its files (listed in inputs.json)" if e.get("usedFiles") else ""
        manifest = f", its {src['manifest']['file']} sha256 `{src['manifest']['sha256'][:12]}`" if src.get("manifest") else ""
        this_run = "regenerated in this run" if Path(e["source"]).is_dir() else "read as committed in this run (folder absent)"
        outputs = ", ".join(f"[{o}]({o})" for o in e["outputs"])
        print(f"- {outputs}: {e['what']}. Source: {e['source']} ({src['count']} files, {src['bytes']} bytes, "
              f"sha256 `{src['sha256'][:12]}`{manifest}{part}), measured with {e['measuredWith']} on {e['date']} by "
              f"`{e['command']}`; {this_run}.")
    return 0


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__.split("\n\n", 1)[1])
    sub = parser.add_subparsers(dest="action", required=True)
    r = sub.add_parser("record")
    r.add_argument("results")
    r.add_argument("name")
    r.add_argument("--source", required=True)
    r.add_argument("--outputs", nargs="+", required=True)
    r.add_argument("--command", required=True)
    r.add_argument("--what", required=True)
    r.add_argument("--used", nargs="+", help="the files measured, when a part of the source")
    r.add_argument("--used-morph", help="a motorbench morph JSON whose scenes are the files measured")
    r.add_argument("--commit", help="the measuring commit, when not this checkout's HEAD")
    r.add_argument("--date", help="the date measured, when not now")
    for name in ("check", "markdown"):
        sub.add_parser(name).add_argument("results")
    args = parser.parse_args(argv)
    if args.action == "record":
        record(args)
        return 0
    return check(args) if args.action == "check" else markdown(args)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
