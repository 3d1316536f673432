#!/usr/bin/python3
"""Pairs the segments of bench/timedemo_signs.replay's timedemo (its `timedemo-segment` lines on
stdin): the sign mode alternates every second, so each "shafts" segment is compared with the "off"
segment just before it, frame time median against frame time median (the solver's steps, every
third tick, fall in both alike), and the ratios' median printed for the segments before the smoke
(shafts alone: on / off) and after it (shafts + smoke / smoke alone).

Usage: obscura --headless --timedemo bench/timedemo_signs.replay | bench/sign_cost.py
"""
import re
import statistics
import sys


def main():
    segments = []
    for line in sys.stdin:
        if not line.startswith("timedemo-segment "):
            continue
        fields = dict(re.findall(r'(\w+)=("[^"]*"|\S+)', line))
        segments.append((fields["label"].strip('"'), float(fields["median_ms"]), int(fields["frames"])))
    smoke = False
    pairs = {False: [], True: []}
    previous = None
    for label, median, frames in segments:
        if label.startswith("smoke-at"):
            smoke = True
            continue
        mode = label.split("=", 1)[1] if label.startswith("sign-mode=") else None
        if mode == "shafts" and previous and previous[0] == "off" and previous[2] == smoke:
            pairs[smoke].append((median, previous[1]))
        previous = (mode, median, smoke) if mode else None
    if not pairs[False] and not pairs[True]:
        print("sign_cost: no sign-mode segments on stdin", file=sys.stderr)
        return 1
    for has_smoke, name in ((False, "shafts on / off (no smoke)"), (True, "shafts + smoke / smoke alone")):
        p = pairs[has_smoke]
        if not p:
            continue
        ratios = [a / b for a, b in p]
        print(f"{name}: median ratio {statistics.median(ratios):.3f} over {len(p)} pairs "
              f"(min {min(ratios):.3f}, max {max(ratios):.3f}); frame medians on "
              f"{statistics.median(a for a, _ in p):.1f} ms, off {statistics.median(b for _, b in p):.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
