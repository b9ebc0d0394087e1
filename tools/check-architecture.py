#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Fails on a dependency that goes the wrong way (docs/architecture.md).

The stage order is the list in core/CMakeLists.txt, low to high. Each stage's
USES (core/<stage>/CMakeLists.txt) may name only stages before it, so the
graph has no cycles. Every `#include "<stage>/..."` in a stage must name the
stage itself or one it reaches through USES. core/ never includes Qt or
widgets/. Within widgets/, the include graph has no cycles.

The build already refuses an include that a stage does not link; this check
also refuses the link itself when it points up the order, and says why.
"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
core = root / "core"
errors = []


def cmake_words(text, keyword):
    """The arguments after `keyword` in a tactus_stage(...) call."""
    call = re.search(r"tactus_stage\((.*?)\)\s*$", text, re.S | re.M)
    if not call:
        return None
    words = call.group(1).split()
    keys = {"SOURCES", "USES", "PUBLIC", "PRIVATE"}
    out, on = [], False
    for w in words:
        if w in keys:
            on = w == keyword
        elif on:
            out.append(w)
    return out


order_match = re.search(r"foreach\(stage (.*?)\)", (core / "CMakeLists.txt").read_text(), re.S)
if not order_match:
    sys.exit("check-architecture: no stage list in core/CMakeLists.txt")
order = order_match.group(1).split()
rank = {s: i for i, s in enumerate(order)}

uses = {}
for stage in order:
    cm = core / stage / "CMakeLists.txt"
    if not cm.exists():
        errors.append(f"core/{stage}: listed in core/CMakeLists.txt but has no CMakeLists.txt")
        continue
    u = cmake_words(cm.read_text(), "USES")
    if u is None:
        errors.append(f"core/{stage}/CMakeLists.txt: no tactus_stage(...) call")
        continue
    uses[stage] = u
    for dep in u:
        if dep not in rank:
            errors.append(f"core/{stage} uses '{dep}', which is not a stage")
        elif rank[dep] >= rank[stage]:
            errors.append(f"core/{stage} uses core/{dep}, which is not below it in the stage order "
                          f"({' < '.join(order)}): move the shared part down, or invert the call")

for d in sorted(p.name for p in core.iterdir() if p.is_dir()):
    if d not in rank:
        errors.append(f"core/{d}: a folder that is not in the stage list of core/CMakeLists.txt")


def closure(stage, seen=None):
    seen = set() if seen is None else seen
    for dep in uses.get(stage, []):
        if dep not in seen:
            seen.add(dep)
            closure(dep, seen)
    return seen


include_re = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
for stage in order:
    allowed = closure(stage) | {stage}
    for f in sorted((core / stage).glob("*.[ch]pp")):
        for inc in include_re.findall(f.read_text()):
            first = inc.split("/")[0]
            rel = f.relative_to(root)
            if inc.startswith("Q") or first.startswith("Qt"):
                errors.append(f"{rel}: includes <{inc}>: core stays free of Qt")
            elif "/" in inc and first in rank and first not in allowed:
                errors.append(f"{rel}: includes \"{inc}\", but core/{stage} does not use core/{first} "
                              f"(it uses: {', '.join(sorted(closure(stage))) or 'nothing'})")
            elif first == "widgets" or inc.endswith("main_window.hpp"):
                errors.append(f"{rel}: includes \"{inc}\": core never includes widgets")

# widgets/: no include cycles between its files.
widgets = root / "widgets"
graph = {}
for f in widgets.glob("*.[ch]pp"):
    graph[f.stem] = {pathlib.Path(i).stem for i in include_re.findall(f.read_text())
                     if "/" not in i and (widgets / i).exists()} - {f.stem}
state = {}


def visit(node, path):
    state[node] = "open"
    for nxt in sorted(graph.get(node, ())):
        if state.get(nxt) == "open":
            cyc = path[path.index(nxt):] + [nxt] if nxt in path else [node, nxt]
            errors.append("widgets/: include cycle " + " -> ".join(cyc))
        elif nxt not in state:
            visit(nxt, path + [nxt])
    state[node] = "done"


for n in sorted(graph):
    if n not in state:
        visit(n, [n])

if errors:
    print("check-architecture: dependencies that go the wrong way:", file=sys.stderr)
    for e in errors:
        print("  " + e, file=sys.stderr)
    sys.exit(1)
print(f"check-architecture: {len(order)} stages, {sum(len(v) for v in uses.values())} edges, "
      "no upward edge, no cycle, every include declared")
