#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Fails on a dependency that goes the wrong way (docs/architecture.md).

The stage order is the list in core/CMakeLists.txt, low to high. Each stage's
USES (core/<stage>/CMakeLists.txt) may name only stages before it, so the
graph has no cycles. Every `#include "<stage>/..."` in a stage must name the
stage itself or one it reaches through USES. core/ never includes Qt or
widgets/. Within widgets/, the include graph has no cycles.

Only core/platform/ includes an operating system's headers (unistd.h, sys/*,
termios.h, windows.h, io.h, ...): everything else in core/, app/ and widgets/
reaches the system through its interfaces, so the same sources build for
POSIX and for Windows (docs/windows.md). There, each concern's POSIX and
Windows implementations come in pairs (x_posix.cpp beside x_win.cpp).

Usage: check-architecture.py [ROOT]   (ROOT: the source tree; this script's by default)

The build already refuses an include that a stage does not link; this check
also refuses the link itself when it points up the order, and says why.
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1]).resolve() if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
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

# The operating system only behind core/platform/.
PLATFORM = "platform"
OS_HEADERS = {
    # POSIX and its usual companions
    "unistd.h", "fcntl.h", "termios.h", "poll.h", "pty.h", "dirent.h", "pwd.h", "grp.h", "signal.h",
    "csignal", "spawn.h", "dlfcn.h", "syslog.h", "libgen.h", "utmp.h", "semaphore.h", "netdb.h",
    "ifaddrs.h", "glob.h", "fnmatch.h", "wordexp.h", "termio.h", "sgtty.h", "utime.h", "pthread.h",
    # Windows
    "windows.h", "winsock2.h", "ws2tcpip.h", "winbase.h", "winioctl.h", "io.h", "process.h", "direct.h",
    "conio.h", "shlobj.h", "shellapi.h", "setupapi.h", "tlhelp32.h", "psapi.h", "aclapi.h", "winerror.h",
    "winreg.h", "winuser.h", "objbase.h", "combaseapi.h", "knownfolders.h",
}
OS_HEADER_DIRS = ("sys/", "arpa/", "netinet/", "net/", "linux/", "mach/", "asm/", "bits/")
angle_include_re = re.compile(r'^\s*#\s*include\s*<([^>]+)>', re.M)


def os_header(inc):
    low = inc.lower()
    return low in OS_HEADERS or low.startswith(OS_HEADER_DIRS)


platform_dir = core / PLATFORM
if PLATFORM not in rank:
    errors.append(f"core/{PLATFORM}: the platform layer is missing from the stage list of core/CMakeLists.txt")
elif order[0] != PLATFORM:
    errors.append(f"core/{PLATFORM} must be the lowest stage (first in core/CMakeLists.txt): every stage may use it")
for top in ("core", "app", "widgets"):
    base = root / top
    if not base.is_dir():
        continue
    for f in sorted(base.rglob("*")):
        if f.suffix not in (".cpp", ".hpp", ".h", ".c", ".cc") or not f.is_file():
            continue
        if platform_dir in f.parents:
            continue
        for inc in angle_include_re.findall(f.read_text(errors="replace")):
            if os_header(inc):
                errors.append(f"{f.relative_to(root)}: includes <{inc}>, an operating system header: only "
                              f"core/{PLATFORM}/ may; call or add an interface there (docs/windows.md)")
if platform_dir.is_dir():
    for f in sorted(platform_dir.glob("*_posix.cpp")):
        twin = f.with_name(f.name[: -len("_posix.cpp")] + "_win.cpp")
        if not twin.exists():
            errors.append(f"{f.relative_to(root)}: no Windows twin {twin.name}")
    for f in sorted(platform_dir.glob("*_win.cpp")):
        twin = f.with_name(f.name[: -len("_win.cpp")] + "_posix.cpp")
        if not twin.exists():
            errors.append(f"{f.relative_to(root)}: no POSIX twin {twin.name}")

if errors:
    print("check-architecture: dependencies that go the wrong way:", file=sys.stderr)
    for e in errors:
        print("  " + e, file=sys.stderr)
    sys.exit(1)
print(f"check-architecture: {len(order)} stages, {sum(len(v) for v in uses.values())} edges, "
      "no upward edge, no cycle, every include declared, OS headers only in core/platform")
