#!/usr/bin/env python3
"""Soak: a long scripted session of continuous fire, reloads, a grenade every 2 s and movement,
played by the real game (headless, every tick rendered) while this script samples the process's
resident memory (VmRSS) and CPU time (utime + stime, every thread) at every 600th tick.

The session is a replay script written here (so the run is deterministic and needs no window):
  - the rifle held down for 200 ticks (its 30 rounds at 10 a second, then dry), released, R tapped:
    one magazine and one reload every 6 s;
  - G tapped every 120 ticks (2 s): with the smoke cap of 4 volumes the oldest cloud is recycled
    every 2 s, the whole life cycle of a volume (spawn, step, carve, drop) over and over;
  - strafing left and right in turn every 3 s and turning 90 degrees a cycle, so shots, bullet
    holes and grenades land on changing walls and floors.

Verdict (the issue's soak goals):
  - RSS growth after warm-up <= 5 %: the mean of the last 10 samples against the mean of the 10
    samples after the warm-up (the first WARMUP_MINUTES simulated minutes fill the decal ring,
    the smoke cap and OGRE's caches and are not counted);
  - CPU per 600 ticks: reported sample by sample; "flat" is judged as the last third's median
    against the first third's (after warm-up), a ratio printed beside its limit.
Exit 0 when both hold, 1 otherwise, 2 on a usage or run error.

Usage: tools/soak/soak.py GAME [--minutes 30] [--smoke-resolution 32|64] [--out bench/soak.txt] [--keep-script F]
Run under an X server (xvfb-run -a). A sanitizer build with detect_leaks=1 in ASAN_OPTIONS makes
a short run the LeakSanitizer check (tests/soak).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

TICK_RATE = 60
SAMPLE_TICKS = 600          # one sample per 10 s of game time
CYCLE_TICKS = 360           # fire 200 ticks, reload, strafe the other way, turn
WARMUP_MINUTES = 2          # decal ring (256) full after ~26 s of fire; smoke cap full after 8 s
RSS_GROWTH_LIMIT = 0.05     # the goal
CPU_DRIFT_LIMIT = 1.10      # last third's median CPU per sample against the first third's


def write_script(path, minutes):
    ticks = int(minutes * 60 * TICK_RATE)
    lines = ["# tools/soak/soak.py: continuous fire, reloads, a grenade every 2 s, movement",
             "obscura-replay 1", "level media/levels/arena.map", "seed 7", "resolution 160 90",
             "tickrate %d" % TICK_RATE, "start 0 1.65 0 30 -5", ""]
    events = []
    for start in range(0, ticks, CYCLE_TICKS):
        side = "a" if (start // CYCLE_TICKS) % 2 == 0 else "d"
        events += [(start + 1, "button left down"), (start + 201, "button left up"),
                   (start + 202, "key r tap"), (start + 1, "key %s down" % side),
                   (start + 180, "key %s up" % side), (start + 210, "mouse 4090 0")]
    for t in range(60, ticks, 120):
        events.append((t, "key g tap"))
    for t in range(SAMPLE_TICKS, ticks + 1, SAMPLE_TICKS):
        events.append((t - 1, "hash"))
    events = sorted(e for e in events if e[0] < ticks)
    lines += ["%d %s" % e for e in events] + ["%d end" % ticks]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return ticks


def proc_sample(pid):
    with open("/proc/%d/status" % pid) as f:
        rss_kb = next(int(l.split()[1]) for l in f if l.startswith("VmRSS:"))
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    cpu_s = (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime
    return rss_kb / 1024.0, cpu_s


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("game")
    ap.add_argument("--minutes", type=float, default=30.0, help="simulated minutes (default 30)")
    ap.add_argument("--out", help="also write the report here")
    ap.add_argument("--smoke-resolution", default="64", choices=["32", "64"],
                    help="the smoke grid (32: an eighth of the solver's cost, for a 30-minute run here)")
    ap.add_argument("--keep-script", help="write the replay script here instead of a temp file")
    a = ap.parse_args()
    if not (0.2 <= a.minutes <= 600):
        print("soak: --minutes must be 0.2 to 600", file=sys.stderr)
        return 2

    work = tempfile.mkdtemp(prefix="obscura-soak-")
    script = a.keep_script or os.path.join(work, "soak.replay")
    ticks = write_script(script, a.minutes)
    p = subprocess.Popen([a.game, "--replay", script, "--capture-dir", work, "--smoke-resolution", a.smoke_resolution], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, bufsize=1)
    samples, tail = [], []
    for line in p.stdout:
        tail = (tail + [line.rstrip()])[-20:]
        if line.startswith("hash "):
            tick = int(line.split()[1]) + 1
            rss, cpu = proc_sample(p.pid)
            samples.append((tick, rss, cpu))
            if len(samples) % 18 == 0:  # every 3 simulated minutes
                print("soak: tick %d of %d, RSS %.1f MiB" % (tick, ticks, rss), file=sys.stderr, flush=True)
    rc = p.wait()
    if rc != 0 or len(samples) < 3:
        print("soak: the game exited %d after %d samples:\n%s" % (rc, len(samples), "\n".join(tail)), file=sys.stderr)
        return 2

    out = ["soak: %s, %.1f simulated minutes (%d ticks at %d Hz, 160x90, every tick rendered, smoke grid %s^3)"
           % (os.path.basename(script), a.minutes, ticks, TICK_RATE, a.smoke_resolution),
           "  tick    game-min   RSS MiB   CPU s/600 ticks"]
    prev_cpu = 0.0
    per = []
    for tick, rss, cpu in samples:
        per.append(cpu - prev_cpu)
        out.append("  %6d  %8.1f  %8.1f  %8.2f" % (tick, tick / TICK_RATE / 60, rss, cpu - prev_cpu))
        prev_cpu = cpu
    warm = [i for i, s in enumerate(samples) if s[0] > WARMUP_MINUTES * 60 * TICK_RATE]
    ok = True
    if len(warm) >= 6:
        n = min(10, len(warm) // 3)
        first = statistics.mean(samples[i][1] for i in warm[:n])
        last = statistics.mean(samples[i][1] for i in warm[-n:])
        growth = last / first - 1
        third = max(1, len(warm) // 3)
        cpu_first = statistics.median(per[i] for i in warm[:third])
        cpu_last = statistics.median(per[i] for i in warm[-third:])
        drift = cpu_last / cpu_first
        ok = growth <= RSS_GROWTH_LIMIT and drift <= CPU_DRIFT_LIMIT
        out += ["RSS after warm-up (%d min): %.1f MiB -> %.1f MiB, growth %+.2f %% (limit %+.0f %%)"
                % (WARMUP_MINUTES, first, last, growth * 100, RSS_GROWTH_LIMIT * 100),
                "CPU per 600 ticks: first third median %.2f s, last third %.2f s, ratio %.3f (limit %.2f)"
                % (cpu_first, cpu_last, drift, CPU_DRIFT_LIMIT),
                "verdict: %s" % ("pass" if ok else "FAIL")]
    else:
        out.append("verdict: too short for the growth figures (%d samples after warm-up); the run itself passed"
                   % len(warm))
    report = "\n".join(out) + "\n"
    sys.stdout.write(report)
    if a.out:
        with open(a.out, "w") as f:
            f.write(report)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
