#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes every AT-SPI event one application sends, one tab-separated line each:
monotonic time, event type, source role, source name. The Orca harness
(orca_session.py) runs it beside Orca and counts the lines of each step, so a
test can bound how many events a screen reader must swallow (a progress bar that
changes per strike floods Orca into its "DELUGE" mode).

usage: atspi_event_log.py APP_NAME OUT_FILE
The first line written is "READY" once the listener is registered.
"""
import sys
import time

import pyatspi


def main():
    app_name, path = sys.argv[1], sys.argv[2]
    out = open(path, "w", buffering=1, encoding="utf-8")

    def on_event(event):
        try:
            app = event.host_application
            if app is None or app.name != app_name:
                return
            # source_role / source_name come with the event: no round trip to the app.
            role = event.source_role
            name = (event.source_name or "").replace("\t", " ").replace("\n", " ")
        except Exception:  # the source died while the event was in flight
            return
        out.write(f"{time.monotonic():.3f}\t{event.type}\t{role}\t{name}\n")

    pyatspi.Registry.registerEventListener(on_event, "object:", "window:", "focus:")
    out.write("READY\n")
    pyatspi.Registry.start()


if __name__ == "__main__":
    main()
