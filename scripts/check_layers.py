#!/usr/bin/env python3
"""Check that the source tree's dependencies point one way.

A unit is a header and its source (x.hpp + x.cpp in one folder). A unit
depends on another when its header or source #includes the other's header.
Checked:
  * no include loop between units (strongly connected components of the
    unit graph, Tarjan);
  * each folder includes only its own layer and the layers below it
    (LAYERS below: core's layers bottom-up, then the plugin);
  * the public headers (core/include/mcmd, plugin/lib/include) include only
    public headers.
Prints one line per problem and exits 1 when there is any; tests/ and
bench/ are not checked (they may reach any layer).
"""
from __future__ import annotations

import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Folder -> rank: a folder may include folders of lower or equal rank.
LAYERS = {
    "core/include/mcmd": 0,
    "core/common": 1,
    "core/roughness": 2,
    "core/paper": 3,
    "core/thin_plate": 3,
    "core/method": 4,
    "core/morphology": 5,
    "core/raster": 6,
    "core/raster/tiles": 6,
    "core/terrain/methods": 7,
    "core/terrain/skeleton": 7,
    "core/terrain/constraints": 7,
    "core/terrain/erosion": 7,
    "core/terrain/finishing": 7,
    "core/terrain": 8,
    "plugin/lib/include": 9,
    "plugin/lib": 10,
    "plugin/cli": 11,
    "plugin/terrain": 11,
    "python/src": 12,
}
PUBLIC = {"core/include/mcmd", "plugin/lib/include"}
# Where a quoted include is looked for, per top folder (first match wins).
SEARCH = {
    "core": ["core", "core/include"],
    "plugin": ["plugin", "core/include", "plugin/lib/include"],
    "python": ["python/src", "plugin", "core/include", "plugin/lib/include"],
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def sources():
    for top in SEARCH:
        for d, _, files in os.walk(os.path.join(ROOT, top)):
            for f in files:
                if f.endswith((".hpp", ".cpp", ".h", ".c")):
                    yield os.path.relpath(os.path.join(d, f), ROOT)


def resolve(name: str, src: str) -> str | None:
    here = os.path.dirname(src)
    for base in [here] + SEARCH[src.split("/")[0]]:
        p = os.path.normpath(os.path.join(base, name))
        if os.path.exists(os.path.join(ROOT, p)):
            return p
    return None  # a system or GDAL header


def unit(path: str) -> str:
    return os.path.splitext(path)[0]


def folder(path: str) -> str:
    return os.path.dirname(path)


def main() -> int:
    problems = []
    edges: dict[str, set[str]] = {}
    for src in sources():
        text = open(os.path.join(ROOT, src), encoding="utf-8").read()
        u = unit(src)
        edges.setdefault(u, set())
        for name in INCLUDE.findall(text):
            dep = resolve(name, src)
            if dep is None:
                continue
            if unit(dep) != u:
                edges[u].add(unit(dep))
            fs, fd = folder(src), folder(dep)
            if fs in PUBLIC and src.endswith((".hpp", ".h")) and fd not in PUBLIC:
                problems.append(f"{src}: public header includes internal {dep}")
            rs, rd = LAYERS.get(fs), LAYERS.get(fd)
            if rs is not None and rd is not None and rd > rs:
                problems.append(f"{src}: includes {dep}, a layer above ({fd} over {fs})")
    # Tarjan's strongly connected components: any of more than one unit is a loop.
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    counter = [0]

    def visit(v: str):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                problems.append("include loop: " + " <-> ".join(sorted(comp)))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    for p in problems:
        print(p)
    n = len(edges)
    print(f"check_layers: {n} units, {sum(len(e) for e in edges.values())} dependencies, "
          f"{len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
