#!/usr/bin/env python3
"""Unity batches that do not clash: cmake/motorbench.cmake's mb_unity runs this at configure time.

    unity_groups.py ROOT BATCH FILE...   prints one line per FILE: its batch number, or '-' (alone)

Two files of one batch are one translation unit, so a name each defines at file scope (a helper
in an anonymous namespace, a static, a kConstant, a struct) would be defined twice there. This
reads the names every file defines at column 0 and fills the batches first-fit, never putting
two files that define the same name together; so file-local helpers need not be renamed for
the batches. Conservative: a name counts as defined even when it is an overload or an external
definition (that only costs a batch). A file defining an *_IMPLEMENTATION macro or
re-including itself per SIMD target (HWY_TARGET_INCLUDE), or whose first line is
'// MB_UNITY_ALONE', stays alone. A file-scope line that is the same text in both files (using
json = nlohmann::json;) is no clash. What this misses (an indented definition in a namespace) is
still caught by the build: scripts/build_fallback.sh then builds file by file and says why.
"""
import os
import re
import sys

ALONE = re.compile(r"HWY_TARGET_INCLUDE|#define [A-Z_]+_IMPLEMENTATION")
# The name a column-0 line defines, tried in order; group 1 is the name.
DEFINES = [
    re.compile(r"(?:struct|class|union|enum(?:\s+class)?)\s+(\w+)"),
    re.compile(r"#define\s+(\w+)"),
    re.compile(r"(?:[\w:<>,*&\s]+?[\s*&])(\w+)\s*\("),  # a function (not Type::member)
    re.compile(r"(?:[\w:<>,*&\s]+?[\s*&])(\w+)\s*(?:\[[^\]]*\])?\s*(?:=|\{|;)"),  # a variable
]
SAME_TEXT_OK = re.compile(r"(?:using|namespace)\s+(\w+)\s*=|using\s+[\w:]+::(\w+)\s*;|#define\s+(\w+)")
SKIP = re.compile(r"(?:namespace\b|using\s+namespace\b|extern\b|template\b|return\b|[}#/\s]|TEST)")


HEADER = "(declared by an included header)"
NAMESPACE_OPEN = re.compile(r"namespace(\s+[\w:]+)?\s*\{")
NAMED_NAMESPACE = re.compile(r"namespace\s+\w")
DECLARATORS = re.compile(r",\s*(\w+)\s*=(?!=)")


def names_in(text, header=None):
    """Column-0 names in `text` -> what they are. In a header (`header`: its path): HEADER for a
    function, macro or using-declaration (another header's overload, guarded copy or the same
    entity is no clash), the line for an alias, the header's path for a type or constant (two
    headers' kUShort are ambiguous once two files' `using namespace` meet in a batch). In a .cpp: the line for a same-text-ok line (an alias, a
    using-declaration), else None. Also the names defined inside an anonymous namespace or static
    (file-local even where a header declares the same name: an overload beside it)."""
    names, local, scopes = {}, set(), []
    for line in text.splitlines():
        line = line.rstrip()
        if NAMESPACE_OPEN.match(line):
            scopes.append(not NAMED_NAMESPACE.match(line))
            continue
        if line.startswith("}") and "namespace" in line and scopes:
            scopes.pop()
            continue
        m = SAME_TEXT_OK.match(line)
        if m:
            # In a header: an alias is its line, a using-declaration or macro names what exists.
            names[m.group(1) or m.group(2) or m.group(3)] = line if header is None or m.group(1) else HEADER
            continue
        if not line or SKIP.match(line):
            continue
        for pattern in DEFINES:
            m = pattern.match(line)
            if m and m.group(1) != "main":
                found = [m.group(1)]
                if pattern is DEFINES[3]:  # every declarator: constexpr int kA = 1, kB = 2;
                    found += DECLARATORS.findall(line)
                for name in found:
                    names[name] = None if header is None else HEADER if pattern in DEFINES[1:3] else header
                    if scopes and scopes[-1] or line.startswith("static "):
                        local.add(name)
                break
    return names, local


INCLUDE = re.compile(r'^#include\s+"([^"]+)"', re.M)
PARSED = {}  # header path -> (text, its own names): a header is read and parsed once per run


def parsed(path):
    if path not in PARSED:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        PARSED[path] = (text, names_in(text, header=path)[0])
    return PARSED[path]


def header_names(root, path, text, seen):
    """The names of the project headers `text` (the file at `path`) includes, recursively."""
    names = {}
    for inc in INCLUDE.findall(text):
        for cand in (os.path.join(root, inc), os.path.join(os.path.dirname(path), inc)):
            cand = os.path.normpath(cand)
            if os.path.isfile(cand):
                if cand not in seen:
                    seen.add(cand)
                    htext, own = parsed(cand)
                    names.update(header_names(root, cand, htext, seen))
                    names.update(own)
                break
    return names


def defined(root, path):
    """Names the file defines or includes at file scope, or None if it stays alone."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    if ALONE.search(text) or text.startswith("// MB_UNITY_ALONE"):
        return None
    names = header_names(root, path, text, set())
    own, local = names_in(text)
    for name, line in own.items():
        if name not in names or name in local:  # else the definition of what a header declares
            names[name] = line
    return names


def clash(a, b):
    """Two name sets clash on a name both have unless both say the same (HEADER, one header, one
    line)."""
    return any(k in b and not (a[k] == b[k] and a[k] is not None) for k in a)


def merge(into, names):
    for k, v in names.items():
        if into.get(k, HEADER) == HEADER:  # a file's own name outranks a header's
            into[k] = v


def main():
    root, batch = sys.argv[1], int(sys.argv[2])
    groups = []  # [(merged names, member count)]
    out = []
    for path in sys.argv[3:]:
        names = defined(root, path)
        if names is None:
            out.append("-")
            continue
        for i, (merged, count) in enumerate(groups):
            if count < batch and not clash(names, merged):
                merge(merged, names)
                groups[i] = (merged, count + 1)
                out.append(str(i))
                break
        else:
            groups.append((dict(names), 1))
            out.append(str(len(groups) - 1))
    # A batch of one file is that file compiled alone.
    sizes = {g: out.count(g) for g in set(out)}
    print("\n".join(g if g == "-" or sizes[g] > 1 else "-" for g in out))


if __name__ == "__main__":
    main()
