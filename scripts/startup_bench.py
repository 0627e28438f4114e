#!/usr/bin/env python3
"""The game's start-up, whole process (docs/performance.md, "Start-up").

Launches build/bin/killswitch as a player does (the loading screen, then the main menu over levels/main.json)
and with `--screen play` (the level's first frame), with KS_STARTUP_TRACE (common/core/startup_trace.h), and
stops it once the frame it waits for is on screen. Wall time counts from just before the launch, so process
start and dynamic linking are in it; the breakdown is the time between the game's own marks. Each launch gets
fresh config and data folders (default options); the cache folder (XDG_CACHE_HOME) is empty for a cold
start, or one an earlier launch filled for a warm start. Launches are interleaved (one of each column per
round) so the machine's load falls on all columns alike.

--before OLD_EXE adds same-run before/after columns: the whole process of `--screen menu|play --screenshot
FILE --frames 1` (window, load, one frame, PNG, exit) for both executables, and the traced first frames of
both (the old one must write the trace too, as every build since the trace came does), each cold and warm.

Run it under a display:
  xvfb-run -a -s "-screen 0 1280x720x24" scripts/startup_bench.py [--runs 5] [--before OLD_EXE] [--exe EXE]
"""
import argparse
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SCENARIOS = [
    ("main menu (no option: loading screen, then the menu over levels/main.json)", "frame: menu", []),
    ("level (--screen play, levels/main.json)", "frame: playing", ["--screen", "play"]),
]


def environment(home, cache, trace=None):
    env = {k: v for k, v in os.environ.items() if not k.startswith("XDG_") and k != "KS_STARTUP_TRACE"}
    env["XDG_CONFIG_HOME"] = os.path.join(home, "config")
    env["XDG_DATA_HOME"] = os.path.join(home, "data")
    env["XDG_CACHE_HOME"] = cache
    if trace:
        env["KS_STARTUP_TRACE"] = trace
    return env


def parse_trace(path, screen_mark):
    """The marks (phase, monotonic ns, thread CPU ns, process CPU ns) up to the first frame presented after
    `screen_mark`; None while that frame has not come."""
    try:
        with open(path) as f:
            lines = f.read().splitlines()
    except OSError:
        return None
    marks, seen = [], False
    for line in lines:
        parts = line.split("\t")
        if len(parts) != 4:
            continue
        marks.append((parts[0], int(parts[1]), int(parts[2]), int(parts[3])))
        seen = seen or parts[0] == screen_mark
        if seen and parts[0] == "presented":
            return marks
    return None


def traced_launch(exe, args, screen_mark, home, cache):
    trace = os.path.join(home, "trace.txt")
    if os.path.exists(trace):
        os.remove(trace)
    env = environment(home, cache, trace)
    start = time.monotonic_ns()  # CLOCK_MONOTONIC, the clock the trace writes
    proc = subprocess.Popen([exe] + args, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    marks, deadline = None, time.monotonic() + 120
    while time.monotonic() < deadline:
        marks = parse_trace(trace, screen_mark)
        if marks or proc.poll() is not None:
            break
        time.sleep(0.002)
    if proc.poll() is None:
        proc.send_signal(signal.SIGKILL)
    proc.wait()
    if not marks:
        sys.exit(f"{exe} {' '.join(args)}: no '{screen_mark}' frame in the trace")
    # Each phase's wall time and process CPU time (all threads: llvmpipe's too) since the mark before it; the
    # CPU time is the steadier figure on a shared machine.
    phases, previous, previous_cpu = [], start, 0
    for phase, mono, _, cpu in marks:
        if phase != "presented" and not phase.startswith("frame: "):
            name = "process start, dynamic linking" if phase == "main" else phase
            phases.append((name, (mono - previous) / 1e6, (cpu - previous_cpu) / 1e6))
            previous, previous_cpu = mono, cpu
    phases.append(("frames until the screen is shown (first render)", (marks[-1][1] - previous) / 1e6,
                   (marks[-1][3] - previous_cpu) / 1e6))
    return {
        "wall": (marks[-1][1] - start) / 1e6,
        "main thread CPU": marks[-1][2] / 1e6,
        "process CPU (all threads)": marks[-1][3] / 1e6,
        "phases": phases,
    }


def exit_launch(exe, args, home, cache):
    """Whole process of a one-frame screenshot run: launch to exit."""
    shot = os.path.join(home, "shot.png")
    start = time.monotonic_ns()
    subprocess.run([exe] + args + ["--screenshot", shot, "--frames", "1"], env=environment(home, cache),
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return (time.monotonic_ns() - start) / 1e6


def table(title, columns, rows):
    print(f"\n{title}")
    print(f"{'':50}" + "".join(f"{c:>17}" for c in columns))
    for name, values in rows:
        print(f"{name[:50]:50}" + "".join(f"{v:>17.0f}" for v in values))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "bin", "killswitch"))
    parser.add_argument("--before", help="an older killswitch (with the trace) for same-run before/after columns")
    opts = parser.parse_args()
    exe = os.path.abspath(opts.exe)
    root = tempfile.mkdtemp(prefix="ks_startup_")
    # (label, executable): the build measured, and with --before the older one, each cold and warm.
    builds = [("before", os.path.abspath(opts.before))] if opts.before else []
    builds.append(("after" if opts.before else "", exe))
    try:
        if opts.before:
            columns = [f"{b} {c}" for b, _ in builds for c in ("cold", "warm")]
            for name, _, args in SCENARIOS:
                shot_args = args if args else ["--screen", "menu"]
                times = {c: [] for c in columns}
                for r in range(opts.runs):
                    for label, program in builds:
                        for c in ("cold", "warm"):
                            home = os.path.join(root, "home_exit")
                            shutil.rmtree(home, ignore_errors=True)
                            os.makedirs(home)
                            cache = os.path.join(root, f"{label}_{c}_exit")
                            if c == "cold":
                                shutil.rmtree(cache, ignore_errors=True)
                            elif r == 0:
                                exit_launch(program, shot_args, home, cache)
                            times[f"{label} {c}"].append(exit_launch(program, shot_args, home, cache))
                med = [statistics.median(times[c]) for c in columns]
                table(f"{name}: whole process of {' '.join(shot_args)} --screenshot F --frames 1, "
                      f"median of {opts.runs} (ms)", columns, [("launch to exit", med),
                                                                ("ratio to before cold", [100 * m / med[0] for m in med])])
        for name, mark, args in SCENARIOS:
            columns = [f"{b} {c}".strip() for b, _ in builds for c in ("cold", "warm")]
            results = {c: [] for c in columns}
            shown = [f"{c} {k}" for c in columns for k in ("wall", "CPU")]
            shot_args = args if args else ["--screen", "menu"]
            for r in range(opts.runs):
                for label, program in builds:
                    for c in ("cold", "warm"):
                        home = os.path.join(root, "home")
                        shutil.rmtree(home, ignore_errors=True)
                        os.makedirs(home)
                        cache = os.path.join(root, f"{label}_{c}")
                        if c == "cold":
                            shutil.rmtree(cache, ignore_errors=True)
                        elif r == 0:
                            # Filled by a launch that runs to its end: an interactive start computes the full
                            # light bake on a worker after the first frame and stores it when done.
                            exit_launch(program, shot_args, home, cache)
                        results[f"{label} {c}".strip()].append(traced_launch(program, args, mark, home, cache))
            rows = []
            def med(c, key):
                return statistics.median(x[key] for x in results[c])
            rows.append(("first frame (wall; CPU: all threads)",
                         [v for c in columns for v in (med(c, "wall"), med(c, "process CPU (all threads)"))]))
            rows.append(("  of which the main thread's CPU",
                         [v for c in columns for v in (float("nan"), med(c, "main thread CPU"))]))
            order = []
            for c in columns:
                for x in results[c]:
                    for phase, _, _ in x["phases"]:
                        if phase not in order:
                            order.append(phase)
            for phase in order:
                values = []
                for c in columns:
                    for i in (1, 2):
                        values.append(statistics.median(sum(p[i] for p in x["phases"] if p[0] == phase)
                                                        for x in results[c]))
                rows.append(("  " + phase, values))
            table(f"{name}: first frame, median of {opts.runs} (ms; each phase since the mark before it)",
                  shown, rows)
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    main()
