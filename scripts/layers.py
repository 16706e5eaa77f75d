#!/usr/bin/env python3
"""Import graph of src/: cycles between top-level modules and arrows that run up the floors.

Usage: python3 scripts/layers.py [--files]
Floors (low -> high): field, poly, algebraic/numberfield, matrix, jordan, pencil, system, realization, multibody,
structure; io, study (parameter families read from files), report, api (the front door), cli on top; float apart (it may use anything below io).
An arrow A -> B is "up" when B's floor is higher than A's. Cycles are reported between
top-level modules and between files (a file-level cycle: files that reach each other through
`use` paths, within a module or across); any of the three fails the check (exit 1).
"""
import os, re, sys
from collections import defaultdict

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src")
FLOOR = {
    "error": 0, "rng": 0, "field": 1, "qkernels": 1, "poly": 2, "mpoly": 2, "ratfunc": 2, "algebraic": 3, "numberfield": 3,
    "matrix": 4, "jordan": 5, "pencil": 5.5, "system": 6, "realization": 7, "multibody": 7.5, "structure": 8,
    "float": 9, "io": 10, "study": 10.5, "report": 11, "api": 11.5, "cli": 12,
}
USE_RE = re.compile(r"crate::([a-z_][a-z0-9_]*)((?:::[a-z_][a-z0-9_]*)*)")
GROUP_RE = re.compile(r"use\s+crate::\{([^;]*)\};", re.S)


def strip_tests(src):
    # drop `#[cfg(test)] mod tests { ... }` blocks (tests may look anywhere)
    out, i = [], 0
    for m in re.finditer(r"#\[cfg\(test\)\]\s*mod\s+\w+\s*\{", src):
        if m.start() < i:
            continue
        out.append(src[i:m.start()])
        depth, j = 1, m.end()
        while j < len(src) and depth:
            depth += {"{": 1, "}": -1}.get(src[j], 0)
            j += 1
        i = j
    out.append(src[i:])
    return "".join(out)


def comment_free(src):
    return "\n".join(l for l in src.splitlines() if not l.lstrip().startswith("//"))


def file_key(path):
    rel = os.path.relpath(path, ROOT)[:-3]
    parts = rel.split(os.sep)
    if parts[-1] == "mod":
        parts = parts[:-1]
    return "::".join(parts)


def deps_of(src, key):
    src = comment_free(strip_tests(src))
    paths = set()
    # relative paths: super::x (from a file, `super` is the parent module)
    is_mod = key.endswith("::__mod__")
    key = key.replace("::__mod__", "")
    here = key.split("::")
    for m in re.finditer(r"\b((?:super::)+)([a-z_][a-z0-9_]*(?:::[a-z_][a-z0-9_]*)*)", src):
        ups = m.group(1).count("super::")
        base = here if is_mod else here[:-1]
        base = base[: len(base) - (ups - 1)] if ups > 1 else base
        if len(base) >= 1 or ups == 1:
            paths.add("::".join(base + m.group(2).split("::")))
    if is_mod:
        for m in re.finditer(r"\bself::([a-z_][a-z0-9_]*(?:::[a-z_][a-z0-9_]*)*)", src):
            paths.add("::".join(here + m.group(1).split("::")))
    for g in GROUP_RE.finditer(src):
        for item in re.split(r",(?![^{]*\})", g.group(1)):
            item = item.strip()
            head = re.match(r"([a-z_][a-z0-9_]*)((?:::[a-z_][a-z0-9_]*)*)", item)
            if head:
                paths.add(head.group(1) + head.group(2))
    for m in USE_RE.finditer(src):
        paths.add(m.group(1) + m.group(2))
    return paths


def main():
    files = {}
    for d, _, fs in os.walk(ROOT):
        for f in fs:
            if f.endswith(".rs") and "bin" not in os.path.relpath(d, ROOT).split(os.sep):
                p = os.path.join(d, f)
                if os.path.relpath(p, ROOT) == "lib.rs":
                    continue
                k = file_key(p)
                files[k] = deps_of(open(p).read(), k + ("::__mod__" if f == "mod.rs" else ""))
    keys = set(files)
    top = defaultdict(set)
    up = []
    file_graph = defaultdict(set)
    for k, ds in files.items():
        a = k.split("::")[0]
        for d in ds:
            b = d.split("::")[0]
            # resolve to the longest file key prefix
            parts = d.split("::")
            target = None
            for n in range(len(parts), 0, -1):
                cand = "::".join(parts[:n])
                if cand in keys:
                    target = cand
                    break
            if target and target != k:
                file_graph[k].add(target)
            if b == a or b not in FLOOR:
                continue
            top[a].add(b)
            fa, fb = FLOOR.get(a), FLOOR[b]
            if fa is not None and fb > fa and not (a == "float" and fb < FLOOR["io"]):
                up.append((k, d))
    cycles = sccs(top)
    print("top-level edges:")
    for a in sorted(top, key=lambda x: FLOOR.get(x, 99)):
        print(f"  {a:12} -> {', '.join(sorted(top[a], key=lambda x: FLOOR.get(x, 99)))}")
    print(f"top-level cycles: {len(cycles)}")
    for c in cycles:
        print("  " + " <-> ".join(sorted(c)))
    ups = sorted(set(up))
    pres = [u for u in ups if u[1].split("::")[0] in ("io", "report", "cli")]
    print(f"arrows up a floor: {len(ups)} (of which {len(pres)} into io/report/cli)")
    for k, d in ups:
        print(f"  {k} -> crate::{d}")
    fc = sccs(file_graph)
    print(f"file-level cycles: {len(fc)}")
    if "--files" in sys.argv or True:
        for c in fc:
            print("  " + " <-> ".join(sorted(c)))
    return 1 if (cycles or ups or fc) else 0


def sccs(g):
    idx, low, st, on, out, n = {}, {}, [], set(), [], [0]
    nodes = set(g) | {v for vs in g.values() for v in vs}

    def visit(v):
        idx[v] = low[v] = n[0]; n[0] += 1; st.append(v); on.add(v)
        for w in g.get(v, ()):
            if w not in idx:
                visit(w); low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], idx[w])
        if low[v] == idx[v]:
            comp = []
            while True:
                w = st.pop(); on.discard(w); comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(comp)

    sys.setrecursionlimit(10000)
    for v in sorted(nodes):
        if v not in idx:
            visit(v)
    return out


if __name__ == "__main__":
    sys.exit(main())
