#!/usr/bin/python3
"""Pairs the segments of bench/timedemo_signs.replay's timedemo (its `timedemo-segment` lines on
stdin): the sign mode alternates every second, so each "shafts" segment is compared with the mean of
the "off" segments just before and just after it, in frame time medians and in the process's CPU
time a frame (which a busy machine disturbs less); the solver's steps, every third tick, fall in
all alike. The mean of the two neighbours cancels a drift that is linear over the three seconds:
the smoke cloud keeps spreading, so pairing with the second before alone would charge its growth
to the shafts. A shafts segment without an off on both sides is not paired, nor is the first
segment after the smoke's release (its bloom: the cloud grows from nothing). Printed: the ratios'
median for the segments before the smoke (shafts alone: on / off) and after it (shafts + smoke /
smoke alone).

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
        segments.append((fields["label"].strip('"'), float(fields["median_ms"]), float(fields["cpu_ms"])))
    # (mode, (median ms, process CPU ms a frame), after the smoke's release, the bloom) per segment.
    rows = []
    smoke = bloom = False
    for label, median, cpu in segments:
        if label.startswith("smoke-at"):
            smoke = bloom = True
            continue
        mode = label.split("=", 1)[1] if label.startswith("sign-mode=") else None
        rows.append((mode, (median, cpu), smoke, bloom))
        bloom = False
    pairs = {False: [], True: []}
    for k in range(1, len(rows) - 1):
        (before, on, after) = rows[k - 1], rows[k], rows[k + 1]
        if on[0] != "shafts" or before[0] != "off" or after[0] != "off":
            continue
        if not (before[2] == on[2] == after[2]) or before[3]:
            continue
        pairs[on[2]].append(tuple((on[1][m], (before[1][m] + after[1][m]) / 2) for m in (0, 1)))
    if not pairs[False] and not pairs[True]:
        print("sign_cost: no sign-mode segments on stdin", file=sys.stderr)
        return 1
    for has_smoke, name in ((False, "shafts on / off (no smoke)"), (True, "shafts + smoke / smoke alone")):
        p = pairs[has_smoke]
        if not p:
            continue
        for m, what in ((0, "wall time"), (1, "process CPU time")):
            ratios = [q[m][0] / q[m][1] for q in p]
            print(f"{name}, {what}: median ratio {statistics.median(ratios):.3f} over {len(p)} pairs "
                  f"(min {min(ratios):.3f}, max {max(ratios):.3f}); frame medians on "
                  f"{statistics.median(q[m][0] for q in p):.1f} ms, off {statistics.median(q[m][1] for q in p):.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
