#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Noise campaign against the reference firmware in s51 (never run by the unit tests).

    ninja -C build/default tactus-cli firmware_emu
    python3 bench/firmware/noise_campaign.py [--seeds N] [--rates 1e-3,1e-2,2e-2]

For each rate and seed: `tactus-cli sim --firmware ... --pty --noise R --seed S`
(bytes dropped, bit-flipped and duplicated, each at R, both ways, on the line
between the pty and the emulated chip's UART) and `tactus-cli emboss` of the
bundled firmware-note.md at 9600 baud. Each run must either complete with the
strikes read from the chip's pins equal to a clean run's (which the emulator
tests compare with the plan) or fail cleanly (exit 1 or 4 with "resume with
--start-sheet", and what was struck a prefix of the clean run's). Throughput:
the clean run's first-to-last strike time over the noisy run's, both in the
emulator's own clock (s51's cycle count, so the machine's load does not
enter). Writes bench/firmware/noise-last-run.json.

With --cpp the same runs go to the C++ simulated controller speaking protocol
3 as the firmware does (`sim --pty --firmware-tables` with the emulator
build's ramp.json, motion in real time): the pty path of the campaign the
unit tests run in process over hundreds of seeds (NoiseCampaignV3). Its
clock is the controller's simulated one. Writes noise-last-run-cpp.json.
"""
import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def strikes(path):
    out = []
    for line in Path(path).read_text().splitlines():
        j = json.loads(line)
        out.append((j["sheet"], j["hammer"], j["carriage_step"], j["feed_step"], j["time_s"]))
    return out


def places(log):
    return [s[:4] for s in log]


def span(log):
    """First to last strike in the emulator's own clock (s51's cycles)."""
    return log[-1][4] - log[0][4] if len(log) > 1 else 0.0


def run(cli, fw, tables, note, rate, seed, tmp, cpp=False):
    log = Path(tmp) / f"strikes-{rate}-{seed}.jsonl"
    if cpp:
        sim = [cli, "sim", "--pty", "--baud", "9600", "--firmware-tables", str(tables), "--strike-log", str(log)]
    else:
        sim = [cli, "sim", "--firmware", str(fw), "--pty", "--strike-log", str(log)]
    if rate > 0:
        sim += ["--noise", str(rate), "--seed", str(seed)]
    server = subprocess.Popen(sim, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    pty = server.stdout.readline().strip()
    t0 = time.monotonic()
    client = subprocess.run([cli, "emboss", str(note), "--device", f"pty:{pty}?baud=9600",
                             "--firmware-tables", str(tables)], capture_output=True, text=True)
    seconds = time.monotonic() - t0
    server.terminate()
    _, err = server.communicate()
    return {"rate": rate, "seed": seed, "exit": client.returncode, "seconds": seconds,
            "output": (client.stdout + client.stderr).strip().splitlines()[-1:],
            "sim": err.strip().splitlines()[-1:], "strikes": strikes(log) if log.exists() else [],
            "emulator_ended": "ended by itself" in err}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default=str(ROOT / "build/default/app/tactus-cli"))
    ap.add_argument("--firmware", default=str(ROOT / "build/default/firmware-emu/tactus-fw.ihx"))
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--rates", default="1e-3,1e-2,2e-2")
    ap.add_argument("--cpp", action="store_true", help="the C++ controller on protocol 3 instead of the firmware")
    a = ap.parse_args()
    fw = Path(a.firmware)
    tables = fw.with_name("ramp.json")
    note = ROOT / "resources/samples/firmware-note.md"
    results = {"runs": [], "summary": {}}
    with tempfile.TemporaryDirectory() as tmp:
        clean = run(a.cli, fw, tables, note, 0, 0, tmp, a.cpp)
        if clean["exit"] != 0:
            sys.exit(f"the clean run failed: {clean['output']}")
        want = places(clean["strikes"])
        clean_span = span(clean["strikes"])
        print(f"clean: {len(want)} strikes, {clean_span:.2f} s emulated from the first to the last")
        for rate in [float(r) for r in a.rates.split(",")]:
            done = clean_fail = wrong = ended = 0
            secs = 0.0
            for seed in range(1, a.seeds + 1):
                r = run(a.cli, fw, tables, note, rate, seed, tmp, a.cpp)
                got = places(r["strikes"])
                ended += r["emulator_ended"]
                if r["exit"] == 0 and got == want:
                    done += 1
                    secs += span(r["strikes"])
                    verdict = "exact"
                elif r["exit"] in (1, 4) and got == want[:len(got)] and (
                        "--start-sheet" in " ".join(r["output"]) or not got):
                    clean_fail += 1
                    verdict = "failed cleanly"
                else:
                    wrong += 1
                    verdict = "WRONG"
                print(f"noise {rate:g} seed {seed}: {verdict}, {len(got)}/{len(want)} strikes, "
                      f"{r['seconds']:.1f} s wall; {' '.join(r['sim'])}", flush=True)
                if r["exit"] != 0:
                    print(f"  exit {r['exit']}: {' '.join(r['output'])}", flush=True)
                r.pop("strikes")
                results["runs"].append(r)
            thr = 100 * clean_span * done / secs if secs else 0
            results["summary"][str(rate)] = {"runs": a.seeds, "exact": done, "failed_cleanly": clean_fail,
                                             "wrong": wrong, "throughput_pct": round(thr, 1),
                                             "emulator_ended": ended}
            print(f"noise {rate:g}: {done} exact, {clean_fail} failed cleanly, {wrong} wrong of {a.seeds}; "
                  f"throughput {thr:.1f} % of a clean line; s51 ended by itself {ended} times")
    out = "noise-last-run-cpp.json" if a.cpp else "noise-last-run.json"
    (ROOT / "bench/firmware" / out).write_text(json.dumps(results, indent=1) + "\n")


if __name__ == "__main__":
    main()
