#!/usr/bin/env python3
"""Writes docs/default-old-new.md for scripts/compare-defaults.sh: the old and the new default's
interior miss, from the demo's headless README.txt files and the quick benchmark's miss baselines
(tests/bench/miss_baseline.csv of each revision). Standard library only."""
import argparse
import csv
import re
import statistics

SWEEP_SCENES = ["plane-edge-0", "plane-edge-20", "plane-edge-45", "plane-spot", "plane-disk", "plane-albedo"]
# The sweep's footprints (tests/bench/sweep_geometry.hpp): 0.05 * 40^(k/6). Frames shrink as the
# footprint grows, so each plane's frame sizes, largest first, are these footprints in order.
FOOTPRINTS = [0.05 * 40 ** (k / 6) for k in range(7)]


def sweep(path):
    """{footprint: [(scene, miss, worst channel)]} of the default (separable, 17 taps, follow-surface)."""
    rows = [r for r in csv.DictReader(open(path)) if r["scene"] in SWEEP_SCENES
            and r["method"] == "separable" and r["taps"] == "17" and r["follow_surface"] == "1"]
    out = {f: [] for f in FOOTPRINTS}
    for scene in SWEEP_SCENES:
        mine = sorted((r for r in rows if r["scene"] == scene), key=lambda r: -int(r["width"]))
        if len(mine) != len(FOOTPRINTS):
            raise SystemExit(f"{path}: {scene} has {len(mine)} sweep rows, expected {len(FOOTPRINTS)}")
        for f, r in zip(FOOTPRINTS, mine):
            worst = max(float(r["miss_interior_" + c]) for c in "rgb")
            out[f].append((scene, float(r["miss_interior"]), worst))
    return out


def demo(path):
    text = open(path).read()
    m = re.search(r"^\s*(\w+)\s+marked.*?interior \((\d+) px\) miss ([0-9.]+|inf) \(worst channel ([0-9.]+|inf); no SSS: 1\); "
                  r"relative RMSE ([0-9.]+) with SSS, ([0-9.]+) without", text, re.M)
    if not m:
        raise SystemExit(f"{path}: no error line")
    return m.group(1), float(m.group(3)), float(m.group(4)), float(m.group(5)), float(m.group(6))


def demo_time(path):
    """The sss pass's median time (ms) in the demo's README.txt."""
    m = re.search(r"^\s*\w+\s+shadow.*?sss\s+([0-9.]+)", open(path).read(), re.M)
    return float(m.group(1)) if m else float("nan")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--old-revision", required=True)
    p.add_argument("--old-miss", required=True)
    p.add_argument("--new-miss", required=True)
    p.add_argument("--old-demo", nargs="+", required=True)
    p.add_argument("--new-demo", nargs="+", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    old, new = sweep(a.old_miss), sweep(a.new_miss)
    md = ["# The old and the new default side by side", "",
          "What changed for a host that upgrades from 0.1 with default settings, in pictures and `miss`; the "
          "changes themselves and what to do about them: [migration.md](migration.md).", "",
          f"Written by `scripts/compare-defaults.sh` (old: revision {a.old_revision}, sss 0.1's default: Table 1 at "
          "`width = 1.5 · world units per mm`, fixed taps read bilinearly; new: this checkout's default, physical "
          "units and footprint-aware taps, docs/kernel-fits.md); do not edit by hand. `miss` = ‖result − exact‖ / "
          "‖input − exact‖ on the interior (0: exact, 1: as wrong as doing nothing; docs/benchmarks.md).", "",
          "## The demo's head (960×540, llvmpipe, EGL)", "",
          "| shot | old interior miss | old worst channel | new interior miss | new worst channel | old rel. RMSE | "
          "new rel. RMSE | no filter rel. RMSE |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    times = []
    for o, n in zip(a.old_demo, a.new_demo):
        so, mo, wo, ro, none = demo(o)
        sn, mn, wn, rn, _ = demo(n)
        md.append(f"| {so} | {mo:.3f} | {wo:.3f} | {mn:.3f} | {wn:.3f} | {ro:.4f} | {rn:.4f} | {none:.4f} |")
        times.append((so, demo_time(o), demo_time(n)))
    md += ["", "The filter's pass time in the same run (median of the demo's timed frames, glFinish around each "
           "pass, milliseconds; the two demos ran one after the other on this machine):", "",
           "| shot | old sss ms | new sss ms |", "|---|---:|---:|"]
    md += [f"| {shot} | {old_ms:.2f} | {new_ms:.2f} |" for shot, old_ms, new_ms in times]
    md += ["", "Pictures (old | new): the nose shadow at the close-up, "
           "[after](demo/default-old-new-close.png) and [|error| heat map](demo/default-old-new-close-heat.png); "
           "the far shot, [after](demo/default-old-new-far.png) and [heat map](demo/default-old-new-far-heat.png).",
           "", "## The footprint sweep (the quick benchmark's planes, default 17 taps)", "",
           "Interior miss over the six planes facing the camera at each footprint: median, largest, and the worst "
           "single channel (above 1: that channel made worse than doing nothing).", "",
           "| mm per pixel | old median | old largest | old worst channel | new median | new largest | new worst channel |",
           "|---:|---:|---:|---:|---:|---:|---:|"]
    every_old, every_new = [], []
    for f in FOOTPRINTS:
        mo = [m for _, m, _ in old[f]]
        mn = [m for _, m, _ in new[f]]
        every_old += mo
        every_new += mn
        md.append(f"| {f:.3g} | {statistics.median(mo):.3f} | {max(mo):.3f} | {max(w for *_, w in old[f]):.2f} | "
                  f"{statistics.median(mn):.3f} | {max(mn):.3f} | {max(w for *_, w in new[f]):.2f} |")
    md.append(f"| all | {statistics.median(every_old):.3f} | {max(every_old):.3f} | "
              f"{max(w for f in FOOTPRINTS for *_, w in old[f]):.2f} | {statistics.median(every_new):.3f} | "
              f"{max(every_new):.3f} | {max(w for f in FOOTPRINTS for *_, w in new[f]):.2f} |")
    md += ["", "Per plane (old → new):", "", "| plane | " + " | ".join(f"{f:.3g}" for f in FOOTPRINTS) + " |",
           "|---|" + "---:|" * len(FOOTPRINTS)]
    for i, scene in enumerate(SWEEP_SCENES):
        md.append(f"| {scene} | " + " | ".join(f"{old[f][i][1]:.2f} → {new[f][i][1]:.2f}" for f in FOOTPRINTS) + " |")
    open(a.out, "w").write("\n".join(md) + "\n")


if __name__ == "__main__":
    main()
