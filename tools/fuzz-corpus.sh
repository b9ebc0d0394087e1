#!/usr/bin/env bash
# Assemble the seed corpus of one fuzz target into DIR: the files of
# tests/fuzz/corpus/<target>/ and the test fixtures its seeds.txt names (one
# repository path a line; the fixtures stay where their tests read them, so
# each file is kept once).
#   tools/fuzz-corpus.sh fuzz_import_docx /tmp/fz
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 TARGET DIR" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
name=$1 dir=$2
corpus=$root/tests/fuzz/corpus/${name#fuzz_}
[ -d "$corpus" ] || corpus=$root/tests/fuzz/corpus/$name
mkdir -p "$dir"
[ -d "$corpus" ] || exit 0
find "$corpus" -maxdepth 1 -type f ! -name seeds.txt -exec cp {} "$dir"/ \;
if [ -f "$corpus/seeds.txt" ]; then
  while IFS= read -r seed; do
    case $seed in ''|'#'*) continue ;; esac
    [ -f "$root/$seed" ] || { echo "$corpus/seeds.txt: no such file: $seed" >&2; exit 3; }
    cp "$root/$seed" "$dir/seed-$(basename "$seed")"
  done < "$corpus/seeds.txt"
fi
