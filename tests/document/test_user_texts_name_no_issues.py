"""What a user reads names no issue of the project's tracker: `motorbench help`, `motorbench help
<command>` for every command that list names, README.md, and the texts results/ holds (every .md,
.txt and .html under it, and the plots' titles, captions, series and labels in plots/index.json)
hold no "issue N". A reader of the help or of a report has no tracker to look N up in; what a
reference meant is said in words, and history is git log's. Each hit is reported as FILE:LINE (or
the command) with the line.

MB_RESULTS_DIR points the results part at another folder (e.g. a report just made into /tmp);
when the results folder is absent, that part alone is skipped.
"""
import concurrent.futures
import json
import os
import re
import subprocess
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ.get("MB_MOTORBENCH_EXE", os.path.join(REPO, "build", "harness", "motorbench"))
RESULTS = os.environ.get("MB_RESULTS_DIR", os.path.join(REPO, "results"))
README = os.path.join(REPO, "README.md")

# The word, then a number: "<word> 35", "<Word> 36 item 6", "<word>s 18 and 35", "<word> #12".
ISSUE = re.compile(r"\b[Ii]ssues? #?[0-9]+")
# The planted references below are spelled through W, so that this file holds none itself
# (`git grep -nE '[Ii]ssue [0-9]+'` over the code finds nothing here).
W = "issue"
TEXT_SUFFIXES = (".md", ".txt", ".html")


def around(text, match, width=70):
    """The match with up to `width` characters either side, on one line."""
    start, end = max(match.start() - width, 0), min(match.end() + width, len(text))
    return ("..." if start else "") + text[start:end].strip() + ("..." if end < len(text) else "")


def hits_in_lines(where, text):
    """["WHERE:LINE: ...the words around the reference..."] for every line of `text` that names an
    issue."""
    return [f"{where}:{n}: {around(line, m)}"
            for n, line in enumerate(text.splitlines(), 1) for m in [ISSUE.search(line)] if m]


def json_strings(value, path=""):
    """(path, string) for every string in a JSON value, keys included."""
    if isinstance(value, str):
        yield path, value
    elif isinstance(value, dict):
        for k, v in value.items():
            yield f"{path}.{k}", k
            yield from json_strings(v, f"{path}.{k}")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from json_strings(v, f"{path}[{i}]")


def hits_in_folder(folder):
    """Every hit in the text files and plot indexes under `folder`, and how many files were read."""
    hits, read = [], 0
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(root, name)
            shown = os.path.relpath(path, folder)
            if name.endswith(TEXT_SUFFIXES):
                with open(path, encoding="utf-8", errors="replace") as f:
                    hits += hits_in_lines(shown, f.read())
                read += 1
            elif name == "index.json" and os.path.basename(root) == "plots":
                with open(path, encoding="utf-8") as f:
                    index = json.load(f)
                hits += [f"{shown}{p}: {around(s, m)}"
                         for p, s in json_strings(index) for m in [ISSUE.search(s)] if m]
                read += 1
    return hits, read


def motorbench(*args):
    """(exit status, stdout + stderr) of one motorbench run."""
    r = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=60)
    return r.returncode, r.stdout + r.stderr


def listed_commands(help_text):
    """The command names `motorbench help` lists under "commands:" (two spaces, then the name)."""
    body = help_text.split("commands:", 1)[-1]
    return [m.group(1) for m in re.finditer(r"^  ([a-z][a-z0-9_-]*)\s", body, re.M)]


class ScannerFindsWhatItLooksFor(unittest.TestCase):
    """The scan itself, on a folder written here: without this, a scan that reads nothing passes."""

    def test_hits_name_file_and_line(self):
        with tempfile.TemporaryDirectory(prefix="mb-issue-scan-") as d:
            os.makedirs(os.path.join(d, "corpus"))
            os.makedirs(os.path.join(d, "plots"))
            with open(os.path.join(d, "report.md"), "w") as f:
                f.write(f"# Report\nclean line\nthe fallback ({W} 34) counted\n")
            with open(os.path.join(d, "corpus", "notes.txt"), "w") as f:
                f.write(f"{W.title()} 36 item 2: the answer\n")
            with open(os.path.join(d, "plots", "index.json"), "w") as f:
                json.dump({"files": [{"title": "Design space", "caption": f"as {W}s 18 and 35 asked"}]}, f)
            with open(os.path.join(d, "image.png"), "w") as f:
                f.write(f"{W} 1\n")  # not a text the scan reads
            hits, read = hits_in_folder(d)
        self.assertEqual(read, 3)
        self.assertEqual(sorted(hits), [f"corpus/notes.txt:1: {W.title()} 36 item 2: the answer",
                                        f"plots/index.json.files[0].caption: as {W}s 18 and 35 asked",
                                        f"report.md:3: the fallback ({W} 34) counted"])

    def test_words_that_only_contain_issue_pass(self):
        self.assertEqual(hits_in_lines("x", f"t{W} 5\n{W} tracker\nmis{W} 3\n"), [])
        self.assertEqual(len(hits_in_lines("x", f"{W} #12\n{W.title()}s 4 and 5\n")), 2)


class HelpNamesNoIssue(unittest.TestCase):
    def test_help_and_every_commands_help(self):
        self.assertTrue(os.access(EXE, os.X_OK), f"{EXE}: not built (MB_MOTORBENCH_EXE names another)")
        status, top = motorbench("help")
        self.assertEqual(status, 0, top)
        commands = listed_commands(top)
        # The list is what every other help is found by: it must hold the commands a user starts with.
        for expected in ("report", "compare", "check", "render", "inspect"):
            self.assertIn(expected, commands, f"`motorbench help` lists no {expected}:\n{top}")
        hits = hits_in_lines("motorbench help", top)
        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
            runs = dict(zip(commands, pool.map(lambda c: motorbench("help", c), commands)))
        for command, (status, text) in runs.items():
            self.assertEqual(status, 0, f"motorbench help {command}:\n{text}")
            self.assertTrue(text.strip(), f"motorbench help {command}: printed nothing")
            hits += hits_in_lines(f"motorbench help {command}", text)
        self.assertEqual(hits, [], "help texts name issues:\n" + "\n".join(hits))


class DocumentsNameNoIssue(unittest.TestCase):
    def test_readme(self):
        with open(README, encoding="utf-8") as f:
            hits = hits_in_lines("README.md", f.read())
        self.assertEqual(hits, [], "README.md names issues:\n" + "\n".join(hits))

    def test_results_texts(self):
        if not os.path.isdir(RESULTS):
            self.skipTest(f"{RESULTS}: no results folder")
        hits, read = hits_in_folder(RESULTS)
        self.assertGreater(read, 0, f"{RESULTS}: no .md, .txt, .html or plots/index.json to read")
        self.assertEqual(hits, [], f"texts under {RESULTS} name issues:\n" + "\n".join(hits))


if __name__ == "__main__":
    unittest.main()
