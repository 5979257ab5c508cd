#!/usr/bin/env python3
"""The redistributable real glTF corpus: its MANIFEST.tsv agrees with its files and licenses.

The corpus is looked for at $MB_BUNDLED_CORPUS, then tests/corpus (when it holds a MANIFEST.tsv),
then ../shared/corpus-bundled; its checks skip when none is there. The checker itself is tested on
small corpora built here (always run), and so is scripts/gltf_validate.mjs (when node and the
validator package that scripts/setup.sh installs are present).
"""
import base64
import csv
import hashlib
import json
import os
import shutil
import struct
import subprocess
import tempfile
import unittest
import urllib.parse

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
VALIDATE = os.path.join(REPO, "scripts", "gltf_validate.mjs")
VALIDATOR_PACKAGE = os.path.join(REPO, "scripts", "node_modules", "gltf-validator", "package.json")

ALLOWED_LICENSES = {"CC0-1.0", "CC-BY-4.0", "MIT", "Apache-2.0"}
LICENSE_MARKERS = {  # a phrase each license text holds, so an empty or wrong file is caught
    "CC0-1.0": "CC0 1.0 Universal",
    "CC-BY-4.0": "Attribution 4.0 International",
    "MIT": "Permission is hereby granted, free of charge",
    "Apache-2.0": "Apache License",
}
COLUMNS = ["path", "source_repo", "repo_path", "commit", "license", "attribution", "sha256", "bytes",
           "kind", "validator_errors", "validator_warnings"]
KIND_TAGS = {"static", "skinned", "morph", "animated", "draco", "meshopt", "instanced",
             "multi-primitive", "normal-mapped", "textured", "untextured"}
NOT_LISTED = {"MANIFEST.tsv", "README.md"}  # corpus files that describe it rather than belong to it
MAX_BYTES = 30 * 1000 * 1000
MIN_MODELS = 40
MIN_SOURCES = 6


def find_corpus():
    candidates = [os.environ.get("MB_BUNDLED_CORPUS", ""), os.path.join(REPO, "tests", "corpus"),
                  os.path.join(REPO, "..", "shared", "corpus-bundled")]
    for folder in candidates:
        if folder and os.path.isfile(os.path.join(folder, "MANIFEST.tsv")):
            return os.path.abspath(folder)
    return None


def read_manifest(corpus):
    with open(os.path.join(corpus, "MANIFEST.tsv"), encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f, delimiter="\t", quoting=csv.QUOTE_NONE))


def gltf_json(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":
        length, = struct.unpack_from("<I", data, 12)
        return json.loads(data[20:20 + length])
    return json.loads(data)


def texture_keys(material):
    """Names of the textureInfo objects a material holds, its extensions' included."""
    keys = []
    stack = [material]
    while stack:
        obj = stack.pop()
        if isinstance(obj, dict):
            for key, value in obj.items():
                if key.endswith("Texture") and isinstance(value, dict) and "index" in value:
                    keys.append(key)
                stack.append(value)
        elif isinstance(obj, list):
            stack.extend(obj)
    return keys


def kind_tags(doc):
    """The MANIFEST kind tags, derived from the glTF JSON alone."""
    used = set(doc.get("extensionsUsed", []))
    meshes = doc.get("meshes", [])
    primitives = [p for m in meshes for p in m.get("primitives", [])]
    skinned = bool(doc.get("skins")) and any("skin" in n and "mesh" in n for n in doc.get("nodes", []))
    morph = any(p.get("targets") for p in primitives)
    animated = bool(doc.get("animations"))
    textures = [k for m in doc.get("materials", []) for k in texture_keys(m)]
    tags = {"textured" if textures else "untextured"}
    flags = {"static": not (skinned or morph or animated), "skinned": skinned, "morph": morph,
             "animated": animated, "draco": "KHR_draco_mesh_compression" in used,
             "meshopt": bool(used & {"EXT_meshopt_compression", "KHR_meshopt_compression"}),
             "instanced": "EXT_mesh_gpu_instancing" in used,
             "multi-primitive": any(len(m.get("primitives", [])) > 1 for m in meshes),
             "normal-mapped": "normalTexture" in textures}
    return tags | {tag for tag, on in flags.items() if on}


def external_uris(doc):
    for key in ("buffers", "images"):
        for item in doc.get(key, []):
            uri = item.get("uri")
            if uri and not uri.startswith("data:"):
                yield urllib.parse.unquote(uri)


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def is_model(row):
    return row["kind"] != "dependency"


def row_problems(corpus, row):
    """What is wrong with one MANIFEST row: its file, its license, its attribution, its tags."""
    out = []
    name = row["path"]
    full = os.path.join(corpus, name)
    if not os.path.isfile(full):
        return [f"{name}: listed but missing"]
    if str(os.path.getsize(full)) != row["bytes"]:
        out.append(f"{name}: {os.path.getsize(full)} bytes, MANIFEST says {row['bytes']}")
    if sha256(full) != row["sha256"]:
        out.append(f"{name}: sha256 differs from the MANIFEST")
    license_id = row["license"]
    if license_id not in ALLOWED_LICENSES:
        out.append(f"{name}: license {license_id!r} is not one of {sorted(ALLOWED_LICENSES)}")
    else:
        text_path = os.path.join(corpus, "LICENSES", f"{license_id}.txt")
        if not os.path.isfile(text_path):
            out.append(f"{name}: LICENSES/{license_id}.txt is missing")
        else:
            with open(text_path, encoding="utf-8") as f:
                if LICENSE_MARKERS[license_id] not in f.read():
                    out.append(f"LICENSES/{license_id}.txt does not hold the {license_id} text")
    if not row["attribution"].strip():
        out.append(f"{name}: no attribution")
    if license_id == "CC-BY-4.0" and "CC BY 4.0" not in row["attribution"]:
        out.append(f"{name}: CC-BY attribution does not name the license (CC BY 4.0)")
    if len(row["commit"]) != 40:
        out.append(f"{name}: commit {row['commit']!r} is not a full git hash")
    if is_model(row):
        out.extend(model_problems(corpus, row, full))
    return out


def model_problems(corpus, row, full):
    out = []
    name = row["path"]
    tags = set(row["kind"].split(","))
    if not tags <= KIND_TAGS:
        out.append(f"{name}: unknown kind tags {sorted(tags - KIND_TAGS)}")
    doc = gltf_json(full)
    derived = kind_tags(doc)
    if tags != derived:
        out.append(f"{name}: kind {row['kind']} but the file is {','.join(sorted(derived))}")
    for column in ("validator_errors", "validator_warnings"):
        if not row[column].isdigit():
            out.append(f"{name}: {column} {row[column]!r} is not a count")
    for uri in external_uris(doc):
        dep = os.path.normpath(os.path.join(os.path.dirname(name), uri))
        if not os.path.isfile(os.path.join(corpus, dep)):
            out.append(f"{name}: its resource {uri} is missing")
    return out


def corpus_problems(corpus, max_bytes=MAX_BYTES, min_models=MIN_MODELS, min_sources=MIN_SOURCES):
    """Everything wrong with a corpus folder and its MANIFEST.tsv, as readable lines."""
    rows = read_manifest(corpus)
    if not rows:
        return ["MANIFEST.tsv has no rows"]
    missing_columns = [c for c in COLUMNS if c not in rows[0]]
    if missing_columns:
        return [f"MANIFEST.tsv lacks the columns {missing_columns}"]
    out = [p for row in rows for p in row_problems(corpus, row)]
    listed = {row["path"] for row in rows}
    for root, _, files in os.walk(corpus):
        for f in files:
            rel = os.path.relpath(os.path.join(root, f), corpus).replace(os.sep, "/")
            if rel not in listed and rel not in NOT_LISTED and not rel.startswith("LICENSES/"):
                out.append(f"{rel}: in the corpus but not in MANIFEST.tsv")
    models = [row for row in rows if is_model(row)]
    total = sum(int(row["bytes"]) for row in rows if row["bytes"].isdigit())
    if total > max_bytes:
        out.append(f"{total} bytes in all, more than {max_bytes}")
    if len(models) < min_models:
        out.append(f"{len(models)} models, fewer than {min_models}")
    sources = {row["source_repo"] for row in models}
    if len(sources) < min_sources:
        out.append(f"{len(sources)} source repositories, fewer than {min_sources}")
    readme = os.path.join(corpus, "README.md")
    readme_text = open(readme, encoding="utf-8").read() if os.path.isfile(readme) else ""
    for row in models:
        line = f"`{row['path']}`: {row['attribution']}"
        if row["license"] == "CC-BY-4.0" and line not in readme_text:
            out.append(f"{row['path']}: CC-BY file without its attribution line in README.md ({line})")
    return out


def triangle_gltf(buffer_uri):
    """A one-triangle glTF whose positions lie in the buffer at buffer_uri."""
    return {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
            "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "buffers": [{"byteLength": 36, "uri": buffer_uri}],
            "bufferViews": [{"buffer": 0, "byteLength": 36, "target": 34962}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 0]}]}


TRIANGLE_POSITIONS = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)


class SyntheticCorpus:
    """A two-file corpus (a .gltf and its .bin) with a correct MANIFEST, to break on purpose."""

    def __init__(self, root):
        self.root = root
        self.rows = []
        os.makedirs(os.path.join(root, "LICENSES"))
        with open(os.path.join(root, "LICENSES", "CC0-1.0.txt"), "w", encoding="utf-8") as f:
            f.write("Creative Commons Legal Code\n\nCC0 1.0 Universal\n")
        self.add("some+repo/tri.bin", TRIANGLE_POSITIONS, "dependency")
        self.add("some+repo/tri.gltf", json.dumps(triangle_gltf("tri.bin")).encode(), "static,untextured")
        self.write_manifest()

    def add(self, path, data, kind):
        full = os.path.join(self.root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "wb") as f:
            f.write(data)
        self.rows.append({"path": path, "source_repo": "some/repo", "repo_path": path.split("/", 1)[1],
                          "commit": "0" * 40, "license": "CC0-1.0", "attribution": "Someone, CC0",
                          "sha256": hashlib.sha256(data).hexdigest(), "bytes": str(len(data)),
                          "kind": kind, "validator_errors": "0" if kind != "dependency" else "-",
                          "validator_warnings": "0" if kind != "dependency" else "-"})

    def write_manifest(self):
        with open(os.path.join(self.root, "MANIFEST.tsv"), "w", encoding="utf-8") as f:
            f.write("\t".join(COLUMNS) + "\n")
            for row in self.rows:
                f.write("\t".join(row[c] for c in COLUMNS) + "\n")

    def problems(self):
        return corpus_problems(self.root, min_models=1, min_sources=1)


class CheckerCatches(unittest.TestCase):
    """corpus_problems on a corpus built here: quiet when it is right, loud on each defect."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="bundled-corpus-")
        self.corpus = SyntheticCorpus(os.path.join(self.dir, "c"))

    def tearDown(self):
        shutil.rmtree(self.dir)

    def assertProblem(self, needle):
        problems = self.corpus.problems()
        self.assertTrue(any(needle in p for p in problems), f"no problem with {needle!r} in {problems}")

    def test_a_correct_corpus_has_no_problem(self):
        self.assertEqual(self.corpus.problems(), [])

    def test_a_missing_license_text(self):
        os.remove(os.path.join(self.corpus.root, "LICENSES", "CC0-1.0.txt"))
        self.assertProblem("LICENSES/CC0-1.0.txt is missing")

    def test_a_license_not_allowed(self):
        self.corpus.rows[1]["license"] = "CC-BY-NC-4.0"
        self.corpus.write_manifest()
        self.assertProblem("license 'CC-BY-NC-4.0' is not one of")

    def test_cc_by_without_attribution(self):
        with open(os.path.join(self.corpus.root, "LICENSES", "CC-BY-4.0.txt"), "w", encoding="utf-8") as f:
            f.write("Attribution 4.0 International\n")
        self.corpus.rows[1].update(license="CC-BY-4.0", attribution="")
        self.corpus.write_manifest()
        self.assertProblem("no attribution")
        self.assertProblem("CC-BY file without its attribution line in README.md")

    def test_a_changed_byte(self):
        with open(os.path.join(self.corpus.root, "some+repo", "tri.bin"), "r+b") as f:
            f.write(b"\x01")
        self.assertProblem("some+repo/tri.bin: sha256 differs")

    def test_an_unlisted_file(self):
        with open(os.path.join(self.corpus.root, "some+repo", "extra.png"), "wb") as f:
            f.write(b"\x89PNG")
        self.assertProblem("some+repo/extra.png: in the corpus but not in MANIFEST.tsv")

    def test_a_missing_dependency(self):
        del self.corpus.rows[0]
        self.corpus.write_manifest()
        os.remove(os.path.join(self.corpus.root, "some+repo", "tri.bin"))
        self.assertProblem("its resource tri.bin is missing")

    def test_kind_tags_that_do_not_match_the_file(self):
        self.corpus.rows[1]["kind"] = "skinned,untextured"
        self.corpus.write_manifest()
        self.assertProblem("kind skinned,untextured but the file is static,untextured")

    def test_too_few_models_and_sources(self):
        problems = corpus_problems(self.corpus.root)
        self.assertIn(f"1 models, fewer than {MIN_MODELS}", problems)
        self.assertIn(f"1 source repositories, fewer than {MIN_SOURCES}", problems)


@unittest.skipUnless(find_corpus(), "no bundled corpus ($MB_BUNDLED_CORPUS, tests/corpus, ../shared/corpus-bundled)")
class BundledCorpus(unittest.TestCase):
    def test_manifest_agrees_with_files_and_licenses(self):
        self.assertEqual(corpus_problems(find_corpus()), [])


@unittest.skipUnless(shutil.which("node") and os.path.isfile(VALIDATOR_PACKAGE),
                     "node or scripts/node_modules/gltf-validator absent (scripts/setup.sh installs them)")
class GltfValidateScript(unittest.TestCase):
    """scripts/gltf_validate.mjs reads external buffers, counts errors, and fails with --strict."""

    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="gltf-validate-")
        cls.write("external.gltf", json.dumps(triangle_gltf("external.bin")).encode())
        cls.write("external.bin", TRIANGLE_POSITIONS)
        cls.write("no_buffer.gltf", json.dumps(triangle_gltf("absent.bin")).encode())
        embedded = "data:application/octet-stream;base64," + base64.b64encode(TRIANGLE_POSITIONS).decode()
        broken = triangle_gltf(embedded)
        broken["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7  # no accessor 7
        cls.write("broken.gltf", json.dumps(broken).encode())

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir)

    @classmethod
    def write(cls, name, data):
        with open(os.path.join(cls.dir, name), "wb") as f:
            f.write(data)

    def run_script(self, *args):
        return subprocess.run(["node", VALIDATE, *args], capture_output=True, text=True, timeout=60)

    def test_rows_per_file(self):
        proc = self.run_script(self.dir)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        lines = proc.stdout.splitlines()
        self.assertEqual(lines[0].split("\t"), ["path", "errors", "warnings", "infos", "hints", "codes"])
        rows = {os.path.basename(line.split("\t")[0]): line.split("\t") for line in lines[1:]}
        self.assertEqual(sorted(rows), ["broken.gltf", "external.gltf", "no_buffer.gltf"])
        self.assertEqual(rows["external.gltf"][1:3], ["0", "0"])
        self.assertEqual(rows["no_buffer.gltf"][1], "1")
        self.assertIn("IO_ERROR*1", rows["no_buffer.gltf"][5])
        self.assertIn("UNRESOLVED_REFERENCE", rows["broken.gltf"][5])

    def test_strict_fails_on_an_error_only(self):
        self.assertEqual(self.run_script("--strict", os.path.join(self.dir, "external.gltf")).returncode, 0)
        self.assertEqual(self.run_script("--strict", os.path.join(self.dir, "broken.gltf")).returncode, 1)

    def test_json_output(self):
        proc = self.run_script("--json", os.path.join(self.dir, "no_buffer.gltf"))
        rows = json.loads(proc.stdout)
        self.assertEqual([(r["errors"], r["codes"]) for r in rows], [(1, ["IO_ERROR*1"])])

    def test_not_gltf_is_one_error_with_the_reason(self):
        path = os.path.join(self.dir, "..", "not_gltf_" + os.path.basename(self.dir) + ".glb")
        with open(path, "wb") as f:
            f.write(b"plain text")
        try:
            rows = json.loads(self.run_script("--json", path).stdout)
        finally:
            os.remove(path)
        self.assertEqual(rows[0]["errors"], 1)
        self.assertIn("could not detect glTF format", rows[0]["failure"])


if __name__ == "__main__":
    unittest.main()
