#!/usr/bin/env python3
"""Include-layer check: every #include in the product folders points down or within
its own layer, never up or sideways (docs/architecture.md, "Layers").

    scripts/check_layers.py [--root DIR]

Prints one line per violation, `file:line: <from-layer> must not include <to-layer>
(<header>)`, and exits 1; exits 0 when the tree is clean, 2 on a usage error.
tests/, bench/, examples/ and fuzz/ may include anything and are not checked.
"""

import argparse
import os
import re
import sys

# common/ in order, lowest first; a layer includes its own and lower ones. core (the
# exception root) may not exist yet: a missing folder is simply never seen.
COMMON_ORDER = ["core", "geometry", "map", "scene", "raycast", "slicing", "planning", "io", "gis"]

CHECKED = ["common", "protocol", "app", "server", "client"]
# Folders the product never includes, whatever its layer.
NEVER_INCLUDED = ["tests", "bench", "examples", "fuzz"]
SERVER_PARTS = ["core", "daemon", "cli", "web"]

COMMON = ["common/" + c for c in COMMON_ORDER]
BASE = COMMON + ["protocol", "app"]
ALLOWED = {
    "protocol": COMMON + ["protocol"],
    "app": BASE,
    "server/core": BASE + ["server/core"],
    "server/daemon": BASE + ["server/core", "server/daemon"],
    "server/cli": BASE + ["server/core", "server/cli"],
    "server/web": BASE + ["server/core", "server/web"],
    "client": BASE + ["client"],
    "client/sim": BASE + ["client", "client/sim"],
}
for i, c in enumerate(COMMON):
    ALLOWED[c] = COMMON[: i + 1]

# System headers that mean a database or the network: common/ has neither.
COMMON_FORBIDDEN_SYSTEM = [
    (re.compile(r"^mysql\+\+"), "the database"),
    (re.compile(r"^(mysql|mariadb)(\.h$|/)"), "the database"),
    (re.compile(r"^boost/asio"), "the network"),
    (re.compile(r"^boost/beast"), "the network"),
]

SOURCE_SUFFIXES = (".h", ".hpp", ".hh", ".ipp", ".inl", ".c", ".cc", ".cpp", ".cxx")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


def layer_of(path):
    """Layer of a repo-relative path ('common/map/map.h' -> 'common/map'), or None when the
    path is in no product folder; 'common/<unknown>' when common/ has a folder not in
    COMMON_ORDER (or a file at its top)."""
    parts = path.split("/")
    top = parts[0]
    if top == "common":
        sub = parts[1] if len(parts) > 2 else "(top)"
        return "common/" + sub
    if top in ("protocol", "app"):
        return top
    if top == "server":
        sub = parts[1] if len(parts) > 2 else "(top)"
        return "server/" + sub
    if top == "client":
        return "client/sim" if len(parts) > 2 and parts[1] == "sim" else "client"
    if top in NEVER_INCLUDED:
        return top
    return None


def resolve(root, including, header):
    """Repo-relative path of a quoted include. Includes are rooted at the repository;
    one relative to the including file's folder is accepted too, so a header named that
    way is still checked."""
    header = os.path.normpath(header).replace(os.sep, "/")
    if header.split("/")[0] in CHECKED + NEVER_INCLUDED:
        return header
    beside = os.path.normpath(os.path.join(os.path.dirname(including), header)).replace(os.sep, "/")
    if os.path.exists(os.path.join(root, beside)):
        return beside
    return None  # a third-party header spelled with quotes: not ours to place


def check_file(root, rel, out):
    src = layer_of(rel)
    if src not in ALLOWED:
        known = ", ".join(sorted(ALLOWED))
        out.append(f"{rel}:1: {src} is not a known layer (known: {known}; see scripts/check_layers.py)")
        return 0
    count = 0
    with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
        for lineno, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            count += 1
            kind, header = m.groups()
            if kind == "<":
                if src.startswith("common/"):
                    for pattern, what in COMMON_FORBIDDEN_SYSTEM:
                        if pattern.search(header):
                            out.append(f"{rel}:{lineno}: {src} must not include {what} (<{header}>)")
                continue
            target = resolve(root, rel, header)
            if target is None:
                continue
            dst = layer_of(target)
            if dst is not None and dst not in ALLOWED[src]:
                out.append(f"{rel}:{lineno}: {src} must not include {dst} ({header})")
    return count


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."),
                    help="repository root (default: the checkout holding this script)")
    args = ap.parse_args(argv)
    root = os.path.abspath(args.root)
    if not os.path.isdir(os.path.join(root, "common")):
        print(f"check_layers: {root} has no common/ folder; expected the repository root", file=sys.stderr)
        return 2

    violations, files, includes = [], 0, 0
    for top in CHECKED:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames.sort()
            for name in sorted(filenames):
                if not name.endswith(SOURCE_SUFFIXES):
                    continue
                rel = os.path.relpath(os.path.join(dirpath, name), root).replace(os.sep, "/")
                files += 1
                includes += check_file(root, rel, violations)

    for v in violations:
        print(v)
    if violations:
        print(f"check_layers: {len(violations)} violation(s) in {files} files", file=sys.stderr)
        return 1
    print(f"check_layers: {files} files, {includes} includes, every one points down or within its layer")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
