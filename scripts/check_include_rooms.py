#!/usr/bin/env python3
"""Checks that every #include between the project's rooms goes in an allowed direction.

A room is a folder whose README.md has a line

    May include: `pipelines/scene`, `shaders`

(or "May include: nothing"). A source file belongs to the deepest room folder above it, and a
quoted #include "a/b/c.h" lands in the deepest room folder that is a prefix of "a/b/c.h". An
include is allowed when it lands in the file's own room or in a room its README lists (exactly:
listing `pipelines` does not admit `pipelines/matrix`). Includes outside every room
(tests/, system headers) are not checked here. So the picture in README.md's Architecture
section -- pipelines never include harness; shaders include nothing else -- stays true.

A room that measures nothing (MEASURES_NOTHING: harness/claims) may not include a room that
measures or renders, even where its README lists it.

Usage: scripts/check_include_rooms.py [REPO_ROOT]   exit 0 when clean, 1 with one line per
violation ("file:line: room X includes Y (room Z); X may include: ...").
"""
import os
import re
import sys

SOURCE_SUFFIXES = (".h", ".cpp", ".inl", ".inc", ".glsl", ".vs", ".fs")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
RULE = re.compile(r"^May include:\s*(.*)$", re.MULTILINE)
CHECKED_TOPS = ("harness", "kernels", "pipelines", "shaders")
# Rooms that measure nothing: they judge or print figures other rooms measured, so no include
# may reach a room that measures or renders (a prefix covers its sub-rooms), whatever their
# README lists.
MEASURES_NOTHING = {
    "harness/claims": ("harness/ops", "harness/isa", "harness/render", "harness/timing", "harness/bench",
                       "harness/report", "harness/accuracy", "harness/process", "harness/check", "pipelines",
                       "shaders"),
}


def measuring(target, forbidden):
    """Whether room `target` is one of `forbidden` or below one of them."""
    return any(target == f or target.startswith(f + "/") for f in forbidden)


def read_rooms(root):
    """{room path: set of allowed room paths} from every README.md with a May include line."""
    rooms = {}
    for top in CHECKED_TOPS:
        for folder, _, files in os.walk(os.path.join(root, top)):
            if "README.md" not in files:
                continue
            with open(os.path.join(folder, "README.md"), encoding="utf-8") as f:
                m = RULE.search(f.read())
            if not m:
                continue
            rel = os.path.relpath(folder, root).replace(os.sep, "/")
            listed = m.group(1).strip()
            allowed = set() if listed.startswith("nothing") else set(re.findall(r"`([^`]+)`", listed))
            rooms[rel] = allowed
    return rooms


def room_of(path, rooms):
    """The deepest room that is `path` or a folder above it; None outside every room."""
    parts = path.split("/")
    for n in range(len(parts), 0, -1):
        candidate = "/".join(parts[:n])
        if candidate in rooms:
            return candidate
    return None


def violations(root):
    rooms = read_rooms(root)
    found = []
    for room in sorted(rooms):
        for folder, _, files in os.walk(os.path.join(root, room)):
            for name in sorted(files):
                if not name.endswith(SOURCE_SUFFIXES):
                    continue
                path = os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/")
                own = room_of(os.path.dirname(path), rooms)
                if own != room:
                    continue  # a deeper room checks it
                with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                    for line_no, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = room_of(os.path.dirname(m.group(1)), rooms)
                        if target is not None and measuring(target, MEASURES_NOTHING.get(own, ())):
                            found.append(f"{path}:{line_no}: room {own} measures nothing but includes "
                                         f"{m.group(1)} (room {target}, which measures or renders)")
                            continue
                        if target is None or target == own or target in rooms[own]:
                            continue
                        allowed = ", ".join(sorted(rooms[own])) or "nothing"
                        found.append(f"{path}:{line_no}: room {own} includes {m.group(1)} "
                                     f"(room {target}); {own} may include: {allowed}")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    rooms = read_rooms(root)
    if not rooms:
        print(f"check_include_rooms: no README.md with 'May include:' under {root}", file=sys.stderr)
        return 2
    found = violations(root)
    for v in found:
        print(v)
    print(f"check_include_rooms: {len(rooms)} rooms, {len(found)} violations")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
