"""The include direction of README.md's Architecture section (scripts/check_include_rooms.py).

The repository itself must be clean; a copy of its room rules with one forbidden include added
(a pipelines/ file including a harness/ header, a harness room including the cli) must fail,
naming the file, the line and the rule.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SCRIPT = os.path.join(REPO, "scripts", "check_include_rooms.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
import check_include_rooms  # noqa: E402


def copy_rules(dst):
    """Only the README.md files that declare rooms: a tree with rooms and no sources."""
    for top in check_include_rooms.CHECKED_TOPS:
        for folder, _, files in os.walk(os.path.join(REPO, top)):
            if "README.md" in files:
                rel = os.path.relpath(folder, REPO)
                os.makedirs(os.path.join(dst, rel), exist_ok=True)
                shutil.copy(os.path.join(folder, "README.md"), os.path.join(dst, rel, "README.md"))


def write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


class IncludeRooms(unittest.TestCase):
    def test_repository_follows_its_rooms(self):
        run = subprocess.run([sys.executable, SCRIPT, REPO], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn(" 0 violations", run.stdout)

    def test_every_harness_and_pipelines_folder_is_a_room(self):
        rooms = check_include_rooms.read_rooms(REPO)
        for top in ("harness", "pipelines"):
            for entry in os.scandir(os.path.join(REPO, top)):
                if entry.is_dir():
                    self.assertIn(f"{top}/{entry.name}", rooms, f"{top}/{entry.name} has no README.md with 'May include:'")
        self.assertEqual(rooms["shaders"], set())
        for room, allowed in rooms.items():
            if room.startswith("pipelines"):
                self.assertFalse([a for a in allowed if a.startswith("harness")], room)

    def test_pipelines_including_harness_fails(self):
        with tempfile.TemporaryDirectory() as tmp:
            copy_rules(tmp)
            write(tmp, "pipelines/scene/loader.cpp", '#include <vector>\n#include "pipelines/result.h"\n')
            write(tmp, "pipelines/motor/bad.cpp", '#include "pipelines/scene/scene.h"\n\n#include "harness/render/render_frame.h"\n')
            run = subprocess.run([sys.executable, SCRIPT, tmp], capture_output=True, text=True)
            self.assertEqual(run.returncode, 1, run.stdout)
            self.assertIn("pipelines/motor/bad.cpp:3: room pipelines/motor includes harness/render/render_frame.h", run.stdout)
            self.assertNotIn("loader.cpp", run.stdout)
            self.assertIn(" 1 violations", run.stdout)

    def test_lower_harness_room_including_cli_fails(self):
        with tempfile.TemporaryDirectory() as tmp:
            copy_rules(tmp)
            write(tmp, "harness/render/frame.cpp", '#include "harness/options/args.h"\n#include "harness/cli/command.h"\n')
            write(tmp, "shaders/x.glsl", '#include "pipelines/scene/scene.h"\n')
            found = check_include_rooms.violations(tmp)
            self.assertEqual(len(found), 2, found)
            self.assertTrue(found[0].startswith("harness/render/frame.cpp:2: room harness/render includes harness/cli/command.h"), found)
            self.assertTrue(found[1].startswith("shaders/x.glsl:1: room shaders includes"), found)

    def test_claims_including_a_measuring_room_fails_even_when_listed(self):
        with tempfile.TemporaryDirectory() as tmp:
            copy_rules(tmp)
            readme = os.path.join(tmp, "harness", "claims", "README.md")
            with open(readme, encoding="utf-8") as f:
                text = f.read()
            with open(readme, "w", encoding="utf-8") as f:  # the README admits it: still refused
                f.write(text.replace("May include: `harness/figures`", "May include: `harness/ops`, `harness/figures`"))
            write(tmp, "harness/claims/rows.cpp", '#include "harness/figures/figure.h"\n#include "harness/ops/op_count.h"\n')
            write(tmp, "harness/claims/other.cpp", '#include "pipelines/motor/motor_rig.h"\n')
            found = check_include_rooms.violations(tmp)
            self.assertEqual(len(found), 2, found)
            self.assertTrue(found[0].startswith("harness/claims/other.cpp:1: room harness/claims measures nothing"), found)
            self.assertTrue(found[1].startswith("harness/claims/rows.cpp:2: room harness/claims measures nothing but "
                                                "includes harness/ops/op_count.h"), found)


if __name__ == "__main__":
    unittest.main()
