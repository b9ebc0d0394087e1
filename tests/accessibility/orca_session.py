#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Orca in the loop: what a blind user actually hears, as data a test can assert.

Runs inside tests/accessibility/x11_session.sh (Xvfb, a D-Bus session and an AT-SPI
bus). `OrcaSession` adds what a screen reader user's desktop has on top of that:
a window manager (openbox; window activation events need one) and the real Orca
screen reader, started with a fresh profile and a debug log. Orca writes every
utterance to that log as `SPEECH OUTPUT: '...'`; the session parses it as it grows.
Beside Orca, atspi_event_log.py records every AT-SPI event the app sends, so a
step can also be held to an event budget.

A test is a list of steps. Each step presses keys (xdotool, into whatever window
has the focus, as a user's keyboard does), waits for the phrases that must be
heard (waiting on Orca's log, never on fixed sleeps), then lets Orca finish
speaking and records what was heard, the AT-SPI events, and how long the user
waited for the first word. A step fails when an expected phrase never comes,
when it was silent, when it overruns its event budget, or when Orca says DELUGE.

Speech itself is not produced: speech-dispatcher would block without an audio
device, so Orca is pointed at a socket that does not exist and logs what it
would have said (orca-notes.md).
"""
import datetime
import os
import re
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP = 77  # ctest SKIP_RETURN_CODE: the machine lacks Orca or a window manager

_SPEECH = re.compile(r"^(\d\d):(\d\d):(\d\d\.\d+) - SPEECH OUTPUT: '(.*)'(?: voice=\S+)?\s?\{.*\}\s*$", re.S)
_SPEECH_START = re.compile(r"^\d\d:\d\d:\d\d\.\d+ - SPEECH OUTPUT: '")


class StepFailed(AssertionError):
    pass


@dataclass
class Phrase:
    text: str
    seconds: float  # wall clock, seconds since local midnight (Orca's log format)
    key_echo: bool  # Orca echoing a key the user pressed, not something the app said


@dataclass
class StepRecord:
    name: str
    phrases: list = field(default_factory=list)  # what the app made Orca say
    events: int = 0
    event_types: dict = field(default_factory=dict)
    first_word_after: float | None = None  # seconds from the step's keys to the first phrase
    seconds: float = 0.0


def _now_seconds():
    n = datetime.datetime.now()
    return n.hour * 3600 + n.minute * 60 + n.second + n.microsecond / 1e6


def tools_missing():
    """Names of the programs an Orca session needs that are not installed."""
    need = ["orca", "openbox", "xdotool"]
    missing = [p for p in need if shutil.which(p) is None]
    try:
        import pyatspi  # noqa: F401
    except ImportError:
        missing.append("python3-pyatspi")
    return missing


class OrcaLog:
    """Incremental parser of Orca's debug log."""

    def __init__(self, path):
        self.path = path
        self.offset = 0
        self.pending = ""  # a partial line, or a SPEECH OUTPUT line whose text spans lines
        self.in_key = False
        self.phrases = []
        self.deluges = []
        self.lines = 0

    def poll(self):
        try:
            with open(self.path, "r", encoding="utf-8", errors="replace") as f:
                f.seek(self.offset)
                chunk = f.read()
                self.offset = f.tell()
        except FileNotFoundError:
            return
        data = self.pending + chunk
        lines = data.split("\n")
        self.pending = lines.pop()  # unfinished last line
        speech = None
        for line in lines:
            self.lines += 1
            if speech is not None:
                speech += "\n" + line
                if self._speech_done(speech):
                    self._add_speech(speech)
                    speech = None
                continue
            if line.startswith("vvvvv PROCESS ATSPI_KEY"):
                self.in_key = True
            elif line.startswith("^^^^^ PROCESS ATSPI_KEY"):
                self.in_key = False
            elif "DELUGE" in line:
                self.deluges.append(line)
            elif _SPEECH_START.match(line):
                if self._speech_done(line):
                    self._add_speech(line)
                else:
                    speech = line
        if speech is not None:
            self.pending = speech + "\n" + self.pending

    @staticmethod
    def _speech_done(text):
        return _SPEECH.match(text) is not None

    def _add_speech(self, text):
        m = _SPEECH.match(text)
        h, mi, s, said = int(m.group(1)), int(m.group(2)), float(m.group(3)), m.group(4)
        self.phrases.append(Phrase(said, h * 3600 + mi * 60 + s, self.in_key))


class EventLog:
    """Reads atspi_event_log.py's output."""

    def __init__(self, path):
        self.path = path
        self.offset = 0
        self.events = []  # (monotonic time, type, role, name)
        self.ready = False

    def poll(self):
        try:
            with open(self.path, "r", encoding="utf-8", errors="replace") as f:
                f.seek(self.offset)
                data = f.read()
        except FileNotFoundError:
            return
        end = data.rfind("\n")
        if end < 0:
            return
        self.offset += len(data[: end + 1].encode("utf-8"))
        for line in data[: end + 1].splitlines():
            if line == "READY":
                self.ready = True
                continue
            parts = line.split("\t")
            if len(parts) == 4:
                self.events.append((float(parts[0]), parts[1], parts[2], parts[3]))


class OrcaSession:
    """Openbox, Orca and the app under test, with keys and a transcript."""

    def __init__(self, app_name, work=None, verbose=True):
        self.app_name = app_name
        self.work = work or os.environ.get("TACTUS_WORK") or "/tmp"
        self.verbose = verbose
        self.procs = []
        self.app = None
        self.orca_log = OrcaLog(os.path.join(self.work, "orca.log"))
        self.event_log = EventLog(os.path.join(self.work, "atspi-events.log"))
        self.steps = []

    # ---- processes ----

    def _spawn(self, argv, env=None, log_name=None):
        out = open(os.path.join(self.work, log_name), "w") if log_name else subprocess.DEVNULL
        p = subprocess.Popen(argv, env=env, stdout=out, stderr=subprocess.STDOUT, cwd=self.work)
        self.procs.append(p)
        return p

    def start(self, timeout=90):
        if "DISPLAY" not in os.environ:
            raise SystemExit("orca_session: run me inside x11_session.sh")
        home = os.path.join(self.work, "home")
        os.makedirs(home, exist_ok=True)
        env = dict(os.environ, HOME=home,
                   # No audio here: let Orca fail to reach speech-dispatcher quickly
                   # instead of blocking on a sound card (it still logs every phrase).
                   SPEECHD_ADDRESS="unix_socket:" + os.path.join(self.work, "no-speechd", "socket"),
                   # ... and not try to start one. Orca connects again whenever a
                   # script becomes active (the app's window), and each try ran
                   # `speech-dispatcher --spawn` and waited for it inside Orca's
                   # main loop: 3 s on a loaded machine, while the app's events
                   # piled up past Orca's flood limit (50) and it dropped the
                   # app's notifications. A desktop has speech-dispatcher running.
                   SPEECHD_CMD=os.path.join(self.work, "no-speechd", "speech-dispatcher"))
        self._spawn(["openbox", "--sm-disable"], env=env, log_name="openbox.log")
        self._spawn(["/usr/bin/python3", os.path.join(HERE, "orca_line_buffered.py"), "-u", os.path.join(home, "orca-prefs"),
                     "--debug-file", self.orca_log.path], env=env, log_name="orca.out")
        self._wait(lambda: any(p.text.startswith("Screen reader on") for p in self.orca_log.phrases),
                   "Orca to start", timeout)
        self._spawn(["/usr/bin/python3", os.path.join(HERE, "atspi_event_log.py"), self.app_name,
                     self.event_log.path], log_name="atspi-events.out")
        self._wait(lambda: self.event_log.ready, "the AT-SPI event logger", 30)

    def launch(self, argv, env=None, timeout=60):
        """Starts the app; returns once Orca has announced its window."""
        mark = self.mark()
        e = dict(os.environ, QT_LINUX_ACCESSIBILITY_ALWAYS_ON="1", QT_QPA_PLATFORM="xcb", QT_ACCESSIBILITY="1")
        e.update(env or {})
        self.app = self._spawn(argv, env=e, log_name="app.log")
        self._wait(lambda: self.phrases_since(mark), "Orca to announce the app's window", timeout)
        self.settle(mark)
        if self.verbose:
            print("[launch] heard:", [p.text for p in self.phrases_since(mark)], flush=True)

    def stop(self):
        for p in reversed(self.procs):
            if p.poll() is None:
                p.terminate()
        for p in reversed(self.procs):
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        self.procs.clear()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()
        return False

    # ---- the transcript ----

    def poll(self):
        self.orca_log.poll()
        self.event_log.poll()

    def mark(self):
        """A point in the transcript: (phrases so far, events so far, time)."""
        self.poll()
        return (len(self.orca_log.phrases), len(self.event_log.events), _now_seconds(), time.monotonic(),
                len(self.orca_log.deluges))

    def phrases_since(self, mark, key_echo=False):
        self.poll()
        return [p for p in self.orca_log.phrases[mark[0]:] if key_echo or not p.key_echo]

    def events_since(self, mark):
        self.poll()
        return self.event_log.events[mark[1]:]

    def deluges(self):
        self.poll()
        return list(self.orca_log.deluges)

    def _wait(self, ready, what, timeout):
        end = time.monotonic() + timeout
        while True:
            self.poll()
            value = ready()
            if value:
                return value
            if self.app is not None and self.app.poll() is not None:
                raise StepFailed(f"the app exited (status {self.app.returncode}) while waiting for {what}")
            if time.monotonic() > end:
                raise StepFailed(f"timed out after {timeout} s waiting for {what}")
            time.sleep(0.05)

    def wait_phrase(self, pattern, mark, timeout=30, what=None):
        """Waits until Orca says something matching `pattern` (a regex) after `mark`."""
        rx = re.compile(pattern, re.I | re.S)
        try:
            return self._wait(lambda: next((p for p in self.phrases_since(mark) if rx.search(p.text)), None),
                              what or f"Orca to say /{pattern}/", timeout)
        except StepFailed as e:
            heard = [p.text for p in self.phrases_since(mark, key_echo=True)]
            raise StepFailed(f"{e}; Orca said {heard}") from None

    def settle(self, mark, quiet=1.5, timeout=60):
        """Waits until Orca has spoken and received nothing for `quiet` seconds: the
        end of what the user hears for a step. Only decides where a step's transcript
        ends; no assertion depends on how long this takes."""
        end = time.monotonic() + timeout
        last = (-1, -1)
        still_since = time.monotonic()
        while time.monotonic() < end:
            self.poll()
            now = (self.orca_log.lines, len(self.event_log.events))
            if now != last:
                last = now
                still_since = time.monotonic()
            elif time.monotonic() - still_since >= quiet:
                return
            time.sleep(0.05)

    # ---- the keyboard ----

    def key(self, *keys):
        for k in keys:
            subprocess.run(["xdotool", "key", "--clearmodifiers", k], check=True, timeout=20)

    def type(self, text):
        subprocess.run(["xdotool", "type", "--delay", "20", text], check=True, timeout=60)

    # ---- steps ----

    def step(self, name, keys=(), type_text=None, expect=(), forbid=(), max_events=None, timeout=30,
             quiet=1.5, allow_silent=False, once=(), allow_deluge=False, settle=True):
        """One user action and what must be heard after it.

        keys / type_text: what the user presses. expect: regexes that must each be
        heard (in this order of waiting). forbid: regexes that must not be heard.
        once: regexes that must be heard exactly once (no repeated announcement).
        max_events: AT-SPI event budget for the step. allow_deluge: do not fail
        when Orca is flooded during this step (Qt's own file dialog floods it
        while a path is typed; that is not the app's doing). Returns the StepRecord."""
        mark = self.mark()
        for k in keys:
            self.key(k)
        if type_text is not None:
            self.type(type_text)
        rec = StepRecord(name)
        failure = None
        try:
            for pattern in expect:
                self.wait_phrase(pattern, mark, timeout, what=f"'{name}': Orca to say /{pattern}/")
            if not expect and not allow_silent:
                self._wait(lambda: self.phrases_since(mark), f"'{name}': Orca to say anything", timeout)
        except StepFailed as e:
            failure = str(e)
        if settle:  # else the next step follows at once (a job still running)
            self.settle(mark, quiet)
        heard = self.phrases_since(mark)
        rec.phrases = [p.text for p in heard]
        if heard:
            rec.first_word_after = max(0.0, heard[0].seconds - mark[2])
        events = self.events_since(mark)
        rec.events = len(events)
        for _, t, _, _ in events:
            rec.event_types[t] = rec.event_types.get(t, 0) + 1
        rec.seconds = time.monotonic() - mark[3]
        self.steps.append(rec)
        if self.verbose:
            print(f"[{name}] heard {rec.phrases}; {rec.events} AT-SPI events"
                  + (f"; first word after {rec.first_word_after:.1f} s" if rec.first_word_after is not None else ""),
                  flush=True)
        if failure is None and not heard and not allow_silent:
            failure = f"'{name}' was silent"
        if failure is None:
            for pattern in forbid:
                hit = [t for t in rec.phrases if re.search(pattern, t, re.I | re.S)]
                if hit:
                    failure = f"'{name}': Orca said {hit}, which must not be heard"
                    break
        if failure is None:
            for pattern in once:
                n = sum(1 for t in rec.phrases if re.search(pattern, t, re.I | re.S))
                if n != 1:
                    failure = f"'{name}': /{pattern}/ heard {n} times, not once: {rec.phrases}"
                    break
        if failure is None and max_events is not None and rec.events > max_events:
            top = sorted(rec.event_types.items(), key=lambda kv: -kv[1])[:5]
            failure = f"'{name}': {rec.events} AT-SPI events, more than {max_events} (most: {top})"
        deluges = self.orca_log.deluges[mark[4]:]
        if failure is None and deluges and not allow_deluge:
            failure = f"'{name}': Orca was flooded ({len(deluges)} times): {deluges[0].strip()}"
        if failure:
            raise StepFailed(failure)
        return rec

    def summary(self):
        lines = []
        for r in self.steps:
            first = "-" if r.first_word_after is None else f"{r.first_word_after:.1f}"
            lines.append(f"{r.name:40s} phrases={len(r.phrases):3d} events={r.events:6d} first_word_s={first}")
        spoken = [r for r in self.steps if r.first_word_after is not None]
        if spoken:
            worst = max(spoken, key=lambda r: r.first_word_after)
            lines.append(f"longest wait for the first word: {worst.first_word_after:.1f} s ({worst.name})")
        return "\n".join(lines)


def run(main):
    """Runs `main(session_factory)` with the right exit codes: 77 when Orca or a
    window manager is missing, 1 with the transcript on a failed step."""
    missing = tools_missing()
    if missing:
        print("SKIP: not installed: " + ", ".join(missing) + " (tools/install-deps.sh)", file=sys.stderr)
        return SKIP
    try:
        return main() or 0
    except StepFailed as e:
        print("FAIL:", e, file=sys.stderr)
        return 1
    finally:
        # Orca's log and the AT-SPI events, for a CI artefact or a closer look.
        keep = os.environ.get("TACTUS_ORCA_ARTIFACTS")
        work = os.environ.get("TACTUS_WORK")
        if keep and work:
            os.makedirs(keep, exist_ok=True)
            for name in ("orca.log", "atspi-events.log", "app.log"):
                if os.path.exists(os.path.join(work, name)):
                    shutil.copy(os.path.join(work, name), os.path.join(keep, name))
