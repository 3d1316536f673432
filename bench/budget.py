#!/usr/bin/python3
"""The frame's budget table from bench/timedemo_budget.replay's timedemo (its `timedemo-segment`
lines on stdin): each effect's added cost as a ratio of the plain frame, in frame-time medians and
in process CPU time a frame (which a busy machine disturbs less).

  AO, sign light   each such segment against the mean of the plain segments either side of it
                   (a drift linear over the three seconds cancels)
  clouds           the clouds-alone segments against the plain segments before the release (the
                   clouds cannot be taken away again; the machine's drift over the run is in it)
  all              AO + signs + clouds segments against the same plain frame
  p99 / median     of the clouds' segments (p95 where the game printed no p99)

Usage: obscura --headless --timedemo bench/timedemo_budget.replay | bench/budget.py
"""
import re
import statistics
import sys


def main():
    segs = []
    for line in sys.stdin:
        if line.startswith("timedemo-segment "):
            f = dict(re.findall(r'(\w+)=("[^"]*"|\S+)', line))
            segs.append({"label": f["label"].strip('"'), "median": float(f["median_ms"]), "cpu": float(f["cpu_ms"]),
                         "tail": float(f.get("p99_ms", f["p95_ms"])), "frames": int(f["frames"])})
    if len(segs) < 11:
        sys.exit("budget.py: expected the 11 segments of bench/timedemo_budget.replay, got %d" % len(segs))

    def kind(i):
        label = segs[i]["label"]
        if "smoke-at" in label:
            return "bloom"
        smoke = any("smoke-at" in s["label"] for s in segs[:i])
        on = "ssao=combined" in label
        signs = "sign-mode=shafts" in label
        if smoke:
            return "all" if on and signs else ("clouds" if not on and not signs else "?")
        if label == "start" or (not on and not signs):
            return "plain"
        return "ao" if on else "signs"

    kinds = [kind(i) for i in range(len(segs))]
    plainBefore = [s for s, k in zip(segs, kinds) if k == "plain"]
    base = {m: statistics.mean(s[m] for s in plainBefore) for m in ("median", "cpu")}
    rows = []

    def neighbours(i, m):
        near = [segs[j][m] for j in (i - 1, i + 1) if 0 <= j < len(segs) and kinds[j] == "plain"]
        return statistics.mean(near) if len(near) == 2 else None

    for name, k in (("default AO (combined)", "ao"), ("sign light, no sign in view", "signs")):
        for m in ("median", "cpu"):
            r = [segs[i][m] / neighbours(i, m) - 1 for i in range(len(segs)) if kinds[i] == k and neighbours(i, m)]
            rows.append((name, m, "+%.3f" % statistics.median(r) if r else "-"))
    for name, k, total in (("two clouds (added)", "clouds", False), ("AO + signs + two clouds (total)", "all", True)):
        for m in ("median", "cpu"):
            r = [s[m] / base[m] - (0 if total else 1) for s, kk in zip(segs, kinds) if kk == k]
            rows.append((name, m, ("%.2fx" if total else "+%.2fx") % statistics.median(r) if r else "-"))
    clouds = [s for s, k in zip(segs, kinds) if k in ("clouds", "all")]
    print("plain frame: median %.1f ms, process CPU %.1f ms a frame (the %d plain segments before the smoke)"
          % (base["median"], base["cpu"], len(plainBefore)))
    print("| effect | measure | vs the plain frame |")
    print("|---|---|---|")
    for name, m, v in rows:
        print("| %s | %s | %s |" % (name, "frame median" if m == "median" else "process CPU", v))
    print("| smoke in view: tail / median | p99 (or p95) / median, worst segment | %.2f |"
          % max(s["tail"] / s["median"] for s in clouds))


if __name__ == "__main__":
    main()
