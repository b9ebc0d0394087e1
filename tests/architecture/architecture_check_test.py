#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""tools/check-architecture.py: passes on the tree, and fails, naming the file
and the header, on a copy where a file outside core/platform includes an
operating system header; an OS header inside core/platform stays allowed.

Usage: architecture_check_test.py SOURCE_ROOT
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile
import unittest

SOURCE = pathlib.Path(sys.argv.pop(1)).resolve() if len(sys.argv) > 1 else \
    pathlib.Path(__file__).resolve().parents[2]
CHECK = SOURCE / "tools" / "check-architecture.py"


def run_check(root):
    return subprocess.run([sys.executable, str(CHECK), str(root)], capture_output=True, text=True)


class ArchitectureCheck(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # One copy of what the check reads; each case puts back what it changed.
        cls.tmp = tempfile.TemporaryDirectory(prefix="tactus-arch-")
        cls.root = pathlib.Path(cls.tmp.name)
        for top in ("core", "app", "widgets"):
            shutil.copytree(SOURCE / top, cls.root / top, symlinks=True,
                            ignore=shutil.ignore_patterns("*.md", "*.json", "*.txt.in"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def setUp(self):
        self.saved = {}

    def tearDown(self):
        for f, text in self.saved.items():
            f.write_text(text)

    def save(self, rel):
        f = self.root / rel
        self.saved.setdefault(f, f.read_text())
        return f

    def add_line(self, rel, line):
        f = self.save(rel)
        f.write_text(line + "\n" + f.read_text())

    def test_passes_on_the_tree(self):
        r = run_check(SOURCE)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("OS headers only in core/platform", r.stdout)

    def test_passes_on_an_unchanged_copy(self):
        r = run_check(self.root)
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_unistd_outside_the_platform_layer_fails(self):
        self.add_line("core/layout/braille_pages.cpp", "#include <unistd.h>")
        r = run_check(self.root)
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn("core/layout/braille_pages.cpp: includes <unistd.h>", r.stderr)

    def test_os_headers_in_app_and_widgets_fail(self):
        self.add_line("app/cli/main.cpp", "#  include <sys/wait.h>")
        self.add_line("widgets/main_window.cpp", "#include <Windows.h>")
        r = run_check(self.root)
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn("app/cli/main.cpp: includes <sys/wait.h>", r.stderr)
        self.assertIn("widgets/main_window.cpp: includes <Windows.h>", r.stderr)

    def test_standard_headers_pass(self):
        self.add_line("core/layout/braille_pages.cpp", "#include <filesystem>\n#include <system_error>")
        r = run_check(self.root)
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_os_headers_inside_the_platform_layer_pass(self):
        self.add_line("core/platform/process_info_posix.cpp", "#include <sys/wait.h>")
        r = run_check(self.root)
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_a_platform_file_without_its_windows_twin_fails(self):
        self.save("core/platform/process_info_win.cpp").unlink()
        r = run_check(self.root)
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn("process_info_posix.cpp: no Windows twin process_info_win.cpp", r.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
